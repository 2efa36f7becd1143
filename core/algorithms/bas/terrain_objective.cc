#include "core/algorithms/bas/terrain_objective.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "core/random.h"

namespace swarmplan {

absl::StatusOr<std::unique_ptr<TerrainObjective>> TerrainObjective::Create(const Problem& problem,
                                                                           double penalty) {
  const Terrain* terrain = problem.map ? problem.map->terrain() : nullptr;
  if (terrain == nullptr) {
    return absl::InvalidArgumentError("terrain path: the map is not a terrain");
  }
  const int sx = static_cast<int>(std::lround(problem.start.x()));
  const int gx = static_cast<int>(std::lround(problem.goal.x()));
  if (std::abs(gx - sx) < 2) {
    return absl::InvalidArgumentError(absl::StrCat(
        "terrain path: start (column ", sx, ") and goal (column ", gx,
        ") must be at least two columns apart (one waypoint per column between them)"));
  }
  for (const Point3* p : {&problem.start, &problem.goal}) {
    if (p->x() < 0 || p->y() < 0 || p->x() > terrain->width() - 1 ||
        p->y() > terrain->depth() - 1) {
      return absl::InvalidArgumentError(
          absl::StrCat("terrain path: start/goal (", p->x(), ", ", p->y(), ") outside the grid"));
    }
  }
  return std::unique_ptr<TerrainObjective>(new TerrainObjective(*terrain, problem, penalty));
}

TerrainObjective::TerrainObjective(const Terrain& terrain, const Problem& problem, double penalty)
    : terrain_(terrain),
      start_(problem.start),
      goal_(problem.goal),
      clearance_(problem.clearance),
      penalty_(penalty) {
  const int sx = static_cast<int>(std::lround(start_.x()));
  const int gx = static_cast<int>(std::lround(goal_.x()));
  direction_ = gx > sx ? 1 : -1;
  first_column_ = sx + direction_;
  columns_ = std::abs(gx - sx) - 1;
  no_data_violation_ = std::max(1.0, terrain.ceiling() - terrain.min_height());
  lower_.resize(2 * columns_);
  upper_.resize(2 * columns_);
  for (int k = 0; k < columns_; ++k) {
    lower_[2 * k] = 0.0;
    upper_[2 * k] = terrain.depth() - 1;
    lower_[2 * k + 1] = terrain.min_height();
    upper_[2 * k + 1] = terrain.ceiling();
  }
}

double TerrainObjective::SegmentViolation(const Point3& a, const Point3& b) const {
  const double horizontal = (b.head<2>() - a.head<2>()).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(horizontal * 4.0)));
  double violation = 0.0;
  for (int s = 1; s <= steps; ++s) {
    const Point3 p = a + (b - a) * (static_cast<double>(s) / steps);
    const double ground = terrain_.GroundAt(p.x(), p.y());
    if (std::isnan(ground)) {
      violation += no_data_violation_;
      continue;
    }
    violation += std::max(0.0, ground + clearance_ - p.z());
    violation += std::max(0.0, p.z() - terrain_.ceiling());
  }
  return violation;
}

Evaluation TerrainObjective::Evaluate(const Eigen::VectorXd& x) {
  double fitness = 0.0;
  double violation = 0.0;
  Point3 prev = start_;
  for (int k = 0; k <= columns_; ++k) {
    const Point3 p = k < columns_ ? Waypoint(x, k) : goal_;
    fitness += (p - prev).norm() + p.z();
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
    const double ground = terrain_.GroundAt(ColumnX(k), x[2 * k]);
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
