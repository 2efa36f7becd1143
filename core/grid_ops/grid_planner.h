#pragma once

#include <utility>

#include "absl/status/statusor.h"
#include "core/grid_ops/grid_space.h"
#include "core/planner.h"
#include "core/problem.h"
#include "core/stop_token.h"

namespace swarmplan {

// A planner that searches the grid space of its problem (the occupancy grid, or the shape world
// rasterised at Params::resolution). The search itself is the overload
//   absl::StatusOr<SearchResult> RunGridSearch(const Params&, const Problem&, const GridSpace&,
//                                              const StopToken&, Observer&);
// declared next to Params and found by argument-dependent lookup.
template <typename Params>
class GridPlanner final : public Planner {
 public:
  explicit GridPlanner(Params params) : params_(std::move(params)) {}

  absl::StatusOr<SearchResult> Solve(const Problem& problem, const StopToken& stop,
                                     Observer& observer) override {
    absl::StatusOr<GridSpace> space = MakeGridSpace(problem, params_.resolution);
    if (!space.ok()) return space.status();
    return RunGridSearch(params_, problem, *space, stop, observer);
  }

  // The start and goal cells of the grid space must be usable.
  absl::Status CheckProblem(const Problem& problem) const override {
    return MakeGridSpace(problem, params_.resolution).status();
  }

 private:
  Params params_;
};

}  // namespace swarmplan
