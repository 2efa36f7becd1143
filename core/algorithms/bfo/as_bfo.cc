#include "core/algorithms/bfo/as_bfo.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "core/algorithms/citations.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/grid_ops/grid_space.h"
#include "core/grid_ops/shortcut.h"
#include "core/random.h"

namespace swarmplan {
namespace {

struct Bacterium {
  std::vector<Cell> cells;
  double cost = 0.0;
  double health = 0.0;
};

// One A*-repaired tumble: cells[index] moved to `to`; nullopt when a gap cannot be repaired.
std::optional<std::vector<Cell>> Tumble(GridMoves& moves, const std::vector<Cell>& cells,
                                        size_t index, Cell to, GridSearchContext* context) {
  std::vector<Cell> out = cells;
  out[index] = to;
  if (!RepairGaps(moves, out, context, index - 1, index + 1)) return std::nullopt;
  RemoveLoops(out);
  return out;
}

class AsBfoSearch {
 public:
  AsBfoSearch(const AsBfoParams& p, const Problem& problem, const GridSpace& space)
      : p_(p),
        problem_(problem),
        space_(space),
        moves_(*space.grid,
               MoveRules{Neighbourhood::k8, !p.allow_corner_cutting, problem.clearance}),
        rng_(problem.seed) {}

  absl::StatusOr<SearchResult> Run(const StopToken& stop, Observer& observer) {
    SearchResult result;
    reachable_ = ReachableCells(moves_, space_.start);
    const OccupancyGrid& grid = *space_.grid;
    in_reach_.assign(static_cast<size_t>(grid.width()) * grid.height(), 0);
    for (const Cell& c : reachable_) in_reach_[Index(c)] = 1;
    if (!in_reach_[Index(space_.goal)]) return result;  // start and goal not connected

    if (p_.seeding.seeded) {
      absl::StatusOr<GridSeeds> seeds =
          GridSeeds::Find(problem_, space_, moves_, p_.seeding.seeds, stop, &context_);
      if (!seeds.ok()) return seeds.status();
      seeds_ = *std::move(seeds);
    }
    bacteria_.resize(p_.population);
    for (size_t i = 0; i < bacteria_.size(); ++i) {
      Bacterium& b = bacteria_[i];
      if (!seeds_) {
        Disperse(b, 0);
        continue;
      }
      b.cells = seeds_->ForMember(i);
      b.cost = Evaluate(b.cells);
      if (i >= seeds_->cell_paths().size()) Chemotaxis(b, 0);
      Offer(b, 0);
    }

    ConvergenceLog log(observer);
    int iteration = 0;
    for (int l = 0; l < p_.elimination_steps && !stopped_; ++l) {
      for (int k = 0; k < p_.reproduction_steps && !stopped_; ++k) {
        for (Bacterium& b : bacteria_) b.health = 0.0;
        for (int j = 0; j < p_.chemotactic_steps; ++j) {
          if (StopReason why = stop.Check(iteration); why != StopReason::kNone) {
            result.stop_reason = why;
            stopped_ = true;
            break;
          }
          double sum = 0.0;
          for (Bacterium& b : bacteria_) {
            Chemotaxis(b, iteration);
            sum += b.cost;
          }
          log.Record(iteration, seeds_ ? seeds_->Incumbent(best_.cost) : best_.cost,
                     sum / bacteria_.size(), evaluations_, true);
          ++iteration;
        }
        if (!stopped_) Reproduce();
      }
      if (!stopped_) {
        for (Bacterium& b : bacteria_) {
          if (rng_.Bernoulli(p_.elimination_probability)) Disperse(b, iteration);
        }
      }
    }
    result.iterations = iteration;
    result.evaluations = evaluations_;
    result.best_iteration = best_iteration_;
    result.convergence = log.Take();
    if (!seeds_) {
      SetGridPath(space_, best_.cells, best_.cost, result);
    } else if (seeds_->SetResult(best_.cells, stop, result)) {
      result.best_iteration = 0;
    }
    return result;
  }

 private:
  size_t Index(Cell c) const { return static_cast<size_t>(c.y) * space_.grid->width() + c.x; }
  bool Allowed(Cell c) const { return space_.grid->InBounds(c) && in_reach_[Index(c)]; }

