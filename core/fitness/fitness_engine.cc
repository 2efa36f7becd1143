#include "core/fitness/fitness_engine.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace swarmplan {
namespace {

// Path points held per batch: bounds the point buffers whatever the sample count.
constexpr int64_t kBatchPoints = 1 << 14;
// How far (field cells) the fleet objective's shortfall below the hard clearance starts below
// it, so that a path along an obstacle's boundary costs nothing for the raster's error.
constexpr double kHardSlackCells = 2.0;
// The curvature of an exact reversal, where the discrete formula divides by zero.
constexpr double kReversalCurvature = 1e9;

DistanceField GridDistanceField(const OccupancyGrid& grid) {
  std::vector<uint8_t> blocked(static_cast<size_t>(grid.width()) * grid.height());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      blocked[static_cast<size_t>(y) * grid.width() + x] = grid.IsBlocked(x, y) ? 1 : 0;
    }
  }
  return DistanceField::FromBlockedCells(grid.width(), grid.height(), blocked, grid.resolution(),
                                         grid.origin(), /*cap_at_edge=*/false);
}

}  // namespace

absl::StatusOr<FitnessEngine> FitnessEngine::Create(const Problem& problem,
                                                    const WaypointFitnessOptions& options) {
  if (problem.map == nullptr) return absl::InvalidArgumentError("waypoint objective: no map");
  if (options.waypoints < 1) {
    return absl::InvalidArgumentError("waypoint objective: waypoints must be at least 1");
  }
  if (options.samples < 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("waypoint objective: samples must be at least 2, got ", options.samples));
  }
  if (options.fleet) {
    if (absl::Status status = ValidateFleetObjective(*options.fleet); !status.ok()) return status;
  }
  absl::StatusOr<ObstacleProximity> proximity = ObstacleProximity::Create(
      *problem.map,
      options.fleet ? problem.clearance : std::max(options.d_safe, problem.clearance));
  if (!proximity.ok()) return proximity.status();
  FitnessEngine engine(problem, options, *std::move(proximity));
  if (options.fleet) {
    if (const ShapeWorld* world = problem.map->world()) {
      engine.field_ = &world->distance_field();
    } else {
      const Map& map = *problem.map;
      engine.owned_field_ = map.Derived<DistanceField>(
          "fitness-distance-field", [&map] { return GridDistanceField(*map.grid()); });
      engine.field_ = engine.owned_field_.get();
    }
  }
  return engine;
}

FitnessEngine::FitnessEngine(const Problem& problem, const WaypointFitnessOptions& options,
                             ObstacleProximity proximity)
    : map_(problem.map),
      waypoints_(options.waypoints),
      penalty_(options.penalty),
      fleet_(options.fleet),
      hard_clearance_(problem.clearance),
      matrix_(CachedInterpolationMatrix(options.interpolation, options.waypoints, options.samples)),
      proximity_(std::move(proximity)) {
  const int k = waypoints_;
  const int n = matrix_->points();
  weights_x_ = matrix_->x.middleCols(1, k);
  weights_y_ = matrix_->y.middleCols(1, k);
  offset_x_ = matrix_->x.col(0) * problem.start.x() + matrix_->x.col(k + 1) * problem.goal.x();
  offset_y_ = matrix_->y.col(0) * problem.start.y() + matrix_->y.col(k + 1) * problem.goal.y();
  const int batch = static_cast<int>(std::clamp<int64_t>(kBatchPoints / n, 1, 64));
  points_x_.resize(n, batch);
  points_y_.resize(n, batch);
  segment_.resize(n);
  clearance_.resize(n);
}

void FitnessEngine::Interpolate(const Eigen::Ref<const Eigen::MatrixXd>& xs, int first, int count) {
  const int k = waypoints_;
  auto px = points_x_.leftCols(count);
  auto py = points_y_.leftCols(count);
  px.noalias() = weights_x_ * xs.block(0, first, k, count);
  py.noalias() = weights_y_ * xs.block(k, first, k, count);
  px.colwise() += offset_x_;
  py.colwise() += offset_y_;
}

