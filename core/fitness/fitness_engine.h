#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "core/fitness/fleet_objective.h"
#include "core/fitness/interpolation_basis.h"
#include "core/fitness/rounded_corner_path.h"
#include "core/geometry/grid_collision.h"
#include "core/map/distance_field.h"
#include "core/operators/objective.h"
#include "core/operators/obstacle_proximity.h"
#include "core/problem.h"

namespace swarmplan {

struct WaypointFitnessOptions {
  int waypoints = 3;
  Interpolation interpolation = Interpolation::kSpline;
  int samples = 100;     // spline sample count
  double penalty = 100;  // M
  double d_safe = 1.5;   // the safety distance; the problem's clearance when larger
  // When set, the fleet objective replaces the papers' L (1 + M xi).
  std::optional<FleetObjective> fleet;
  // The spline's parameter at each knot, start and goal included (waypoints + 2 increasing
  // values); empty: 0, 1, 2, ... as the papers' paths have it.
  std::vector<double> knot_parameters;
  // > 0 (world units): the knots are the corners of a RoundedCornerPath turning no tighter than
  // this, instead of the interpolation; `samples` then bounds its straight parts' points.
  double rounded_corner_radius = 0.0;
  // Price curvature above 1 / turning radius with the violation weight when larger: for
  // searches whose result must turn within the radius.
  bool curvature_as_violation = false;
};

// The fitness of 2D waypoint paths, shared by every waypoint planner. A decision vector
// [x1..xk, y1..yk] becomes the path start -> waypoints -> goal through the cached
// InterpolationBasis (each point a local combination of the knots and, for the spline, of their
// second derivatives from one tridiagonal sweep), or as a RoundedCornerPath: O(k + points) per
// path. Then one pass over its points:
// - the papers' z = L (1 + M xi) (AEM-BSO eq 21): xi from ObstacleProximity's screened count,
//   which reads the map's distance field once per point and tests exactly only the segments
//   near an obstacle, so xi is the reference count; feasible when xi = 0;
// - or the FleetObjective J, its distances by bilinear interpolation in the distance field
//   (the ShapeWorld's own, or one built from the grid and cached with the map); feasible when
//   no obstacle is closer than the hard clearance, the verdict of the map's CollisionChecker:
//   ObstacleProximity's count (exact segment distances on worlds; on grids, the components
//   whose cells the path crosses) and, on a grid where that count is 0, the checker's exact test
//   of every segment the field cannot prove clear, one more obstacle when one fails.
// Single-threaded; buffers are sized at creation, so evaluating allocates nothing.
class FitnessEngine {
 public:
  static absl::StatusOr<FitnessEngine> Create(const Problem& problem,
                                              const WaypointFitnessOptions& options);

  int waypoints() const { return waypoints_; }
  // Points of each decoded path.
  int points() const { return rounded_ ? rounded_->max_points() : basis_->points(); }
  const ObstacleProximity& proximity() const { return proximity_; }

  // out[j] = the fitness of column j of xs (2k rows).
  void Evaluate(const Eigen::Ref<const Eigen::MatrixXd>& xs, Evaluation* out);
  Evaluation Evaluate(const Eigen::VectorXd& x) { return Evaluate(x.data()); }
  // The fitness of the waypoints x[0..2k).
  Evaluation Evaluate(const double* x);
  // The fleet objective's terms for x (the engine must have been created with a fleet).
  FleetTerms Terms(const Eigen::VectorXd& x);
  // The fleet objective's terms for any path (fleet engines only): the clearance terms read at
  // points every half field cell along it, the curvature at its own vertices.
  FleetTerms PathTerms(const Path& path);
  // The path x stands for, exactly as evaluated.
  void Decode(const Eigen::VectorXd& x, Path& path) const;

 private:
  FitnessEngine(const Problem& problem, const WaypointFitnessOptions& options,
                ObstacleProximity proximity);
  // Fills the point buffers with the path of the waypoints x[0..2k).
  void Interpolate(const double* x);
  // The path in the point buffers: segment lengths, then the objective.
  Evaluation EvaluatePath(FleetTerms* terms);
  // Sizes the per-point buffers for paths of n points.
  void Reserve(int n);
  // Fills cell_ and cell_value_ for the n points: the screen of the exact count.
  void LocatePoints(const double* x, const double* y, int n);
  Evaluation PaperPenalty(const double* x, const double* y, double length);
  Evaluation Fleet(const double* x, const double* y, double length, FleetTerms* terms);
  // Length, clearance and violation terms of the n points (segment_ holds their segments); sets
  // feasible_.
  FleetTerms ClearanceTerms(const double* x, const double* y, int n, double length);
  // On a grid, whether a segment of the n points comes closer to a blocked cell than the hard
  // clearance (the checker's exact test where the located cells' values cannot rule it out).
  bool GridSegmentTooClose(const double* x, const double* y, int n) const;
  // The weighted curvature excess of the n points with the given segment lengths.
  double CurvatureTerm(const double* x, const double* y, const double* segment, int n) const;

  MapPtr map_;  // keeps the map, which the proximity and the field point into, alive
  int waypoints_;
  double penalty_;
  std::optional<FleetObjective> fleet_;
  double hard_clearance_;
  // The fleet's curvature weight, or with curvature_as_violation its violation weight when
  // larger.
  double curvature_weight_ = 0.0;
  std::shared_ptr<const InterpolationBasis> basis_;   // unless rounded_
  std::shared_ptr<const RoundedCornerPath> rounded_;  // when rounded_corner_radius > 0
  // The knots start, waypoints, goal per coordinate, and the basis's scratch.
  std::vector<double> knot_x_, knot_y_, moments_;
  ObstacleProximity proximity_;
  // A grid's exact collision checker (fleet objective), which decides feasibility.
  std::shared_ptr<const GridCollisionChecker> grid_checker_;
  std::vector<double> points_x_, points_y_;  // the path being evaluated, n_ points of them
  int n_ = 0;
  std::vector<double> segment_;    // segment lengths of one path
  std::vector<int32_t> cell_;      // their cells in the proximity's field
  std::vector<float> cell_value_;  // and the field's value there
  bool feasible_ = false;          // of the last ClearanceTerms
};

}  // namespace swarmplan
