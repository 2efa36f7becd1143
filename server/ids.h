#pragma once

#include <string>

namespace swarmplan::server {

// A fresh random identifier: prefix + 16 hex digits, e.g. "job-3f09a1c2b4d5e6f7".
std::string NewId(const std::string& prefix);

}  // namespace swarmplan::server