void FitnessEngine::Evaluate(const Eigen::Ref<const Eigen::MatrixXd>& xs, Evaluation* out) {
  const int total = static_cast<int>(xs.cols());
  const int batch = static_cast<int>(points_x_.cols());
  for (int first = 0; first < total; first += batch) {
    const int count = std::min(batch, total - first);
    Interpolate(xs, first, count);
    for (int j = 0; j < count; ++j) out[first + j] = EvaluatePath(j, nullptr);
  }
}

Evaluation FitnessEngine::Evaluate(const Eigen::VectorXd& x) {
  Interpolate(x, 0, 1);
  return EvaluatePath(0, nullptr);
}

FleetTerms FitnessEngine::Terms(const Eigen::VectorXd& x) {
  FleetTerms terms;
  Interpolate(x, 0, 1);
  EvaluatePath(0, &terms);
  return terms;
}

void FitnessEngine::Decode(const Eigen::VectorXd& x, Path& path) const {
  const int k = waypoints_;
  const Eigen::VectorXd px = weights_x_ * x.head(k) + offset_x_;
  const Eigen::VectorXd py = weights_y_ * x.tail(k) + offset_y_;
  path.resize(px.size());
  for (int i = 0; i < px.size(); ++i) path[i] = Point3(px[i], py[i], 0.0);
}

Evaluation FitnessEngine::EvaluatePath(int column, FleetTerms* terms) {
  const double* x = points_x_.col(column).data();
  const double* y = points_y_.col(column).data();
  const int n = static_cast<int>(points_x_.rows());
  double length = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double dx = x[i + 1] - x[i], dy = y[i + 1] - y[i];
    segment_[i] = std::sqrt(dx * dx + dy * dy);
    length += segment_[i];
  }
  return fleet_ ? Fleet(x, y, length, terms) : PaperPenalty(x, y, length);
}

Evaluation FitnessEngine::PaperPenalty(const double* x, const double* y, double length) {
  const int n = static_cast<int>(points_x_.rows());
  const int violations = proximity_.CountViolationsScreened(x, y, segment_.data(), n);
  return {length * (1.0 + penalty_ * violations), violations == 0};
}

Evaluation FitnessEngine::Fleet(const double* x, const double* y, double length,
                                FleetTerms* terms) {
  const int n = static_cast<int>(points_x_.rows());
  FleetTerms t = ClearanceTerms(x, y, n, length);
  t.curvature = CurvatureTerm(x, y, segment_.data(), n);
  if (terms != nullptr) *terms = t;
  return {t.Total(), feasible_};
}

FleetTerms FitnessEngine::ClearanceTerms(const double* x, const double* y, int n, double length) {
  const FleetObjective& f = *fleet_;
  const Point2 lo = proximity_.lower(), hi = proximity_.upper();
  // Pass 1: the clearance at every point and the shortfalls, each point weighted by half of
  // each segment beside it.
  double shortfall = 0.0, violation = 0.0;
  bool outside = false;
  for (int i = 0; i < n; ++i) {
    clearance_[i] = field_->Bilinear(x[i], y[i]);
    outside |= x[i] < lo.x() || x[i] > hi.x() || y[i] < lo.y() || y[i] > hi.y();
  }
  // The conservative raster may read a point on an obstacle's boundary up to about 1.5 cells
  // inside it: the shortfall below the hard clearance counts beyond kHardSlackCells only, and
  // the exact count below decides feasibility.
  const double hard = hard_clearance_ - kHardSlackCells * field_->cell_size();
  for (int i = 0; i < n; ++i) {
    const double ds = 0.5 * ((i > 0 ? segment_[i - 1] : 0.0) + (i + 1 < n ? segment_[i] : 0.0));
    shortfall += std::max(0.0, f.preferred_clearance - clearance_[i]) * ds;
    violation += std::max(0.0, hard - clearance_[i]) * ds;
  }
  const int obstacles = proximity_.CountViolationsScreened(x, y, segment_.data(), n);
  violation += length * obstacles;
  if (outside) {
    for (int i = 0; i < n; ++i) {
      const double ds = 0.5 * ((i > 0 ? segment_[i - 1] : 0.0) + (i + 1 < n ? segment_[i] : 0.0));
      const double inside =
          std::min(std::min(x[i] - lo.x(), hi.x() - x[i]), std::min(y[i] - lo.y(), hi.y() - y[i]));
      violation += std::max(0.0, -inside) * ds;
    }
  }
  feasible_ = !outside && obstacles == 0;
  FleetTerms t;
  t.length = length;
  t.clearance = f.preferred_clearance > 0 ? f.clearance_weight * shortfall : 0.0;
  t.violation = f.violation_weight * violation;
  return t;
}

