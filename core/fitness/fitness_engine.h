#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "core/fitness/fleet_objective.h"
#include "core/fitness/interpolation_matrix.h"
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
};

// The fitness of 2D waypoint paths, shared by every waypoint planner. A decision vector
// [x1..xk, y1..yk] becomes the path start -> waypoints -> goal by one product with the cached
// InterpolationMatrix (no spline solve), for a whole population at once (the columns of a
// matrix). Then, per path, one pass over its points:
// - the papers' z = L (1 + M xi) (AEM-BSO eq 21): xi from ObstacleProximity's screened count,
//   which reads the map's distance field once per point and tests exactly only the segments
//   near an obstacle, so xi is the reference count; feasible when xi = 0;
// - or the FleetObjective J, its distances by bilinear interpolation in the distance field
//   (the ShapeWorld's own, or one built from the grid and cached with the map); feasible when
//   ObstacleProximity's exact count below the hard clearance is 0.
// Single-threaded; buffers are sized at creation, so evaluating allocates nothing.
class FitnessEngine {
 public:
  static absl::StatusOr<FitnessEngine> Create(const Problem& problem,
                                              const WaypointFitnessOptions& options);

  int waypoints() const { return waypoints_; }
  // Points of each decoded path.
  int points() const { return matrix_->points(); }
  const ObstacleProximity& proximity() const { return proximity_; }

  // out[j] = the fitness of column j of xs (2k rows).
  void Evaluate(const Eigen::Ref<const Eigen::MatrixXd>& xs, Evaluation* out);
  Evaluation Evaluate(const Eigen::VectorXd& x);
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
  // Fills the point buffers' first `count` columns from xs.middleCols(first, count).
  void Interpolate(const Eigen::Ref<const Eigen::MatrixXd>& xs, int first, int count);
  // Column j of the point buffers: segment lengths, then the objective.
  Evaluation EvaluatePath(int column, FleetTerms* terms);
  Evaluation PaperPenalty(const double* x, const double* y, double length);
  Evaluation Fleet(const double* x, const double* y, double length, FleetTerms* terms);
  // Length, clearance and violation terms of the n points (segment_ holds their segments); sets
  // feasible_.
  FleetTerms ClearanceTerms(const double* x, const double* y, int n, double length);
  // The weighted curvature excess of the n points with the given segment lengths.
  double CurvatureTerm(const double* x, const double* y, const double* segment, int n) const;

  MapPtr map_;  // keeps the map, which the proximity and the field point into, alive
  int waypoints_;
  double penalty_;
  std::optional<FleetObjective> fleet_;
  double hard_clearance_;
  std::shared_ptr<const InterpolationMatrix> matrix_;
  // The interior columns of the matrix (the waypoints' weights) and the start's and goal's
  // fixed contribution.
  Eigen::MatrixXd weights_x_, weights_y_;
  Eigen::VectorXd offset_x_, offset_y_;
  ObstacleProximity proximity_;
  const DistanceField* field_ = nullptr;
  std::shared_ptr<const DistanceField> owned_field_;  // a grid's, cached with the map
  Eigen::MatrixXd points_x_, points_y_;               // (points) x (batch) buffers
  std::vector<double> segment_;                       // segment lengths of one path
  std::vector<double> clearance_;                     // the field at its points (fleet objective)
  bool feasible_ = false;                             // of the last ClearanceTerms
};

}  // namespace swarmplan
