#pragma once

// A digest of a report's deterministic parts, so that a test notices when a change to a
// planner or an experiment shifts a table that is committed under bench/results/.

#include <cstdint>
#include <string>
#include <vector>

#include "absl/strings/string_view.h"

namespace swarmplan::bench {

// The report without the sections ("## " headings up to the next "## ") whose heading starts
// with one of `skipped_headings` (e.g. "## Time", whose wall times differ from run to run).
std::string WithoutSections(absl::string_view report,
                            const std::vector<std::string>& skipped_headings);

// The report with every cell of its Markdown tables' time columns (a header that mentions
// "time" or "s/run") left empty, since wall times differ from run to run.
std::string WithoutTimeColumns(absl::string_view report);

// FNV-1a (64 bit) of WithoutSections(report, skipped_headings), as 16 hexadecimal digits.
std::string ReportDigest(absl::string_view report,
                         const std::vector<std::string>& skipped_headings);

}  // namespace swarmplan::bench
