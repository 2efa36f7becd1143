#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace grpc {
class CallbackServerContext;
class Status;
}  // namespace grpc

namespace swarmplan::server {

// Optional bearer-token check: with a token, every call but health checking (reflection
// included) must carry the metadata "authorization: Bearer <token>"; the scheme word is
// case-insensitive (RFC 7235), the token is not. Without one, every call passes.
class Authenticator {
 public:
  Authenticator() = default;
  explicit Authenticator(std::string token) : token_(std::move(token)) {}
  // Reads the token from a file (surrounding whitespace ignored); an empty path disables auth.
  static absl::StatusOr<Authenticator> FromFile(const std::string& path);

  bool enabled() const { return !token_.empty(); }
  // OK or UNAUTHENTICATED.
  grpc::Status Check(const grpc::CallbackServerContext& context) const;

 private:
  std::string token_;
};

// A warning naming the file and its mode when the token file at `path` with permission bits
// `mode` can be read by its group or by others; "" when it cannot.
std::string TokenFileModeWarning(const std::string& path, unsigned mode);
// The same for the file at `path` as it is now ("" also when it cannot be examined).
std::string TokenFileModeWarning(const std::string& path);

}  // namespace swarmplan::server
