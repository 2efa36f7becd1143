#include "server/auth.h"

#include <grpcpp/server_context.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/strip.h"

namespace swarmplan::server {
namespace {

// Compares without an early exit, so the time taken says nothing about the token.
bool ConstantTimeEquals(const std::string& a, const std::string& b) {
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (size_t i = 0; i < a.size(); ++i) diff |= a[i] ^ b[i % (b.empty() ? 1 : b.size())];
  return diff == 0 && !b.empty();
}

}  // namespace

absl::StatusOr<Authenticator> Authenticator::FromFile(const std::string& path) {
  if (path.empty()) return Authenticator();
  std::ifstream in(path);
  if (!in) {
    return absl::FailedPreconditionError(absl::StrCat("--token-file ", path, ": cannot read"));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string token(absl::StripAsciiWhitespace(buffer.str()));
  if (token.empty()) {
    return absl::FailedPreconditionError(absl::StrCat("--token-file ", path, ": file is empty"));
  }
  return Authenticator(std::move(token));
}

grpc::Status Authenticator::Check(const grpc::CallbackServerContext& context) const {
  if (token_.empty()) return grpc::Status::OK;
  const auto& metadata = context.client_metadata();
  auto it = metadata.find("authorization");
  if (it == metadata.end()) {
    return grpc::Status(grpc::StatusCode::UNAUTHENTICATED,
                        "missing 'authorization: Bearer <token>' metadata");
  }
  const absl::string_view value(it->second.data(), it->second.size());
  // "<scheme> <token>": the scheme compares case-insensitively, the token exactly.
  const size_t space = value.find(' ');
  if (space == absl::string_view::npos ||
      !absl::EqualsIgnoreCase(value.substr(0, space), "bearer")) {
    return grpc::Status(grpc::StatusCode::UNAUTHENTICATED,
                        "authorization: expected the scheme 'Bearer <token>'");
  }
  const std::string presented(absl::StripLeadingAsciiWhitespace(value.substr(space + 1)));
  if (!ConstantTimeEquals(presented, token_)) {
    return grpc::Status(grpc::StatusCode::UNAUTHENTICATED, "invalid bearer token");
  }
  return grpc::Status::OK;
}

std::string TokenFileModeWarning(const std::string& path, unsigned mode) {
  if ((mode & (S_IRGRP | S_IROTH)) == 0) return "";
  return absl::StrFormat(
      "--token-file %s has mode %04o: readable by %s; chmod 600 it so only the server's user "
      "can read the token",
      path, mode & 07777,
      (mode & S_IRGRP) == 0 ? "others"
                            : ((mode & S_IROTH) == 0 ? "its group" : "its group and others"));
}

std::string TokenFileModeWarning(const std::string& path) {
  struct stat st;
  if (path.empty() || stat(path.c_str(), &st) != 0) return "";
  return TokenFileModeWarning(path, static_cast<unsigned>(st.st_mode));
}

}  // namespace swarmplan::server
