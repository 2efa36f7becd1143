#include "bench/bench_options.h"

#include <string>
#include <vector>

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

absl::StatusOr<ParsedArgs> Parse(std::vector<std::string> args) {
  args.insert(args.begin(), "swarmplan-bench");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  return ParseBenchArgs(static_cast<int>(argv.size()), argv.data());
}

// The error message of a parse that must fail.
std::string ErrorOf(std::vector<std::string> args) {
  absl::StatusOr<ParsedArgs> parsed = Parse(std::move(args));
  EXPECT_FALSE(parsed.ok());
  if (parsed.ok()) return "";
  EXPECT_EQ(parsed.status().code(), absl::StatusCode::kInvalidArgument);
  return std::string(parsed.status().message());
}

TEST(BenchOptionsTest, ParsesAScenarioRun) {
  absl::StatusOr<ParsedArgs> parsed =
      Parse({"--planner",       "astar",   "--planner",        "dijkstra",
             "--map",           "a.map",   "--scen",           "a.map.scen",
             "--runs",          "3",       "--seed",           "7",
             "--csv",           "out.csv", "--markdown",       "out.md",
             "--bucket-sample", "2",       "--max-iterations", "50",
             "--time-budget",   "1.5",     "--clearance",      "0.25"});
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  const BenchOptions& o = parsed->options;
  EXPECT_TRUE(parsed->help.empty());
  EXPECT_EQ(o.planners, (std::vector<std::string>{"astar", "dijkstra"}));
  EXPECT_EQ(o.maps, std::vector<std::string>{"a.map"});
  EXPECT_EQ(o.scenario_files, std::vector<std::string>{"a.map.scen"});
  EXPECT_EQ(o.scenario_selection.mode, ScenarioSelection::Mode::kPerBucket);
  EXPECT_EQ(o.scenario_selection.count, 2);
  EXPECT_EQ(o.runs, 3);
  EXPECT_EQ(o.seed, 7u);
  EXPECT_EQ(o.csv_path, "out.csv");
  EXPECT_EQ(o.markdown_path, "out.md");
  EXPECT_EQ(o.max_iterations, 50);
  EXPECT_EQ(o.time_budget_seconds, 1.5);
  EXPECT_EQ(o.clearance, 0.25);
  EXPECT_FALSE(o.start.has_value());
}

TEST(BenchOptionsTest, DefaultsToOneScenarioPerBucketOneRunSeedOne) {
  absl::StatusOr<ParsedArgs> parsed =
      Parse({"--planner", "all", "--map", "a.map", "--scen", "a.map.scen"});
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  const BenchOptions& o = parsed->options;
  EXPECT_EQ(o.scenario_selection.mode, ScenarioSelection::Mode::kPerBucket);
  EXPECT_EQ(o.scenario_selection.count, 1);
  EXPECT_EQ(o.runs, 1);
  EXPECT_EQ(o.seed, 1u);
  EXPECT_EQ(o.smoothing, "none");
  EXPECT_FALSE(o.time_budget_seconds.has_value());
  EXPECT_TRUE(o.csv_path.empty());
}

TEST(BenchOptionsTest, ParsesStartGoalAndParams) {
  absl::StatusOr<ParsedArgs> parsed = Parse(
      {"--planner", "astar", "--map", "w.json", "--start", "1.5,2", "--goal=-3,4,5", "--param",
       "astar.diagonal=true", "--param", "astar.weight=2", "--param", "astar.mode=fast"});
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  const BenchOptions& o = parsed->options;
  ASSERT_TRUE(o.start && o.goal);
  EXPECT_EQ(*o.start, Point3(1.5, 2, 0));
  EXPECT_EQ(*o.goal, Point3(-3, 4, 5));
  const std::map<std::string, std::string>& astar = o.params.at("astar");
  EXPECT_EQ(astar.at("diagonal"), "true");
  EXPECT_EQ(astar.at("weight"), "2");
  EXPECT_EQ(astar.at("mode"), "fast");
}

TEST(BenchOptionsTest, ScenariosCountOrAll) {
  absl::StatusOr<ParsedArgs> n =
      Parse({"--planner", "astar", "--map", "a.map", "--scen", "s", "--scenarios", "20"});
  ASSERT_TRUE(n.ok()) << n.status();
  EXPECT_EQ(n->options.scenario_selection.mode, ScenarioSelection::Mode::kEvenly);
  EXPECT_EQ(n->options.scenario_selection.count, 20);
  absl::StatusOr<ParsedArgs> all =
      Parse({"--planner", "astar", "--map", "a.map", "--scen", "s", "--scenarios", "all"});
  ASSERT_TRUE(all.ok()) << all.status();
  EXPECT_EQ(all->options.scenario_selection.mode, ScenarioSelection::Mode::kAll);
}

