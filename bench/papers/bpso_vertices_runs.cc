#include "bench/papers/bpso_vertices_runs.h"

#include <memory>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/time.h"
#include "bench/papers/bpso_vertices_encoding.h"
#include "bench/papers/bpso_vertices_worlds.h"
#include "core/map/io/map_io.h"

namespace swarmplan::bench::bpso {
namespace {

constexpr double kGaResolution = 4.0;  // start and goal are centres of 4 x 4 cells

Point3 At(const Point2& p) { return Point3(p.x(), p.y(), 0.0); }

// A found path must be collision-free, run from start to goal and be no shorter than the exact
// optimum; anything else is a bug and fails the experiment.
absl::Status CheckPath(const PlanResult& result, const World& world, const std::string& label) {
  const std::string what = absl::StrFormat("bpso-vertices: %s on %s (seed %d)", label, world.name,
                                           static_cast<int64_t>(result.seed));
  if (absl::Status s =
          CheckFoundPath(result, At(BpsoVerticesStart()), At(BpsoVerticesGoal()), what, 1e-6);
      !s.ok()) {
    return s;
  }
  if (result.found && result.raw_metrics.length < world.optimum - 1e-6) {
    return absl::InternalError(
        absl::StrFormat("%s: the path is shorter (%.9g) than the visibility-graph optimum (%.9g)",
                        what, result.raw_metrics.length, world.optimum));
  }
  return absl::OkStatus();
}

}  // namespace

std::string WorldFileName(int vertices) { return absl::StrCat("vertices-", vertices, ".json"); }

absl::StatusOr<World> MakeWorld(MapPtr map, int vertices, const std::string& name) {
  World world;
  world.vertices = vertices;
  world.name = name;
  world.map = std::move(map);
  PlanSpec exact_spec;
  exact_spec.algorithm = "visibility-graph";
  absl::StatusOr<PlanResult> exact =
      PlanOnce(exact_spec, world.map, At(BpsoVerticesStart()), At(BpsoVerticesGoal()), 1);
  if (!exact.ok()) return exact.status();
  if (!exact->found) return absl::InternalError(absl::StrCat(name, ": no visibility-graph path"));
  world.optimum = exact->raw_metrics.length;
  world.encoding_optimum =
      BestOrderedVertexPath(*world.map->world(), BpsoVerticesStart(), BpsoVerticesGoal());
  if (world.encoding_optimum && *world.encoding_optimum < world.optimum - 1e-6) {
    return absl::InternalError(absl::StrFormat(
        "%s: the best ordered vertex path (%.9g) is shorter than the visibility-graph optimum "
        "(%.9g)",
        name, *world.encoding_optimum, world.optimum));
  }
  return world;
}

absl::StatusOr<World> LoadShippedWorld(const ExperimentOptions& options, int vertices) {
  const std::string path =
      absl::StrCat(options.worlds_dir, "/bpso-vertices/", WorldFileName(vertices));
  absl::StatusOr<Map> map = LoadMapFile(path, "shapes-json");
  if (!map.ok()) return map.status();
  return MakeWorld(std::make_shared<const Map>(*std::move(map)), vertices, WorldFileName(vertices));
}

absl::StatusOr<Runs> RunMany(const PlanSpec& spec, const World& world, int count,
                             uint64_t first_seed, const std::string& label, std::ostream* log) {
  Runs runs;
  runs.count = count;
  for (int i = 0; i < count; ++i) {
    absl::StatusOr<PlanResult> result =
        PlanOnce(spec, world.map, At(BpsoVerticesStart()), At(BpsoVerticesGoal()), first_seed + i);
    if (!result.ok()) return result.status();
    runs.seconds.push_back(absl::ToDoubleSeconds(result->wall_time));
    runs.convergence.push_back(std::move(result->convergence));
    if (!result->found) continue;
    if (absl::Status status = CheckPath(*result, world, label); !status.ok()) return status;
    runs.lengths.push_back(result->raw_metrics.length);
    runs.best_iterations.push_back(result->best_iteration + 1.0);
  }
  if (log != nullptr) {
    *log << "bpso-vertices: " << label << ", " << world.name << ": " << runs.found() << "/" << count
         << " found\n";
  }
  return runs;
}

PlanSpec BpsoSpec(int iterations, double swarm_factor, double mutation, bool double_structure) {
  PlanSpec spec;
  spec.algorithm = "bpso";
  spec.params = {{"init", std::string("paper")},
                 {"iterations", static_cast<int64_t>(iterations)},
                 {"swarm_factor", swarm_factor},
                 {"mutation_probability", mutation},
                 {"double_structure", double_structure}};
  return spec;
}

PlanSpec GaSpec(int generations) {
  PlanSpec spec;
  spec.algorithm = "ga";
  spec.params = {{"init", std::string("paper")},
                 {"generations", static_cast<int64_t>(generations)},
                 {"resolution", kGaResolution}};
  return spec;
}

std::string SwarmLabel(double swarm_factor) {
  return swarm_factor == 1.0 ? "1D" : absl::StrFormat("%gD", swarm_factor);
}

}  // namespace swarmplan::bench::bpso
