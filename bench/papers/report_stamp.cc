#include "bench/papers/report_stamp.h"

#include <cstdio>
#include <memory>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"

namespace swarmplan::bench {
namespace {

// What `command` prints on standard output; empty when it fails.
std::string CommandOutput(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (pipe == nullptr) return "";
  std::string out;
  char buffer[256];
  while (fgets(buffer, sizeof buffer, pipe.get()) != nullptr) out += buffer;
  if (pclose(pipe.release()) != 0) return "";
  return std::string(absl::StripAsciiWhitespace(out));
}

std::string Quoted(const std::string& path) {
  std::string out = "'";
  for (char c : path) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string ReportStamp(const std::string& command, const std::string& source_dir,
                        const std::string& build_type) {
  const std::string git = absl::StrCat("git -C ", Quoted(source_dir));
  const std::string commit = CommandOutput(git + " rev-parse --short=12 HEAD 2>/dev/null");
  std::string tree;
  if (commit.empty()) {
    tree = "an unknown commit (no git checkout)";
  } else {
    const std::string changes =
        CommandOutput(absl::StrCat(git, " status --porcelain --untracked-files=no -- ':(top)' ",
                                   "':(top,exclude)", kReportsDir, "' 2>/dev/null"));
    tree =
        absl::StrCat("commit `", commit, "`", changes.empty() ? "" : " with uncommitted changes");
  }
  return absl::StrCat("*Produced by `", command, "` at ", tree, ", ",
                      build_type.empty() ? "an unnamed" : build_type, " build.*\n");
}

std::string InsertStamp(const std::string& report, const std::string& stamp) {
  if (report.rfind("# ", 0) == 0) {
    const size_t end = report.find('\n');
    if (end != std::string::npos) {
      return absl::StrCat(report.substr(0, end + 1), "\n", stamp, report.substr(end + 1));
    }
  }
  return absl::StrCat(stamp, "\n", report);
}

}  // namespace swarmplan::bench
