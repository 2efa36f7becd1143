// The terrain part of bench/results/exact-yardsticks.md: on every shared DEM, the
// terrain-lattice optimum of a long query and how the terrain planners compare with it.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/time.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/plan_once.h"
#include "bench/statistics.h"
#include "core/algorithms/exact/terrain_lattice.h"
#include "core/geometry/terrain_collision.h"
#include "core/map/io/map_io.h"
#include "core/operators/terrain_path_cost.h"

namespace swarmplan::bench {
namespace {

constexpr double kClearance = 1.0;            // height units
constexpr double kStartAboveClearance = 1.0;  // start and goal this far above ground + clearance
constexpr int kLatticeRuns = 3;               // timed lattice queries per DEM

const char* const kDems[] = {"alps_tiny.asc", "alps_small.asc", "alps_medium.asc",
                             "DEM-kootenai_37x50_1x1.asc", "west_bijou_gully.asc"};
const char* const kPlanners[] = {"bas", "lfs-bas", "aco-bas", "sio-bas", "multi-bas", "aco"};

std::string BenchmarksDir(const ExperimentOptions& options) {
  if (const char* dir = std::getenv("SWARMPLAN_BENCHMARKS")) return dir;
  return (std::filesystem::path(options.worlds_dir) / ".." / ".." / ".." / "shared" / "benchmarks")
      .lexically_normal()
      .string();
}

// The long query: on the middle row (or the nearest row with two usable cells), from its
// westernmost to its easternmost cell centre whose ground is defined, kStartAboveClearance above
// ground + clearance.
bool LongQuery(const Terrain& terrain, Point3& start, Point3& goal) {
  const TerrainCollisionChecker checker(terrain);
  const int middle = terrain.depth() / 2;
  for (int offset = 0; offset < terrain.depth(); ++offset) {
    for (const int j : {middle - offset, middle + offset}) {
      if (j < 0 || j >= terrain.depth()) continue;
      int first = -1, last = -1;
      for (int i = 0; i < terrain.width(); ++i) {
        const Point2 xy = terrain.CellCentre(i, j);
        if (std::isnan(terrain.GroundAt(xy))) continue;
        if (first < 0) first = i;
        last = i;
      }
      if (first < 0 || last - first < 2) continue;
      const auto at = [&](int i) {
        const Point2 xy = terrain.CellCentre(i, j);
        return Point3(xy.x(), xy.y(), terrain.GroundAt(xy) + kClearance + kStartAboveClearance);
      };
      start = at(first);
      goal = at(last);
      return true;
    }
  }
  return false;
}

std::string PointText(const Point3& p) {
  return absl::StrFormat("(%.9g, %.9g, %.6g)", p.x(), p.y(), p.z());
}

}  // namespace

absl::StatusOr<std::string> RunTerrainYardsticks(const ExperimentOptions& options) {
  const std::string dir = BenchmarksDir(options) + "/terrain";
  const int runs = options.quick ? 1 : (options.runs > 0 ? options.runs : 3);
  const int iterations = options.quick ? 10 : 0;  // 0: the planners' defaults
  const int lattice_runs = options.quick ? 1 : kLatticeRuns;
  if (!std::filesystem::is_directory(dir)) {
    return absl::StrCat("## Terrain (DEMs)\n\nSkipped: no shared DEMs at ", dir,
                        " (set SWARMPLAN_BENCHMARKS to the benchmarks folder).\n");
  }
  MarkdownTable lattice_table({"DEM", "cells", "cell size", "query (start -> goal, world)",
                               "levels (step)", "lattice nodes", "expanded", "lattice optimum",
                               "time per query (s)"});
  MarkdownTable planner_table(
      {"DEM", "planner", "found", "best", "best / lattice", "mean / lattice", "mean time (s)"});
  for (const char* name : kDems) {
    const std::string file = absl::StrCat(dir, "/", name);
    absl::StatusOr<Map> loaded = LoadMapFile(file);
    if (!loaded.ok()) return loaded.status();
    const MapPtr map = std::make_shared<const Map>(std::move(*loaded));
    const Terrain& terrain = *map->terrain();
    Point3 start, goal;
    if (!LongQuery(terrain, start, goal)) {
      return absl::InternalError(absl::StrCat("terrain-yardsticks: ", name, " has no long query"));
    }
    PlanSpec lattice_spec;
    lattice_spec.algorithm = "terrain-lattice";
    lattice_spec.clearance = kClearance;
    std::vector<double> seconds;
    absl::StatusOr<PlanResult> lattice;
    for (int r = 0; r < lattice_runs; ++r) {
      lattice = PlanOnce(lattice_spec, map, start, goal, 1);
      if (!lattice.ok()) return lattice.status();
      seconds.push_back(absl::ToDoubleSeconds(lattice->wall_time));
    }
    if (absl::Status s = CheckFoundPath(*lattice, start, goal, name); !s.ok()) return s;
    TerrainLatticeOptions lattice_options;
    absl::StatusOr<TerrainLatticeResult> shape =
        TerrainLatticeOptimum(terrain, start, goal, kClearance, lattice_options);
    if (!shape.ok()) return shape.status();
    const double optimum = lattice->found ? lattice->fitness : 0.0;
    lattice_table.AddRow(
        {name, absl::StrCat(terrain.width(), " x ", terrain.depth()),
         absl::StrFormat("%.9g", terrain.cell_size()),
         absl::StrCat(PointText(start), " -> ", PointText(goal)),
         absl::StrCat(shape->levels.count, " (", NumberCell(shape->levels.step), ")"),
         absl::StrCat(shape->nodes), absl::StrCat(lattice->evaluations),
         lattice->found ? NumberCell(optimum, 6) : "none", NumberCell(Median(seconds))});
    for (const char* planner : kPlanners) {
      PlanSpec spec;
      spec.algorithm = planner;
      spec.clearance = kClearance;
      spec.max_iterations = iterations;
      std::vector<double> costs, times;
      for (int r = 0; r < runs; ++r) {
        const uint64_t seed = options.seed + static_cast<uint64_t>(r);
        absl::StatusOr<PlanResult> result = PlanOnce(spec, map, start, goal, seed);
        if (!result.ok()) {
          if (options.log != nullptr) {
            *options.log << name << " " << planner << ": " << result.status() << "\n";
          }
          break;
        }
        const std::string what = absl::StrCat(name, " ", planner, " seed ", seed);
        if (absl::Status s = CheckFoundPath(*result, start, goal, what); !s.ok()) return s;
        times.push_back(absl::ToDoubleSeconds(result->wall_time));
        if (result->found) costs.push_back(TerrainPathCost(result->raw_path, terrain.cell_size()));
      }
      const auto ratio = [&](std::optional<double> v) -> std::optional<double> {
        if (!v.has_value() || !lattice->found) return std::nullopt;
        return *v / optimum;
      };
      planner_table.AddRow(
          {name, planner, times.empty() ? "refused" : absl::StrCat(costs.size(), "/", times.size()),
           NumberCell(Min(costs), 6), NumberCell(ratio(Min(costs))), NumberCell(ratio(Mean(costs))),
           NumberCell(Mean(times))});
    }
  }
  std::string report = "## Terrain (DEMs)\n\n";
  absl::StrAppend(
      &report, "Generated by `swarmplan-papers run terrain-yardsticks`",
      options.quick ? " in quick mode (the numbers say nothing)" : "",
      ". Every DEM of `../shared/benchmarks/terrain` (override with SWARMPLAN_BENCHMARKS), in "
      "world units as loaded: x and y in the file's cellsize unit, z in its height unit. **The "
      "alps_* files have their cellsize in degrees (1 arc second, about 21 m east-west by 31 m "
      "north-south there) and heights in metres; the loader does not convert, so on them "
      "horizontal lengths are in degrees and the objective is dominated by the heights: their "
      "rows compare planners with each other, not with any physical length.**\n\n"
      "- **Query.** The long query of each DEM: on the middle row (or the nearest row with data), "
      "from the westernmost to the easternmost cell centre with defined ground, ",
      kStartAboveClearance, " above ground + clearance; clearance ", kClearance,
      " (height units).\n"
      "- **Objective.** The terrain planners' own (core/operators/terrain_path_cost.h): each "
      "segment costs its length plus the height of its end per cell of x-advance, which is the "
      "BAS paper's eq. 3 on one-waypoint-per-column paths. `best` and the ratios use it on the "
      "raw paths.\n"
      "- **Lattice optimum.** `terrain-lattice` at its defaults: cell centres x levels from the "
      "lowest ground + clearance to the ceiling, one cell size apart but at most 64 levels, "
      "26-neighbourhood, A*; exact on the lattice and an upper bound on the optimum over all "
      "paths. Time per query: the median of ",
      lattice_runs,
      " plans through RunPlan (wall time, search and metrics), on a shared, loaded "
      "2-core machine.\n"
      "- **Terrain planners.** Default parameters, ",
      runs, " runs each (seeds ", options.seed,
      ", ...). A ratio below 1 is possible: the "
      "planners' paths are continuous and the lattice optimum is only an upper bound on the "
      "continuous optimum. `refused`: the planner rejected the request (e.g. the ACO's pheromone "
      "table, one level per cell size of height, is too large for cells in degrees).\n"
      "- **Reading.** The objective charges every column the height flown, counted from zero as "
      "in the paper, so on DEMs hundreds of metres above sea level the sum of the heights "
      "dominates it: ratios near 1 on kootenai and west_bijou mean that the planners fly about "
      "as low as the lattice, not that their paths are otherwise alike.\n\n");
  absl::StrAppend(&report, lattice_table.ToString(), "\n", planner_table.ToString());
  return report;
}

}  // namespace swarmplan::bench
