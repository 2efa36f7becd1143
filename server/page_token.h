#pragma once

#include <cstdint>
#include <string>
#include <tuple>

#include "absl/status/statusor.h"

namespace swarmplan::server {

// Where a listing stands: the sort key of the last item of the previous page. Lists are
// ordered by (created_us, id), so the next page starts after this key whether or not the item
// it came from still exists.
struct PageKey {
  int64_t created_us = 0;
  std::string id;

  friend bool operator<(const PageKey& a, const PageKey& b) {
    return std::tie(a.created_us, a.id) < std::tie(b.created_us, b.id);
  }
  friend bool operator==(const PageKey& a, const PageKey& b) {
    return a.created_us == b.created_us && a.id == b.id;
  }
};

// Whether an item of `item_bytes` (its serialized size) still fits on a page that holds
// `page_bytes` so far under `budget`. The first item always fits, so every page makes progress.
bool FitsPage(size_t page_bytes, size_t item_bytes, size_t budget);

// An opaque, URL-safe next_page_token for `key`, bound to `scope` (the list and its filter), so
// that a token is only accepted by the listing that issued it.
std::string EncodePageToken(const PageKey& key, const std::string& scope);

// The key of a token EncodePageToken made for `scope`. INVALID_ARGUMENT naming `page_token` when
// the token is malformed, altered, or was issued by another listing or filter.
absl::StatusOr<PageKey> DecodePageToken(const std::string& token, const std::string& scope);

}  // namespace swarmplan::server
