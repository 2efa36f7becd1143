#include "core/fitness/fitness_engine.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace swarmplan {
namespace {

// How far (field cells) the fleet objective's shortfall below the hard clearance starts below
// it, so that a path along an obstacle's boundary costs nothing for the raster's error.
constexpr double kHardSlackCells = 2.0;
// The curvature of an exact reversal, where the discrete formula divides by zero.
constexpr double kReversalCurvature = 1e9;

// A point's cell in a distance field (ObstacleProximity::FieldCell's arithmetic) with the
// field's value there, and on request its bilinear value, from one scaling of the point.
class FieldPointLocator {
 public:
  // A point in the field's grid coordinates, (p - origin) / cell size.
  struct GridCoordinates {
    double u, v;
  };

  explicit FieldPointLocator(const DistanceField& field)
      : field_(field),
        inv_(field.inverse_cell_size()),
        ox_(field.origin().x()),
        oy_(field.origin().y()),
        w_(static_cast<unsigned>(field.width())),
        h_(static_cast<unsigned>(field.height())),
        values_(field.values()) {}

  // Sets `cell` (-1 outside the field) and `value` (0 outside) for (x, y).
  GridCoordinates Locate(double x, double y, int32_t& cell, float& value) const {
    const GridCoordinates g{(x - ox_) * inv_, (y - oy_) * inv_};
    const int cx = FloorToInt(g.u), cy = FloorToInt(g.v);
    const bool inside = static_cast<unsigned>(cx) < w_ && static_cast<unsigned>(cy) < h_;
    cell = inside ? cy * static_cast<int32_t>(w_) + cx : -1;
    value = inside ? values_[cell] : 0.0f;
    return g;
  }
  double Bilinear(const GridCoordinates& g) const { return field_.BilinearAtGrid(g.u, g.v); }

 private:
  const DistanceField& field_;
  double inv_, ox_, oy_;
  unsigned w_, h_;
  const float* values_;
};

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
  if (!std::isfinite(options.rounded_corner_radius) || options.rounded_corner_radius < 0) {
    return absl::InvalidArgumentError(
        "waypoint objective: rounded_corner_radius must be finite and >= 0");
  }
  if (options.fleet) {
    if (absl::Status status = ValidateFleetObjective(*options.fleet); !status.ok()) return status;
  }
  if (!options.knot_parameters.empty()) {
    const std::vector<double>& t = options.knot_parameters;
    if (static_cast<int>(t.size()) != options.waypoints + 2) {
      return absl::InvalidArgumentError(absl::StrCat(
          "waypoint objective: knot_parameters needs waypoints + 2 = ", options.waypoints + 2,
          " values, got ", t.size()));
    }
    for (size_t i = 0; i + 1 < t.size(); ++i) {
      if (!(t[i + 1] > t[i]) || !std::isfinite(t[i + 1] - t[i])) {
        return absl::InvalidArgumentError(
            "waypoint objective: knot_parameters must be finite and increasing");
      }
    }
  }
  absl::StatusOr<ObstacleProximity> proximity = ObstacleProximity::Create(
      *problem.map,
      options.fleet ? problem.clearance : std::max(options.d_safe, problem.clearance));
  if (!proximity.ok()) return proximity.status();
  return FitnessEngine(problem, options, *std::move(proximity));
}