double FitnessEngine::CurvatureTerm(const double* x, const double* y, const double* segment,
                                    int n) const {
  const FleetObjective& f = *fleet_;
  if (f.turning_radius <= 0) return 0.0;
  // The discrete curvature 2 tan(theta / 2) / mean segment at each interior point, theta its
  // turn: exact on a circle sampled at equal chords, unbounded toward a reversal.
  const double max_curvature = 1.0 / f.turning_radius;
  double excess = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    const double before = segment[i - 1], after = segment[i];
    const double ux = x[i] - x[i - 1], uy = y[i] - y[i - 1];
    const double vx = x[i + 1] - x[i], vy = y[i + 1] - y[i];
    const double cross = std::abs(ux * vy - uy * vx);
    const double denominator = (before * after + ux * vx + uy * vy) * (before + after);
    double curvature = 0.0;
    if (denominator > 0) {
      // Most turns are below 1 / R: the division only where it may exceed it.
      if (4.0 * cross <= max_curvature * denominator) continue;
      curvature = 4.0 * cross / denominator;
    } else if (before * after > 0) {
      curvature = kReversalCurvature;
    }
    excess += std::max(0.0, curvature - max_curvature) * 0.5 * (before + after);
  }
  return f.curvature_weight * excess;
}

FleetTerms FitnessEngine::PathTerms(const Path& path) {
  if (path.size() < 2) return {};
  // The clearance terms at points at most half a field cell apart, the path's vertices among
  // them; the curvature at the path's own vertices.
  const double spacing = 0.5 * field_->cell_size();
  std::vector<double> x, y, vertex_x, vertex_y, vertex_segment;
  for (size_t i = 0; i < path.size(); ++i) {
    vertex_x.push_back(path[i].x());
    vertex_y.push_back(path[i].y());
    if (i + 1 == path.size()) break;
    const Point3 step = path[i + 1] - path[i];
    vertex_segment.push_back(step.head<2>().norm());
    const int pieces = std::max(1, static_cast<int>(std::ceil(vertex_segment.back() / spacing)));
    for (int j = 0; j < pieces; ++j) {
      x.push_back(path[i].x() + step.x() * j / pieces);
      y.push_back(path[i].y() + step.y() * j / pieces);
    }
  }
  x.push_back(path.back().x());
  y.push_back(path.back().y());
  const int n = static_cast<int>(x.size());
  if (segment_.size() < x.size()) segment_.resize(x.size());
  if (clearance_.size() < x.size()) clearance_.resize(x.size());
  double length = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    segment_[i] = std::hypot(x[i + 1] - x[i], y[i + 1] - y[i]);
    length += segment_[i];
  }
  FleetTerms terms = ClearanceTerms(x.data(), y.data(), n, length);
  terms.curvature = CurvatureTerm(vertex_x.data(), vertex_y.data(), vertex_segment.data(),
                                  static_cast<int>(vertex_x.size()));
  return terms;
}

}  // namespace swarmplan
