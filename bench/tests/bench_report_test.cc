#include <cmath>
#include <limits>

#include "bench/report.h"
#include "bench/statistics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

RunRecord Record(const std::string& planner, const std::string& map, bool success, double length,
                 std::optional<double> optimal, double seconds) {
  RunRecord r;
  r.planner = planner;
  r.map = map;
  r.scenario = "0";
  r.seed = 1;
  r.success = success;
  if (success) r.length = length;
  r.optimal = optimal;
  r.ratio = LengthRatio(success, r.length, optimal);
  r.wall_seconds = seconds;
  return r;
}

TEST(BenchStatisticsTest, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(Median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(Median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(Median({7.0}), 7.0);
  EXPECT_FALSE(Median({}).has_value());
}

TEST(BenchStatisticsTest, MaxOfValues) {
  EXPECT_EQ(Max({1.0, 5.0, 2.0}), 5.0);
  EXPECT_FALSE(Max({}).has_value());
}

TEST(BenchStatisticsTest, MinMeanAndSampleStdDev) {
  EXPECT_EQ(Min({3.0, -1.0, 2.0}), -1.0);
  EXPECT_DOUBLE_EQ(*Mean({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0}), 5.0);
  // Sum of squared deviations 32 over n - 1 = 7.
  EXPECT_DOUBLE_EQ(*StdDev({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0}), std::sqrt(32.0 / 7.0));
  EXPECT_EQ(StdDev({3.0}), 0.0);
  EXPECT_FALSE(Min({}).has_value());
  EXPECT_FALSE(Mean({}).has_value());
  EXPECT_FALSE(StdDev({}).has_value());
}

TEST(BenchReportTest, LengthRatioNeedsSuccessAndOptimum) {
  EXPECT_DOUBLE_EQ(*LengthRatio(true, 12.0, 10.0), 1.2);
  EXPECT_FALSE(LengthRatio(false, 12.0, 10.0).has_value());
  EXPECT_FALSE(LengthRatio(true, 12.0, std::nullopt).has_value());
  EXPECT_FALSE(LengthRatio(true, std::nullopt, 10.0).has_value());
  EXPECT_EQ(LengthRatio(true, 0.0, 0.0), 1.0);  // start == goal
  EXPECT_FALSE(LengthRatio(true, 1.0, 0.0).has_value());
}

TEST(BenchReportTest, FormatNumberHandlesSpecialValues) {
  EXPECT_EQ(FormatNumber(1.5), "1.5");
  EXPECT_EQ(FormatNumber(62.1543289), "62.1543289");
  EXPECT_EQ(FormatNumber(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(FormatNumber(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(FormatNumber(std::nan("")), "nan");
}

TEST(BenchReportTest, CsvFieldQuotesOnlyWhenNeeded) {
  EXPECT_EQ(CsvField("arena.map"), "arena.map");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(CsvField("cr\r"), "\"cr\r\"");
  EXPECT_EQ(CsvField(""), "");
}

TEST(BenchReportTest, CsvHeaderHasTheDocumentedColumns) {
  EXPECT_EQ(CsvHeader(),
            "map,scenario,planner,seed,success,length,optimal,ratio,scen_optimal,min_clearance,"
            "max_curvature,iterations,evaluations,wall_seconds,fitness,initial_fitness,"
            "best_iteration,objective,seed_objective,seed_penalty,seconds_to_1.05,seconds_to_1.02,"
            "alternatives,distinct_corridors\n");
}

TEST(BenchReportTest, CsvRowOfASuccessfulRun) {
  RunRecord r = Record("astar", "my,map.map", true, 12.5, 10.0, 0.25);
  r.scenario = "(1 2)->(3 4)";
  r.seed = 42;
  r.scen_optimal = 10.5;
  r.min_clearance = 0.5;
  r.max_curvature = 0.0;
  r.iterations = 3;
  r.evaluations = 120;
  r.fitness = 12.5;
  r.initial_fitness = 13.0;
  r.best_iteration = 2;
  r.objective = 12.75;
  r.seed_objective = 13.5;
  r.seed_penalty = 0.5;
  r.seconds_to_1_05 = 0.125;
  EXPECT_EQ(CsvRow(r),
            "\"my,map.map\",(1 2)->(3 4),astar,42,true,12.5,10,1.25,10.5,0.5,0,3,120,0.250000,12.5,"
            "13,2,12.75,13.5,0.5,0.125,,,\n");
}

TEST(BenchReportTest, CsvRowOfAFailedRunLeavesMeasuresEmpty) {
  const RunRecord r = Record("pso", "arena.map", false, 0.0, std::nullopt, 1.0);
  EXPECT_EQ(CsvRow(r), "arena.map,0,pso,1,false,,,,,,,0,0,1.000000,,,0,,,,,,,\n");
}

TEST(BenchReportTest, SummarizeGroupsByPlannerAndMapInFirstSeenOrder) {
  const std::vector<RunRecord> records = {
      Record("astar", "a.map", true, 10.0, 10.0, 1.0),
      Record("pso", "a.map", true, 12.0, 10.0, 3.0),
      Record("astar", "b.map", true, 5.0, 5.0, 2.0),
      Record("pso", "a.map", false, 0.0, 10.0, 5.0),
      Record("pso", "a.map", true, 11.0, 10.0, 4.0),
  };
  const std::vector<SummaryRow> rows = Summarize(records);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].planner, "astar");
  EXPECT_EQ(rows[0].map, "a.map");
  EXPECT_EQ(rows[1].planner, "pso");
  EXPECT_EQ(rows[1].map, "a.map");
  EXPECT_EQ(rows[2].map, "b.map");

  const SummaryRow& pso = rows[1];
  EXPECT_EQ(pso.runs, 3);
  EXPECT_EQ(pso.successes, 2);
  EXPECT_DOUBLE_EQ(*pso.median_ratio, 1.15);
  EXPECT_DOUBLE_EQ(*pso.worst_ratio, 1.2);
  EXPECT_DOUBLE_EQ(*pso.median_length, 11.5);
  EXPECT_DOUBLE_EQ(*pso.median_seconds, 4.0);  // over every run, failed ones included
}

TEST(BenchReportTest, SummaryWithoutOptimumHasNoRatio) {
  const std::vector<SummaryRow> rows = Summarize({Record("astar", "m", true, 3.0, {}, 1.0)});
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_FALSE(rows[0].median_ratio.has_value());
  EXPECT_FALSE(rows[0].worst_ratio.has_value());
  EXPECT_DOUBLE_EQ(*rows[0].median_length, 3.0);
}

TEST(BenchReportTest, MarkdownSummaryTable) {
  const std::vector<RunRecord> records = {
      Record("astar", "a|b.map", true, 10.0, 10.0, 0.5),
      Record("pso", "a|b.map", false, 0.0, 10.0, 2.0),
  };
  EXPECT_EQ(MarkdownSummary(Summarize(records)),
            "| planner | map | runs | success | median ratio | worst ratio | median length | "
            "median time (s) |\n"
            "|---|---|---:|---:|---:|---:|---:|---:|\n"
            "| astar | a\\|b.map | 1 | 100.0% | 1.000000 | 1.000000 | 10.0000 | 0.500000 |\n"
            "| pso | a\\|b.map | 1 | 0.0% | – | – | – | 2.000000 |\n");
  EXPECT_EQ(MarkdownSummary({}), "");
}

TEST(BenchReportTest, ConvergenceCsvHasARowPerIteration) {
  RunRecord r = Record("aem-bso", "arena.map", true, 12.5, 10.0, 0.5);
  r.seed = 2;
  r.convergence = {{0.125, 14.0, false}, {0.25, 12.5, true}};
  EXPECT_EQ(ConvergenceCsvHeader(),
            "map,scenario,planner,seed,iteration,seconds,best_fitness,feasible\n");
  EXPECT_EQ(ConvergenceCsvRows(r),
            "arena.map,0,aem-bso,2,0,0.125000,14,false\n"
            "arena.map,0,aem-bso,2,1,0.250000,12.5,true\n");
}

}  // namespace
}  // namespace swarmplan::bench
