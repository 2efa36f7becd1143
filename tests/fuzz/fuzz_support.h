#pragma once

// What every map-parser harness checks: a parser either returns a map or fails with
// INVALID_ARGUMENT / RESOURCE_EXHAUSTED naming the file it blames. Anything else (a crash, a
// sanitizer report, another code, an anonymous message) aborts, which libFuzzer records.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/io/map_io.h"

namespace swarmplan::fuzz {

// Small enough that one input never takes long or much memory, large enough for every path.
inline LoadOptions FuzzLoadOptions() {
  LoadOptions options;
  options.limits.max_cells = 1 << 20;
  options.limits.max_file_bytes = 1 << 20;
  options.limits.max_obstacles = 10000;
  options.limits.max_vertices = 100000;
  return options;
}

[[noreturn]] inline void Fail(const std::string& what, const absl::Status& status) {
  std::fprintf(stderr, "fuzz check failed: %s: %s\n", what.c_str(), status.ToString().c_str());
  std::abort();
}

// A failure must be a client error that names one of `files`.
inline void CheckError(const absl::Status& status, const std::vector<MapFile>& files) {
  if (status.ok()) return;
  if (status.code() != absl::StatusCode::kInvalidArgument &&
      status.code() != absl::StatusCode::kResourceExhausted) {
    Fail("unexpected status code", status);
  }
  for (const MapFile& file : files) {
    if (status.message().find(file.name) != std::string::npos) return;
  }
  Fail("the error names no file", status);
}

inline std::string Bytes(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace swarmplan::fuzz
