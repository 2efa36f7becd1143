#pragma once

#include <list>
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

// The maps the server can plan on. The store holds every map and its description, so every
// replica on a shared store sees the same maps; this process keeps only the parsed maps it
// planned on last, at most `cache_entries` of them, keyed by content hash. Thread-safe.
class MapCatalog {
 public:
  MapCatalog(Store& store, LoadOptions load_options, int cache_entries)
      : store_(store), load_options_(std::move(load_options)), cache_entries_(cache_entries) {}

  // Describes the stored maps an earlier version stored without a description (parsing each
  // once). A map that no longer parses is reported in the returned warnings.
  absl::StatusOr<std::vector<std::string>> Load();

  struct UploadResult {
    v1::MapInfo info;
    bool created = false;
  };
  // Parses, stores (as the next version of `name`), then caches the map. Content identical to
  // the name's latest version returns that version.
  absl::StatusOr<UploadResult> Upload(const std::string& name, const v1::MapSource& source);

  // The map as stored now (NOT_FOUND naming the id when it is not), parsed: from the cache, or
  // from the store's source.
  absl::StatusOr<std::shared_ptr<const CatalogEntry>> Get(const std::string& id);
  // The description alone, without parsing.
  absl::StatusOr<v1::MapInfo> GetInfo(const std::string& id) const;
  absl::StatusOr<v1::MapSource> GetSource(const std::string& id) const;
  // The description of version `version` of the map `name` (0: its latest); INVALID_ARGUMENT
  // naming the field for a bad name or version, NOT_FOUND when there is no such version.
  absl::StatusOr<v1::MapInfo> GetVersionInfo(const std::string& name, int64_t version) const;
  struct Page {
    std::vector<v1::MapInfo> maps;
    std::string next_page_token;  // empty on the last page
  };
  // Oldest first (by creation time, then id), or with a `name` that map's versions by version,
  // continuing after `page_token`: at most `page_size` maps and `max_bytes` serialized bytes
  // (FitsPage). INVALID_ARGUMENT naming page_token for a token this listing did not issue.
  absl::StatusOr<Page> List(const std::string& name, int page_size, size_t max_bytes,
                            const std::string& page_token) const;
  absl::Status Delete(const std::string& id);
  // Maps in the store; -1 when the store cannot say.
  int64_t size() const;
  // Parsed maps held in memory.
  int cached() const;

 private:
  // The parsed map of `stored` (which carries its source), from the cache or parsed now.
  absl::StatusOr<MapPtr> Parsed(const StoredMap& stored);
  void Cache(const std::string& content_hash, MapPtr map) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);

  Store& store_;
  const LoadOptions load_options_;
  const int cache_entries_;
  mutable absl::Mutex mu_;
  // Parsed maps by content hash, most recently used first.
  std::list<std::pair<std::string, MapPtr>> cache_ ABSL_GUARDED_BY(mu_);
  std::map<std::string, std::list<std::pair<std::string, MapPtr>>::iterator> cache_pos_
      ABSL_GUARDED_BY(mu_);
  absl::Mutex upload_mu_;  // serialises uploads so identical concurrent uploads dedupe
};

}  // namespace swarmplan::server
