#include "bench/papers/parallel_jobs.h"

#include <atomic>
#include <sstream>
#include <vector>

#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

TEST(RunJobsTest, RunsEveryJobOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 7, 100}) {
    std::vector<std::atomic<int>> runs(37);
    ASSERT_TRUE(RunJobs(37, threads, [&](int i) {
                  ++runs[i];
                  return absl::OkStatus();
                }).ok());
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1) << threads;
  }
  EXPECT_TRUE(RunJobs(0, 4, [](int) { return absl::InternalError("never"); }).ok());
}

TEST(RunJobsTest, ReturnsTheLowestNumberedErrorAfterRunningEveryJob) {
  std::atomic<int> ran{0};
  const absl::Status status = RunJobs(20, 3, [&](int i) {
    ++ran;
    return i == 5 || i == 12 ? absl::InternalError(absl::StrCat("job ", i)) : absl::OkStatus();
  });
  EXPECT_EQ(ran.load(), 20);
  EXPECT_EQ(status, absl::InternalError("job 5"));
}

TEST(ProgressLogTest, WritesWholeLinesAndToleratesNoStream) {
  std::ostringstream out;
  ProgressLog log(&out);
  ASSERT_TRUE(RunJobs(8, 4, [&](int i) {
                log.Line(absl::StrCat("line ", i));
                return absl::OkStatus();
              }).ok());
  int lines = 0;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) {
    EXPECT_EQ(line.rfind("line ", 0), 0u) << line;
    ++lines;
  }
  EXPECT_EQ(lines, 8);
  ProgressLog silent(nullptr);
  silent.Line("dropped");
}

}  // namespace
}  // namespace swarmplan::bench
