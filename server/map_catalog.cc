#include "server/map_catalog.h"

#include <algorithm>
#include <optional>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "server/ids.h"
#include "server/map_source.h"
#include "server/proto_convert.h"
#include "server/request_validation.h"

namespace swarmplan::server {
namespace {

absl::StatusOr<std::shared_ptr<const CatalogEntry>> MakeEntry(const StoredMap& stored,
                                                              const v1::MapSource& source,
                                                              const LoadOptions& options) {
  absl::StatusOr<Map> map = BuildMap(source, options);
  if (!map.ok()) return map.status();
  auto entry = std::make_shared<CatalogEntry>();
  entry->info = DescribeMap(*map);
  entry->info.set_id(stored.id);
  entry->info.set_name(stored.name);
  *entry->info.mutable_created_at() = ToProto(stored.created_at);
  entry->info.set_content_hash(stored.content_hash);
  entry->info.set_format(stored.format);
  entry->map = std::make_shared<const Map>(std::move(*map));
  return entry;
}

// Where a map stands in listings.
PageKey KeyOf(const CatalogEntry& entry) {
  return PageKey{absl::ToUnixMicros(FromProto(entry.info.created_at())), entry.info.id()};
}

constexpr char kListScope[] = "maps";

}  // namespace

absl::StatusOr<std::vector<std::string>> MapCatalog::Load() {
  absl::StatusOr<std::vector<StoredMap>> stored = store_.LoadMaps();
  if (!stored.ok()) return stored.status();
  std::vector<std::string> warnings;
  std::vector<std::shared_ptr<const CatalogEntry>> entries;
  for (const StoredMap& m : *stored) {
    v1::MapSource source;
    if (!source.ParseFromString(m.source)) {
      warnings.push_back(absl::StrCat("map ", m.id, ": stored source is corrupt"));
      continue;
    }
    absl::StatusOr<std::shared_ptr<const CatalogEntry>> entry = MakeEntry(m, source, load_options_);
    if (!entry.ok()) {
      warnings.push_back(absl::StrCat("map ", m.id, ": ", entry.status().message()));
      continue;
    }
    entries.push_back(std::move(*entry));
  }
  absl::MutexLock lock(&mu_);
  entries_ = std::move(entries);
  return warnings;
}

absl::StatusOr<MapCatalog::UploadResult> MapCatalog::Upload(const std::string& name,
                                                            const v1::MapSource& source) {
  if (absl::Status s = CheckMapName(name); !s.ok()) return s;
  StoredMap stored;
  source.SerializeToString(&stored.source);
  stored.content_hash = ContentHash(stored.source);
  stored.name = name;
  stored.format = SourceFormat(source);

  absl::MutexLock upload_lock(&upload_mu_);
  {
    absl::MutexLock lock(&mu_);
    for (const auto& e : entries_) {
      if (e->info.name() == name && e->info.content_hash() == stored.content_hash) {
        return UploadResult{e->info, false};
      }
    }
  }
  stored.id = NewId("map-");
  // Microseconds: what the store keeps, so a map reads the same before and after a restart.
  stored.created_at = absl::FromUnixMicros(absl::ToUnixMicros(absl::Now()));
  absl::StatusOr<std::shared_ptr<const CatalogEntry>> entry =
      MakeEntry(stored, source, load_options_);
  if (!entry.ok()) return entry.status();
  if (absl::Status s = store_.PutMap(stored); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  const PageKey key = KeyOf(**entry);
  entries_.insert(std::upper_bound(entries_.begin(), entries_.end(), key,
                                   [](const PageKey& k, const auto& e) { return k < KeyOf(*e); }),
                  *entry);
  return UploadResult{(*entry)->info, true};
}

absl::StatusOr<std::shared_ptr<const CatalogEntry>> MapCatalog::Get(const std::string& id) const {
  if (id.empty()) return absl::InvalidArgumentError("map id: required");
  absl::MutexLock lock(&mu_);
  for (const auto& e : entries_) {
    if (e->info.id() == id) return e;
  }
  return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
}

absl::StatusOr<v1::MapSource> MapCatalog::GetSource(const std::string& id) const {
  absl::StatusOr<StoredMap> stored = store_.GetMap(id);
  if (!stored.ok()) return stored.status();
  v1::MapSource source;
  if (!source.ParseFromString(stored->source)) {
    return absl::DataLossError(absl::StrCat("map '", id, "': stored source is corrupt"));
  }
  return source;
}

absl::StatusOr<MapCatalog::Page> MapCatalog::List(int page_size, size_t max_bytes,
                                                  const std::string& page_token) const {
  std::optional<PageKey> after;
  if (!page_token.empty()) {
    absl::StatusOr<PageKey> key = DecodePageToken(page_token, kListScope);
    if (!key.ok()) return key.status();
    after = std::move(*key);
  }
  absl::MutexLock lock(&mu_);
  auto it = entries_.begin();
  if (after.has_value()) {
    it = std::upper_bound(entries_.begin(), entries_.end(), *after,
                          [](const PageKey& k, const auto& e) { return k < KeyOf(*e); });
  }
  Page page;
  size_t bytes = 0;
  for (; it != entries_.end() && static_cast<int>(page.maps.size()) < page_size; ++it) {
    const size_t item = (*it)->info.ByteSizeLong();
    if (!FitsPage(bytes, item, max_bytes)) break;
    bytes += item;
    page.maps.push_back((*it)->info);
  }
  if (it != entries_.end() && !page.maps.empty()) {
    page.next_page_token = EncodePageToken(KeyOf(**std::prev(it)), kListScope);
  }
  return page;
}

absl::Status MapCatalog::Delete(const std::string& id) {
  if (id.empty()) return absl::InvalidArgumentError("id: required");
  absl::MutexLock upload_lock(&upload_mu_);
  {
    absl::MutexLock lock(&mu_);
    auto it = std::find_if(entries_.begin(), entries_.end(),
                           [&](const auto& e) { return e->info.id() == id; });
    if (it == entries_.end()) return absl::NotFoundError(absl::StrCat("map '", id, "' not found"));
  }
  if (absl::Status s = store_.DeleteMap(id); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                [&](const auto& e) { return e->info.id() == id; }),
                 entries_.end());
  return absl::OkStatus();
}

int MapCatalog::size() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(entries_.size());
}

}  // namespace swarmplan::server
