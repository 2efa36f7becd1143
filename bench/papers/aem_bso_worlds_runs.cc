#include "bench/papers/aem_bso_worlds_runs.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/aem_bso_worlds_generate.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::aem_bso {
namespace {

Point3 Start() { return Point3(AemBsoStart().x(), AemBsoStart().y(), 0.0); }
Point3 Goal() { return Point3(AemBsoGoal().x(), AemBsoGoal().y(), 0.0); }

}  // namespace

PlanSpec PaperPlan(const std::string& planner, const std::string& interpolation, int iterations) {
  PlanSpec plan{planner,
                {{"init", std::string("paper")},
                 {"interpolation", interpolation},
                 {"iterations", int64_t{iterations}},
                 {"population", int64_t{kPopulation}},
                 {"penalty", kPenalty},
                 {"d_safe", kAemBsoSafeDistance}},
                "none",
                iterations,
                kAemBsoSafeDistance};
  if (planner == "pso") {  // the paper's PSO factors (section 3); our default is 2
    plan.params["c1"] = kPaperFactor;
    plan.params["c2"] = kPaperFactor;
  }
  return plan;
}

absl::StatusOr<CellStats> RunCell(const PlanSpec& plan, const MapPtr& map,
                                  const ExperimentOptions& options, int runs,
                                  const std::string& what) {
  CellStats cell;
  for (int run = 0; run < runs; ++run) {
    const uint64_t seed = options.seed + static_cast<uint64_t>(run);
    absl::StatusOr<PlanResult> result = PlanOnce(plan, map, Start(), Goal(), seed);
    if (!result.ok()) return result.status();
    if (absl::Status s =
            CheckFoundPath(*result, Start(), Goal(), absl::StrCat(what, " seed ", seed));
        !s.ok()) {
      return s;
    }
    ++cell.runs;
    if (result->found) cell.lengths.push_back(result->raw_metrics.length);
    cell.fitnesses.push_back(result->fitness);
    cell.seconds.push_back(absl::ToDoubleSeconds(result->wall_time));
    cell.cpu_seconds.push_back(absl::ToDoubleSeconds(result->cpu_time));
    cell.best_iterations.push_back(result->best_iteration);
    cell.evaluations.push_back(static_cast<double>(result->evaluations));
    std::vector<double>& curve = cell.convergence.emplace_back();
    for (const IterationStats& stats : result->convergence) curve.push_back(stats.best_fitness);
  }
  if (options.log != nullptr) {
    *options.log << absl::StrFormat(
        "aem-bso-worlds: %s: %d/%d found, best %s, mean %s, %.2f s/run\n", what, cell.found(),
        cell.runs, NumberCell(Min(cell.lengths)), NumberCell(Mean(cell.lengths)),
        Mean(cell.seconds).value_or(0.0));
  }
  return cell;
}

absl::StatusOr<double> ExactOptimum(const MapPtr& map, uint64_t seed, const std::string& what) {
  const PlanSpec exact{"visibility-graph", {}, "none", 0, kAemBsoSafeDistance};
  absl::StatusOr<PlanResult> optimum = PlanOnce(exact, map, Start(), Goal(), seed);
  if (!optimum.ok()) return optimum.status();
  if (!optimum->found) {
    return absl::FailedPreconditionError(absl::StrCat(what, ": no path keeps d_safe"));
  }
  if (absl::Status s = CheckFoundPath(*optimum, Start(), Goal(), what + " visibility-graph");
      !s.ok()) {
    return s;
  }
  return optimum->raw_metrics.length;
}

}  // namespace swarmplan::bench::aem_bso
