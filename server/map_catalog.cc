#include "server/map_catalog.h"

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

constexpr char kListScope[] = "maps";

// Maps per store read while Load looks for maps without a description.
constexpr int kLoadBatch = 256;

// The description of a stored map, as clients see it.
absl::StatusOr<v1::MapInfo> InfoOf(const StoredMap& stored) {
  v1::MapInfo info;
  if (!info.ParseFromString(stored.info)) {
    return absl::DataLossError(
        absl::StrCat("map '", stored.id, "': stored description is corrupt"));
  }
  info.set_id(stored.id);
  info.set_name(stored.name);
  *info.mutable_created_at() = ToProto(stored.created_at);
  info.set_content_hash(stored.content_hash);
  info.set_format(stored.format);
  info.set_version(stored.version);
  return info;
}

absl::StatusOr<Map> Parse(const StoredMap& stored, const LoadOptions& options) {
  v1::MapSource source;
  if (!source.ParseFromString(stored.source)) {
    return absl::DataLossError(absl::StrCat("map '", stored.id, "': stored source is corrupt"));
  }
  return BuildMap(source, options);
}

}  // namespace

absl::StatusOr<std::vector<std::string>> MapCatalog::Load() {
  std::vector<std::string> warnings;
  std::optional<MapCursor> after;
  while (true) {
    absl::StatusOr<std::vector<StoredMap>> batch =
        store_.ListMaps(after.has_value() ? &*after : nullptr, kLoadBatch);
    if (!batch.ok()) return batch.status();
    for (const StoredMap& listed : *batch) {
      if (!listed.info.empty() && listed.version != 0) continue;
      absl::StatusOr<StoredMap> stored = store_.GetMap(listed.id);
      if (absl::IsNotFound(stored.status())) continue;  // deleted meanwhile
      if (!stored.ok()) return stored.status();
      if (stored->info.empty()) {
        absl::StatusOr<Map> map = Parse(*stored, load_options_);
        if (map.ok()) {
          DescribeMap(*map).SerializeToString(&stored->info);
        } else {
          warnings.push_back(absl::StrCat("map ", stored->id, ": ", map.status().message()));
        }
      }
      // Version 0 numbers the map after the older maps of its name (the listing is oldest first),
      // unless another replica numbered it meanwhile.
      if (absl::StatusOr<int64_t> v = store_.PutMap(*stored); !v.ok()) return v.status();
    }
    if (batch->size() < static_cast<size_t>(kLoadBatch)) break;
    after = MapCursor{absl::ToUnixMicros(batch->back().created_at), batch->back().id};
  }
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
  absl::StatusOr<StoredMap> latest = store_.FindMapVersion(name, 0);
  if (latest.ok() && latest->content_hash == stored.content_hash) {
    absl::StatusOr<v1::MapInfo> info = InfoOf(*latest);
    if (!info.ok()) return info.status();
    return UploadResult{*std::move(info), false};
  }
  if (!latest.ok() && !absl::IsNotFound(latest.status())) return latest.status();

  absl::StatusOr<Map> map = BuildMap(source, load_options_);
  if (!map.ok()) return map.status();
  stored.id = NewId("map-");
  // Microseconds: what the store keeps, so a map reads the same before and after a restart.
  stored.created_at = absl::FromUnixMicros(absl::ToUnixMicros(absl::Now()));
  DescribeMap(*map).SerializeToString(&stored.info);
  absl::StatusOr<int64_t> version = store_.PutMap(stored);
  if (!version.ok()) return version.status();
  stored.version = *version;
  absl::StatusOr<v1::MapInfo> info = InfoOf(stored);
  if (!info.ok()) return info.status();
  absl::MutexLock lock(&mu_);
  Cache(stored.content_hash, std::make_shared<const Map>(*std::move(map)));
  return UploadResult{*std::move(info), true};
}

void MapCatalog::Cache(const std::string& content_hash, MapPtr map) {
  if (auto it = cache_pos_.find(content_hash); it != cache_pos_.end()) {
    cache_.splice(cache_.begin(), cache_, it->second);
    return;
  }
  if (cache_entries_ <= 0) return;
  cache_.emplace_front(content_hash, std::move(map));
  cache_pos_[content_hash] = cache_.begin();
  while (cache_.size() > static_cast<size_t>(cache_entries_)) {
    cache_pos_.erase(cache_.back().first);
    cache_.pop_back();
  }
}