FitnessEngine::FitnessEngine(const Problem& problem, const WaypointFitnessOptions& options,
                             ObstacleProximity proximity)
    : map_(problem.map),
      waypoints_(options.waypoints),
      penalty_(options.penalty),
      fleet_(options.fleet),
      hard_clearance_(problem.clearance),
      proximity_(std::move(proximity)) {
  const int knots = waypoints_ + 2;
  if (options.rounded_corner_radius > 0) {
    // Straight parts read the field every half cell.
    rounded_ = std::make_shared<const RoundedCornerPath>(knots, options.rounded_corner_radius,
                                                         0.5 * proximity_.field().cell_size(),
                                                         options.samples);
  } else if (options.knot_parameters.empty()) {
    basis_ = CachedInterpolationBasis(options.interpolation, options.waypoints, options.samples);
  } else {
    basis_ = std::make_shared<const InterpolationBasis>(options.interpolation,
                                                        options.knot_parameters, options.samples);
  }
  if (fleet_) {
    curvature_weight_ = options.curvature_as_violation
                            ? std::max(fleet_->curvature_weight, fleet_->violation_weight)
                            : fleet_->curvature_weight;
  }
  if (fleet_ && map_->grid() != nullptr) {
    grid_checker_ = std::make_shared<const GridCollisionChecker>(*map_->grid());
  }
  const int n = points();
  knot_x_.assign(knots, 0.0);
  knot_y_.assign(knots, 0.0);
  knot_x_.front() = problem.start.x();
  knot_y_.front() = problem.start.y();
  knot_x_.back() = problem.goal.x();
  knot_y_.back() = problem.goal.y();
  moments_.resize(2 * knots);
  points_x_.resize(n);
  points_y_.resize(n);
  Reserve(n);
}

void FitnessEngine::Reserve(int n) {
  if (static_cast<int>(segment_.size()) >= n) return;
  segment_.resize(n);
  cell_.resize(n);
  cell_value_.resize(n);
}

void FitnessEngine::Interpolate(const double* x) {
  const int k = waypoints_;
  std::copy(x, x + k, knot_x_.begin() + 1);
  std::copy(x + k, x + 2 * k, knot_y_.begin() + 1);
  if (rounded_) {
    n_ = rounded_->Apply(knot_x_.data(), knot_y_.data(), points_x_.data(), points_y_.data(),
                         moments_.data());
  } else {
    basis_->Apply(knot_x_.data(), knot_y_.data(), points_x_.data(), points_y_.data(),
                  moments_.data());
    n_ = basis_->points();
  }
}

void FitnessEngine::Evaluate(const Eigen::Ref<const Eigen::MatrixXd>& xs, Evaluation* out) {
  for (Eigen::Index j = 0; j < xs.cols(); ++j) out[j] = Evaluate(xs.col(j).data());
}

Evaluation FitnessEngine::Evaluate(const double* x) {
  Interpolate(x);
  return EvaluatePath(nullptr);
}

FleetTerms FitnessEngine::Terms(const Eigen::VectorXd& x) {
  FleetTerms terms;
  Interpolate(x.data());
  EvaluatePath(&terms);
  return terms;
}

void FitnessEngine::Decode(const Eigen::VectorXd& x, Path& path) const {
  const int k = waypoints_;
  std::vector<double> kx = knot_x_, ky = knot_y_, moments(moments_.size());
  std::copy(x.data(), x.data() + k, kx.begin() + 1);
  std::copy(x.data() + k, x.data() + 2 * k, ky.begin() + 1);
  std::vector<double> px(points_x_.size()), py(points_y_.size());
  int n = static_cast<int>(px.size());
  if (rounded_) {
    n = rounded_->Apply(kx.data(), ky.data(), px.data(), py.data(), moments.data());
  } else {
    basis_->Apply(kx.data(), ky.data(), px.data(), py.data(), moments.data());
  }
  path.resize(n);
  for (int i = 0; i < n; ++i) path[i] = Point3(px[i], py[i], 0.0);
}

Evaluation FitnessEngine::EvaluatePath(FleetTerms* terms) {
  const double* x = points_x_.data();
  const double* y = points_y_.data();
  const int n = n_;
  double length = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double dx = x[i + 1] - x[i], dy = y[i + 1] - y[i];
    segment_[i] = std::sqrt(dx * dx + dy * dy);
    length += segment_[i];
  }
  return fleet_ ? Fleet(x, y, length, terms) : PaperPenalty(x, y, length);
}

void FitnessEngine::LocatePoints(const double* x, const double* y, int n) {
  const FieldPointLocator locator(proximity_.field());
  for (int i = 0; i < n; ++i) locator.Locate(x[i], y[i], cell_[i], cell_value_[i]);
}

