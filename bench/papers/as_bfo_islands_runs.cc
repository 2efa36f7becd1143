#include "bench/papers/as_bfo_islands_runs.h"

#include <memory>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/time.h"
#include "bench/papers/as_bfo_islands_check.h"
#include "bench/papers/as_bfo_islands_world.h"
#include "core/map/map.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

Point3 CellPoint(const OccupancyGrid& grid, Cell c) {
  const Point2 p = grid.CellCenter(c);
  return Point3(p.x(), p.y(), 0.0);
}

}  // namespace

absl::StatusOr<World> MakeWorld(const std::string& environment, OccupancyGrid grid, uint64_t seed) {
  World world;
  world.environment = environment;
  world.n = grid.width();
  world.start = IslandStart(world.n);
  world.goal = IslandGoal(world.n);
  world.blocked = grid.BlockedCount();
  world.islands = CountIslands(grid);
  world.map = std::make_shared<const Map>(Map(std::move(grid)));
  const OccupancyGrid& cells = *world.map->grid();
  const std::string what = absl::StrCat(environment, " ", world.n, "x", world.n);
  absl::StatusOr<PlanResult> exact =
      PlanOnce(PlanSpec{"astar", {}}, world.map, CellPoint(cells, world.start),
               CellPoint(cells, world.goal), seed);
  if (!exact.ok()) return exact.status();
  if (!exact->found) {
    return absl::FailedPreconditionError(absl::StrCat(what, ": A* finds no path"));
  }
  world.optimum = exact->raw_metrics.length;
  if (absl::Status s = CheckGridPath(cells, exact->raw_path, exact->raw_metrics, world.start,
                                     world.goal, world.optimum);
      !s.ok()) {
    return absl::InternalError(absl::StrCat(what, ": astar: ", s.message()));
  }
  return world;
}

absl::StatusOr<Outcome> RunConfig(const PlanSpec& spec, const World& world, int runs,
                                  uint64_t seed) {
  const OccupancyGrid& grid = *world.map->grid();
  Outcome outcome;
  for (int i = 0; i < runs; ++i) {
    const uint64_t run_seed = seed + static_cast<uint64_t>(i);
    absl::StatusOr<PlanResult> result = PlanOnce(spec, world.map, CellPoint(grid, world.start),
                                                 CellPoint(grid, world.goal), run_seed);
    const std::string where = absl::StrCat(spec.algorithm, " on ", world.environment, " ", world.n,
                                           "x", world.n, ", seed ", run_seed, ": ");
    if (!result.ok()) return absl::InternalError(where + std::string(result.status().message()));
    ++outcome.runs;
    outcome.millis.push_back(absl::ToDoubleMilliseconds(result->wall_time));
    outcome.evaluations.push_back(static_cast<double>(result->evaluations));
    if (!result->found) continue;
    if (absl::Status s = CheckGridPath(grid, result->raw_path, result->raw_metrics, world.start,
                                       world.goal, world.optimum);
        !s.ok()) {
      return absl::InternalError(where + std::string(s.message()));
    }
    outcome.lengths.push_back(result->raw_metrics.length);
    outcome.ains.push_back(result->best_iteration + 1.0);
  }
  return outcome;
}

int OptimalRuns(const Outcome& outcome, double optimum) {
  int count = 0;
  for (double length : outcome.lengths) count += length <= optimum + 1e-9 ? 1 : 0;
  return count;
}

}  // namespace swarmplan::bench::as_bfo_islands