TEST(BenchOptionsTest, HelpIsNotAnError) {
  absl::StatusOr<ParsedArgs> parsed = Parse({"--help"});
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  EXPECT_NE(parsed->help.find("--planner"), std::string::npos);
  EXPECT_NE(parsed->help.find("--scen"), std::string::npos);
}

TEST(BenchOptionsTest, ListPlannersNeedsNothingElse) {
  absl::StatusOr<ParsedArgs> parsed = Parse({"--list-planners"});
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  EXPECT_TRUE(parsed->options.list_planners);
}

TEST(BenchOptionsTest, RejectsMissingPlannerMapOrProblem) {
  EXPECT_NE(ErrorOf({"--map", "a.map", "--scen", "s"}).find("--planner"), std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--scen", "s"}).find("--map"), std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map"}).find("--start"), std::string::npos);
}

TEST(BenchOptionsTest, RejectsBadValuesNamingTheOption) {
  const std::vector<std::string> base = {"--planner", "astar", "--map", "a.map", "--scen", "s"};
  auto with = [&base](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  EXPECT_NE(ErrorOf(with({"--runs", "0"})).find("--runs"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--runs", "many"})).find("--runs"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--seed", "0"})).find("--seed"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--time-budget", "0"})).find("--time-budget"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--clearance", "-1"})).find("--clearance"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--smoothing", "wiggly"})).find("--smoothing"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--format", "bmp"})).find("--format"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--scenarios", "0"})).find("--scenarios"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--scenarios", "3", "--bucket-sample", "2"})).find("exclude"),
            std::string::npos);
  EXPECT_NE(ErrorOf(with({"--param", "astar"})).find("--param"), std::string::npos);
  EXPECT_NE(ErrorOf(with({"--bogus"})).find("--bogus"), std::string::npos);
}

TEST(BenchOptionsTest, RejectsInconsistentProblems) {
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map", "--map", "b.map", "--scen", "s"})
                .find("one .scen file per map"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map", "--start", "1,2"}).find("--goal"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map", "--scen", "s", "--start", "1,2",
                     "--goal", "3,4"})
                .find("exclude"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map", "--start", "1,x", "--goal", "3,4"})
                .find("--start"),
            std::string::npos);
  EXPECT_NE(ErrorOf({"--planner", "astar", "--map", "a.map", "--start", "1,2", "--goal", "3,4",
                     "--scenarios", "5"})
                .find("need --scen"),
            std::string::npos);
}

TEST(BenchOptionsTest, ParsePoint) {
  EXPECT_EQ(*ParsePoint("1,2"), Point3(1, 2, 0));
  EXPECT_EQ(*ParsePoint("1,2,3.5"), Point3(1, 2, 3.5));
  EXPECT_FALSE(ParsePoint("1").ok());
  EXPECT_FALSE(ParsePoint("1,2,3,4").ok());
  EXPECT_FALSE(ParsePoint("1,").ok());
  EXPECT_FALSE(ParsePoint("1,inf").ok());
}

TEST(BenchOptionsTest, ParseParamValueFollowsTheDeclaredType) {
  EXPECT_EQ(*ParseParamValue("false", ParamType::kBool), ParamValue(false));
  EXPECT_EQ(*ParseParamValue("-4", ParamType::kInt), ParamValue(int64_t{-4}));
  EXPECT_EQ(*ParseParamValue("0.5", ParamType::kDouble), ParamValue(0.5));
  EXPECT_EQ(*ParseParamValue("3", ParamType::kDouble), ParamValue(3.0));
  // An enum whose choices look like numbers stays a string.
  EXPECT_EQ(*ParseParamValue("4", ParamType::kEnum), ParamValue(std::string("4")));
  EXPECT_FALSE(ParseParamValue("yes", ParamType::kBool).ok());
  EXPECT_FALSE(ParseParamValue("0.5", ParamType::kInt).ok());
  EXPECT_FALSE(ParseParamValue("fast", ParamType::kDouble).ok());
}

TEST(BenchOptionsTest, AddParamAssignmentSplitsPlannerNameAndValue) {
  RawParams params;
  ASSERT_TRUE(AddParamAssignment("aem-bso.population=30", params).ok());
  ASSERT_TRUE(AddParamAssignment("aem-bso.mode=a=b", params).ok());
  EXPECT_EQ(params.at("aem-bso").at("population"), "30");
  EXPECT_EQ(params.at("aem-bso").at("mode"), "a=b");
  EXPECT_FALSE(AddParamAssignment("population=30", params).ok());
  EXPECT_FALSE(AddParamAssignment(".population=30", params).ok());
  EXPECT_FALSE(AddParamAssignment("astar.=1", params).ok());
  EXPECT_FALSE(AddParamAssignment("astar.weight=", params).ok());
}

}  // namespace
}  // namespace swarmplan::bench
