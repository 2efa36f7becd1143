#include "core/operators/seeded_waypoint_objective.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "absl/strings/str_cat.h"
#include "core/fitness/rounded_corner_path.h"
#include "core/geometry/collision.h"
#include "core/path_metrics.h"
#include "core/random.h"
#include "core/smoothing/bounded_curvature.h"

namespace swarmplan {
namespace {

// Path points the engine reads per evaluation at most, and the spacing it aims for between
// them in cells of the map's distance field.
constexpr int kMaxPoints = 4096;
constexpr double kPointSpacingCells = 0.5;

// A control point of a seed: its arc length position and the vertex it is, if any.
struct Station {
  double s = 0.0;
  int vertex = -1;  // index into the seed's path, or -1 on a segment
};

// The stations of one seed, `k` of them: interior vertices, then the midpoints of the longest
// gaps between stations; evenly chosen vertices when there are more than k. `reserved[v]` (empty:
// none) is how far along the path on each side of vertex v no midpoint should go: the extent of
// its rounded corner, which a control point inside would cut short. A gap's free part is what
// the stations at its ends leave of it; the longest free part gets the midpoint, or, without
// reservations and none left anywhere, the longest gap; with reservations there are then fewer
// than k stations.
std::vector<Station> Stations(const Path& path, int k, const std::vector<double>& reserved) {
  std::vector<double> at(path.size(), 0.0);
  for (size_t i = 1; i < path.size(); ++i)
    at[i] = at[i - 1] + (path[i] - path[i - 1]).head<2>().norm();
  const double total = at.back();
  const int interior = static_cast<int>(path.size()) - 2;
  std::vector<Station> stations;
  if (interior > k) {
    for (int i = 0; i < k; ++i) {
      const int v = k == 1 ? 1 + interior / 2
                           : 1 + static_cast<int>(std::llround((interior - 1.0) * i / (k - 1)));
      stations.push_back({at[v], v});
    }
  } else {
    for (int v = 1; v <= interior; ++v) stations.push_back({at[v], v});
  }
  auto reach = [&](const Station& station) {
    return station.vertex > 0 && !reserved.empty() ? reserved[station.vertex] : 0.0;
  };
  while (static_cast<int>(stations.size()) < k) {
    double best_free = -std::numeric_limits<double>::infinity(), best_mid = 0.0;
    double best_gap = -1.0, gap_mid = 0.0;
    for (size_t i = 0; i <= stations.size(); ++i) {
      const double from = i > 0 ? stations[i - 1].s : 0.0;
      const double to = i < stations.size() ? stations[i].s : total;
      const double free_from = from + (i > 0 ? reach(stations[i - 1]) : 0.0);
      const double free_to = to - (i < stations.size() ? reach(stations[i]) : 0.0);
      if (free_to - free_from > best_free) {
        best_free = free_to - free_from;
        best_mid = 0.5 * (free_from + free_to);
      }
      if (to - from > best_gap) {
        best_gap = to - from;
        gap_mid = 0.5 * (from + to);
      }
    }
    if (best_free <= 0 && !reserved.empty()) break;
    stations.push_back({best_free > 0 ? best_mid : gap_mid, -1});
    std::sort(stations.begin(), stations.end(),
              [](const Station& a, const Station& b) { return a.s < b.s; });
  }
  return stations;
}

// Where the line p + t n first meets the polyline, |t| smallest within [-below, above]; none
// when it does not meet it there.
std::optional<double> CrossingAlong(const Point2& p, const Point2& n, double below, double above,
                                    const Path& polyline) {
  std::optional<double> best;
  for (size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point2 a = polyline[i].head<2>(), b = polyline[i + 1].head<2>();
    const Point2 d = b - a;
    const double denominator = n.x() * d.y() - n.y() * d.x();
    if (std::abs(denominator) < 1e-12 * d.norm()) continue;
    const Point2 ap = a - p;
    const double t = (ap.x() * d.y() - ap.y() * d.x()) / denominator;
    const double u = (ap.x() * n.y() - ap.y() * n.x()) / denominator;
    if (u < 0.0 || u > 1.0 || t < -below || t > above) continue;
    if (!best || std::abs(t) < std::abs(*best)) best = t;
  }
  return best;
}

// How far along the path each vertex's corner reaches when RoundedCornerPath rounds it.
std::vector<double> CornerExtents(const Path& polygon, double radius) {
  const int n = static_cast<int>(polygon.size());
  std::vector<double> x(n), y(n), segment(n), extent(n);
  for (int i = 0; i < n; ++i) {
    x[i] = polygon[i].x();
    y[i] = polygon[i].y();
  }
  RoundedCornerPath(n, radius, 1.0, 2)
      .CornerDistances(x.data(), y.data(), segment.data(), extent.data());
  return extent;
}

double FieldCell(const Map& map) {
  if (const OccupancyGrid* grid = map.grid()) return grid->resolution();
  return map.world()->distance_field().cell_size();
}

}  // namespace

absl::StatusOr<std::unique_ptr<SeededWaypointObjective>> SeededWaypointObjective::Create(
    const Problem& problem, WaypointFitnessOptions options, const std::vector<SeedPath>& seeds,
    int max_control_points) {
  if (problem.map == nullptr || problem.map->is_3d()) {
    return absl::InvalidArgumentError("seeded waypoint objective: needs a 2D map");
  }
  if (seeds.empty()) return absl::InvalidArgumentError("seeded waypoint objective: no seed path");
  if (max_control_points < 1) {
    return absl::InvalidArgumentError("seeded waypoint objective: max_control_points must be >= 1");
  }
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(*problem.map);
  const double cell = FieldCell(*problem.map);
  // The search spaces ("entries"), one or two per seed. With a turning radius, where the
  // bounded-curvature smoothing of a seed is clear, the control points sit on the lines whose
  // corners it rounded, and the entry's engine rounds their corners in the same way
  // (RoundedCornerPath): with every offset 0 the path is the smoothed seed, and each path the
  // swarm finds that turns no tighter than the radius is one the smoothing keeps as it is.
  // Elsewhere the control points sit on the seed and a spline joins them; a seed whose smoothing
  // has corners without room for the radius gets both entries, the rounded one for polygons
  // whose corners find room, the spline for curves that leave the seed's corners.
  const double radius = options.fleet ? options.fleet->turning_radius : 0.0;
  std::vector<int> entry_seed;
  std::vector<Path> bases;
  std::vector<bool> rounded;
  std::vector<std::optional<Path>> smoothed;  // the seed after the smoothing, if it is clear
  for (size_t j = 0; j < seeds.size(); ++j) {
    auto add = [&](Path base, bool is_rounded, std::optional<Path> smoothed_seed) {
      entry_seed.push_back(static_cast<int>(j));
      bases.push_back(std::move(base));
      rounded.push_back(is_rounded);
      smoothed.push_back(std::move(smoothed_seed));
    };
    if (radius <= 0) {
      add(seeds[j].path, false, std::nullopt);
      continue;
    }
    BoundedCurvatureOptions smoothing;
    smoothing.turning_radius = radius;
    smoothing.clearance = problem.clearance;
    BoundedCurvatureResult result = SmoothToTurningRadius(seeds[j].path, smoothing, *checker);
    if (!result.collision_free) {
      add(seeds[j].path, false, std::nullopt);
      continue;
    }
    if (result.corners_over > 0 || result.corner_polygon.size() < 2) {
      add(seeds[j].path, false, result.path);
    }
    if (result.corner_polygon.size() >= 2) add(result.corner_polygon, true, std::nullopt);
  }
  // One control point per interior vertex and per segment, the same count for every seed.
  int k = 1;
  for (const Path& base : bases) k = std::max(k, 2 * static_cast<int>(base.size()) - 3);
  k = std::min(k, max_control_points);
  std::vector<std::vector<ControlPoint>> corridors;
  // Per seed, the spline's parameter at each knot, from the arc length between its stations.
  std::vector<std::vector<double>> parameters;
  for (size_t j = 0; j < bases.size(); ++j) {
    const Path& base = bases[j];
    const double base_length = PathLength(base);
    // A rounded seed has as many control points as its own vertices and segments (a control
    // point inside a curve would cut it short); the others share the largest count.
    const int own = std::min(k, std::max(1, 2 * static_cast<int>(base.size()) - 3));
    const std::vector<Station> stations =
        rounded[j] ? Stations(base, own, CornerExtents(base, radius)) : Stations(base, k, {});
    std::vector<ControlPoint> points;
    // The spline's parameter is centripetal: each step the square root of the arc length
    // between the stations (at least a millionth of a cell's).
    auto centripetal_step = [least = 1e-6 * cell](double arc) {
      return std::sqrt(std::max(arc, least));
    };
    std::vector<double> t = {0.0};
    for (size_t i = 0; i < stations.size(); ++i) {
      const double before = stations[i].s - (i > 0 ? stations[i - 1].s : 0.0);
      const double after =
          (i + 1 < stations.size() ? stations[i + 1].s : base_length) - stations[i].s;
      const PathPosition at = PositionAt(base, stations[i].s);
      const Point2 normal = stations[i].vertex > 0 ? VertexNormal(base, stations[i].vertex)
                                                   : SegmentNormal(base, at.segment);
      const double reach = std::max(before + after, 4.0 * cell);
      ControlPoint c;
      c.section = SectionAt(*checker, at.point, normal, problem.clearance, reach, 0.05 * cell);
      c.tangent = Point2(normal.y(), -normal.x());
      c.along = 0.5 * std::min(before, after);
      points.push_back(c);
      t.push_back(t.back() + centripetal_step(stations[i].s - (i > 0 ? stations[i - 1].s : 0.0)));
    }
    t.push_back(t.back() + centripetal_step(base_length - stations.back().s));
    corridors.push_back(std::move(points));
    parameters.push_back(std::move(t));
  }

  if (options.interpolation == Interpolation::kLinear)
    options.interpolation = Interpolation::kPolyline;
  // Per seed an engine whose spline follows the seed's arc length, with points enough to read
  // the field every half cell along a path half again as long as the seed.
  std::vector<FitnessEngine> engines;
  std::vector<WaypointFitnessOptions> seed_options;
  for (size_t j = 0; j < bases.size(); ++j) {
    WaypointFitnessOptions o = options;
    o.waypoints = static_cast<int>(corridors[j].size());
    const int wanted = static_cast<int>(std::min<double>(
        kMaxPoints, std::ceil(1.5 * seeds[entry_seed[j]].length / (kPointSpacingCells * cell))));
    o.samples = std::max(options.samples, wanted);
    o.knot_parameters = parameters[j];
    if (rounded[j]) o.rounded_corner_radius = radius;
    o.curvature_as_violation = radius > 0;
    absl::StatusOr<FitnessEngine> engine = FitnessEngine::Create(problem, o);
    if (!engine.ok()) return engine.status();
    engines.push_back(*std::move(engine));
    seed_options.push_back(std::move(o));
  }

  std::unique_ptr<SeededWaypointObjective> objective(
      new SeededWaypointObjective(k, std::move(corridors), std::move(engines)));
  objective->entry_seed_ = entry_seed;
  objective->seed_count_ = static_cast<int>(seeds.size());
  objective->away_ = std::max(cell, options.fleet ? options.fleet->preferred_clearance : 0.0);
  for (size_t j = 0; j < bases.size(); ++j) {
    if (smoothed[j] && !rounded[j]) objective->FitSmoothedSeed(static_cast<int>(j), *smoothed[j]);
  }

  // The best seed by the same fitness, read as the polyline it is, or where the engine rounds its
  // corners, as the smoothed seed it is then.
  objective->guesses_ = objective->BuildGuesses();
  const std::vector<Eigen::VectorXd>& guesses = objective->guesses_;
  Eigen::VectorXd waypoints(2 * k);
  for (size_t j = 0; j < bases.size(); ++j) {
    objective->Waypoints(guesses[j].data(), waypoints.data());
    Evaluation e;
    if (rounded[j]) {
      e = objective->engines_[j].Evaluate(waypoints);
    } else {
      WaypointFitnessOptions polyline = seed_options[j];
      polyline.interpolation = Interpolation::kPolyline;
      absl::StatusOr<FitnessEngine> polyline_engine = FitnessEngine::Create(problem, polyline);
      if (!polyline_engine.ok()) return polyline_engine.status();
      e = polyline_engine->Evaluate(waypoints);
    }
    objective->seed_paths_.push_back(KnownPath{seeds[entry_seed[j]].path, e.fitness});
    if (e.fitness < objective->seed_paths_[objective->best_seed_].fitness) {
      objective->best_seed_ = static_cast<int>(j);
    }
  }
  return objective;
}

SeededWaypointObjective::SeededWaypointObjective(int k,
                                                 std::vector<std::vector<ControlPoint>> corridors,
                                                 std::vector<FitnessEngine> engines)
    : k_(k), corridors_(std::move(corridors)), engines_(std::move(engines)) {
  lower_ = Eigen::VectorXd::Constant(1 + 2 * k_, -1.0);
  upper_ = Eigen::VectorXd::Constant(1 + 2 * k_, 1.0);
  single_.resize(2 * k_);
  lower_[0] = 0.0;
  upper_[0] = static_cast<double>(corridors_.size());
}

int SeededWaypointObjective::SeedIndex(double selector) const {
  const int last = static_cast<int>(corridors_.size()) - 1;
  return std::clamp(static_cast<int>(std::floor(selector)), 0, last);
}

int SeededWaypointObjective::CorridorOf(const Eigen::VectorXd& x) const {
  return entry_seed_[SeedIndex(x[0])];
}

std::optional<PathObjective::KnownPath> SeededWaypointObjective::KnownPathIn(int corridor) {
  std::optional<KnownPath> best;
  for (size_t j = 0; j < seed_paths_.size(); ++j) {
    if (entry_seed_[j] == corridor && (!best || seed_paths_[j].fitness < best->fitness)) {
      best = seed_paths_[j];
    }
  }
  return best;
}

void SeededWaypointObjective::Waypoints(const double* x, double* waypoints) const {
  const std::vector<ControlPoint>& points = corridors_[SeedIndex(x[0])];
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    const ControlPoint& c = points[i];
    const double u = x[1 + i], v = x[1 + k_ + i];
    const double across = v >= 0 ? v * c.section.left : v * c.section.right;
    const Point2 p = c.section.point + u * c.along * c.tangent + across * c.section.normal;
    waypoints[i] = p.x();
    waypoints[n + i] = p.y();
  }
}

