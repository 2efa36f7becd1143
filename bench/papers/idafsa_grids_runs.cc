#include "bench/papers/idafsa_grids_runs.h"

#include <memory>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/time.h"
#include "bench/papers/plan_once.h"
#include "core/geometry/collision.h"
#include "core/map/io/map_io.h"
#include "core/smoothing/bezier.h"

namespace swarmplan::bench {
namespace {

Point3 CellPoint(const OccupancyGrid& grid, Cell c) {
  const Point2 p = grid.CellCenter(c);
  return Point3(p.x(), p.y(), 0.0);
}

absl::Status Prefixed(const std::string& what, const absl::Status& status) {
  return absl::Status(status.code(), absl::StrCat(what, ": ", status.message()));
}

}  // namespace

ParamValues PaperFishParams(const FishConfig& config, const IdafsaGridWorld& world,
                            int max_generations) {
  ParamValues params = {
      {"init", std::string("paper")},
      {"population", int64_t{50}},
      {"try_number", int64_t{8}},
      {"max_generations", int64_t{max_generations}},
      {"visual", 5.0},
      {"crowding", 0.618},
  };
  if (config.algorithm == "idafsa") params["feedback_gain"] = world.size <= 10 ? 17.0 : 10.0;
  for (const auto& [name, value] : config.params) params[name] = value;
  return params;
}

absl::StatusOr<FishRunStats> RunFishConfig(const FishConfig& config, const IdafsaGridWorld& world,
                                           const MapPtr& map, const ExperimentOptions& options,
                                           int runs, int max_generations) {
  const OccupancyGrid& grid = *map->grid();
  const Point3 start = CellPoint(grid, IdafsaStart(world));
  const Point3 goal = CellPoint(grid, IdafsaGoal(world));
  PlanSpec spec;
  spec.algorithm = config.algorithm;
  spec.params = PaperFishParams(config, world, max_generations);
  spec.smoothing = "bezier";
  const BezierOptions bezier = DefaultBezierOptions(*map, 0.0);
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*map);

  FishRunStats stats;
  for (int r = 0; r < runs; ++r) {
    const uint64_t seed = options.seed + static_cast<uint64_t>(r);
    const std::string what = absl::StrCat(config.label, " on ", world.file, ", seed ", seed);
    absl::StatusOr<PlanResult> plan = PlanOnce(spec, map, start, goal, seed);
    if (!plan.ok()) return Prefixed(what, plan.status());
    ++stats.runs;
    stats.millis.push_back(absl::ToDoubleMilliseconds(plan->wall_time));
    stats.iterations.push_back(plan->iterations);
    if (!plan->raw_path.empty()) stats.all_arrival_lengths.push_back(plan->raw_metrics.length);
    if (!plan->found) {
      if (!plan->raw_path.empty()) {
        ++(PassesThroughBlockedCell(grid, plan->raw_path) ? stats.jumped : stats.cut_corner);
      }
      continue;
    }
    if (absl::Status s = CheckFoundPath(*plan, start, goal, what); !s.ok()) return s;
    stats.lengths.push_back(plan->raw_metrics.length);
    stats.turning_points.push_back(plan->raw_metrics.turning_points);
    stats.best_iterations.push_back(plan->best_iteration);

    const BezierResult smoothed = SmoothWithBezier(plan->raw_path, bezier, checker.get());
    stats.kappa.push_back(smoothed.max_curvature);
    stats.sampled_kappa.push_back(plan->smoothed_metrics.max_curvature);
    stats.smoothed_lengths.push_back(plan->smoothed_metrics.length);
    stats.corners += smoothed.corners;
    stats.corners_limited += smoothed.corners_limited;
    stats.corners_shrunk += smoothed.corners_shrunk;
    stats.corners_sharp += smoothed.corners_sharp;
    if (smoothed.max_curvature <= 1.0 / bezier.min_turning_radius + 1e-9) {
      ++stats.kappa_within_bound;
    }
    if (plan->smoothing_collision_free) ++stats.smoothed_free;
  }
  return stats;
}

absl::StatusOr<PlanResult> RunReference(const std::string& algorithm, const IdafsaGridWorld& world,
                                        const MapPtr& map) {
  const OccupancyGrid& grid = *map->grid();
  const Point3 start = CellPoint(grid, IdafsaStart(world));
  const Point3 goal = CellPoint(grid, IdafsaGoal(world));
  PlanSpec spec;
  spec.algorithm = algorithm;
  const std::string what = absl::StrCat(algorithm, " on ", world.file);
  absl::StatusOr<PlanResult> plan = PlanOnce(spec, map, start, goal, 1);
  if (!plan.ok()) return Prefixed(what, plan.status());
  if (!plan->found) return absl::InternalError(absl::StrCat(what, ": no path on a connected grid"));
  if (absl::Status s = CheckFoundPath(*plan, start, goal, what); !s.ok()) return s;
  return plan;
}

absl::StatusOr<MapPtr> LoadIdafsaWorld(const ExperimentOptions& options,
                                       const IdafsaGridWorld& world) {
  const std::string path = options.worlds_dir + "/idafsa-grids/" + world.file;
  absl::StatusOr<Map> map = LoadMapFile(path, "ascii");
  if (!map.ok()) return map.status();
  if (map->grid() == nullptr || map->grid()->width() != world.size ||
      map->grid()->height() != world.size) {
    return absl::FailedPreconditionError(
        absl::StrCat(path, ": expected a ", world.size, " x ", world.size, " grid"));
  }
  return std::make_shared<const Map>(std::move(*map));
}

}  // namespace swarmplan::bench