Evaluation FitnessEngine::PaperPenalty(const double* x, const double* y, double length) {
  const int n = n_;
  LocatePoints(x, y, n);
  const int violations = proximity_.CountViolationsScreened(x, y, segment_.data(), cell_.data(),
                                                            cell_value_.data(), n);
  return {length * (1.0 + penalty_ * violations), violations == 0};
}

Evaluation FitnessEngine::Fleet(const double* x, const double* y, double length,
                                FleetTerms* terms) {
  const int n = n_;
  FleetTerms t = ClearanceTerms(x, y, n, length);
  t.curvature = CurvatureTerm(x, y, segment_.data(), n);
  if (terms != nullptr) *terms = t;
  return {t.Total(), feasible_};
}

FleetTerms FitnessEngine::ClearanceTerms(const double* x, const double* y, int n, double length) {
  const FleetObjective& f = *fleet_;
  const Point2 lo = proximity_.lower(), hi = proximity_.upper();
  const DistanceField& field = proximity_.field();
  const FieldPointLocator locator(field);
  // The conservative raster may read a point on an obstacle's boundary up to about 1.5 cells
  // inside it: the shortfall below the hard clearance counts beyond kHardSlackCells only, and
  // the exact count below decides feasibility.
  const double hard = hard_clearance_ - kHardSlackCells * field.cell_size();
  // A point whose cell's value clears by the field's bilinear drop bound the hard clearance, and
  // the preferred one where there is one (the shortfall is not used otherwise), adds 0 to the
  // sums that count, so its bilinear value is not read.
  const double unaffected =
      (f.preferred_clearance > 0 ? std::max(f.preferred_clearance, hard) : hard) +
      field.bilinear_drop_bound();
  // Each point weighted by half of each segment beside it; located and read in one pass.
  double shortfall = 0.0, violation = 0.0;
  bool outside = false;
  for (int i = 0; i < n; ++i) {
    outside |= x[i] < lo.x() || x[i] > hi.x() || y[i] < lo.y() || y[i] > hi.y();
    const FieldPointLocator::GridCoordinates g =
        locator.Locate(x[i], y[i], cell_[i], cell_value_[i]);
    if (cell_[i] >= 0 && cell_value_[i] >= unaffected) continue;
    const double clearance = locator.Bilinear(g);
    const double ds = 0.5 * ((i > 0 ? segment_[i - 1] : 0.0) + (i + 1 < n ? segment_[i] : 0.0));
    shortfall += std::max(0.0, f.preferred_clearance - clearance) * ds;
    violation += std::max(0.0, hard - clearance) * ds;
  }
  int obstacles = proximity_.CountViolationsScreened(x, y, segment_.data(), cell_.data(),
                                                     cell_value_.data(), n);
  if (obstacles == 0 && grid_checker_ && GridSegmentTooClose(x, y, n)) obstacles = 1;
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

bool FitnessEngine::GridSegmentTooClose(const double* x, const double* y, int n) const {
  // The component labels are read per cell: a path may pass within the hard clearance of a
  // blocked cell while every cell it crosses is farther. A segment whose ends' cells prove both
  // ends farther than the clearance plus half its length is clear; the others get the exact test.
  const double slack = DistanceField::kCellSlack * proximity_.field().cell_size();
  for (int i = 0; i + 1 < n; ++i) {
    if (cell_[i] >= 0 && cell_[i + 1] >= 0 &&
        std::min(cell_value_[i], cell_value_[i + 1]) - slack >=
            hard_clearance_ + 0.5 * segment_[i]) {
      continue;
    }
    if (!grid_checker_->SegmentFreeByScan(Point3(x[i], y[i], 0.0), Point3(x[i + 1], y[i + 1], 0.0),
                                          hard_clearance_)) {
      return true;
    }
  }
  return false;
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
  return curvature_weight_ * excess;
}

FleetTerms FitnessEngine::PathTerms(const Path& path) {
  if (path.size() < 2) return {};
  // The clearance terms at points at most half a field cell apart, the path's vertices among
  // them; the curvature at the path's own vertices.
  const double spacing = 0.5 * proximity_.field().cell_size();
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
  Reserve(n);
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