Evaluation SeededWaypointObjective::Evaluate(const Eigen::VectorXd& x) {
  Waypoints(x.data(), single_.data());
  return engines_[SeedIndex(x[0])].Evaluate(single_);
}

void SeededWaypointObjective::EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out) {
  for (int j = 0; j < xs.cols(); ++j) {
    Waypoints(xs.col(j).data(), single_.data());
    out[j] = engines_[SeedIndex(xs(0, j))].Evaluate(single_.data());
  }
}

Path SeededWaypointObjective::Decode(const Eigen::VectorXd& x) {
  Eigen::VectorXd waypoints(2 * k_);
  Waypoints(x.data(), waypoints.data());
  Path path;
  engines_[SeedIndex(x[0])].Decode(waypoints, path);
  return path;
}

void SeededWaypointObjective::FitSmoothedSeed(int j, const Path& smoothed) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(1 + 2 * k_);
  x[0] = static_cast<double>(j) + 0.5;
  for (size_t i = 0; i < corridors_[j].size(); ++i) {
    const CorridorSection& s = corridors_[j][i].section;
    const std::optional<double> t = CrossingAlong(s.point, s.normal, s.right, s.left, smoothed);
    if (!t) return;
    if (*t > 0) x[1 + k_ + i] = *t / s.left;
    if (*t < 0) x[1 + k_ + i] = *t / s.right;
  }
  smoothed_guesses_.push_back(std::move(x));
}

