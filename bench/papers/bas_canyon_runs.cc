#include "bench/papers/bas_canyon_runs.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/time.h"
#include "bench/papers/parallel_jobs.h"

namespace swarmplan::bench::bas {
namespace {

// One run's outcome, written by its own job.
struct RunOutcome {
  bool found = false;
  double fitness = 0.0;
  double length = 0.0;
  double seconds = 0.0;
  int best_iteration = 0;
  bool right_branch = false;
};

}  // namespace

ParamValues PaperBeetleParams(int iterations) {
  return {{"iterations", int64_t{iterations}},
          {"init", std::string("paper")},
          {"reject_infeasible", false},
          {"step_units", std::string("cells")},
          {"step0", 8.0},
          {"step_decay", 0.998},
          {"c", 2.0},
          {"theta0", 21.0},
          {"theta_decay", 0.998}};
}

ParamValues PaperAcoParams(int iterations) {
  return {{"iterations", int64_t{iterations}}, {"ants", int64_t{20}}};
}

ParamValues RejectInfeasible(ParamValues params) {
  params["reject_infeasible"] = true;
  return params;
}

ParamValues MapScaledSteps(ParamValues params, double step_fraction) {
  params["step_units"] = std::string("map");
  params["step_fraction"] = step_fraction;
  return params;
}

PlanSpec Spec(const std::string& algorithm, ParamValues params) {
  PlanSpec spec;
  spec.algorithm = algorithm;
  spec.params = std::move(params);
  return spec;
}

const RowRuns* RowSet::Find(const std::string& label) const {
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].label == label) return &runs[r];
  }
  return nullptr;
}

RowSet Merged(const RowSet& a, const RowSet& b) {
  RowSet out = a;
  out.rows.insert(out.rows.end(), b.rows.begin(), b.rows.end());
  out.runs.insert(out.runs.end(), b.runs.begin(), b.runs.end());
  return out;
}

absl::StatusOr<RowSet> RunRows(std::vector<Row> rows, const CanyonWorld& world,
                               const ExperimentOptions& options, int runs) {
  std::vector<RunOutcome> outcomes(rows.size() * runs);
  ProgressLog log(options.log);
  const absl::Status status =
      RunJobs(static_cast<int>(outcomes.size()), options.jobs, [&](int job) -> absl::Status {
        const Row& row = rows[job / runs];
        const uint64_t seed = options.seed + static_cast<uint64_t>(job % runs);
        const std::string what =
            absl::StrCat("bas-canyon world ", world.index, ": ", row.label, " seed ", seed);
        absl::StatusOr<PlanResult> result =
            PlanOnce(row.spec, world.map, world.start, world.goal, seed);
        if (!result.ok()) {
          return absl::Status(result.status().code(),
                              absl::StrCat(what, ": ", result.status().message()));
        }
        if (absl::Status s = CheckFoundPath(*result, world.start, world.goal, what); !s.ok()) {
          return s;
        }
        RunOutcome& out = outcomes[job];
        out.seconds = absl::ToDoubleSeconds(result->wall_time);
        out.found = result->found;
        if (!result->found) return absl::OkStatus();
        out.fitness = result->fitness;
        out.length = result->raw_metrics.length;
        out.best_iteration = result->best_iteration;
        out.right_branch = InRightBranch(result->raw_path);
        log.Line(absl::StrCat(what, ": fitness ", result->fitness));
        return absl::OkStatus();
      });
  if (!status.ok()) return status;
  RowSet out;
  out.runs.resize(rows.size());
  for (size_t job = 0; job < outcomes.size(); ++job) {
    const RunOutcome& o = outcomes[job];
    RowRuns& r = out.runs[job / runs];
    ++r.runs;
    r.seconds.push_back(o.seconds);
    if (!o.found) continue;
    r.fitness.push_back(o.fitness);
    r.length.push_back(o.length);
    r.best_iteration.push_back(o.best_iteration);
    if (o.right_branch) ++r.right_branch;
    if (o.best_iteration > 0) ++r.improved;
  }
  out.rows = std::move(rows);
  return out;
}

}  // namespace swarmplan::bench::bas
