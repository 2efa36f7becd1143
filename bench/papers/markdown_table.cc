#include "bench/papers/markdown_table.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"

namespace swarmplan::bench {

MarkdownTable::MarkdownTable(std::vector<std::string> header, int label_columns)
    : header_(std::move(header)), label_columns_(label_columns) {}

void MarkdownTable::AddRow(std::vector<std::string> cells) {
  cells.resize(header_.size());
  rows_.push_back(std::move(cells));
}

std::string MarkdownTable::ToString() const {
  std::vector<std::string> rule;
  for (size_t column = 0; column < header_.size(); ++column) {
    rule.push_back(static_cast<int>(column) < label_columns_ ? "---" : "---:");
  }
  std::string text = absl::StrCat("| ", absl::StrJoin(header_, " | "), " |\n");
  absl::StrAppend(&text, "|", absl::StrJoin(rule, "|"), "|\n");
  for (const std::vector<std::string>& row : rows_) {
    absl::StrAppend(&text, "| ", absl::StrJoin(row, " | "), " |\n");
  }
  return text;
}

std::string NumberCell(std::optional<double> value, int significant) {
  if (!value) return "–";
  if (std::isnan(*value)) return "nan";
  if (std::isinf(*value)) return *value > 0 ? "inf" : "-inf";
  const double magnitude = std::fabs(*value);
  if (magnitude != 0.0 && (magnitude < 1e-3 || magnitude >= 1e7)) {
    return absl::StrFormat("%.*e", significant - 1, *value);
  }
  const int integer_digits =
      magnitude == 0.0 ? 1 : static_cast<int>(std::floor(std::log10(magnitude))) + 1;
  const int decimals = std::max(0, significant - integer_digits);
  return absl::StrFormat("%.*f", decimals, *value);
}

std::string PercentCell(double fraction) { return absl::StrFormat("%.0f%%", 100.0 * fraction); }

}  // namespace swarmplan::bench
