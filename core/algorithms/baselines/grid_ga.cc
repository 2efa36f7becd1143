#include <algorithm>

#include "absl/container/flat_hash_map.h"
#include "core/algorithms/baselines/grid_baselines.h"
#include "core/algorithms/citations.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/grid_seeding.h"
#include "core/grid_ops/grid_space.h"
#include "core/grid_ops/roulette.h"
#include "core/grid_ops/shortcut.h"
#include "core/random.h"

namespace swarmplan {
namespace {

struct Individual {
  std::vector<Cell> cells;
  double cost = 0.0;  // the cell path length, or with init=seeded GridSeeds::Cost
};

class GridGaSearch {
 public:
  GridGaSearch(const GridGaParams& p, const Problem& problem, const GridSpace& space)
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
    if (!in_reach_[Index(space_.goal)]) return result;

    if (p_.seeding.seeded) {
      absl::StatusOr<GridSeeds> seeds =
          GridSeeds::Find(problem_, space_, moves_, p_.seeding.seeds, stop, &context_);
      if (!seeds.ok()) return seeds.status();
      seeds_ = *std::move(seeds);
    }
    std::vector<Individual> pop(p_.population);
    for (size_t i = 0; i < pop.size(); ++i) {
      Individual& ind = pop[i];
      if (seeds_) {
        ind.cells = seeds_->ForMember(i);
        if (i >= seeds_->cell_paths().size()) Mutate(ind.cells);
      } else {
        ind.cells = *RandomFeasiblePath(moves_, space_.start, space_.goal, reachable_,
                                        p_.max_waypoints, rng_, &context_);
      }
      Evaluate(ind, 0);
    }
    ConvergenceLog log(observer);
    int generation = 0;
    for (; generation < p_.generations; ++generation) {
      if (StopReason why = stop.Check(generation); why != StopReason::kNone) {
        result.stop_reason = why;
        break;
      }
      std::vector<double> weights;
      for (const Individual& ind : pop) weights.push_back(1.0 / std::max(ind.cost, 1e-12));
      std::vector<Individual> next{best_};  // elitism
      while (static_cast<int>(next.size()) < p_.population) {
        Individual a = pop[RouletteSelect(weights, rng_)];
        Individual b = pop[RouletteSelect(weights, rng_)];
        if (rng_.Bernoulli(p_.crossover_probability)) Crossover(a.cells, b.cells);
        for (Individual* child : {&a, &b}) {
          if (rng_.Bernoulli(p_.mutation_probability)) Mutate(child->cells);
          Evaluate(*child, generation);
          if (static_cast<int>(next.size()) < p_.population) next.push_back(*child);
        }
      }
      pop = std::move(next);
      double sum = 0.0;
      for (const Individual& ind : pop) sum += ind.cost;
      log.Record(generation, seeds_ ? seeds_->Incumbent(best_.cost) : best_.cost, sum / pop.size(),
                 evaluations_, true);
    }
    result.iterations = generation;
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

  void Evaluate(Individual& ind, int generation) {
    ++evaluations_;
    ind.cost = seeds_ ? seeds_->Cost(ind.cells) : space_.PathLength(ind.cells);
    if (best_.cells.empty() || ind.cost < best_.cost - 1e-12) {
      best_ = ind;
      best_iteration_ = generation;
    }
  }

  // One-point crossover at a cell both paths share (not an end).
  void Crossover(std::vector<Cell>& a, std::vector<Cell>& b) {
    absl::flat_hash_map<int64_t, size_t> in_b;
    for (size_t j = 1; j + 1 < b.size(); ++j) in_b[CellKey(b[j])] = j;
    std::vector<std::pair<size_t, size_t>> shared;
    for (size_t i = 1; i + 1 < a.size(); ++i) {
      if (auto it = in_b.find(CellKey(a[i])); it != in_b.end()) shared.push_back({i, it->second});
    }
    if (shared.empty()) return;
    const auto [i, j] = shared[rng_.UniformInt(0, static_cast<int64_t>(shared.size()) - 1)];
    std::vector<Cell> c1(a.begin(), a.begin() + i + 1), c2(b.begin(), b.begin() + j + 1);
    c1.insert(c1.end(), b.begin() + j + 1, b.end());
    c2.insert(c2.end(), a.begin() + i + 1, a.end());
    RemoveLoops(c1);
    RemoveLoops(c2);
    a = std::move(c1);
    b = std::move(c2);
  }

