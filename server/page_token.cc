#include "server/page_token.h"

#include <vector>

#include "absl/status/status.h"
#include "absl/strings/escaping.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "server/map_source.h"

namespace swarmplan::server {
namespace {

constexpr char kVersion[] = "p1";

// Detects corrupted or edited tokens and tokens of another scope. Not a secret: a token only
// says where a listing continues, which any client may choose freely.
std::string Check(const std::string& scope, const std::string& payload) {
  return ContentHash(absl::StrCat(scope, "\n", payload)).substr(0, 16);
}

absl::Status Invalid() {
  return absl::InvalidArgumentError(
      "page_token: not a token this listing issued (pass the next_page_token of the previous "
      "page, with the same filter, or an empty token for the first page)");
}

}  // namespace

bool FitsPage(size_t page_bytes, size_t item_bytes, size_t budget) {
  // A repeated message field spends a tag and a length prefix on each item.
  constexpr size_t kItemFraming = 1 + 5;
  return page_bytes == 0 || page_bytes + item_bytes + kItemFraming <= budget;
}

std::string EncodePageToken(const PageKey& key, const std::string& scope) {
  const std::string payload = absl::StrCat(kVersion, ":", key.created_us, ":", key.id);
  return absl::WebSafeBase64Escape(absl::StrCat(payload, ":", Check(scope, payload)));
}

absl::StatusOr<PageKey> DecodePageToken(const std::string& token, const std::string& scope) {
  std::string decoded;
  if (!absl::WebSafeBase64Unescape(token, &decoded)) return Invalid();
  const size_t last = decoded.rfind(':');
  if (last == std::string::npos) return Invalid();
  const std::string payload = decoded.substr(0, last);
  if (decoded.substr(last + 1) != Check(scope, payload)) return Invalid();
  const std::vector<std::string> parts = absl::StrSplit(payload, absl::MaxSplits(':', 2));
  PageKey key;
  if (parts.size() != 3 || parts[0] != kVersion || !absl::SimpleAtoi(parts[1], &key.created_us)) {
    return Invalid();
  }
  key.id = std::string(parts[2]);
  return key;
}

}  // namespace swarmplan::server
