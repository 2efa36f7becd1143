#pragma once

// Helpers shared by the text-format loaders: line splitting, number parsing, and errors that
// name the file and line. Internal to core/map/io.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/status.h"
#include "core/map/limits.h"

namespace swarmplan::map_io_internal {

// Splits text into lines at '\n' and drops one trailing '\r' (CRLF files). The last line may
// lack a newline; an empty text has no lines.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool Next(std::string_view* line);
  // 1-based number of the line last returned by Next.
  int line_number() const { return line_number_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_number_ = 0;
};

std::string_view Trim(std::string_view s);
// Splits at runs of spaces and tabs; no empty pieces.
std::vector<std::string_view> SplitWhitespace(std::string_view s);
// Splits at every `sep`; n separators give n + 1 pieces.
std::vector<std::string_view> Split(std::string_view s, char sep);
std::string Lower(std::string_view s);

// The whole text must be a number (a leading '+' is allowed). Non-finite values are rejected.
bool ParseFiniteDouble(std::string_view s, double* out);
bool ParseInt(std::string_view s, int64_t* out);

// A printable excerpt of untrusted text for error messages.
std::string Quote(std::string_view s);

// "file:line: message" / "file: message".
absl::Status InvalidAt(const std::string& file, int line, const std::string& message);
absl::Status Invalid(const std::string& file, const std::string& message);
// The same status with "file: " in front of its message (kept when already there).
absl::Status WithFile(const std::string& file, const absl::Status& status);

absl::Status CheckFileSize(const std::string& file, size_t bytes, const MapLimits& limits);
// Checked before allocating width * height cells.
absl::Status CheckCellCount(const std::string& file, int64_t width, int64_t height,
                            const MapLimits& limits);

}  // namespace swarmplan::map_io_internal