absl::StatusOr<MapPtr> MapCatalog::Parsed(const StoredMap& stored) {
  {
    absl::MutexLock lock(&mu_);
    if (auto it = cache_pos_.find(stored.content_hash); it != cache_pos_.end()) {
      MapPtr map = it->second->second;
      Cache(stored.content_hash, map);  // most recently used now
      return map;
    }
  }
  absl::StatusOr<StoredMap> with_source = store_.GetMap(stored.id);
  if (!with_source.ok()) return with_source.status();
  absl::StatusOr<Map> map = Parse(*with_source, load_options_);
  if (!map.ok()) {
    return absl::FailedPreconditionError(absl::StrCat(
        "map '", stored.id, "' no longer parses (", map.status().message(), "); upload it again"));
  }
  auto parsed = std::make_shared<const Map>(*std::move(map));
  absl::MutexLock lock(&mu_);
  Cache(stored.content_hash, parsed);
  return parsed;
}

absl::StatusOr<std::shared_ptr<const CatalogEntry>> MapCatalog::Get(const std::string& id) {
  if (id.empty()) return absl::InvalidArgumentError("map id: required");
  absl::StatusOr<StoredMap> stored = store_.GetMapInfo(id);
  if (!stored.ok()) return stored.status();
  auto entry = std::make_shared<CatalogEntry>();
  absl::StatusOr<v1::MapInfo> info = InfoOf(*stored);
  if (!info.ok()) return info.status();
  entry->info = *std::move(info);
  absl::StatusOr<MapPtr> map = Parsed(*stored);
  if (!map.ok()) return map.status();
  entry->map = *std::move(map);
  return entry;
}

absl::StatusOr<v1::MapInfo> MapCatalog::GetInfo(const std::string& id) const {
  if (id.empty()) return absl::InvalidArgumentError("map id: required");
  absl::StatusOr<StoredMap> stored = store_.GetMapInfo(id);
  if (!stored.ok()) return stored.status();
  return InfoOf(*stored);
}

absl::StatusOr<v1::MapInfo> MapCatalog::GetVersionInfo(const std::string& name,
                                                       int64_t version) const {
  if (absl::Status s = CheckMapName(name); !s.ok()) return s;
  if (version < 0) {
    return absl::InvalidArgumentError(absl::StrCat("version: ", version, "; must be >= 0"));
  }
  absl::StatusOr<StoredMap> stored = store_.FindMapVersion(name, version);
  if (!stored.ok()) return stored.status();
  return InfoOf(*stored);
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

absl::StatusOr<MapCatalog::Page> MapCatalog::List(const std::string& name, int page_size,
                                                  size_t max_bytes,
                                                  const std::string& page_token) const {
  if (!name.empty()) {
    if (absl::Status s = CheckMapName(name); !s.ok()) return s;
  }
  // A token continues the listing it came from: all maps by creation, or one name's versions.
  const std::string scope = name.empty() ? kListScope : absl::StrCat(kListScope, "@", name);
  std::optional<PageKey> after;
  if (!page_token.empty()) {
    absl::StatusOr<PageKey> key = DecodePageToken(page_token, scope);
    if (!key.ok()) return key.status();
    after = *key;
  }
  // One more row than the page says whether another page follows.
  absl::StatusOr<std::vector<StoredMap>> rows;
  if (name.empty()) {
    const std::optional<MapCursor> cursor =
        after.has_value() ? std::optional<MapCursor>({after->created_us, after->id}) : std::nullopt;
    rows = store_.ListMaps(cursor.has_value() ? &*cursor : nullptr, page_size + 1);
  } else {
    rows = store_.ListMapVersions(name, after.has_value() ? after->created_us : 0, page_size + 1);
  }
  if (!rows.ok()) return rows.status();
  Page page;
  size_t bytes = 0;
  size_t used = 0;
  for (; used < rows->size() && static_cast<int>(page.maps.size()) < page_size; ++used) {
    absl::StatusOr<v1::MapInfo> info = InfoOf((*rows)[used]);
    if (!info.ok()) return info.status();
    if (!FitsPage(bytes, info->ByteSizeLong(), max_bytes)) break;
    bytes += info->ByteSizeLong();
    page.maps.push_back(*std::move(info));
  }
  if (used < rows->size() && used > 0) {
    const StoredMap& last = (*rows)[used - 1];
    const int64_t position = name.empty() ? absl::ToUnixMicros(last.created_at) : last.version;
    page.next_page_token = EncodePageToken(PageKey{position, last.id}, scope);
  }
  return page;
}

absl::Status MapCatalog::Delete(const std::string& id) {
  if (id.empty()) return absl::InvalidArgumentError("id: required");
  absl::MutexLock upload_lock(&upload_mu_);
  return store_.DeleteMap(id);
}

int64_t MapCatalog::size() const {
  absl::StatusOr<int64_t> n = store_.CountMaps();
  return n.ok() ? *n : -1;
}

int MapCatalog::cached() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(cache_.size());
}

}  // namespace swarmplan::server
