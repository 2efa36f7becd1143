#include "bench/papers/bpso_vertices_assistant.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "bench/papers/bpso_vertices_paper.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"
#include "core/algorithms/bpso/binary_pso.h"
#include "core/geometry/collision.h"
#include "core/path_metrics.h"

namespace swarmplan::bench::bpso {
namespace {

// The bits of a run count as frozen when at least this share of positions is saturated.
constexpr double kFrozenShare = 0.5;

SuccessCount Found(const Runs& runs) { return {runs.found(), runs.count}; }

Point3 At(const Point2& p) { return Point3(p.x(), p.y(), 0.0); }

absl::Status CheckTracedPath(const SearchResult& result, const World& world,
                             const std::string& what) {
  if (!result.found) return absl::OkStatus();
  const Point3 start = At(BpsoVerticesStart()), goal = At(BpsoVerticesGoal());
  if (result.path.empty() || result.path.front() != start || result.path.back() != goal) {
    return absl::InternalError(absl::StrCat(what, ": the path does not join start and goal"));
  }
  if (!MakeCollisionChecker(*world.map)->PathFree(result.path, 0.0)) {
    return absl::InternalError(absl::StrCat(what, ": the found path collides"));
  }
  if (PathLength(result.path) < world.optimum - 1e-6) {
    return absl::InternalError(absl::StrCat(what, ": the path is shorter than the optimum"));
  }
  return absl::OkStatus();
}

absl::StatusOr<AssistantRuns> RunVariant(const AssistantVariant& variant, const World& world,
                                         uint64_t first_seed, int runs, int iterations) {
  BinaryPsoParams params;
  params.iterations = iterations;
  params.swarm_factor = kPaperSwarmFactor;
  params.mutation_probability = variant.mutation;
  params.assistant_bound = variant.bound;
  AssistantRuns out;
  out.runs.count = runs;
  for (int i = 0; i < runs; ++i) {
    Problem problem;
    problem.map = world.map;
    problem.start = At(BpsoVerticesStart());
    problem.goal = At(BpsoVerticesGoal());
    problem.seed = first_seed + static_cast<uint64_t>(i);
    BinaryPsoPlanner planner(params);
    AssistantTrace trace;
    planner.TraceAssistants(&trace);
    NullObserver observer;
    const absl::Time began = absl::Now();
    absl::StatusOr<SearchResult> result = planner.Solve(problem, StopToken(), observer);
    if (!result.ok()) return result.status();
    out.runs.seconds.push_back(absl::ToDoubleSeconds(absl::Now() - began));
    const std::string what = absl::StrFormat("bpso-vertices: %s on %s (seed %d)", variant.label,
                                             world.name, static_cast<int64_t>(problem.seed));
    if (absl::Status s = CheckTracedPath(*result, world, what); !s.ok()) return s;
    out.saturated.push_back(trace.saturated_fraction);
    out.final_magnitude.push_back(trace.mean_magnitude.empty() ? 0.0 : trace.mean_magnitude.back());
    out.runs.convergence.push_back(std::move(result->convergence));
    if (!result->found) continue;
    out.runs.lengths.push_back(PathLength(result->path));
    out.runs.best_iterations.push_back(result->best_iteration + 1.0);
  }
  return out;
}

// The median over runs of the saturated share after iteration `iteration` (1-based).
std::optional<double> MedianSaturated(const AssistantRuns& runs, int iteration) {
  std::vector<double> shares;
  for (const std::vector<double>& run : runs.saturated) {
    if (static_cast<int>(run.size()) >= iteration) shares.push_back(run[iteration - 1]);
  }
  return Median(shares);
}

std::string PercentCell(std::optional<double> share) {
  return share.has_value() ? absl::StrFormat("%.0f %%", 100.0 * *share) : "–";
}

std::vector<int> Checkpoints(int iterations) {
  std::vector<int> out;
  for (int t : {1, iterations / 10, iterations / 4, iterations / 2, iterations}) {
    if (t >= 1 && (out.empty() || t > out.back())) out.push_back(t);
  }
  return out;
}

int LastIteration(const AssistantWorld& world) {
  int last = 0;
  for (const AssistantRuns& v : world.variants) {
    for (const std::vector<double>& run : v.saturated) {
      last = std::max(last, static_cast<int>(run.size()));
    }
  }
  return last;
}

}  // namespace

const std::vector<AssistantVariant>& AssistantVariants() {
  static const std::vector<AssistantVariant>* const variants = new std::vector<AssistantVariant>{
      {"mutation 0.1, unbounded (the paper's)", kPaperMutation, 0.0},
      {absl::StrFormat("mutation 0.1, bounded to ±%g", kAssistantBound), kPaperMutation,
       kAssistantBound},
      {"no mutation, unbounded", 0.0, 0.0},
      {absl::StrFormat("no mutation, bounded to ±%g", kAssistantBound), 0.0, kAssistantBound},
  };
  return *variants;
}

absl::StatusOr<std::vector<AssistantWorld>> RunAssistantWorlds(const FigureRuns& figures,
                                                               uint64_t first_seed, int runs,
                                                               int iterations, std::ostream* log) {
  std::vector<AssistantWorld> out;
  for (const ConvergenceWorld& convergence : figures.convergence) {
    AssistantWorld world;
    world.world = convergence.world;
    for (const AssistantVariant& variant : AssistantVariants()) {
      absl::StatusOr<AssistantRuns> variant_runs =
          RunVariant(variant, figures.worlds[convergence.world], first_seed, runs, iterations);
      if (!variant_runs.ok()) return variant_runs.status();
      if (log != nullptr) {
        *log << "bpso-vertices: assistant " << variant.label << ", "
             << figures.worlds[convergence.world].name << ": " << variant_runs->runs.found() << "/"
             << runs << " found\n";
      }
      world.variants.push_back(*std::move(variant_runs));
    }
    out.push_back(std::move(world));
  }
  return out;
}

std::string AssistantSection(const FigureRuns& figures, const std::vector<AssistantWorld>& worlds,
                             std::string* summary) {
  std::string out = absl::StrFormat(
      "## The assistant positions (Fig. 5's explanation, instrumented)\n\n"
      "The double structure draws each bit from sigmoid(x) of its continuous assistant position "
      "x (eqs 6-7), which the paper does not bound. A position with |x| >= ln 99 = 4.6 is "
      "*saturated*: its bit flips against it in fewer than 1 %% of updates. The planner's trace "
      "gives the share of saturated positions over the whole swarm after each iteration; here "
      "on the Fig. 5 worlds (N = %g D), with and without mutation, unbounded (the paper's) and "
      "with every position kept within ±%g (`assistant_bound`). Medians over %d runs.\n\n",
      kPaperSwarmFactor, kAssistantBound, figures.runs);
  std::vector<std::string> header = {"D", "variant"};
  const int last = worlds.empty() ? 0 : LastIteration(worlds.front());
  const std::vector<int> checkpoints = Checkpoints(last);
  for (int t : checkpoints) header.push_back(absl::StrCat("saturated after ", t));
  header.push_back("mean |x| at the end");
  MarkdownTable saturation(header, 2);
  MarkdownTable effects(
      {"D", "variant", "found", "Fisher (found)", "median length [95 % CI]", "rank-sum (length)",
       "median iteration of the final best", "rank-sum (iteration)"},
      1);
  std::string frozen, effects_text;
  int unbounded_cells = 0, frozen_cells = 0;
  for (const AssistantWorld& world : worlds) {
    const std::string d = absl::StrCat(figures.worlds[world.world].vertices);
    for (size_t v = 0; v < world.variants.size(); ++v) {
      const AssistantRuns& runs = world.variants[v];
      std::vector<std::string> row = {d, AssistantVariants()[v].label};
      for (int t : checkpoints) row.push_back(PercentCell(MedianSaturated(runs, t)));
      row.push_back(NumberCell(Median(runs.final_magnitude), 3));
      saturation.AddRow(std::move(row));

      // A bounded variant against the unbounded one with the same mutation.
      const bool bounded = AssistantVariants()[v].bound > 0;
      const AssistantRuns& reference = world.variants[bounded ? v - 1 : v];
      const std::optional<double> found_p =
          bounded ? SuccessP(Found(reference.runs), Found(runs.runs)) : std::nullopt;
      const std::optional<double> length_p =
          bounded ? RankSumP(reference.runs.lengths, runs.runs.lengths) : std::nullopt;
      const std::optional<double> iteration_p =
          bounded ? RankSumP(reference.runs.best_iterations, runs.runs.best_iterations)
                  : std::nullopt;
      effects.AddRow(
          {d, AssistantVariants()[v].label, absl::StrCat(runs.runs.found(), "/", runs.runs.count),
           bounded ? PValueCell(found_p) : "", MedianWithInterval(runs.runs.lengths),
           bounded ? PValueCell(length_p) : "", NumberCell(Median(runs.runs.best_iterations), 3),
           bounded ? PValueCell(iteration_p) : ""});
      if (!bounded) {
        const std::optional<double> end = MedianSaturated(runs, last);
        ++unbounded_cells;
        if (end.value_or(0.0) >= kFrozenShare) ++frozen_cells;
        AppendListItem(
            &frozen,
            absl::StrCat("D = ", d, " ", AssistantVariants()[v].label, " ", PercentCell(end),
                         end.value_or(0.0) >= kFrozenShare ? " (frozen)" : ""),
            "; ");
        continue;
      }
      const std::string label = absl::StrCat("D = ", d, " ", AssistantVariants()[v].label);
      std::string differences;
      AppendListItem(&differences,
                     SuccessDifference(label, Found(reference.runs), Found(runs.runs), found_p));
      AppendListItem(&differences, ValueDifference(label, "final length", reference.runs.lengths,
                                                   runs.runs.lengths, length_p));
      AppendListItem(&differences, ValueDifference(label, "iteration of the final best",
                                                   reference.runs.best_iterations,
                                                   runs.runs.best_iterations, iteration_p));
      AppendListItem(
          &effects_text,
          differences.empty() ? absl::StrCat(label, ": no significant difference") : differences,
          "; ");
    }
  }
  absl::StrAppend(&out, saturation.ToString(),
                  "\nEach bounded variant against the unbounded one with the same mutation "
                  "(Fisher; rank-sum):\n\n",
                  effects.ToString(), "\n");
  absl::StrAppend(
      summary,
      "- *The assistant positions, instrumented* (the section above). The earlier reading was "
      "that in the double structure the unbounded assistant positions drift far from 0 and "
      "freeze the bits, leaving mutation as the main exploration, where plain BPSO redraws each "
      "bit from sigmoid(v) of a clamped v. Share of saturated positions at the last iteration "
      "(median over runs; frozen from ",
      PercentCell(kFrozenShare), "): ", frozen,
      frozen_cells == 0 ? ", so the positions do not freeze the bits and the reading is refuted"
      : frozen_cells < unbounded_cells ? ", so they freeze the bits in some settings only"
                                       : ", so they do freeze the bits",
      ". Bounding them to ±", absl::StrFormat("%g", kAssistantBound),
      " against unbounded: ", effects_text, ".\n");
  return out;
}

}  // namespace swarmplan::bench::bpso