std::vector<Eigen::VectorXd> SeededWaypointObjective::BuildGuesses() const {
  std::vector<Eigen::VectorXd> guesses;
  for (size_t j = 0; j < corridors_.size(); ++j) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(1 + 2 * k_);
    x[0] = static_cast<double>(j) + 0.5;
    guesses.push_back(std::move(x));
  }
  // Each seed again with every control point moved toward the middle of its section, by at most
  // `away_` and by fractions of it: off the walls the seed grazes, where a spline through it has
  // room to turn.
  for (const double away : {away_, away_ / 4, away_ / 16}) {
    for (size_t j = 0; j < corridors_.size(); ++j) {
      Eigen::VectorXd x = Eigen::VectorXd::Zero(1 + 2 * k_);
      x[0] = static_cast<double>(j) + 0.5;
      for (size_t i = 0; i < corridors_[j].size(); ++i) {
        const CorridorSection& s = corridors_[j][i].section;
        const double move = std::clamp(0.5 * (s.left - s.right), -away, away);
        if (move > 0 && s.left > 0) x[1 + k_ + i] = move / s.left;
        if (move < 0 && s.right > 0) x[1 + k_ + i] = move / s.right;
      }
      guesses.push_back(std::move(x));
    }
  }
  guesses.insert(guesses.end(), smoothed_guesses_.begin(), smoothed_guesses_.end());
  return guesses;
}

bool SeededWaypointObjective::SampleNearGuesses(Rng& rng, Eigen::VectorXd& x) const {
  constexpr double kSmallestScaleLog2 = -8.0;
  x = guesses_[rng.UniformInt(0, static_cast<int64_t>(guesses_.size()) - 1)];
  const double scale = std::exp2(rng.Uniform(kSmallestScaleLog2, 0.0));
  for (int j = 1; j < dim(); ++j) x[j] += scale * rng.Uniform(-1.0, 1.0);
  Clamp(x);
  return true;
}

}  // namespace swarmplan
