#include <algorithm>
#include <cmath>

#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/citations.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/grid_moves.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/grid_ops/grid_space.h"
#include "core/grid_ops/roulette.h"
#include "core/grid_ops/shortcut.h"
#include "core/random.h"

namespace swarmplan {
namespace {

class GridAcoSearch {
 public:
  GridAcoSearch(const GridAcoParams& p, const Problem& problem, const GridSpace& space)
      : p_(p),
        problem_(problem),
        space_(space),
        moves_(*space.grid,
               MoveRules{Neighbourhood::k8, !p.allow_corner_cutting, problem.clearance}),
        rng_(problem.seed) {
    const OccupancyGrid& g = *space.grid;
    cell_count_ = static_cast<size_t>(g.width()) * g.height();
    tau_.assign(cell_count_ * 8, p.tau0);
    visited_.assign(cell_count_, 0);
    unreached_ = static_cast<double>(cell_count_) * g.resolution() * 3.0;
  }

  absl::StatusOr<SearchResult> Run(const StopToken& stop, Observer& observer) {
    SearchResult result;
    best_cost_ = unreached_;
    double q = p_.q;
    if (p_.seeding.seeded) {
      absl::StatusOr<GridSeeds> seeds =
          GridSeeds::Find(problem_, space_, moves_, p_.seeding.seeds, stop, &context_);
      if (absl::IsNotFound(seeds.status())) return result;  // start and goal not connected
      if (!seeds.ok()) return seeds.status();
      seeds_ = *std::move(seeds);
      q *= seeds_->best_cost();
      for (const std::vector<Cell>& cells : seeds_->cell_paths()) {
        const double cost = seeds_->Cost(cells);
        Deposit(cells, q / cost);
        if (cost < best_cost_ - 1e-12) {
          best_cost_ = cost;
          best_cells_ = cells;
        }
      }
    }
    ConvergenceLog log(observer);
    int iteration = 0;
    std::vector<std::pair<std::vector<int>, double>> arrivals;  // move indices, cost
    for (; iteration < p_.iterations; ++iteration) {
      if (StopReason why = stop.Check(iteration); why != StopReason::kNone) {
        result.stop_reason = why;
        break;
      }
      arrivals.clear();
      double sum = 0.0;
      for (int a = 0; a < p_.ants; ++a) {
        std::vector<Cell> cells;
        std::vector<int> edges;
        ++evaluations_;
        if (Walk(cells, edges)) {
          const double cost = seeds_ ? seeds_->Cost(cells) : space_.PathLength(cells);
          sum += cost;
          arrivals.push_back({std::move(edges), cost});
          if (cost < best_cost_ - 1e-12) {
            best_cost_ = cost;
            best_cells_ = cells;
            result.best_iteration = iteration;
          }
        } else {
          sum += unreached_;
        }
      }
      for (double& t : tau_) t *= 1.0 - p_.rho;
      for (const auto& [edges, cost] : arrivals) {
        for (int e : edges) tau_[e] += q / cost;
      }
      log.Record(iteration, seeds_ ? seeds_->Incumbent(best_cost_) : best_cost_,
                 sum / std::max(1, p_.ants), evaluations_, !best_cells_.empty());
    }
    result.iterations = iteration;
    result.evaluations = evaluations_;
    result.convergence = log.Take();
    if (!seeds_) {
      SetGridPath(space_, best_cells_, best_cost_, result);
    } else if (seeds_->SetResult(best_cells_, stop, result)) {
      result.best_iteration = 0;
    }
    return result;
  }

 private:
  // Adds `amount` to the pheromone of every move of a cell path (moves between neighbours).
  void Deposit(const std::vector<Cell>& cells, double amount) {
    const std::vector<Cell>& offsets = MoveOffsets(Neighbourhood::k8);
    for (size_t i = 1; i < cells.size(); ++i) {
      const Cell d{cells[i].x - cells[i - 1].x, cells[i].y - cells[i - 1].y};
      const auto it = std::find(offsets.begin(), offsets.end(), d);
      if (it == offsets.end()) continue;
      tau_[Index(cells[i - 1]) * 8 + static_cast<size_t>(it - offsets.begin())] += amount;
    }
  }

  size_t Index(Cell c) const { return static_cast<size_t>(c.y) * space_.grid->width() + c.x; }

