#pragma once

// The whole of a file, for tests that compare shipped files with what a generator writes.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swarmplan::bench {

// The file's bytes; empty when it cannot be read.
inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace swarmplan::bench
