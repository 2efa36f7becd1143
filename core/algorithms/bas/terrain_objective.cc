#include "core/algorithms/bas/terrain_objective.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/operators/terrain_path_cost.h"
#include "core/random.h"

namespace swarmplan {
namespace {

// The penalty samples every segment at most this many cells apart horizontally.
constexpr double kSampleStepInCells = 0.25;

}  // namespace

absl::StatusOr<std::unique_ptr<TerrainObjective>> TerrainObjective::Create(const Problem& problem,
                                                                           double penalty) {
  const Terrain* terrain = problem.map ? problem.map->terrain() : nullptr;
  if (terrain == nullptr) {
    return absl::InvalidArgumentError("terrain path: the map is not a terrain");
  }
  for (const auto& [p, field] :
       {std::pair{&problem.start, "start"}, std::pair{&problem.goal, "goal"}}) {
    const Point2 lo = terrain->min_xy(), hi = terrain->max_xy();
    if (!(p->x() >= lo.x() && p->y() >= lo.y() && p->x() <= hi.x() && p->y() <= hi.y())) {
      return absl::InvalidArgumentError(
          absl::StrCat("terrain path: ", field, " (", p->x(), ", ", p->y(),
                       ") is outside the terrain's cell "
                       "centres (",
                       lo.x(), ", ", lo.y(), ") .. (", hi.x(), ", ", hi.y(), ")"));
    }
  }
  const int sx = static_cast<int>(std::lround(terrain->ToCell(problem.start.head<2>()).x()));
  const int gx = static_cast<int>(std::lround(terrain->ToCell(problem.goal.head<2>()).x()));
  if (std::abs(gx - sx) < 2) {
    return absl::InvalidArgumentError(absl::StrCat(
        "terrain path: start (column ", sx, ") and goal (column ", gx,
        ") must be at least two columns apart (one waypoint per column between them)"));
  }
  return std::unique_ptr<TerrainObjective>(new TerrainObjective(*terrain, problem, penalty));
}

TerrainObjective::TerrainObjective(const Terrain& terrain, const Problem& problem, double penalty)
    : terrain_(terrain),
      start_(problem.start),
      goal_(problem.goal),
      clearance_(problem.clearance),
      penalty_(penalty) {
  const int sx = static_cast<int>(std::lround(terrain.ToCell(start_.head<2>()).x()));
  const int gx = static_cast<int>(std::lround(terrain.ToCell(goal_.head<2>()).x()));
  direction_ = gx > sx ? 1 : -1;
  first_column_ = sx + direction_;
  columns_ = std::abs(gx - sx) - 1;
  no_data_violation_ = std::max(1.0, terrain.ceiling() - terrain.min_height());
  lower_.resize(2 * columns_);
  upper_.resize(2 * columns_);
  for (int k = 0; k < columns_; ++k) {
    lower_[2 * k] = terrain.min_xy().y();
    upper_[2 * k] = terrain.max_xy().y();
    lower_[2 * k + 1] = terrain.min_height();
    upper_[2 * k + 1] = terrain.ceiling();
  }
}

double TerrainObjective::SegmentViolation(const Point3& a, const Point3& b) const {
  const double horizontal = (b.head<2>() - a.head<2>()).norm();
  const int steps = std::max(
      1, static_cast<int>(std::ceil(horizontal / (kSampleStepInCells * terrain_.cell_size()))));
  double violation = 0.0;
  for (int s = 1; s <= steps; ++s) {
    const Point3 p = a + (b - a) * (static_cast<double>(s) / steps);
    const double ground = terrain_.GroundAt(p.head<2>());
    if (std::isnan(ground)) {
      violation += no_data_violation_;
      continue;
    }
    violation += std::max(0.0, ground + clearance_ - p.z());
    violation += std::max(0.0, p.z() - terrain_.ceiling());
  }
  return violation;
}

Evaluation TerrainObjective::EvaluatePath(const Path& path) const {
  double fitness = 0.0;
  double violation = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    fitness += TerrainSegmentCost(path[i], path[i + 1], terrain_.cell_size());
    violation += SegmentViolation(path[i], path[i + 1]);
  }
  return {fitness + penalty_ * violation, violation == 0.0};
}

Evaluation TerrainObjective::Evaluate(const Eigen::VectorXd& x) {
  double fitness = 0.0;
  double violation = 0.0;
  Point3 prev = start_;
  for (int k = 0; k <= columns_; ++k) {
    const Point3 p = k < columns_ ? Waypoint(x, k) : goal_;
    fitness += TerrainSegmentCost(prev, p, terrain_.cell_size());
    violation += SegmentViolation(prev, p);
    prev = p;
  }
  return {fitness + penalty_ * violation, violation == 0.0};
}

Path TerrainObjective::Decode(const Eigen::VectorXd& x) {
  Path path;
  path.reserve(columns_ + 2);
  path.push_back(start_);
  for (int k = 0; k < columns_; ++k) path.push_back(Waypoint(x, k));
  path.push_back(goal_);
  return path;
}

void TerrainObjective::SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const {
  x.resize(dim());
  for (int k = 0; k < columns_; ++k) {
    const double t = (ColumnX(k) - start_.x()) / (goal_.x() - start_.x());
    const double y = start_.y() + t * (goal_.y() - start_.y()) + rng.Uniform(-band, band);
    x[2 * k] = std::clamp(y, lower_[2 * k], upper_[2 * k]);
    const double ground = terrain_.GroundAt(Point2(ColumnX(k), x[2 * k]));
    const double low = std::isnan(ground) ? terrain_.min_height() : ground + clearance_;
    x[2 * k + 1] = std::min(low + rng.Uniform(0.0, band), terrain_.ceiling());
  }
  Clamp(x);
}

void TerrainObjective::Repair(double theta, Eigen::VectorXd& x) const {
  double prev_y = start_.y();
  double prev_z = start_.z();
  for (int k = 0; k < columns_; ++k) {
    const double dy = x[2 * k] - prev_y;
    if (dy * dy > theta * theta) {
      x[2 * k] = prev_y;
      x[2 * k + 1] = prev_z;
    }
    prev_y = x[2 * k];
    prev_z = x[2 * k + 1];
  }
}

}  // namespace swarmplan