  // One ant from start; false when it gets stuck.
  bool Walk(std::vector<Cell>& cells, std::vector<int>& edges) {
    ++stamp_;
    Cell at = space_.start;
    cells.push_back(at);
    visited_[Index(at)] = stamp_;
    const std::vector<Cell>& offsets = MoveOffsets(Neighbourhood::k8);
    std::vector<double> weights(8);
    for (size_t step = 0; step < cell_count_; ++step) {
      if (at == space_.goal) return true;
      bool any = false;
      for (int d = 0; d < 8; ++d) {
        const Cell to{at.x + offsets[d].x, at.y + offsets[d].y};
        weights[d] = 0.0;
        if (!space_.grid->InBounds(to) || visited_[Index(to)] == stamp_ || !moves_.IsMove(at, to)) {
          continue;
        }
        const double dist = std::hypot(to.x - space_.goal.x, to.y - space_.goal.y);
        const double eta = 1.0 / std::max(dist, 1e-3);
        weights[d] = std::pow(tau_[Index(at) * 8 + d], p_.alpha) * std::pow(eta, p_.beta);
        any = true;
      }
      if (!any) return false;
      const int d = RouletteSelect(weights, rng_);
      edges.push_back(static_cast<int>(Index(at) * 8 + d));
      at = Cell{at.x + offsets[d].x, at.y + offsets[d].y};
      visited_[Index(at)] = stamp_;
      cells.push_back(at);
    }
    return at == space_.goal;
  }

  const GridAcoParams& p_;
  const Problem& problem_;
  const GridSpace& space_;
  GridMoves moves_;
  Rng rng_;
  GridSearchContext context_;
  std::optional<GridSeeds> seeds_;  // init=seeded
  size_t cell_count_ = 0;
  std::vector<double> tau_;
  std::vector<uint32_t> visited_;
  uint32_t stamp_ = 0;
  double unreached_ = 0.0;
  double best_cost_ = 0.0;
  std::vector<Cell> best_cells_;
  int64_t evaluations_ = 0;
};

}  // namespace

std::vector<ParamSpec> GridAcoParams::Specs() {
  const GridAcoParams d;
  std::vector<ParamSpec> specs = {
      ParamSpec::Int("ants", d.ants, 1, 100000, "ants", "ants per iteration").PopulationSize(),
      ParamSpec::Double("alpha", d.alpha, 0.0, 20.0, "", "pheromone exponent α"),
      ParamSpec::Double("beta", d.beta, 0.0, 20.0, "", "heuristic exponent β"),
      ParamSpec::Double("rho", d.rho, 0.0, 1.0, "", "evaporation ρ"),
      ParamSpec::Double("q", d.q, 0.0, 1e9, "", "deposit Q"),
      ParamSpec::Int("iterations", d.iterations, 1, 1000000, "iterations", "iterations").Ours(),
      ParamSpec::Double("tau0", d.tau0, 1e-9, 1e9, "", "initial pheromone").Ours(),
  };
  for (ParamSpec& spec : GridSpaceParamSpecs()) specs.push_back(std::move(spec));
  for (ParamSpec& spec : GridSeedingParams()) specs.push_back(std::move(spec));
  return specs;
}

GridAcoParams GridAcoParams::From(const ParamSet& set) {
  GridAcoParams p;
  p.ants = static_cast<int>(set.Int("ants"));
  p.alpha = set.Double("alpha");
  p.beta = set.Double("beta");
  p.rho = set.Double("rho");
  p.q = set.Double("q");
  p.iterations = static_cast<int>(set.Int("iterations"));
  p.tau0 = set.Double("tau0");
  p.allow_corner_cutting = set.Bool("allow_corner_cutting");
  p.resolution = set.Double("resolution");
  p.seeding = GridSeedingFrom(set);
  return p;
}

absl::StatusOr<SearchResult> RunGridSearch(const GridAcoParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer) {
  GridAcoSearch search(params, problem, space);
  return search.Run(stop, observer);
}

PlannerInfo GridAcoInfo() {
  PlannerInfo info;
  info.id = "aco-grid";
  info.seed_paper = citations::kAntColony;
  info.description =
      "Ant colony on the 8-connected grid (the AS-BFO paper's baseline): ants walk from the "
      "start without revisiting cells, choosing moves with probability ∝ τ^α η^β, η = 1/distance "
      "to the goal; stuck ants die; τ ← (1−ρ)τ plus Q/length on every arriving ant's moves. "
      "α = 1, β = 7, ρ = 0.3, Q = 1, 50 ants. Ours: pheromone on directed moves, τ0 = 1, 100 "
      "iterations; before any ant arrives the streamed fitness is a bound on path lengths. "
      "init=seeded (the default): the seed paths' cells are iteration 0's arrivals, Q is "
      "scaled by the best seed's objective, paths are ranked by the request's objective (the "
      "length, or the fleet objective) of their any-angle paths, never worse than the best "
      "seed.";
  info.encoding = Encoding::kGridNodes;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  info.params = GridAcoParams::Specs();
  info.factory = [](const ParamSet& set) {
    return std::make_unique<GridAcoPlanner>(GridAcoParams::From(set));
  };
  return info;
}

}  // namespace swarmplan