  double Evaluate(const std::vector<Cell>& cells) {
    ++evaluations_;
    return seeds_ ? seeds_->Cost(cells) : space_.PathLength(cells);
  }

  void Offer(const Bacterium& b, int iteration) {
    if (best_.cells.empty() || b.cost < best_.cost - 1e-12) {
      best_ = b;
      best_iteration_ = iteration;
    }
  }

  void Disperse(Bacterium& b, int iteration) {
    if (seeds_) {
      const int64_t count = static_cast<int64_t>(seeds_->cell_paths().size());
      b.cells = seeds_->ForMember(static_cast<size_t>(rng_.UniformInt(0, count - 1)));
      b.cost = Evaluate(b.cells);
      return;
    }
    std::optional<std::vector<Cell>> path = RandomFeasiblePath(
        moves_, space_.start, space_.goal, reachable_, p_.max_waypoints, rng_, &context_);
    b.cells = path ? *std::move(path) : std::vector<Cell>{space_.start};
    b.cost = Evaluate(b.cells);
    Offer(b, iteration);
  }

  void Chemotaxis(Bacterium& b, int iteration) {
    const size_t n = b.cells.size();
    if (n > 2) {
      const size_t index = static_cast<size_t>(rng_.UniformInt(1, static_cast<int64_t>(n) - 2));
      const Cell from = b.cells[index];
      std::vector<Cell> directions;
      for (const Cell& d : MoveOffsets(Neighbourhood::k8)) {
        if (Allowed(Cell{from.x + d.x, from.y + d.y})) directions.push_back(d);
      }
      if (!directions.empty()) {
        const Cell dir = directions[rng_.UniformInt(0, directions.size() - 1)];
        TumbleAndSwim(b, index, dir);
      }
    }
    b.health += b.cost;
    Offer(b, iteration);
  }

  void TumbleAndSwim(Bacterium& b, size_t index, Cell dir) {
    Cell to{b.cells[index].x + dir.x, b.cells[index].y + dir.y};
    std::optional<std::vector<Cell>> moved = Tumble(moves_, b.cells, index, to, &context_);
    if (!moved) return;
    double cost = Evaluate(*moved);
    const double before = b.cost;
    if (!p_.keep_worse_tumbles && cost >= before) return;
    b.cells = *std::move(moved);
    b.cost = cost;
    double last = before;
    for (int m = 0; m < p_.swim_length && b.cost < last; ++m) {
      last = b.cost;
      const auto it = std::find(b.cells.begin() + 1, b.cells.end() - 1, to);
      if (it == b.cells.end() - 1) break;
      const size_t at = static_cast<size_t>(it - b.cells.begin());
      to = Cell{to.x + dir.x, to.y + dir.y};
      if (!Allowed(to)) break;
      moved = Tumble(moves_, b.cells, at, to, &context_);
      if (!moved) break;
      cost = Evaluate(*moved);
      if (cost >= b.cost) break;
      b.cells = *std::move(moved);
      b.cost = cost;
    }
  }

  void Reproduce() {
    std::vector<size_t> order(bacteria_.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return bacteria_[a].health < bacteria_[b].health; });
    std::vector<Bacterium> next;
    next.reserve(bacteria_.size());
    const size_t half = (bacteria_.size() + 1) / 2;
    for (size_t i = 0; i < half; ++i) next.push_back(bacteria_[order[i]]);
    for (size_t i = 0; next.size() < bacteria_.size(); ++i) next.push_back(bacteria_[order[i]]);
    bacteria_ = std::move(next);
  }

  const AsBfoParams& p_;
  const Problem& problem_;
  const GridSpace& space_;
  GridMoves moves_;
  Rng rng_;
  GridSearchContext context_;
  std::vector<Cell> reachable_;
  std::vector<uint8_t> in_reach_;
  std::vector<Bacterium> bacteria_;
  std::optional<GridSeeds> seeds_;  // init=seeded
  Bacterium best_;
  int best_iteration_ = 0;
  int64_t evaluations_ = 0;
  bool stopped_ = false;
};

}  // namespace

