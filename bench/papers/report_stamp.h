#pragma once

#include <string>

namespace swarmplan::bench {

// Where the reports are kept in the source tree. Changes there are the reports themselves, not
// what produced them, so they do not count as uncommitted changes.
inline constexpr char kReportsDir[] = "bench/results";

// Where a report came from, so that a reader can produce it again: the exact command, the
// source tree's commit (and whether it had uncommitted changes outside kReportsDir) and the
// build type. One Markdown paragraph.
std::string ReportStamp(const std::string& command, const std::string& source_dir,
                        const std::string& build_type);

// The report with the stamp after its title line (its first line, when that is a Markdown
// heading), or before everything else.
std::string InsertStamp(const std::string& report, const std::string& stamp);

}  // namespace swarmplan::bench
