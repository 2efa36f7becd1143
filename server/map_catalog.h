#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "core/map/io/map_io.h"
#include "core/map/map.h"
#include "server/page_token.h"
#include "server/store.h"
#include "swarmplan/v1/maps.pb.h"

namespace swarmplan::server {

// A parsed map ready for planning, with its description.
struct CatalogEntry {
  v1::MapInfo info;
  MapPtr map;
};

// The maps the server holds: parsed in memory, stored durably in the Store. Thread-safe.
class MapCatalog {
 public:
  MapCatalog(Store& store, LoadOptions load_options)
      : store_(store), load_options_(std::move(load_options)) {}

  // Parses every stored map. A stored map that no longer parses is skipped and reported in
  // the returned list of warnings.
  absl::StatusOr<std::vector<std::string>> Load();

  struct UploadResult {
    v1::MapInfo info;
    bool created = false;
  };
  // Parses, stores, then adds the map. Identical content under the same name returns the
  // stored map.
  absl::StatusOr<UploadResult> Upload(const std::string& name, const v1::MapSource& source);

  // NOT_FOUND naming the id.
  absl::StatusOr<std::shared_ptr<const CatalogEntry>> Get(const std::string& id) const;
  absl::StatusOr<v1::MapSource> GetSource(const std::string& id) const;
  struct Page {
    std::vector<v1::MapInfo> maps;
    std::string next_page_token;  // empty on the last page
  };
  // Oldest first (by creation time, then id), continuing after `page_token`: at most `page_size`
  // maps and `max_bytes` serialized bytes (FitsPage). INVALID_ARGUMENT naming page_token for a
  // token List did not issue.
  absl::StatusOr<Page> List(int page_size, size_t max_bytes, const std::string& page_token) const;
  absl::Status Delete(const std::string& id);
  int size() const;

 private:
  Store& store_;
  const LoadOptions load_options_;
  mutable absl::Mutex mu_;
  // Ordered by KeyOf (creation time, then id); ids are unique.
  std::vector<std::shared_ptr<const CatalogEntry>> entries_ ABSL_GUARDED_BY(mu_);
  absl::Mutex upload_mu_;  // serialises uploads so identical concurrent uploads dedupe
};

}  // namespace swarmplan::server
