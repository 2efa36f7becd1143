#include "core/map/io/text_util.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace swarmplan::map_io_internal {

bool LineReader::Next(std::string_view* line) {
  if (pos_ >= text_.size()) return false;
  size_t end = text_.find('\n', pos_);
  const size_t next = end == std::string_view::npos ? text_.size() : end + 1;
  if (end == std::string_view::npos) end = text_.size();
  std::string_view l = text_.substr(pos_, end - pos_);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  *line = l;
  pos_ = next;
  ++line_number_;
  return true;
}

namespace {
bool IsBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
}  // namespace

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsBlank(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> SplitWhitespace(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && IsBlank(s[i])) ++i;
    const size_t start = i;
    while (i < s.size() && !IsBlank(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

std::vector<std::string_view> Split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  while (true) {
    const size_t end = s.find(sep, start);
    if (end == std::string_view::npos) {
      out.push_back(s.substr(start));
      return out;
    }
    out.push_back(s.substr(start, end - start));
    start = end + 1;
  }
}

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool ParseFiniteDouble(std::string_view s, double* out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.front() == '+') return false;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(value)) return false;
  *out = value;
  return true;
}

bool ParseInt(std::string_view s, int64_t* out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.front() == '+') return false;
  int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size()) return false;
  *out = value;
  return true;
}

std::string Quote(std::string_view s) {
  constexpr size_t kMax = 40;
  std::string out = "\"";
  for (size_t i = 0; i < s.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > kMax) out += "...";
  out += "\"";
  return out;
}

absl::Status InvalidAt(const std::string& file, int line, const std::string& message) {
  return absl::InvalidArgumentError(absl::StrCat(file, ":", line, ": ", message));
}

absl::Status Invalid(const std::string& file, const std::string& message) {
  return absl::InvalidArgumentError(absl::StrCat(file, ": ", message));
}

absl::Status WithFile(const std::string& file, const absl::Status& status) {
  if (status.ok()) return status;
  const std::string message(status.message());
  if (message.rfind(file + ":", 0) == 0) return status;
  return absl::Status(status.code(), absl::StrCat(file, ": ", message));
}

absl::Status CheckFileSize(const std::string& file, size_t bytes, const MapLimits& limits) {
  if (static_cast<int64_t>(bytes) > limits.max_file_bytes) {
    return absl::ResourceExhaustedError(absl::StrCat(
        file, ": ", bytes, " bytes exceed the limit of ", limits.max_file_bytes, " bytes"));
  }
  return absl::OkStatus();
}

absl::Status CheckCellCount(const std::string& file, int64_t width, int64_t height,
                            const MapLimits& limits) {
  if (width <= 0 || height <= 0) {
    return Invalid(file, absl::StrCat("size ", width, " x ", height, " must be positive"));
  }
  // Compared by division so hostile sizes cannot overflow.
  if (width > limits.max_cells / height) {
    return absl::ResourceExhaustedError(absl::StrCat(file, ": ", width, " x ", height,
                                                     " cells exceed the limit of ",
                                                     limits.max_cells, " cells"));
  }
  return absl::OkStatus();
}

}  // namespace swarmplan::map_io_internal
