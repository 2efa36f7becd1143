#include <string>

#include "bench/papers/experiments.h"
#include "bench/papers/report_digest.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

// The sections whose figures are wall times.
const std::vector<std::string> kTimedSections = {"## Time"};

absl::StatusOr<std::string> QuickReport(int jobs) {
  ExperimentOptions options;
  options.quick = true;
  options.jobs = jobs;
  return RunAemBsoFunctions(options);
}

TEST(AemBsoFunctionsReportTest, SameReportOnOneOrSeveralThreads) {
  absl::StatusOr<std::string> one = QuickReport(1);
  absl::StatusOr<std::string> three = QuickReport(3);
  ASSERT_TRUE(one.ok() && three.ok());
  EXPECT_EQ(WithoutSections(*one, kTimedSections), WithoutSections(*three, kTimedSections));
}

TEST(AemBsoFunctionsReportTest, HasEveryComparisonTheTableNeeds) {
  absl::StatusOr<std::string> report = QuickReport(2);
  ASSERT_TRUE(report.ok()) << report.status();
  for (const char* text :
       {"## D = 30", "## D = 60", "## Significance at D = 30", "## Significance at D = 60",
        "## Equal evaluation budgets (D = 30)", "## The elite mutation constants",
        "| k1 = 0.5, k2 = 0.1, k3 = 1 |", "## Origin-bias check", "| PSO c1, c2 | 1.49 | 1.49",
        "## Fig. 2: convergence on the test functions (D = 30)",
        "| function | optimiser | after 1 | after 2 | after 5 | after 10 | after 20 |",
        "- Fig. 2 (D = 30): AEM-BSO is significantly below BSO, PSO, BA at every checkpoint"}) {
    EXPECT_NE(report->find(text), std::string::npos) << text;
  }
  // Quick mode: 20 individuals, 20 iterations. A beetle swarm evaluates its population, then
  // three points per beetle and iteration, AEM-BSO one mutant per iteration: 20 + 1200 + 20.
  // PSO and BA one point per individual and iteration; three times the iterations: 20 + 1200.
  EXPECT_NE(report->find("evaluations per run: AEM-BSO 1240, PSO 420, PSO x3 1220, BA 420, "
                         "BA x3 1220."),
            std::string::npos);
}

// The quick report's figures (not its times) are fixed by the seeds: a change that moves them
// moves the committed tables too, so bench/results/aem-bso-functions.md must be re-run and
// this digest updated with it.
TEST(AemBsoFunctionsReportTest, QuickReportDigestIsPinned) {
  absl::StatusOr<std::string> report = QuickReport(2);
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(ReportDigest(*report, kTimedSections), "f5c87d9826f73b29");
}

}  // namespace
}  // namespace swarmplan::bench
