#include "bench/papers/aem_bso_functions_runs.h"

#include <chrono>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/parallel_jobs.h"
#include "bench/statistics.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/random.h"
#include "core/registry.h"
#include "core/stop_token.h"

namespace swarmplan::bench::aem_bso {
namespace {

absl::StatusOr<SwarmOptimiser> MakeOptimiser(const OptimiserConfig& config, int population) {
  absl::StatusOr<const PlannerInfo*> info = DefaultRegistry().Get(config.planner_id);
  if (!info.ok()) return info.status();
  ParamValues values = config.overrides;
  values["population"] = static_cast<int64_t>(population);
  absl::StatusOr<ParamSet> params = ParamSet::Resolve((*info)->params, values);
  if (!params.ok()) return params.status();
  return SwarmOptimiserFor(config.planner_id, *params);
}

// Appends a run's best so far at each checkpoint to `best_so_far[k]`.
class CheckpointObserver final : public Observer {
 public:
  CheckpointObserver(const std::vector<int>& checkpoints,
                     std::vector<std::vector<double>>& best_so_far)
      : checkpoints_(checkpoints), best_so_far_(best_so_far) {}
  void OnIteration(const IterationStats& stats) override {
    if (next_ < checkpoints_.size() && stats.iteration + 1 == checkpoints_[next_]) {
      best_so_far_[next_++].push_back(stats.best_fitness);
    }
  }
  bool Complete() const { return next_ == checkpoints_.size(); }

 private:
  const std::vector<int>& checkpoints_;
  std::vector<std::vector<double>>& best_so_far_;
  size_t next_ = 0;
};

absl::StatusOr<FunctionCell> RunJob(const FunctionJob& job, int iterations, int population,
                                    uint64_t seed) {
  absl::StatusOr<SwarmOptimiser> optimiser = MakeOptimiser(job.config, population);
  if (!optimiser.ok()) return optimiser.status();
  const int t_max = iterations * job.config.iteration_factor;
  const TestFunction& function = *job.function;
  FunctionCell cell;
  const std::vector<int> checkpoints = ConvergenceCheckpoints(t_max);
  cell.best_so_far.resize(checkpoints.size());
  double evaluations = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < job.runs; ++r) {
    TestFunctionObjective objective =
        job.shifted
            ? TestFunctionObjective(function, job.dim, ShiftFor(function, job.dim, kShiftFraction))
            : TestFunctionObjective(function, job.dim);
    Rng rng(seed + static_cast<uint64_t>(r));
    CheckpointObserver observer(checkpoints, cell.best_so_far);
    const SearchOutcome outcome = (*optimiser)(objective, t_max, rng, StopToken(), observer);
    if (outcome.iterations != t_max) {
      return absl::InternalError(absl::StrCat(function.id, ": ran ", outcome.iterations,
                                              " iterations instead of ", t_max));
    }
    if (!observer.Complete()) {
      return absl::InternalError(
          absl::StrCat(function.id, ": the optimiser did not report every iteration"));
    }
    if (absl::Status status =
            CheckOptimiserResult(function, objective, outcome.best_x, outcome.best_fitness);
        !status.ok()) {
      return status;
    }
    cell.best_values.push_back(outcome.best_fitness);
    evaluations += static_cast<double>(outcome.evaluations);
  }
  cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  cell.evaluations_per_run = job.runs > 0 ? evaluations / job.runs : 0.0;
  return cell;
}

}  // namespace

std::vector<int> ConvergenceCheckpoints(int t_max) {
  std::vector<int> out;
  for (int t : {t_max / 100, t_max / 20, t_max / 10, t_max / 4, t_max / 2, t_max}) {
    if (t >= 1 && (out.empty() || t > out.back())) out.push_back(t);
  }
  return out;
}

Eigen::VectorXd ShiftFor(const TestFunction& function, int dim, double shift_fraction) {
  Eigen::VectorXd shift(dim);
  for (int j = 0; j < dim; ++j) {
    shift[j] = (j % 2 == 0 ? 1.0 : -1.0) * shift_fraction * function.upper;
  }
  return shift;
}

absl::StatusOr<std::vector<FunctionCell>> RunFunctionJobs(const std::vector<FunctionJob>& jobs,
                                                          int iterations, int population,
                                                          uint64_t seed,
                                                          const ExperimentOptions& options) {
  std::vector<FunctionCell> cells(jobs.size());
  ProgressLog log(options.log);
  const absl::Status status =
      RunJobs(static_cast<int>(jobs.size()), options.jobs, [&](int i) -> absl::Status {
        const FunctionJob& job = jobs[i];
        absl::StatusOr<FunctionCell> cell = RunJob(job, iterations, population, seed);
        const std::string what = absl::StrCat(job.config.label, ", D = ", job.dim, ", ",
                                              job.function->id, job.shifted ? " shifted" : "");
        if (!cell.ok())
          return absl::InternalError(absl::StrCat(what, ": ", cell.status().message()));
        log.Line(absl::StrFormat("aem-bso-functions: %s: mean %.3g (%.1f s)", what,
                                 Mean(cell->best_values).value_or(0.0), cell->seconds));
        cells[i] = *std::move(cell);
        return absl::OkStatus();
      });
  if (!status.ok()) return status;
  return cells;
}

}  // namespace swarmplan::bench::aem_bso
