#include "server/store_url.h"

#include <fstream>
#include <sstream>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "server/redis_store.h"
#include "server/sqlite_store.h"

namespace swarmplan::server {
namespace {

constexpr absl::string_view kSqlite = "sqlite:";

std::string StoreUrl(const ServerConfig& config) {
  return config.store.empty() ? absl::StrCat(kSqlite, config.data_dir) : config.store;
}

absl::StatusOr<std::string> ReadPassword(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return absl::FailedPreconditionError(
        absl::StrCat("--store-password-file ", path, ": cannot read"));
  }
  std::stringstream text;
  text << in.rdbuf();
  std::string password(absl::StripAsciiWhitespace(text.str()));
  if (password.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("--store-password-file ", path, ": is empty"));
  }
  return password;
}

}  // namespace

absl::StatusOr<std::unique_ptr<Store>> OpenStore(const ServerConfig& config) {
  const std::string url = StoreUrl(config);
  if (absl::StartsWith(url, kSqlite)) {
    const std::string dir = url.substr(kSqlite.size());
    if (dir.empty()) {
      return absl::InvalidArgumentError("--store: 'sqlite:' needs a directory (sqlite:DIR)");
    }
    if (!config.store_password_file.empty()) {
      return absl::InvalidArgumentError(
          "--store-password-file: only a redis:// store takes a password");
    }
    absl::StatusOr<std::unique_ptr<SqliteStore>> store = SqliteStore::Open(dir);
    if (!store.ok()) return store.status();
    return std::unique_ptr<Store>(std::move(*store));
  }
  if (absl::StartsWith(url, "redis://")) {
    absl::StatusOr<RedisEndpoint> endpoint = ParseRedisUrl(url, "--store");
    if (!endpoint.ok()) return endpoint.status();
    if (!config.store_password_file.empty()) {
      absl::StatusOr<std::string> password = ReadPassword(config.store_password_file);
      if (!password.ok()) return password.status();
      endpoint->password = std::move(*password);
    }
    absl::StatusOr<std::unique_ptr<RedisStore>> store = RedisStore::Open(*endpoint);
    if (!store.ok()) {
      return absl::Status(store.status().code(),
                          absl::StrCat("--store: ", store.status().message()));
    }
    return std::unique_ptr<Store>(std::move(*store));
  }
  return absl::InvalidArgumentError(
      absl::StrCat("--store: '", url, "' is neither sqlite:DIR nor redis://HOST[:PORT][/DB]"));
}

std::string DescribeStore(const ServerConfig& config) { return StoreUrl(config); }

}  // namespace swarmplan::server
