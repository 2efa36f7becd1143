#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "core/algorithms/bas/terrain_objective.h"
#include "core/map/point.h"
#include "core/operators/objective.h"

namespace swarmplan {

// The terrain path problem of init=seeded: an offset profile along a seed path (the
// terrain-lattice optimum), judged by the TerrainObjective's fitness on the moved polyline. The
// decision vector holds (dY, dZ) at k control points spread evenly over the seed's vertices (one
// per `vertices_per_control` vertices, at least one), each in [-1/2, 1/2] times the map's extent
// in Y and its height range in Z (the TerrainObjective's box); a vertex's offset is the linear
// interpolation of the control points' offsets, 0 at the start and the goal, and its x stays
// the seed's, so the moved path keeps the seed's vertices per column (moves within a column
// included). With every offset 0 the path is the seed itself. A control point moves a run of
// vertices together: the objective charges every change of height as well as the height, so a
// vertex moved alone off a level stretch pays more in length than it gains, while a run lowered
// together gains. The search space grows with the path, not with the map's resolution. There
// is no path rationality check (Repair): the offsets are continuous along the path by
// construction.
class SeededTerrainObjective final : public PathObjective {
 public:
  // `seed` joins the inner objective's start and goal.
  SeededTerrainObjective(std::unique_ptr<TerrainObjective> inner, Path seed,
                         int vertices_per_control);

  int dim() const override { return 2 * k_; }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& u) override;
  Path Decode(const Eigen::VectorXd& u) override;
  // Offsets of up to `band` world units around the seed.
  void SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& u) const override;
  // The seed itself (every offset 0).
  std::vector<Eigen::VectorXd> InitialGuesses() const override {
    return {Eigen::VectorXd::Zero(dim())};
  }
  std::optional<KnownPath> BestKnownPath() override { return known_; }

  int control_points() const { return k_; }

 private:
  void Move(const Eigen::VectorXd& u, Path& path) const;

  std::unique_ptr<TerrainObjective> inner_;
  Path seed_;
  KnownPath known_;
  int k_ = 1;
  double y_range_ = 0.0, z_range_ = 0.0;
  double y_min_ = 0.0, y_max_ = 0.0, z_min_ = 0.0, z_max_ = 0.0;
  std::vector<int> left_;       // per vertex: the control point to its left, -1: the start
  std::vector<double> weight_;  // per vertex: the right control point's weight
  Eigen::VectorXd lower_, upper_;
  Path moved_;  // Evaluate's buffer
};

}  // namespace swarmplan
