#include "bench/papers/report_digest.h"

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"

namespace swarmplan::bench {

std::string WithoutSections(absl::string_view report,
                            const std::vector<std::string>& skipped_headings) {
  std::string out;
  bool skipping = false;
  for (absl::string_view line : absl::StrSplit(report, '\n')) {
    if (absl::StartsWith(line, "## ")) {
      skipping = false;
      for (const std::string& heading : skipped_headings) {
        if (absl::StartsWith(line, heading)) skipping = true;
      }
    }
    if (skipping) continue;
    absl::StrAppend(&out, line, "\n");
  }
  return out;
}

namespace {

bool IsTimeHeader(absl::string_view header) {
  return absl::StrContains(header, "time") || absl::StrContains(header, "s/run");
}

}  // namespace

std::string WithoutTimeColumns(absl::string_view report) {
  std::string out;
  std::vector<bool> timed;  // per cell of the current table's header
  int row = 0;              // of the current table: 0 the header, 1 the alignment row
  for (absl::string_view line : absl::StrSplit(report, '\n')) {
    if (!absl::StartsWith(line, "|")) {
      row = 0;
      absl::StrAppend(&out, line, "\n");
      continue;
    }
    std::vector<std::string> cells = absl::StrSplit(line, '|');
    if (row == 0) {
      timed.clear();
      for (const std::string& cell : cells) timed.push_back(IsTimeHeader(cell));
    } else if (row > 1) {
      for (size_t i = 0; i < cells.size() && i < timed.size(); ++i) {
        if (timed[i]) cells[i] = " ";
      }
    }
    ++row;
    absl::StrAppend(&out, absl::StrJoin(cells, "|"), "\n");
  }
  return out;
}

std::string ReportDigest(absl::string_view report,
                         const std::vector<std::string>& skipped_headings) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (unsigned char c : WithoutSections(report, skipped_headings)) {
    hash ^= c;
    hash *= 0x100000001b3ULL;
  }
  return absl::StrFormat("%016x", hash);
}

}  // namespace swarmplan::bench
