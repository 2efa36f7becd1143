#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "core/fitness/fitness_engine.h"
#include "core/geometry/collision.h"
#include "core/grid_ops/grid_space.h"
#include "core/map/point.h"
#include "core/problem.h"

namespace swarmplan {

// The fitness of a grid-node planner with init=seeded, one definition for all of them: a cell
// path is read as the any-angle path it stands for and ranked by the problem's fleet objective
// (length, plus the shortfall below the preferred clearance, plus the curvature above
// 1 / turning radius, FitnessEngine::PathTerms). Without preferences the objective is the
// length, and the any-angle path is AnyAnglePath's (pulled taut against the corners, so the
// exact optimum is reachable). With a preferred clearance, ShortcutKeepingClearance straightens
// the path without pulling it nearer the walls, so a path the swarm moved away from them keeps
// the clearance it gained, and moves each bend within its cell (to a corner or an edge's
// midpoint) where the objective's length and shortfall are least.
//
// With a turning radius the plan returns the path after the bounded-curvature smoothing, so the
// seeds and the swarm's result, a few paths per plan, are also judged by the smoothing itself
// (Smoothed), as the plan judges them: turning within the radius first, then the objective.
class GridPathCost {
 public:
  static absl::StatusOr<GridPathCost> Create(const Problem& problem, const GridSpace& space);

  // The any-angle path of `cells`; nullopt when its world path is not collision-free.
  std::optional<Path> PathOf(const std::vector<Cell>& cells) const;
  // The objective of a path of the problem (a seed, or PathOf's).
  double Cost(const Path& path);
  // A path after the smoothing the plan gives it.
  struct Judged {
    bool within_turning_radius = true;
    double objective = 0.0;
    // Whether this is the better path for the plan.
    bool operator<(const Judged& other) const {
      return within_turning_radius != other.within_turning_radius ? within_turning_radius
                                                                  : objective < other.objective;
    }
  };
  // With a turning radius, `path` smoothed to it (SmoothToTurningRadius) and its objective;
  // otherwise Cost(path).
  Judged Smoothed(const Path& path);
  // Whether Smoothed judges differently from Cost: with a turning radius.
  bool judges_after_smoothing() const { return turning_radius_ > 0.0; }
  // Cost(PathOf(cells)); infinity without such a path.
  double operator()(const std::vector<Cell>& cells);
  const GridSpace& space() const { return *space_; }

 private:
  GridPathCost(const GridSpace& space, const Problem& problem,
               std::unique_ptr<FitnessEngine> fleet);

  const GridSpace* space_;
  double preferred_clearance_;
  double clearance_weight_;
  double turning_radius_;
  double clearance_;
  std::shared_ptr<const CollisionChecker> checker_;  // the smoothing's, with a turning radius
  std::unique_ptr<FitnessEngine> fleet_;             // null when the objective is the length
};

}  // namespace swarmplan
