#include "bench/papers/report_digest.h"

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
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
