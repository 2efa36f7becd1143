#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "core/operators/objective.h"
#include "core/problem.h"

namespace swarmplan {

// The 3D path model of seed 000 on a Terrain, in world units: one waypoint per column (at the
// x of its cell centres) strictly between the start's and the goal's column, decision vector
// (Y1, Z1, Y2, Z2, ...) with Y between the first and the last row's centre and Z in [lowest
// ground, ceiling]. Fitness (eq 3) f = TerrainPathCost (sum over consecutive points of segment
// length + Z of the later point per cell of x-advance, see terrain_path_cost.h) plus `penalty`
// times the violation (ours): along every segment, sampled every quarter cell, the depth below
// ground + clearance, the height above the ceiling, and a full relief for a point over a cell
// without data. Feasible means no violation (the planner's result is then checked exactly by the
// terrain's collision checker).
class TerrainObjective final : public PathObjective {
 public:
  // INVALID_ARGUMENT unless the map is a terrain and start and goal are two or more columns
  // apart inside it.
  static absl::StatusOr<std::unique_ptr<TerrainObjective>> Create(const Problem& problem,
                                                                  double penalty);

  int dim() const override { return 2 * columns_; }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override;
  Path Decode(const Eigen::VectorXd& x) override;
  // Y within `band` of the straight start-goal line; Z up to `band` above the ground plus
  // clearance (the band in Z is ours), below the ceiling.
  void SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const override;
  // The path rationality check (eq 13): a waypoint whose Y jumps by more than theta from the
  // previous one takes the previous waypoint's Y and Z.
  void Repair(double theta, Eigen::VectorXd& x) const override;

  // The fitness and feasibility of any polyline by this objective: its TerrainPathCost plus
  // penalty times its violation, feasible when there is none.
  Evaluation EvaluatePath(const Path& path) const;

  const Terrain& terrain() const { return terrain_; }
  int columns() const { return columns_; }
  // The world x of interior waypoint k (0-based).
  double ColumnX(int k) const { return terrain_.CellCentre(first_column_ + k * direction_, 0).x(); }
  const Point3& start() const { return start_; }
  const Point3& goal() const { return goal_; }
  double clearance() const { return clearance_; }
  // The violation along the segment a-b (0 when it keeps the clearance under the ceiling).
  double SegmentViolation(const Point3& a, const Point3& b) const;

 private:
  TerrainObjective(const Terrain& terrain, const Problem& problem, double penalty);
  Point3 Waypoint(const Eigen::VectorXd& x, int k) const {
    return Point3(ColumnX(k), x[2 * k], x[2 * k + 1]);
  }

  const Terrain& terrain_;
  Point3 start_, goal_;
  double clearance_;
  double penalty_;
  int first_column_ = 0;
  int direction_ = 1;
  int columns_ = 0;
  double no_data_violation_ = 1.0;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace swarmplan
