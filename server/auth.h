#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace grpc {
class CallbackServerContext;
class Status;
}  // namespace grpc

namespace swarmplan::server {

// Optional bearer-token check: with a token, every call must carry the metadata
// "authorization: Bearer <token>". Without one, every call passes.
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

}  // namespace swarmplan::server