std::vector<ParamSpec> AsBfoParams::Specs() {
  const AsBfoParams d;
  std::vector<ParamSpec> specs = {
      ParamSpec::Int("population", d.population, 2, 10000, "bacteria", "P, the number of bacteria")
          .PopulationSize(),
      ParamSpec::Int("chemotactic_steps", d.chemotactic_steps, 1, 10000, "steps",
                     "Nc, chemotactic steps per reproduction"),
      ParamSpec::Int("reproduction_steps", d.reproduction_steps, 1, 1000, "steps",
                     "Nre, reproductions per elimination-dispersal"),
      ParamSpec::Int("elimination_steps", d.elimination_steps, 1, 1000, "steps",
                     "Ned, elimination-dispersal events"),
      ParamSpec::Int("swim_length", d.swim_length, 0, 1000, "steps",
                     "Ns, the most swim steps after an improving tumble")
          .Ours(),
      ParamSpec::Double("elimination_probability", d.elimination_probability, 0.0, 1.0, "",
                        "Ped, probability that a bacterium is dispersed")
          .Ours(),
      ParamSpec::Int("max_waypoints", d.max_waypoints, 0, 100, "cells",
                     "random cells (1..max) an initial or dispersed path passes through")
          .Ours(),
      ParamSpec::Bool("keep_worse_tumbles", d.keep_worse_tumbles,
                      "a tumble moves the bacterium even when the path gets longer (classic BFO)")
          .Ours(),
  };
  for (ParamSpec& spec : GridSpaceParamSpecs()) specs.push_back(std::move(spec));
  for (ParamSpec& spec : GridSeedingParams()) specs.push_back(std::move(spec));
  return specs;
}

AsBfoParams AsBfoParams::From(const ParamSet& set) {
  AsBfoParams p;
  p.population = static_cast<int>(set.Int("population"));
  p.chemotactic_steps = static_cast<int>(set.Int("chemotactic_steps"));
  p.reproduction_steps = static_cast<int>(set.Int("reproduction_steps"));
  p.elimination_steps = static_cast<int>(set.Int("elimination_steps"));
  p.swim_length = static_cast<int>(set.Int("swim_length"));
  p.elimination_probability = set.Double("elimination_probability");
  p.max_waypoints = static_cast<int>(set.Int("max_waypoints"));
  p.keep_worse_tumbles = set.Bool("keep_worse_tumbles");
  p.allow_corner_cutting = set.Bool("allow_corner_cutting");
  p.resolution = set.Double("resolution");
  p.seeding = GridSeedingFrom(set);
  return p;
}

absl::StatusOr<SearchResult> RunGridSearch(const AsBfoParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer) {
  AsBfoSearch search(params, problem, space);
  return search.Run(stop, observer);
}

PlannerInfo AsBfoInfo() {
  PlannerInfo info;
  info.id = "as-bfo";
  info.description =
      "A*-based bacterial foraging (AS-BFO) on an 8-connected grid without corner cutting. A "
      "bacterium is a variable-length cell path; chemotaxis tumbles a random interior cell to a "
      "random free neighbour, repairs the gaps with A* and removes loops, and swims in the same "
      "direction while the path gets shorter. Reproduction keeps the half with the lowest "
      "accumulated length; elimination-dispersal redraws paths. One iteration is one chemotactic "
      "step of every bacterium (Nc*Nre*Ned in all). Ours: initial paths through 1-3 random cells "
      "joined by A*, Ns = 4, Ped = 0.25, tumbles kept even when worse (classic BFO), no "
      "cell-to-cell term, shape worlds rasterised at `resolution`. init=seeded (the default): "
      "bacteria start from the seed paths' cells and disperse back to them, health is the "
      "request's objective (the length, or the fleet objective) of the any-angle path, and the "
      "result is never worse than the best seed.";
  info.seed_paper = citations::kAsBfo;
  info.encoding = Encoding::kGridNodes;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  info.params = AsBfoParams::Specs();
  info.factory = [](const ParamSet& set) {
    return std::make_unique<AsBfoPlanner>(AsBfoParams::From(set));
  };
  return info;
}

}  // namespace swarmplan
