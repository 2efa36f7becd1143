#include "bench/papers/bpso_vertices_significance.h"

#include <iterator>
#include <utility>

#include "bench/papers/bpso_vertices_paper.h"
#include "bench/papers/comparison.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::bpso {
namespace {

constexpr size_t kOneD = 0, kTwoD = 2;  // indices into kSwarmFactors

SuccessCount Found(const Runs& runs) { return {runs.found(), runs.count}; }

// Orders found lengths by their median, ties (common where many runs reach the optimum) by
// their mean.
std::pair<double, double> RankKey(const Runs& runs) {
  return {Median(runs.lengths).value_or(0.0), Mean(runs.lengths).value_or(0.0)};
}

}  // namespace

std::vector<SwarmSizeTest> TestSwarmSizes(const FigureRuns& figures) {
  std::vector<SwarmSizeTest> out;
  for (size_t w = 0; w < figures.worlds.size(); ++w) {
    const Runs& one = figures.swarm_sizes[w][kOneD];
    const Runs& two = figures.swarm_sizes[w][kTwoD];
    SwarmSizeTest test;
    test.world = w;
    test.length_p = RankSumP(two.lengths, one.lengths);
    test.time_p = RankSumP(two.seconds, one.seconds);
    const std::optional<double> one_time = Median(one.seconds), two_time = Median(two.seconds);
    if (one_time && two_time && *one_time > 0.0) test.ours_time_ratio = *two_time / *one_time;
    const int vertices = figures.worlds[w].vertices;
    const std::optional<PaperTable1Cell> paper_one =
        FindPaperTable1Cell(vertices, kSwarmFactors[kOneD]);
    const std::optional<PaperTable1Cell> paper_two =
        FindPaperTable1Cell(vertices, kSwarmFactors[kTwoD]);
    if (paper_one && paper_two) test.paper_time_ratio = paper_two->seconds / paper_one->seconds;
    out.push_back(test);
  }
  return out;
}

std::optional<double> PaperOverOurTime(const World& world, double swarm_factor, const Runs& runs) {
  const std::optional<PaperTable1Cell> paper = FindPaperTable1Cell(world.vertices, swarm_factor);
  const std::optional<double> ours = Mean(runs.seconds);
  if (!paper || !ours || *ours <= 0.0) return std::nullopt;
  return paper->seconds / *ours;
}

std::vector<double> PaperOverOurTimes(const FigureRuns& figures) {
  std::vector<double> out;
  for (size_t w = 0; w < figures.worlds.size(); ++w) {
    for (size_t f = 0; f < std::size(kSwarmFactors); ++f) {
      if (const std::optional<double> ratio =
              PaperOverOurTime(figures.worlds[w], kSwarmFactors[f], figures.swarm_sizes[w][f])) {
        out.push_back(*ratio);
      }
    }
  }
  return out;
}

std::vector<MutationTest> TestMutations(const FigureRuns& figures) {
  std::vector<MutationTest> out;
  for (size_t w = 0; w < figures.worlds.size(); ++w) {
    const std::vector<Runs>& row = figures.mutations[w];
    MutationTest test;
    test.world = w;
    for (size_t m = 0; m < row.size(); ++m) {
      if (kMutationProbabilities[m] == kPaperMutation) test.paper = m;
      if (row[m].lengths.empty()) continue;
      if (!test.best || RankKey(row[m]) < RankKey(row[*test.best])) test.best = m;
    }
    for (size_t m = 0; m < row.size(); ++m) {
      const bool compared = test.best && m != *test.best;
      test.p_against_best.push_back(compared ? RankSumP(row[m].lengths, row[*test.best].lengths)
                                             : std::nullopt);
      test.worse_than_best.push_back(compared && Significant(test.p_against_best.back()) &&
                                     RankKey(row[*test.best]) < RankKey(row[m]));
    }
    out.push_back(std::move(test));
  }
  return out;
}

std::vector<ConvergenceTest> TestConvergence(const FigureRuns& figures) {
  std::vector<ConvergenceTest> out;
  for (size_t c = 0; c < figures.convergence.size(); ++c) {
    const std::vector<Runs>& variants = figures.convergence[c].variants;
    const Runs& paper = variants[kWithMutation];
    ConvergenceTest test;
    test.convergence = c;
    for (const Runs& runs : variants) {
      const bool self = &runs == &paper;
      test.length_p.push_back(self ? std::nullopt : RankSumP(runs.lengths, paper.lengths));
      test.iteration_p.push_back(self ? std::nullopt
                                      : RankSumP(runs.best_iterations, paper.best_iterations));
      test.success_p.push_back(self ? std::nullopt : SuccessP(Found(runs), Found(paper)));
    }
    out.push_back(std::move(test));
  }
  return out;
}

}  // namespace swarmplan::bench::bpso
