#pragma once

#include <optional>
#include <string>
#include <vector>

namespace swarmplan::bench {

// A GitHub-flavoured Markdown table: a header row and rows of the same width, numbers
// right-aligned (columns after the first `label_columns` ones).
class MarkdownTable {
 public:
  explicit MarkdownTable(std::vector<std::string> header, int label_columns = 1);

  // Cells beyond the header's width are dropped; missing ones are written empty.
  void AddRow(std::vector<std::string> cells);

  std::string ToString() const;

 private:
  std::vector<std::string> header_;
  int label_columns_;
  std::vector<std::vector<std::string>> rows_;
};

// A number in fixed notation with `significant` significant digits (all integer digits kept),
// scientific below 1e-3 and from 1e7; "–" when there is none.
std::string NumberCell(std::optional<double> value, int significant = 4);

// A fraction as a percentage with no decimals, e.g. "95%".
std::string PercentCell(double fraction);

}  // namespace swarmplan::bench
