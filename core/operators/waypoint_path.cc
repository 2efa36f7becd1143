#include "core/operators/waypoint_path.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::StatusOr<Interpolation> ParseInterpolation(const std::string& name) {
  if (name == "spline") return Interpolation::kSpline;
  if (name == "linear") return Interpolation::kLinear;
  if (name == "nearest") return Interpolation::kNearest;
  return absl::InvalidArgumentError(
      absl::StrCat("interpolation: unknown method '", name, "' (spline, linear, nearest)"));
}

std::vector<std::string> InterpolationNames() { return {"spline", "linear", "nearest"}; }

WaypointPathBuilder::WaypointPathBuilder(const Point3& start, const Point3& goal, int waypoints,
                                         Interpolation interpolation, int samples)
    : start_(start.x(), start.y(), 0.0),
      goal_(goal.x(), goal.y(), 0.0),
      waypoints_(waypoints),
      interpolation_(interpolation),
      samples_(samples) {
  knots_.reserve(waypoints + 2);
  path_.reserve(std::max(samples, 3 * (waypoints + 2)));
}

void WaypointPathBuilder::Knots(const Eigen::VectorXd& x, std::vector<Point3>& knots) const {
  knots.clear();
  knots.push_back(start_);
  for (int i = 0; i < waypoints_; ++i) knots.emplace_back(x[i], x[waypoints_ + i], 0.0);
  knots.push_back(goal_);
}

const Path& WaypointPathBuilder::Build(const Eigen::VectorXd& x) {
  Knots(x, knots_);
  switch (interpolation_) {
    case Interpolation::kSpline:
      spline_.Fit(knots_, SplineEnd::kNotAKnot);
      spline_.SampleByCount(samples_, path_);
      break;
    case Interpolation::kLinear:
      path_.assign(knots_.begin(), knots_.end());
      break;
    case Interpolation::kPolyline: {
      const int per_segment = std::max(1, (samples_ - 1) / (waypoints_ + 1));
      path_.clear();
      for (size_t i = 0; i + 1 < knots_.size(); ++i) {
        for (int j = 0; j < per_segment; ++j) {
          const double t = static_cast<double>(j) / per_segment;
          path_.push_back(knots_[i] + t * (knots_[i + 1] - knots_[i]));
        }
      }
      path_.push_back(knots_.back());
      break;
    }
    case Interpolation::kNearest:
      path_.clear();
      path_.push_back(knots_[0]);
      for (size_t i = 0; i + 1 < knots_.size(); ++i) {
        const double mid_x = 0.5 * (knots_[i].x() + knots_[i + 1].x());
        path_.emplace_back(mid_x, knots_[i].y(), 0.0);
        path_.emplace_back(mid_x, knots_[i + 1].y(), 0.0);
        path_.push_back(knots_[i + 1]);
      }
      break;
  }
  return path_;
}

}  // namespace swarmplan
