#include "core/algorithms/bpso/binary_pso.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "absl/status/status.h"
#include "absl/strings/str_format.h"
#include "core/algorithms/citations.h"
#include "core/geometry/collision.h"
#include "core/geometry/obstacle_vertices.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_space.h"
#include "core/operators/waypoint_params.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "core/seeds/corridor.h"
#include "core/seeds/seed_paths.h"

namespace swarmplan {
namespace {

using SegmentBlocked = std::function<bool(const Point2&, const Point2&)>;

// The centres of free cells diagonally outside the convex corners of the blocked region,
// sorted by x then y.
std::vector<Point2> GridCornerVertices(const OccupancyGrid& grid, double clearance) {
  auto usable = [&](int x, int y) { return CellUsable(grid, Cell{x, y}, clearance); };
  std::vector<Cell> cells;
  for (int y = 1; y < grid.height(); ++y) {
    for (int x = 1; x < grid.width(); ++x) {
      const Cell around[4] = {{x - 1, y - 1}, {x, y - 1}, {x - 1, y}, {x, y}};
      int blocked = -1, count = 0;
      for (int i = 0; i < 4; ++i) {
        if (!usable(around[i].x, around[i].y)) {
          blocked = i;
          ++count;
        }
      }
      if (count == 1) cells.push_back(around[3 - blocked]);
    }
  }
  std::sort(cells.begin(), cells.end(),
            [](Cell a, Cell b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<Point2> out;
  for (const Cell& c : cells) out.push_back(grid.CellCenter(c));
  return out;
}

double Sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// The paper's visiting order: projection on the start-goal line.
std::vector<Point2> OrderAlongStartGoal(const Problem& problem,
                                        const std::vector<Point2>& vertices) {
  const Point2 start(problem.start.x(), problem.start.y()),
      goal(problem.goal.x(), problem.goal.y());
  const Point2 axis = goal - start;
  const double len2 = std::max(axis.squaredNorm(), 1e-300);
  std::vector<std::pair<double, Point2>> keyed;
  for (const Point2& v : vertices) keyed.push_back({(v - start).dot(axis) / len2, v});
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Point2> out;
  for (const auto& [t, v] : keyed) out.push_back(v);
  return out;
}

Point2 Flat(const Point3& p) { return Point2(p.x(), p.y()); }

// The candidate vertices of a seeded search, in visiting order, and the seeds' bit patterns.
struct SeededVertices {
  std::vector<Point2> vertices;
  std::vector<std::vector<uint8_t>> patterns;
};

// The vertices within reach of the seeds' corridors: a vertex is kept when it lies within
// radius_i of some segment i of some seed, radius_i being the segment's free width (the larger
// side of its corridor sections, sampled at most `cap` apart, capped at `cap`) plus `margin`.
// Its key is the position (fraction of the seed's length) of its nearest point on the nearest
// such segment; each seed's own interior vertices are added with their own positions, so the
// best seed's pattern reproduces it exactly.
SeededVertices SelectSeededVertices(const std::vector<SeedPath>& seeds,
                                    const std::vector<Point2>& all, const CollisionChecker& checker,
                                    double clearance, double cap, double margin, double tolerance) {
  struct Segment {
    Point2 a, b;
    double s0 = 0.0;  // arc length at a
    double length = 0.0;
    double total = 1.0;  // the seed's length
    double radius = 0.0;
  };
  std::vector<Segment> segments;
  for (const SeedPath& seed : seeds) {
    const double total = std::max(PathLength(seed.path), 1e-300);
    double s = 0.0;
    for (size_t i = 0; i + 1 < seed.path.size(); ++i) {
      Segment seg;
      seg.a = Flat(seed.path[i]);
      seg.b = Flat(seed.path[i + 1]);
      seg.s0 = s;
      seg.length = (seg.b - seg.a).norm();
      seg.total = total;
      const Point2 normal = SegmentNormal(seed.path, i);
      const int samples = std::max(1, static_cast<int>(std::ceil(seg.length / cap)));
      double width = 0.0;
      for (int k = 0; k < samples; ++k) {
        const Point2 at = seg.a + (seg.b - seg.a) * ((k + 0.5) / samples);
        const CorridorSection section = SectionAt(checker, at, normal, clearance, cap, tolerance);
        width = std::max({width, section.left, section.right});
      }
      seg.radius = width + margin;
      segments.push_back(seg);
      s += seg.length;
    }
  }
  std::vector<std::pair<double, Point2>> keyed;
  std::vector<std::pair<Point2, double>> own;  // the seeds' interior vertices and their keys
  for (const SeedPath& seed : seeds) {
    const double total = std::max(PathLength(seed.path), 1e-300);
    double s = 0.0;
    for (size_t i = 1; i + 1 < seed.path.size(); ++i) {
      s += (seed.path[i] - seed.path[i - 1]).head<2>().norm();
      own.push_back({Flat(seed.path[i]), s / total});
    }
  }
  auto is_own = [&](const Point2& v) {
    for (const auto& [p, key] : own) {
      if (p == v) return true;
    }
    return false;
  };
  for (const Point2& v : all) {
    double best = std::numeric_limits<double>::infinity(), key = 0.0;
    for (const Segment& seg : segments) {
      const Point2 ab = seg.b - seg.a;
      const double t =
          std::clamp((v - seg.a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      const double dist = (seg.a + ab * t - v).norm();
      if (dist <= seg.radius && dist < best) {
        best = dist;
        key = (seg.s0 + t * seg.length) / seg.total;
      }
    }
    if (best < std::numeric_limits<double>::infinity() && !is_own(v)) keyed.push_back({key, v});
  }
  // The seeds' own vertices: a vertex shared by two seeds keeps the first seed's key.
  std::vector<std::pair<Point2, double>> unique_own;
  for (const auto& entry : own) {
    bool seen = false;
    for (const auto& u : unique_own) seen = seen || u.first == entry.first;
    if (!seen) unique_own.push_back(entry);
  }
  for (const auto& [p, key] : unique_own) keyed.push_back({key, p});
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  SeededVertices out;
  for (const auto& [key, v] : keyed) out.vertices.push_back(v);
  for (const SeedPath& seed : seeds) {
    std::vector<uint8_t> bits(out.vertices.size(), 0);
    for (size_t i = 1; i + 1 < seed.path.size(); ++i) {
      const Point2 v = Flat(seed.path[i]);
      for (size_t k = 0; k < out.vertices.size(); ++k) {
        if (out.vertices[k] == v) bits[k] = 1;
      }
    }
    out.patterns.push_back(std::move(bits));
  }
  return out;
}

class BinaryPsoSearch {
 public:
  // `vertices` in visiting order; `patterns` (init=seeded) the seeds' bit patterns, best first.
  BinaryPsoSearch(const BinaryPsoParams& p, const Problem& problem, std::vector<Point2> vertices,
                  std::vector<std::vector<uint8_t>> patterns, SegmentBlocked blocked,
                  double penalty, AssistantTrace* trace)
      : p_(p),
        trace_(trace),
        problem_(problem),
        blocked_(std::move(blocked)),
        penalty_(penalty),
        rng_(problem.seed),
        start_(problem.start.x(), problem.start.y()),
        goal_(problem.goal.x(), problem.goal.y()),
        vertices_(std::move(vertices)),
        patterns_(std::move(patterns)) {}

  SearchResult Run(const StopToken& stop, Observer& observer) {
    SearchResult result;
    const size_t d = vertices_.size();
    int n = std::max(1, static_cast<int>(std::ceil(p_.swarm_factor * d)));
    // init=seeded: the corridors of a long path hold thousands of vertices; the swarm stays
    // bounded (ours).
    if (!patterns_.empty())
      n = std::min(n, std::max(p_.max_swarm, static_cast<int>(patterns_.size())));
    std::vector<std::vector<uint8_t>> bits(n, std::vector<uint8_t>(d));
    std::vector<std::vector<double>> aux(n, std::vector<double>(d)), vel = aux;
    // init=seeded: the seeds' patterns, then each in turn with about two bits flipped (ours).
    const double flip = d == 0 ? 0.0 : std::min(0.5, 2.0 / static_cast<double>(d));
    for (int i = 0; i < n; ++i) {
      for (size_t k = 0; k < d; ++k) {
        if (patterns_.empty()) {
          bits[i][k] = rng_.Bernoulli(0.5) ? 1 : 0;
        } else {
          const size_t base = static_cast<size_t>(i) % patterns_.size();
          const bool flipped = static_cast<size_t>(i) >= patterns_.size() && rng_.Bernoulli(flip);
          bits[i][k] = patterns_[base][k] ^ (flipped ? 1 : 0);
        }
        // Agrees with the bit (ours); seeded: firmly, so the first update keeps most bits.
        const double magnitude = patterns_.empty() ? 1.0 : p_.v_max;
        aux[i][k] = (bits[i][k] ? 1.0 : -1.0) * magnitude * rng_.Uniform();
        vel[i][k] = rng_.Uniform(-1.0, 1.0);
      }
    }
    std::vector<double> fit(n);
    for (int i = 0; i < n; ++i) fit[i] = Fitness(bits[i]);
    std::vector<std::vector<uint8_t>> pbest_bits = bits;
    std::vector<std::vector<double>> pbest_aux = aux;
    std::vector<double> pbest_fit = fit;
    int g = static_cast<int>(std::min_element(fit.begin(), fit.end()) - fit.begin());
    std::vector<uint8_t> gbest_bits = bits[g];
    std::vector<double> gbest_aux = aux[g];
    double gbest_fit = fit[g];

    if (trace_ != nullptr) *trace_ = AssistantTrace{};
    ConvergenceLog log(observer);
    int iteration = 0;
    for (; iteration < p_.iterations; ++iteration) {
      if (StopReason why = stop.Check(iteration); why != StopReason::kNone) {
        result.stop_reason = why;
        break;
      }
      const double w = p_.w_max - iteration * (p_.w_max - p_.w_min) / p_.iterations;
      double sum = 0.0;
      for (int i = 0; i < n; ++i) {
        for (size_t k = 0; k < d; ++k) {
          // Plain BPSO uses the bits themselves as positions (eq 1).
          const double x = p_.double_structure ? aux[i][k] : bits[i][k];
          const double pb = p_.double_structure ? pbest_aux[i][k] : pbest_bits[i][k];
          const double gb = p_.double_structure ? gbest_aux[k] : gbest_bits[k];
          double v =
              w * vel[i][k] + p_.c1 * rng_.Uniform() * (pb - x) + p_.c2 * rng_.Uniform() * (gb - x);
          v = std::clamp(v, -p_.v_max, p_.v_max);
          vel[i][k] = v;
          double s;
          if (p_.double_structure) {
            aux[i][k] += v;
            if (p_.assistant_bound > 0) {
              aux[i][k] = std::clamp(aux[i][k], -p_.assistant_bound, p_.assistant_bound);
            }
            s = Sigmoid(aux[i][k]);
          } else {
            s = Sigmoid(v);
          }
          bits[i][k] = s > rng_.Uniform() ? 1 : 0;
          if (p_.mutation_probability > 0 && rng_.Bernoulli(p_.mutation_probability)) {
            bits[i][k] ^= 1;
            aux[i][k] = -aux[i][k];  // the assistant position follows the flipped bit (ours)
          }
        }
        fit[i] = Fitness(bits[i]);
        sum += fit[i];
        if (fit[i] < pbest_fit[i]) {
          pbest_fit[i] = fit[i];
          pbest_bits[i] = bits[i];
          pbest_aux[i] = aux[i];
        }
        if (fit[i] < gbest_fit - 1e-12) {
          gbest_fit = fit[i];
          gbest_bits = bits[i];
          gbest_aux = aux[i];
          result.best_iteration = iteration;
        }
      }
      log.Record(iteration, gbest_fit, sum / n, evaluations_, gbest_fit < penalty_);
      if (trace_ != nullptr) Trace(aux);
    }
    result.iterations = iteration;
    result.evaluations = evaluations_;
    result.convergence = log.Take();
    result.fitness = gbest_fit;
    for (const Point2& p : PathOf(gbest_bits)) result.path.emplace_back(p.x(), p.y(), 0.0);
    result.found = MakeCollisionChecker(*problem_.map)->PathFree(result.path, problem_.clearance);
    if (!result.found) result.path.clear();  // the best vertex subset still collides
    return result;
  }

 private:
  std::vector<Point2> PathOf(const std::vector<uint8_t>& bits) const {
    std::vector<Point2> path{start_};
    for (size_t k = 0; k < bits.size(); ++k) {
      if (bits[k]) path.push_back(vertices_[k]);
    }
    path.push_back(goal_);
    return path;
  }

  void Trace(const std::vector<std::vector<double>>& aux) const {
    int64_t count = 0, saturated = 0;
    double magnitude = 0.0;
    for (const std::vector<double>& particle : aux) {
      for (double x : particle) {
        ++count;
        magnitude += std::abs(x);
        if (std::abs(x) >= kSaturatedAssistant) ++saturated;
      }
    }
    const double per = count > 0 ? 1.0 / static_cast<double>(count) : 0.0;
    trace_->saturated_fraction.push_back(static_cast<double>(saturated) * per);
    trace_->mean_magnitude.push_back(magnitude * per);
  }

  double Fitness(const std::vector<uint8_t>& bits) {
    ++evaluations_;
    const std::vector<Point2> path = PathOf(bits);
    double length = 0.0;
    bool crosses = false;
    for (size_t i = 1; i < path.size(); ++i) {
      length += (path[i] - path[i - 1]).norm();
      if (!crosses && blocked_(path[i - 1], path[i])) crosses = true;
    }
    return length + (crosses ? penalty_ : 0.0);
  }

  const BinaryPsoParams& p_;
  AssistantTrace* trace_;
  const Problem& problem_;
  SegmentBlocked blocked_;
  double penalty_;
  Rng rng_;
  Point2 start_, goal_;
  std::vector<Point2> vertices_;
  std::vector<std::vector<uint8_t>> patterns_;
  int64_t evaluations_ = 0;
};

}  // namespace

std::vector<ParamSpec> BinaryPsoParams::Specs() {
  const BinaryPsoParams d;
  std::vector<ParamSpec> specs = {
      ParamSpec::Bool("double_structure", d.double_structure,
                      "continuous assistant positions drive the bits (eqs 6-7); false: plain "
                      "BPSO (eqs 1-2)"),
      ParamSpec::Double("mutation_probability", d.mutation_probability, 0.0, 1.0, "",
                        "per-bit flip probability after each update (0: no mutation)"),
      ParamSpec::Double("swarm_factor", d.swarm_factor, 0.01, 100.0, "",
                        "swarm size as a multiple of the number of vertices"),
      ParamSpec::Int("iterations", d.iterations, 1, 1000000, "iterations", "iter_max"),
      ParamSpec::Double("c1", d.c1, 0.0, 10.0, "", "cognitive coefficient"),
      ParamSpec::Double("c2", d.c2, 0.0, 10.0, "", "social coefficient"),
      ParamSpec::Double("w_max", d.w_max, 0.0, 2.0, "", "inertia at the first iteration"),
      ParamSpec::Double("w_min", d.w_min, 0.0, 2.0, "", "inertia at the last iteration"),
      ParamSpec::Double("v_max", d.v_max, 0.01, 100.0, "", "velocity clamp").Ours(),
      ParamSpec::Double("assistant_bound", d.assistant_bound, 0.0, 1000.0, "",
                        "double structure: each assistant position is kept within "
                        "[-bound, bound] after its update; 0: unbounded (the paper states none)")
          .Ours(),
      ParamSpec::Double("penalty_factor", d.penalty_factor, 0.0, 1e9, "",
                        "penalty N for a path through an obstacle, times the map's diagonal")
          .Ours(),
      ParamSpec::Double("circle_tolerance", d.circle_tolerance, 1e-6, 0.1, "",
                        "circles become polygons within this fraction of the world's larger side")
          .Ours(),
      ParamSpec::Int("max_vertices", d.max_vertices, 1, 1000000, "vertices",
                     "init=paper: refuse maps with more obstacle vertices (swarm and particle "
                     "both grow with the count)")
          .Ours(),
      ParamSpec::Int("max_swarm", d.max_swarm, 1, 1000000, "particles",
                     "init=seeded: the most particles (swarm_factor x the vertices otherwise)")
          .Ours(),
      ParamSpec::Double("corridor_cap", d.corridor_cap, 1e-4, 1.0, "",
                        "init=seeded: the free width across a seed counted at most, times the "
                        "map's diagonal")
          .Ours(),
      ParamSpec::Double("corridor_margin", d.corridor_margin, 0.0, 1.0, "",
                        "init=seeded: vertices this far beyond a seed's free width count too, "
                        "times the map's diagonal")
          .Ours(),
  };
  AppendParams(specs,
               SeedingParams("the bits choose among the obstacle vertices near the corridors of "
                             "exact seed paths (no vertex cap), visited in their order along the "
                             "nearest seed; the swarm starts from the seeds' patterns and never "
                             "returns a path longer than the best seed",
                             "the paper's: one bit per obstacle vertex of the map, visited along "
                             "the start-goal line, random initial bits, at most max_vertices"));
  return specs;
}

BinaryPsoParams BinaryPsoParams::From(const ParamSet& set) {
  BinaryPsoParams p;
  p.double_structure = set.Bool("double_structure");
  p.mutation_probability = set.Double("mutation_probability");
  p.swarm_factor = set.Double("swarm_factor");
  p.iterations = static_cast<int>(set.Int("iterations"));
  p.c1 = set.Double("c1");
  p.c2 = set.Double("c2");
  p.w_max = set.Double("w_max");
  p.w_min = set.Double("w_min");
  p.v_max = set.Double("v_max");
  p.penalty_factor = set.Double("penalty_factor");
  p.circle_tolerance = set.Double("circle_tolerance");
  p.assistant_bound = set.Double("assistant_bound");
  p.max_vertices = static_cast<int>(set.Int("max_vertices"));
  p.max_swarm = static_cast<int>(set.Int("max_swarm"));
  p.corridor_cap = set.Double("corridor_cap");
  p.corridor_margin = set.Double("corridor_margin");
  const WaypointSeeding seeding = WaypointSeedingFrom(set);
  p.seeded = seeding.seeded;
  p.seeds = seeding.seeds;
  return p;
}

absl::StatusOr<SearchResult> BinaryPsoPlanner::Solve(const Problem& problem, const StopToken& stop,
                                                     Observer& observer) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("map: no map given");
  std::vector<Point2> vertices;
  SegmentBlocked blocked;
  double diagonal = 1.0;
  std::shared_ptr<const GrownObstacles> grown;
  std::shared_ptr<const CollisionChecker> checker;
  if (const ShapeWorld* world = problem.map->world()) {
    const double side = std::max(world->bounds().Width(), world->bounds().Height());
    grown = std::make_shared<const GrownObstacles>(
        GrowObstacles(*world, problem.clearance, params_.circle_tolerance * side));
    for (const GrownObstacles::Corner& c : grown->corners) vertices.push_back(c.point);
    blocked = [grown](const Point2& a, const Point2& b) { return grown->Blocks(a, b); };
    diagonal = std::hypot(world->bounds().Width(), world->bounds().Height());
  } else if (const OccupancyGrid* grid = problem.map->grid()) {
    vertices = GridCornerVertices(*grid, problem.clearance);
    checker = MakeCollisionChecker(*problem.map);
    const double clearance = problem.clearance;
    blocked = [checker, clearance](const Point2& a, const Point2& b) {
      return !checker->SegmentFree(Point3(a.x(), a.y(), 0), Point3(b.x(), b.y(), 0), clearance);
    };
    diagonal = std::hypot(grid->width(), grid->height()) * grid->resolution();
  } else {
    return absl::InvalidArgumentError("bpso plans on shape worlds and occupancy grids");
  }
  const double penalty = params_.penalty_factor * diagonal;
  if (!params_.seeded) {
    if (static_cast<int64_t>(vertices.size()) > params_.max_vertices) {
      return absl::FailedPreconditionError(absl::StrFormat(
          "bpso: the map has %d obstacle vertices, more than max_vertices = %d; the swarm "
          "(1.5x the vertices) would be too slow. Raise max_vertices, use init=seeded or "
          "another planner",
          static_cast<int>(vertices.size()), params_.max_vertices));
    }
    BinaryPsoSearch search(params_, problem, OrderAlongStartGoal(problem, vertices), {},
                           std::move(blocked), penalty, trace_);
    return search.Run(stop, observer);
  }

  // init=seeded: the vertices near the seeds' corridors; segments checked exactly as the result.
  absl::StatusOr<std::vector<SeedPath>> seeds =
      FindSeedPaths(problem, std::max(1, params_.seeds), stop);
  if (!seeds.ok()) return seeds.status();
  if (seeds->empty()) return absl::NotFoundError("bpso: no path from start to goal exists");
  std::shared_ptr<const CollisionChecker> exact = MakeCollisionChecker(*problem.map);
  const double clearance = problem.clearance;
  SeededVertices selected =
      SelectSeededVertices(*seeds, vertices, *exact, clearance, params_.corridor_cap * diagonal,
                           params_.corridor_margin * diagonal, 1e-4 * diagonal);
  if (static_cast<int64_t>(selected.vertices.size()) > kMaxSeededBpsoVertices) {
    return absl::FailedPreconditionError(absl::StrFormat(
        "bpso: %d obstacle vertices lie near the seed corridors, more than %d; lower "
        "corridor_cap or use another planner",
        static_cast<int>(selected.vertices.size()), static_cast<int>(kMaxSeededBpsoVertices)));
  }
  SegmentBlocked exact_blocked = [exact, clearance](const Point2& a, const Point2& b) {
    return !exact->SegmentFree(Point3(a.x(), a.y(), 0), Point3(b.x(), b.y(), 0), clearance);
  };
  BinaryPsoSearch search(params_, problem, std::move(selected.vertices),
                         std::move(selected.patterns), std::move(exact_blocked), penalty, trace_);
  SearchResult result = search.Run(stop, observer);
  const SeedPath& best = seeds->front();
  if (!result.found || result.fitness > best.length) {
    result.path = best.path;  // the best seed is the incumbent: never a longer path
    result.fitness = best.length;
    result.found = true;
  }
  result.seed_path = best.path;
  return result;
}

PlannerInfo BinaryPsoInfo() {
  PlannerInfo info;
  info.id = "bpso";
  info.description =
      "Improved binary PSO on obstacle vertices: one bit per vertex of the obstacles grown by "
      "the clearance (numbered by x, then y); the path visits the chosen vertices ordered by "
      "their projection on the start-goal line (ours; the paper's x order when the goal lies to "
      "the right). Fitness: length plus a penalty N when a segment enters an obstacle. Double "
      "structure (continuous assistant positions, eqs 6-7) with per-bit mutation 0.1; "
      "plain BPSO with double_structure=false, mutation_probability=0. Swarm 1.5x the vertex "
      "count, c1 = c2 = 2, w 0.9 -> 0.4, 100 iterations. Ours: |v| <= 4, N = 100 x the map "
      "diagonal, a mutated bit's assistant position is negated; on grids the vertices are the "
      "free cells diagonally outside convex corners of blocked regions. init=seeded (the default; "
      "ours): the bits choose among the vertices near the corridors of exact seed paths, visited "
      "in their order along the nearest seed, the swarm (at most max_swarm) starts from the seeds' "
      "patterns and the "
      "best seed is the incumbent; init=paper: the paper's initialisation over every vertex.";
  info.seed_paper = citations::kImprovedBinaryPso;
  info.encoding = Encoding::kVertexSubset;
  info.map_kinds = {MapKind::kShapeWorld, MapKind::kOccupancyGrid};
  info.params = BinaryPsoParams::Specs();
  info.factory = [](const ParamSet& set) {
    return std::make_unique<BinaryPsoPlanner>(BinaryPsoParams::From(set));
  };
  return info;
}

}  // namespace swarmplan
