#include "server/ids.h"

#include <random>

#include "absl/strings/str_format.h"

namespace swarmplan::server {

std::string NewId(const std::string& prefix) {
  thread_local std::mt19937_64 engine{std::random_device{}()};
  return absl::StrFormat("%s%016x", prefix, engine());
}

}  // namespace swarmplan::server
