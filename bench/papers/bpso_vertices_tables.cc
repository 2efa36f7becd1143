#include "bench/papers/bpso_vertices_tables.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/bpso_vertices_paper.h"
#include "bench/papers/bpso_vertices_significance.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::bpso {
namespace {

constexpr int kConvergenceCheckpoints[] = {1, 5, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100};

std::string MutationLabel(double mutation) { return absl::StrFormat("%g", mutation); }

// Mean over runs of the best fitness after `iterations` iterations; runs whose best is still
// infeasible (penalised) then are left out and counted in the cell.
std::string ConvergenceCell(const Runs& runs, int iterations) {
  std::vector<double> feasible;
  for (const std::vector<IterationStats>& log : runs.convergence) {
    if (log.empty()) continue;
    const IterationStats& at = log[std::min<size_t>(iterations, log.size()) - 1];
    if (at.feasible) feasible.push_back(at.best_fitness);
  }
  std::string cell = NumberCell(Mean(feasible));
  if (static_cast<int>(feasible.size()) < runs.count) {
    absl::StrAppend(&cell,
                    absl::StrFormat(" (%d/%d)", static_cast<int>(feasible.size()), runs.count));
  }
  return cell;
}

std::string FoundCell(const Runs& runs) { return absl::StrCat(runs.found(), "/", runs.count); }

}  // namespace

std::string WorldsTable(const FigureRuns& figures) {
  MarkdownTable table({"world", "D (vertices)", "straight line", "visibility-graph optimum",
                       "best ordered vertex subset"});
  const double straight = (BpsoVerticesGoal() - BpsoVerticesStart()).norm();
  for (const World& world : figures.worlds) {
    table.AddRow({world.name, absl::StrCat(world.vertices), NumberCell(straight),
                  NumberCell(world.optimum), NumberCell(world.encoding_optimum)});
  }
  return table.ToString();
}

std::string SwarmSizeTable(const FigureRuns& figures) {
  MarkdownTable table({"D", "N", "paper: mean fitness", "ours: mean length", "ours: best",
                       "ours: success", "optimum (VG)", "ours / optimum", "paper: time (s)",
                       "ours: mean time (s)", kPaperOverOurTimeHeader},
                      2);
  for (size_t w = 0; w < figures.worlds.size(); ++w) {
    const World& world = figures.worlds[w];
    for (size_t f = 0; f < std::size(kSwarmFactors); ++f) {
      const double factor = kSwarmFactors[f];
      const Runs& runs = figures.swarm_sizes[w][f];
      const std::optional<PaperTable1Cell> paper = FindPaperTable1Cell(world.vertices, factor);
      const std::optional<double> mean = Mean(runs.lengths);
      table.AddRow({absl::StrCat(world.vertices),
                    absl::StrFormat("%s = %d", SwarmLabel(factor),
                                    static_cast<int>(std::ceil(factor * world.vertices))),
                    NumberCell(paper ? std::optional<double>(paper->fitness) : std::nullopt, 6),
                    NumberCell(mean), NumberCell(Min(runs.lengths)),
                    PercentCell(runs.success_rate()), NumberCell(world.optimum),
                    NumberCell(mean ? std::optional<double>(*mean / world.optimum) : std::nullopt),
                    NumberCell(paper ? std::optional<double>(paper->seconds) : std::nullopt),
                    NumberCell(Mean(runs.seconds)),
                    NumberCell(PaperOverOurTime(world, factor, runs), 3)});
    }
  }
  return table.ToString();
}

std::string SwarmSizeTestTable(const FigureRuns& figures) {
  MarkdownTable table({"D", "1D: median length [95% CI]", "2D: median length [95% CI]",
                       "rank-sum p (length)", "ours: median time 2D / 1D", "rank-sum p (time)",
                       "paper: time 2D / 1D"});
  for (const SwarmSizeTest& test : TestSwarmSizes(figures)) {
    const std::vector<Runs>& row = figures.swarm_sizes[test.world];
    table.AddRow({absl::StrCat(figures.worlds[test.world].vertices),
                  MedianWithInterval(row.front().lengths), MedianWithInterval(row.back().lengths),
                  PValueCell(test.length_p), NumberCell(test.ours_time_ratio, 3),
                  PValueCell(test.time_p), NumberCell(test.paper_time_ratio, 3)});
  }
  return table.ToString();
}

