#include "bench/papers/bas_canyon_sweeps.h"

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_paper.h"
#include "bench/papers/bas_canyon_terrain.h"

namespace swarmplan::bench::bas {
namespace {

constexpr const char* kSweepPlanners[] = {"aco", "bas", "lfs-bas", "aco-bas"};
constexpr int kQuickSweepIterations[] = {2, 5, 10};

ParamValues PaperParams(const std::string& planner, int iterations) {
  if (planner == "aco") return PaperAcoParams(iterations);
  ParamValues params = PaperBeetleParams(iterations);
  if (planner == "aco-bas") params["ants"] = int64_t{20};
  return params;
}

std::string SweepLabel(const std::string& planner, int iterations) {
  return absl::StrCat(planner, ", ", iterations, " iterations");
}

}  // namespace

std::vector<int> SweepIterations(bool quick) {
  if (quick) return {std::begin(kQuickSweepIterations), std::end(kQuickSweepIterations)};
  return {std::begin(kSweepIterations), std::end(kSweepIterations)};
}

std::vector<Row> IterationSweepRows(const std::vector<int>& iterations) {
  std::vector<Row> rows;
  for (const char* planner : kSweepPlanners) {
    for (const int n : iterations) {
      rows.push_back({SweepLabel(planner, n), Spec(planner, PaperParams(planner, n))});
    }
  }
  return rows;
}

std::vector<ClaimedPair> IterationSweepPairs(const std::vector<int>& iterations) {
  std::vector<ClaimedPair> pairs;
  if (iterations.size() < 2) return pairs;
  const int most = iterations.back();
  for (const char* planner : kSweepPlanners) {
    for (const int fewer : {iterations.front(), iterations[iterations.size() - 2]}) {
      pairs.push_back(
          {SweepLabel(planner, fewer), SweepLabel(planner, most),
           absl::StrCat("more iterations lower the fitness (", fewer, " -> ", most, ")")});
      if (iterations.size() == 2) break;
    }
  }
  return pairs;
}

double MovedStartY() {
  const CanyonShape shape;
  return shape.mouth_y - shape.left_bulge;
}

std::vector<Row> MovedStartRows(int iterations) {
  return {{"lfs-bas, moved start", Spec("lfs-bas", PaperParams("lfs-bas", iterations))},
          {"aco-bas, moved start", Spec("aco-bas", PaperParams("aco-bas", iterations))}};
}

MovedStartTest TestMovedStart(const RowSet& set) {
  MovedStartTest test;
  const RowRuns* lfs = set.Find("lfs-bas, moved start");
  const RowRuns* aco_bas = set.Find("aco-bas, moved start");
  if (lfs == nullptr || aco_bas == nullptr) return test;
  test.lfs_right = lfs->right_branch_count();
  test.aco_bas_right = aco_bas->right_branch_count();
  test.p = SuccessP(test.lfs_right, test.aco_bas_right);
  return test;
}

}  // namespace swarmplan::bench::bas
