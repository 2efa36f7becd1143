// swarmplan-bench --ompl-log: OMPL's benchmark log, checked against the grammar of OMPL's
// "How to Benchmark Planners" (section "The benchmark logfile format") line by line.

#include "bench/ompl_log.h"

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "gtest/gtest.h"
#include "tests/unit/grid_planner_test_util.h"

namespace swarmplan::bench {
namespace {

// A reader of the log's lines that fails with the line number and what it expected.
class Lines {
 public:
  explicit Lines(const std::string& text) : lines_(absl::StrSplit(text, '\n')) {
    if (!lines_.empty() && lines_.back().empty()) lines_.pop_back();  // the last EOL
  }
  bool done() const { return next_ >= lines_.size(); }
  const std::string& Peek() const { return lines_[next_]; }
  // The next line when it matches `pattern` (its groups in `groups`).
  bool Take(const std::regex& pattern, std::smatch* groups = nullptr) {
    if (done()) return false;
    std::smatch m;
    if (!std::regex_match(lines_[next_], m, pattern)) return false;
    if (groups) *groups = m;
    ++next_;
    return true;
  }
  std::string Where() const {
    return absl::StrCat("line ", next_ + 1, ": '", done() ? "<end>" : lines_[next_], "'");
  }

 private:
  std::vector<std::string> lines_;
  size_t next_ = 0;
};

const std::string kWord = R"(\S+)";
const std::string kInt = R"(-?[0-9]+)";
const std::string kNum = R"(-?[0-9]+(?:\.[0-9]*)?(?:[eE][-+]?[0-9]+)?)";
const std::string kData = "(?:" + kNum + "|inf|nan|)";

int Count(const std::smatch& m) {
  int n = 0;
  EXPECT_TRUE(absl::SimpleAtoi(m[1].str(), &n));
  return n;
}

// Checks `text` against the grammar; on failure says where. Counts planners and runs.
::testing::AssertionResult MatchesOmplGrammar(const std::string& text, int* planners = nullptr) {
  Lines in(text);
  auto fail = [&](const std::string& expected) {
    return ::testing::AssertionFailure() << "expected " << expected << " at " << in.Where();
  };
  std::smatch m;
  in.Take(std::regex(kWord + " version " + kWord));  // optional
  if (!in.Take(std::regex("Experiment " + kWord))) return fail("Experiment NAME");
  if (in.Take(std::regex("(" + kInt + ") experiment properties"), &m)) {
    for (int i = Count(m); i > 0; --i) {
      if (!in.Take(std::regex(".+ (BOOLEAN|INTEGER|REAL)=" + kNum))) return fail("a property");
    }
  }
  if (!in.Take(std::regex("Running on " + kWord))) return fail("Running on HOST");
  if (!in.Take(std::regex("Starting at " + kWord))) return fail("Starting at DATE");
  for (int block = 0; block < 2; ++block) {  // setup, then the optional cpuinfo
    if (!in.Take(std::regex("<<<\\|"))) {
      if (block == 0) return fail("<<<|");
      break;
    }
    while (!in.Take(std::regex("\\|>>>"))) {
      if (in.done()) return fail("|>>>");
      in.Take(std::regex(".*"));
    }
  }
  if (!in.Take(std::regex(kInt + " is the random seed"))) return fail("the random seed");
  if (!in.Take(std::regex(kNum + " seconds per run"))) return fail("seconds per run");
  if (!in.Take(std::regex(kNum + " MB per run"))) return fail("MB per run");
  in.Take(std::regex(kInt + " runs per planner"));
  if (!in.Take(std::regex(kNum + " seconds spent to collect the data"))) return fail("total time");
  if (in.Take(std::regex("(" + kNum + ") enum type"), &m)) {
    for (int i = Count(m); i > 0; --i) {
      if (!in.Take(std::regex(kWord + "(\\|" + kWord + ")+"))) return fail("an enum");
    }
  }
  if (!in.Take(std::regex("(" + kInt + ") planners"), &m)) return fail("N planners");
  const int planner_count = Count(m);
  for (int p = 0; p < planner_count; ++p) {
    if (!in.Take(std::regex(kWord))) return fail("a planner name");
    if (!in.Take(std::regex("(" + kInt + ") common properties"), &m)) return fail("common");
    for (int i = Count(m); i > 0; --i) {
      if (!in.Take(std::regex(".+ = .*"))) return fail("NAME = VALUE");
    }
    const std::regex property(".+ (BOOLEAN|INTEGER|REAL)");
    if (!in.Take(std::regex("(" + kInt + ") properties for each run"), &m)) return fail("props");
    const int properties = Count(m);
    for (int i = 0; i < properties; ++i) {
      if (!in.Take(property)) return fail("NAME TYPE");
    }
    if (!in.Take(std::regex("(" + kInt + ") runs"), &m)) return fail("N runs");
    std::string run;
    for (int i = 0; i < properties; ++i) run += kData + "; ";
    for (int i = Count(m); i > 0; --i) {
      if (!in.Take(std::regex(run))) return fail(absl::StrCat(properties, " measurements"));
    }
    if (in.Take(std::regex("(" + kInt + ") progress properties for each run"), &m)) {
      const int progress = Count(m);
      for (int i = 0; i < progress; ++i) {
        if (!in.Take(property)) return fail("NAME TYPE");
      }
      if (!in.Take(std::regex("(" + kInt + ") runs"), &m)) return fail("N runs");
      std::string entry;
      for (int i = 0; i < progress; ++i) entry += kData + ",";
      const std::regex line(entry + "(;" + entry + ")*");
      for (int i = Count(m); i > 0; --i) {
        if (!in.Take(line)) return fail("progress measurements");
      }
    }
    if (!in.Take(std::regex("\\."))) return fail("'.'");
  }
  if (!in.done()) return fail("the end");
  if (planners) *planners = planner_count;
  return ::testing::AssertionSuccess();
}

TEST(OmplLogTest, TheCheckerRejectsWhatTheGrammarDoesNot) {
  const std::string good =
      "Experiment e\nRunning on h\nStarting at d\n<<<|\nsetup line\n|>>>\n1 is the random seed\n"
      "1 seconds per run\n0 MB per run\n2 runs per planner\n3.5 seconds spent to collect the "
      "data\n1 planners\np\n0 common properties\n2 properties for each run\ntime REAL\n"
      "solved BOOLEAN\n2 runs\n0.5; 1; \n; 0; \n1 progress properties for each run\ntime REAL\n"
      "2 runs\n0.1,;0.2,\nnan,\n.\n";
  EXPECT_TRUE(MatchesOmplGrammar(good));
  std::string missing_field = good;
  missing_field.replace(missing_field.find("0.5; 1; "), 8, "0.5; 1;");
  EXPECT_FALSE(MatchesOmplGrammar(missing_field));
  std::string spaced_name = good;
  spaced_name.replace(spaced_name.find("Experiment e"), 12, "Experiment e f");
  EXPECT_FALSE(MatchesOmplGrammar(spaced_name));
  EXPECT_FALSE(MatchesOmplGrammar(good.substr(0, good.size() - 2)));  // no final '.'
}

TEST(OmplLogTest, BenchRunsOfTwoPlannersOnTwoProblemsMakeTwoValidExperiments) {
  const MapPtr map = swarmplan::testing::GridMap(swarmplan::testing::TwoWallsRows());
  std::vector<BenchProblem> problems(2);
  for (size_t i = 0; i < 2; ++i) {
    problems[i].map_name = "two walls.map";
    problems[i].map = map;
    problems[i].scenario = absl::StrCat("(0.5 11.5)->(11.5 ", 0.5 + i, ")");
    problems[i].start = Point3(0.5, 11.5, 0);
    problems[i].goal = Point3(11.5, 0.5 + i, 0);
  }
  problems[0].optimal = 16.0;
  BenchOptions options;
  options.planners = {"astar", "pso"};
  options.runs = 2;
  options.max_iterations = 15;
  options.time_budget_seconds = 5.0;
  std::vector<RunRecord> records;
  std::ostringstream notes;
  RunBench(
      DefaultRegistry(), problems, options, {}, [&](const RunRecord& r) { records.push_back(r); },
      notes);
  ASSERT_EQ(records.size(), 8u);

  const std::string path = ::testing::TempDir() + "swarmplan-ompl-log-test.log";
  absl::StatusOr<std::vector<std::string>> files = WriteOmplLogs(
      path, problems, records, options, absl::FromUnixSeconds(1796342400), absl::Seconds(3));
  ASSERT_TRUE(files.ok()) << files.status();
  ASSERT_EQ(files->size(), 2u);
  EXPECT_EQ((*files)[0], ::testing::TempDir() + "swarmplan-ompl-log-test-1.log");
  for (const std::string& file : *files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    int planners = 0;
    EXPECT_TRUE(MatchesOmplGrammar(text.str(), &planners)) << file << ":\n" << text.str();
    EXPECT_EQ(planners, 2);
    EXPECT_NE(text.str().find("Experiment two_walls.map_(0.5_11.5)->(11.5_"), std::string::npos);
    EXPECT_NE(text.str().find("Starting at 2026-12-04T00:00:00Z\n"), std::string::npos);
    EXPECT_NE(text.str().find("\n5 seconds per run\n0 MB per run\n2 runs per planner\n"),
              std::string::npos);
    std::remove(file.c_str());
  }
  // pso's progress: one entry per iteration of each run, as its convergence has them.
  std::ostringstream one;
  OmplExperiment e;
  e.name = "e";
  e.host = "h";
  e.date = "d";
  e.planners = {"pso"};
  for (const RunRecord& r : records) {
    if (r.planner == "pso" && r.scenario == problems[0].scenario) e.records.push_back(r);
  }
  e.runs_per_planner = 2;
  WriteOmplLog(e, one);
  ASSERT_TRUE(MatchesOmplGrammar(one.str()));
  const std::vector<std::string> lines = absl::StrSplit(one.str(), '\n');
  const size_t last = lines.size() - 3;  // ".", "" after the two progress lines
  ASSERT_EQ(e.records.size(), 2u);
  EXPECT_EQ(std::vector<std::string>(absl::StrSplit(lines[last], ';')).size(),
            e.records[1].convergence.size());
  EXPECT_EQ(e.records[1].convergence.size(), 15u);
}

}  // namespace
}  // namespace swarmplan::bench
