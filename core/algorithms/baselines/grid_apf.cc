#include <algorithm>
#include <cmath>

#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/citations.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_space.h"

namespace swarmplan {
namespace {

class GridApfSearch {
 public:
  GridApfSearch(const GridApfParams& p, const Problem& problem, const GridSpace& space)
      : p_(p),
        problem_(problem),
        space_(space),
        moves_(*space.grid,
               MoveRules{Neighbourhood::k8, !p.allow_corner_cutting, problem.clearance}) {
    const OccupancyGrid& g = *space.grid;
    unreached_ = static_cast<double>(g.width()) * g.height() * g.resolution() * 3.0;
  }

  SearchResult Run(const StopToken& stop, Observer& observer) {
    SearchResult result;
    const OccupancyGrid& grid = *space_.grid;
    std::vector<Cell> cells{space_.start};
    Cell at = space_.start;
    double u = Potential(at);
    double best = unreached_ + Dist(at) * grid.resolution();
    ConvergenceLog log(observer);
    int step = 0;
    bool stalled = false;
    for (; step < p_.max_steps && !(at == space_.goal); ++step) {
      if (StopReason why = stop.Check(step); why != StopReason::kNone) {
        result.stop_reason = why;
        break;
      }
      Cell next = at;
      double next_u = u;
      for (const Cell& to : moves_.ValidMoves(at)) {
        const double v = Potential(to);
        if (v < next_u) {
          next_u = v;
          next = to;
        }
      }
      if (next == at) {
        stalled = true;  // a local minimum of the potential: APF's known failure
        log.Record(step, best, u, evaluations_, false);
        ++step;
        break;
      }
      at = next;
      u = next_u;
      cells.push_back(at);
      const double f =
          at == space_.goal ? space_.PathLength(cells) : unreached_ + Dist(at) * grid.resolution();
      if (f < best) {
        best = f;
        result.best_iteration = step;
      }
      log.Record(step, best, u, evaluations_, at == space_.goal);
    }
    result.iterations = step;
    result.evaluations = evaluations_;
    result.convergence = log.Take();
    if (at == space_.goal && !stalled) {
      SetGridPath(space_, cells, space_.PathLength(cells), result);
    } else {
      SetGridPath(space_, {}, best, result);
    }
    return result;
  }

 private:
  double Dist(Cell c) const { return std::hypot(c.x - space_.goal.x, c.y - space_.goal.y); }

  double Potential(Cell c) {
    ++evaluations_;
    const double d = Dist(c);
    double u = 0.5 * p_.k_att * d * d;
    const double rho = CellCenterClearance(*space_.grid, c) / space_.grid->resolution();
    if (rho < p_.influence) {
      const double inv = 1.0 / std::max(rho, 1e-6) - 1.0 / p_.influence;
      u += 0.5 * p_.k_rep * inv * inv;
    }
    return u;
  }

  const GridApfParams& p_;
  const Problem& problem_;
  const GridSpace& space_;
  GridMoves moves_;
  double unreached_ = 0.0;
  int64_t evaluations_ = 0;
};

}  // namespace

std::vector<ParamSpec> GridApfParams::Specs() {
  const GridApfParams d;
  std::vector<ParamSpec> specs = {
      ParamSpec::Double("k_att", d.k_att, 0.0, 1e9, "", "attractive gain").Ours(),
      ParamSpec::Double("k_rep", d.k_rep, 0.0, 1e12, "", "repulsive gain").Ours(),
      ParamSpec::Double("influence", d.influence, 1e-6, 1e6, "cells",
                        "ρ0, distance within which obstacles repel")
          .Ours(),
      ParamSpec::Int("max_steps", d.max_steps, 1, 100000000, "iterations", "most descent steps")
          .Ours(),
  };
  for (ParamSpec& spec : GridSpaceParamSpecs()) specs.push_back(std::move(spec));
  return specs;
}

GridApfParams GridApfParams::From(const ParamSet& set) {
  GridApfParams p;
  p.k_att = set.Double("k_att");
  p.k_rep = set.Double("k_rep");
  p.influence = set.Double("influence");
  p.max_steps = static_cast<int>(set.Int("max_steps"));
  p.allow_corner_cutting = set.Bool("allow_corner_cutting");
  p.resolution = set.Double("resolution");
  return p;
}

absl::StatusOr<SearchResult> RunGridSearch(const GridApfParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer) {
  GridApfSearch search(params, problem, space);
  return search.Run(stop, observer);
}

PlannerInfo GridApfInfo() {
  PlannerInfo info;
  info.id = "apf";
  info.seed_paper = citations::kPotentialField;
  info.description =
      "Artificial potential field on the 8-connected grid: steepest descent of "
      "U = ½k_att·d² + ½k_rep·(1/ρ − 1/ρ0)² (ρ < ρ0) over the neighbours, one step per "
      "iteration. It stalls in local minima (U-shaped obstacles, narrow passages): then it "
      "reports no path (found = false) after fewer than max_steps iterations. Every parameter "
      "is ours.";
  info.encoding = Encoding::kGridNodes;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  info.params = GridApfParams::Specs();
  info.factory = [](const ParamSet& set) {
    return std::make_unique<GridApfPlanner>(GridApfParams::From(set));
  };
  return info;
}

}  // namespace swarmplan