  // Re-routes a random sub-path through a random reachable cell near its middle.
  void Mutate(std::vector<Cell>& cells) {
    if (cells.size() < 2) return;
    const int64_t n = static_cast<int64_t>(cells.size());
    const int64_t i = rng_.UniformInt(0, n - 2);
    const int64_t j = rng_.UniformInt(i + 1, n - 1);
    const Cell mid = cells[(i + j) / 2];
    const int r = p_.mutation_radius;
    const Cell via{mid.x + static_cast<int>(rng_.UniformInt(-r, r)),
                   mid.y + static_cast<int>(rng_.UniformInt(-r, r))};
    if (!space_.grid->InBounds(via) || !in_reach_[Index(via)]) return;
    std::optional<std::vector<Cell>> detour =
        JoinWithAStar(moves_, {cells[i], via, cells[j]}, &context_);
    if (!detour) return;
    std::vector<Cell> out(cells.begin(), cells.begin() + i);
    out.insert(out.end(), detour->begin(), detour->end());
    out.insert(out.end(), cells.begin() + j + 1, cells.end());
    RemoveLoops(out);
    cells = std::move(out);
  }

  const GridGaParams& p_;
  const Problem& problem_;
  const GridSpace& space_;
  GridMoves moves_;
  Rng rng_;
  GridSearchContext context_;
  std::vector<Cell> reachable_;
  std::vector<uint8_t> in_reach_;
  std::optional<GridSeeds> seeds_;  // init=seeded
  Individual best_;
  int best_iteration_ = 0;
  int64_t evaluations_ = 0;
};

}  // namespace

std::vector<ParamSpec> GridGaParams::Specs() {
  const GridGaParams d;
  std::vector<ParamSpec> specs = {
      ParamSpec::Int("population", d.population, 2, 100000, "individuals", "population size")
          .PopulationSize()
          .Ours(),
      ParamSpec::Int("generations", d.generations, 1, 1000000, "iterations", "generations").Ours(),
      ParamSpec::Double("crossover_probability", d.crossover_probability, 0.0, 1.0, "",
                        "probability that a pair crosses over")
          .Ours(),
      ParamSpec::Double("mutation_probability", d.mutation_probability, 0.0, 1.0, "",
                        "probability that a child is mutated")
          .Ours(),
      ParamSpec::Int("mutation_radius", d.mutation_radius, 1, 1000, "cells",
                     "how far from the sub-path a mutation's detour cell may lie")
          .Ours(),
      ParamSpec::Int("max_waypoints", d.max_waypoints, 0, 100, "cells",
                     "random cells (1..max) an initial path passes through")
          .Ours(),
  };
  for (ParamSpec& spec : GridSpaceParamSpecs()) specs.push_back(std::move(spec));
  for (ParamSpec& spec : GridSeedingParams()) specs.push_back(std::move(spec));
  return specs;
}

GridGaParams GridGaParams::From(const ParamSet& set) {
  GridGaParams p;
  p.population = static_cast<int>(set.Int("population"));
  p.generations = static_cast<int>(set.Int("generations"));
  p.crossover_probability = set.Double("crossover_probability");
  p.mutation_probability = set.Double("mutation_probability");
  p.mutation_radius = static_cast<int>(set.Int("mutation_radius"));
  p.max_waypoints = static_cast<int>(set.Int("max_waypoints"));
  p.allow_corner_cutting = set.Bool("allow_corner_cutting");
  p.resolution = set.Double("resolution");
  p.seeding = GridSeedingFrom(set);
  return p;
}

absl::StatusOr<SearchResult> RunGridSearch(const GridGaParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer) {
  GridGaSearch search(params, problem, space);
  return search.Run(stop, observer);
}

PlannerInfo GridGaInfo() {
  PlannerInfo info;
  info.id = "ga";
  info.seed_paper = citations::kGeneticAlgorithm;
  info.description =
      "Genetic algorithm on 8-connected grid paths (the AS-BFO and binary PSO papers' "
      "baseline): initial paths through 1-3 random cells joined by A*, roulette selection on "
      "1/length, crossover at a shared cell, mutation re-routing a random sub-path through a "
      "nearby random cell with A*, loops removed, the best kept. Every parameter is ours: the "
      "papers do not publish theirs. init=seeded (the default): the initial paths are the seed "
      "paths' cells, ranked by the request's objective (the length, or the fleet objective) of "
      "their any-angle paths, never worse than the best seed.";
  info.encoding = Encoding::kGridNodes;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  info.params = GridGaParams::Specs();
  info.factory = [](const ParamSet& set) {
    return std::make_unique<GridGaPlanner>(GridGaParams::From(set));
  };
  return info;
}

}  // namespace swarmplan
