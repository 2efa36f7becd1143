#pragma once

#include <filesystem>
#include <string>

#include "gtest/gtest.h"

namespace swarmplan::testing {

// The shared benchmark data folder (../shared/benchmarks beside the repo), or "" when absent.
inline std::string BenchmarksDir() {
  const std::filesystem::path dir = std::filesystem::path(SWARMPLAN_SHARED_DIR) / "benchmarks";
  return std::filesystem::is_directory(dir) ? dir.string() : std::string();
}

// The repo's own folder, for sample data shipped with the project.
inline std::string SourceDir() { return SWARMPLAN_SOURCE_DIR; }

}  // namespace swarmplan::testing

// Skips the current test with a clear message when ../shared/benchmarks/SUB is missing.
#define SWARMPLAN_REQUIRE_BENCHMARKS(sub)                                                    \
  do {                                                                                       \
    if (::swarmplan::testing::BenchmarksDir().empty() ||                                     \
        !std::filesystem::exists(::swarmplan::testing::BenchmarksDir() + "/" + (sub))) {     \
      GTEST_SKIP() << "benchmark data not found: " << SWARMPLAN_SHARED_DIR << "/benchmarks/" \
                   << (sub) << " (the shared folder beside the repo)";                       \
    }                                                                                        \
  } while (0)