std::string MutationTable(const FigureRuns& figures) {
  std::vector<std::string> header{"mutation probability"};
  for (const World& world : figures.worlds) {
    header.push_back(absl::StrCat("D = ", world.vertices, ": mean length (success)"));
  }
  MarkdownTable table(header);
  for (size_t m = 0; m < std::size(kMutationProbabilities); ++m) {
    std::vector<std::string> row{MutationLabel(kMutationProbabilities[m])};
    for (size_t w = 0; w < figures.worlds.size(); ++w) {
      const Runs& runs = figures.mutations[w][m];
      row.push_back(absl::StrCat(NumberCell(Mean(runs.lengths)), " (",
                                 PercentCell(runs.success_rate()), ")"));
    }
    table.AddRow(std::move(row));
  }
  std::vector<std::string> optimum_row{"optimum (VG)"};
  for (const World& world : figures.worlds) optimum_row.push_back(NumberCell(world.optimum));
  table.AddRow(std::move(optimum_row));
  return table.ToString();
}

std::string MutationTestTable(const FigureRuns& figures) {
  MarkdownTable table({"D", "best probability (lowest median, then mean)",
                       "its median length [95% CI]", "0.1: median length [95% CI]",
                       "rank-sum p (best vs 0.1)", "significantly worse than the best (p < 0.05)",
                       "not significantly worse than the best"});
  for (const MutationTest& test : TestMutations(figures)) {
    const std::vector<Runs>& row = figures.mutations[test.world];
    std::string worse, alike;
    for (size_t m = 0; m < row.size(); ++m) {
      if (test.best && m == *test.best) continue;
      AppendListItem(test.worse_than_best[m] ? &worse : &alike,
                     MutationLabel(kMutationProbabilities[m]));
    }
    table.AddRow({absl::StrCat(figures.worlds[test.world].vertices),
                  test.best ? MutationLabel(kMutationProbabilities[*test.best]) : "–",
                  test.best ? MedianWithInterval(row[*test.best].lengths) : "–",
                  MedianWithInterval(row[test.paper].lengths),
                  test.best && *test.best == test.paper
                      ? "(0.1 is the best)"
                      : PValueCell(test.p_against_best[test.paper]),
                  worse.empty() ? "none" : worse, alike.empty() ? "none" : alike});
  }
  return table.ToString();
}

std::string ConvergenceTables(const FigureRuns& figures) {
  std::vector<int> checkpoints;
  for (int k : kConvergenceCheckpoints) {
    if (k <= figures.iterations) checkpoints.push_back(k);
  }
  if (checkpoints.empty() || checkpoints.back() != figures.iterations) {
    checkpoints.push_back(figures.iterations);
  }
  const std::vector<ConvergenceSpec> variants = ConvergenceVariants(figures.iterations);
  std::string text;
  for (const ConvergenceWorld& convergence : figures.convergence) {
    const World& world = figures.worlds[convergence.world];
    std::vector<std::string> header{"algorithm"};
    for (int k : checkpoints) header.push_back(absl::StrCat("it ", k));
    for (const char* column : {"success", "iteration of final best", "mean time (s)"}) {
      header.push_back(column);
    }
    MarkdownTable table(header);
    for (size_t v = 0; v < variants.size(); ++v) {
      const Runs& runs = convergence.variants[v];
      std::vector<std::string> row{variants[v].label};
      for (int k : checkpoints) row.push_back(ConvergenceCell(runs, k));
      row.push_back(PercentCell(runs.success_rate()));
      row.push_back(NumberCell(Mean(runs.best_iterations), 3));
      row.push_back(NumberCell(Mean(runs.seconds)));
      table.AddRow(std::move(row));
    }
    absl::StrAppend(
        &text,
        absl::StrFormat("D = %d (optimum %s, best ordered vertex subset %s):\n\n", world.vertices,
                        NumberCell(world.optimum), NumberCell(world.encoding_optimum)),
        table.ToString(), "\n");
  }
  return text;
}

std::string ConvergenceTestTable(const FigureRuns& figures) {
  const std::vector<ConvergenceSpec> variants = ConvergenceVariants(figures.iterations);
  MarkdownTable table(
      {"D", "algorithm", "final length: median [95% CI]", "rank-sum p",
       "iteration of final best: median [95% CI]", "rank-sum p", "found", "Fisher p"},
      2);
  for (const ConvergenceTest& test : TestConvergence(figures)) {
    const ConvergenceWorld& convergence = figures.convergence[test.convergence];
    for (size_t v = 0; v < variants.size(); ++v) {
      const Runs& runs = convergence.variants[v];
      table.AddRow({absl::StrCat(figures.worlds[convergence.world].vertices), variants[v].label,
                    MedianWithInterval(runs.lengths), PValueCell(test.length_p[v]),
                    MedianWithInterval(runs.best_iterations, 3), PValueCell(test.iteration_p[v]),
                    FoundCell(runs), PValueCell(test.success_p[v])});
    }
  }
  return table.ToString();
}

}  // namespace swarmplan::bench::bpso
