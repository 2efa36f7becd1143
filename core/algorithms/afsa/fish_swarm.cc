#include "core/algorithms/afsa/fish_swarm.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/algorithms/afsa/fish_moves.h"
#include "core/algorithms/citations.h"
#include "core/graph/grid_search.h"
#include "core/grid_ops/cell_path.h"
#include "core/grid_ops/grid_space.h"
#include "core/grid_ops/shortcut.h"
#include "core/random.h"

namespace swarmplan {
namespace {

struct Fish {
  Cell pos;
  std::vector<Cell> trail;
};

// The paper's larger grid side, in cells: with init=seeded, visual and steps scale with the
// grid's longer side over it.
constexpr double kPaperGridSide = 20.0;

class FishSwarmSearch {
 public:
  FishSwarmSearch(const FishSwarmParams& p, const Problem& problem, const GridSpace& space)
      : p_(p),
        problem_(problem),
        space_(space),
        moves_(*space.grid, MoveRules{p.neighbourhood, p.segment_check, problem.clearance}),
        rng_(problem.seed) {
    const OccupancyGrid& g = *space.grid;
    // Any loop-free path is shorter than this: unreached fish rank behind every arrival.
    unreached_offset_ = static_cast<double>(g.width()) * g.height() * g.resolution() * 3.0;
    dist_min_ = std::max(FishDistance(space.start, space.goal), 1e-9);
    if (p.seeding.seeded) scale_ = std::max(1.0, std::max(g.width(), g.height()) / kPaperGridSide);
  }

  absl::StatusOr<SearchResult> Run(const StopToken& stop, Observer& observer) {
    SearchResult result;
    fish_.assign(p_.population, Fish{space_.start, {space_.start}});
    best_fitness_ = Unreached(space_.start);
    if (p_.seeding.seeded) {
      absl::StatusOr<GridSeeds> seeds =
          GridSeeds::Find(problem_, space_, moves_, p_.seeding.seeds, stop, &context_);
      if (absl::IsNotFound(seeds.status())) return result;  // start and goal not connected
      if (!seeds.ok()) return seeds.status();
      seeds_ = *std::move(seeds);
      best_fitness_ = seeds_->best_cost();
      const size_t per_seed =
          (fish_.size() + seeds_->cell_paths().size() - 1) / seeds_->cell_paths().size();
      for (size_t i = 0; i < fish_.size(); ++i) {
        const std::vector<Cell>& seed = seeds_->ForMember(i);
        const size_t rank = i / seeds_->cell_paths().size();
        PlaceOnSeed(fish_[i], seed, (seed.size() - 1) * rank / per_seed);
      }
    }
    ConvergenceLog log(observer);
    int iteration = 0;
    bool done = false;
    for (; iteration < p_.max_generations && !done; ++iteration) {
      if (StopReason why = stop.Check(iteration); why != StopReason::kNone) {
        result.stop_reason = why;
        break;
      }
      double sum = 0.0;
      for (size_t i = 0; i < fish_.size(); ++i) {
        const double f = Swim(i, iteration);
        sum += f;
        if (!p_.feasible_solutions && !seeds_ && !best_cells_.empty()) done = true;
      }
      log.Record(iteration, best_fitness_, sum / fish_.size(), evaluations_,
                 seeds_ || !best_cells_.empty());
      if (done) {
        ++iteration;
        break;
      }
    }
    result.iterations = iteration;
    result.evaluations = evaluations_;
    result.best_iteration = best_iteration_;
    result.convergence = log.Take();
    if (seeds_) {
      if (seeds_->SetResult(best_cells_, stop, result)) result.best_iteration = 0;
      return result;
    }
    SetGridPath(space_, best_cells_, best_fitness_, result);
    if (best_cells_.empty()) result.fitness = best_fitness_;
    return result;
  }

 private:
  // The fish at cell `index` of a seed's cell path, its trail the path up to there.
  static void PlaceOnSeed(Fish& fish, const std::vector<Cell>& seed, size_t index) {
    fish.trail.assign(seed.begin(), seed.begin() + index + 1);
    fish.pos = seed[index];
  }

  // init=seeded: the cell a fish aims at when it swims straight toward `target`, at most `step`
  // cells away; nullopt when that segment is not collision-free or the fish would not move.
  std::optional<Cell> LineOfSightStep(Cell from, Cell target, double step) const {
    Cell aim = target;
    const double d = FishDistance(from, target);
    if (d > step) {
      const double t = step / d;
      aim = Cell{from.x + static_cast<int>(std::lround((target.x - from.x) * t)),
                 from.y + static_cast<int>(std::lround((target.y - from.y) * t))};
    }
    if (aim == from || !moves_.Usable(aim)) return std::nullopt;
    if (!space_.SegmentFree(space_.Centre(from), space_.Centre(aim))) return std::nullopt;
    return aim;
  }

  double Food(Cell c) {
    ++evaluations_;
    return FishDistance(c, space_.goal);
  }
  double Unreached(Cell c) { return unreached_offset_ + Food(c) * space_.grid->resolution(); }

  void Offer(double fitness, int iteration) {
    if (fitness < best_fitness_ - 1e-12) {
      best_fitness_ = fitness;
      best_iteration_ = iteration;
    }
  }

  // One fish's behaviour for this iteration; returns its fitness afterwards.
  double Swim(size_t i, int iteration) {
    Fish& fish = fish_[i];
    const double y = Food(fish.pos);
    const double visual_max = p_.visual * scale_;
    const double step_min = p_.step_min * scale_, step_max = p_.step_max * scale_;
    double visual = visual_max;
    if (p_.dynamic_visual) {
      const double lambda = p_.feedback_gain * std::max(0.0, 1.0 - y / dist_min_);
      visual = visual_max * std::exp(-lambda * iteration / std::max(1, p_.max_generations));
      // Never narrower than the smallest step (ours): a fish always sees where it can swim.
      visual = std::max(visual, step_min);
    }
    double step = std::numeric_limits<double>::infinity();
    if (p_.adaptive_step) step = (visual >= step_max ? 2.0 : 1.0) * step_min;

    std::vector<Cell> allowed;
    for (const Cell& to : moves_.ValidMoves(fish.pos)) {
      if (FishDistance(fish.pos, to) <= step + 1e-9) allowed.push_back(to);
    }
    if (!allowed.empty()) {
      std::optional<Cell> target = SocialTarget(i, y, visual);
      if (!target) target = PreyTarget(fish.pos, y, visual);
      Cell to = allowed[rng_.UniformInt(0, static_cast<int64_t>(allowed.size()) - 1)];
      std::optional<Cell> straight;
      if (target && seeds_) straight = LineOfSightStep(fish.pos, *target, std::min(step, visual));
      if (straight) {
        to = *straight;
      } else if (target && p_.move == FishSwarmParams::Move::kDirection) {
        const double length = std::min(step, LongestMove()) * rng_.Uniform();
        if (std::optional<Cell> c = DirectionMove(fish.pos, *target, length, allowed)) to = *c;
      } else if (target) {
        const double now = FishDistance(fish.pos, *target);
        std::vector<Cell> closer;
        for (const Cell& c : allowed) {
          if (FishDistance(c, *target) < now - 1e-12) closer.push_back(c);
        }
        if (!closer.empty()) to = closer[rng_.UniformInt(0, closer.size() - 1)];
      }
      fish.pos = to;
      fish.trail.push_back(to);
    }
    if (fish.pos == space_.goal) return Arrive(fish, iteration);
    const double f = Unreached(fish.pos);
    if (best_cells_.empty() && !seeds_) Offer(f, iteration);
    return f;
  }

  double Arrive(Fish& fish, int iteration) {
    std::vector<Cell> cells = fish.trail;
    RemoveLoops(cells);
    if (seeds_) return ArriveSeeded(fish, std::move(cells), iteration);
    const double length = space_.PathLength(cells);
    if (p_.feasible_solutions) {
      if (best_cells_.empty() || length < best_fitness_ - 1e-12) best_cells_ = cells;
      Offer(length, iteration);
      fish = Fish{space_.start, {space_.start}};
    } else if (best_cells_.empty()) {
      best_cells_ = cells;  // the first fish to reach the goal ends the search
      Offer(length, iteration);
    }
    return length;
  }

  // init=seeded: the trail is ranked by GridSeeds::Cost against the best arrival, and the fish
  // restarts from a random place on a random seed, in every variant: a fish that starts on a
  // seed first arrives along that seed's own tail, so stopping there would return the seed.
  double ArriveSeeded(Fish& fish, std::vector<Cell> cells, int iteration) {
    const double cost = seeds_->Cost(cells);
    if (best_cells_.empty() || cost < best_arrival_ - 1e-12) {
      best_cells_ = std::move(cells);
      best_arrival_ = cost;
    }
    Offer(cost, iteration);
    const int64_t count = static_cast<int64_t>(seeds_->cell_paths().size());
    const std::vector<Cell>& seed =
        seeds_->ForMember(static_cast<size_t>(rng_.UniformInt(0, count - 1)));
    PlaceOnSeed(fish, seed,
                static_cast<size_t>(rng_.UniformInt(0, static_cast<int64_t>(seed.size()) - 1)));
    return cost;
  }

  // Follow / swarm: the better of the best neighbour and the neighbours' centre, when it beats
  // the fish's own place and the view is not crowded.
  std::optional<Cell> SocialTarget(size_t i, double y, double visual) {
    const Cell me = fish_[i].pos;
    int count = 0;
    double cx = 0.0, cy = 0.0;
    std::optional<Cell> best;
    double best_y = y;
    for (size_t j = 0; j < fish_.size(); ++j) {
      if (j == i || FishDistance(me, fish_[j].pos) > visual) continue;
      ++count;
      cx += fish_[j].pos.x;
      cy += fish_[j].pos.y;
      const double yj = Food(fish_[j].pos);
      if (yj < best_y) {
        best_y = yj;
        best = fish_[j].pos;
      }
    }
    if (count == 0 || static_cast<double>(count) / fish_.size() > p_.crowding) {
      return std::nullopt;
    }
    const Cell centre{static_cast<int>(std::lround(cx / count)),
                      static_cast<int>(std::lround(cy / count))};
    const double yc = Food(centre);
    if (yc < best_y && !(centre == me)) return centre;
    return best;
  }

  // Prey: the first of try_number random usable cells in view that is closer to the goal.
  std::optional<Cell> PreyTarget(Cell me, double y, double visual) {
    const PreySearch search{p_.try_number, visual, p_.prey_culling};
    return swarmplan::PreyTarget(
        me, y, search, [this](Cell c) { return moves_.Usable(c); },
        [this](Cell c) { return Food(c); }, rng_);
  }

  // The step of eqs 3-5 without eqs 10-11: the neighbourhood's longest move.
  double LongestMove() const {
    switch (p_.neighbourhood) {
      case Neighbourhood::k4:
        return 1.0;
      case Neighbourhood::k8:
        return std::sqrt(2.0);
      case Neighbourhood::k24:
        return 2.0 * std::sqrt(2.0);
    }
    return 1.0;
  }

  const FishSwarmParams& p_;
  const Problem& problem_;
  const GridSpace& space_;
  GridMoves moves_;
  Rng rng_;
  GridSearchContext context_;
  std::optional<GridSeeds> seeds_;  // init=seeded
  double scale_ = 1.0;              // of visual and steps
  std::vector<Fish> fish_;
  std::vector<Cell> best_cells_;
  double best_arrival_ = 0.0;  // init=seeded: seeds_->Cost(best_cells_)
  double best_fitness_ = 0.0;
  int best_iteration_ = 0;
  int64_t evaluations_ = 0;
  double unreached_offset_ = 0.0;
  double dist_min_ = 1.0;
};

const char* NeighbourhoodName(Neighbourhood n) {
  switch (n) {
    case Neighbourhood::k4:
      return "4";
    case Neighbourhood::k8:
      return "8";
    case Neighbourhood::k24:
      return "24";
  }
  return "8";
}

PlannerInfo FishInfo(FishSwarmParams::Variant variant, std::string id, std::string description) {
  PlannerInfo info;
  info.id = std::move(id);
  info.description =
      std::move(description) +
      " init=seeded (the default): fish start spread along the seed paths' cells, visual and "
      "steps scale with the grid (paper's values on a 20 x 20 grid), a fish swims straight to a "
      "target in line of sight, every arrival is recorded and the fish restarts on a seed (no "
      "variant stops at the first arrival), trails are ranked by the request's objective (the "
      "length, or the "
      "fleet objective) of their any-angle paths, and the result is never worse than the best "
      "seed.";
  info.seed_paper = citations::kIdafsa;
  info.encoding = Encoding::kGridNodes;
  info.map_kinds = {MapKind::kOccupancyGrid, MapKind::kShapeWorld};
  info.params = FishSwarmParams::Specs(variant);
  info.factory = [](const ParamSet& set) {
    return std::make_unique<FishSwarmPlanner>(FishSwarmParams::From(set));
  };
  return info;
}

}  // namespace

FishSwarmParams FishSwarmParams::Defaults(Variant variant) {
  FishSwarmParams p;
  if (variant != Variant::kAfsa) {
    p.neighbourhood = Neighbourhood::k24;
    p.segment_check = true;
  }
  if (variant == Variant::kIdafsa) {
    p.feasible_solutions = p.dynamic_visual = p.adaptive_step = true;
  }
  p.prey_culling = variant != Variant::kAfsa;
  return p;
}

std::vector<ParamSpec> FishSwarmParams::Specs(Variant variant) {
  const FishSwarmParams d = Defaults(variant);
  std::vector<ParamSpec> specs = {
      ParamSpec::Enum("neighbourhood", NeighbourhoodName(d.neighbourhood), {"4", "8", "24"},
                      "cells a fish may move to: 4, 8 or 24 (16 directions, steps up to 2√2)"),
      ParamSpec::Bool("segment_check", d.segment_check,
                      "a move's segment must touch no blocked cell (the Dijkstra check)"),
      ParamSpec::Bool("feasible_solutions", d.feasible_solutions,
                      "fish reaching the goal record their trail and restart; the answer is the "
                      "shortest record"),
      ParamSpec::Bool("dynamic_visual", d.dynamic_visual, "feedback visual of eq 9"),
      ParamSpec::Bool("adaptive_step", d.adaptive_step, "adaptive step of eqs 10-11"),
      ParamSpec::Enum("move", d.move == Move::kDirection ? "direction" : "random-closer",
                      {"direction", "random-closer"},
                      "how a fish steps toward its target: direction = eqs 3-5, the valid move "
                      "closer to the target that is nearest to X + rand()·step·(X_j − X)/"
                      "||X_j − X|| (our reading of the equations on a grid); random-closer = a "
                      "random valid move closer to the target (before issue 15)"),
      ParamSpec::Bool("prey_culling", d.prey_culling,
                      "the culled factor: prey search draws each cell in view at most once and "
                      "unusable or out-of-view cells do not use one of the try_number tries "
                      "(paper: with the Dijkstra check, so on for dafsa and idafsa)"),
      ParamSpec::Int("population", d.population, 1, 100000, "fish", "N").PopulationSize(),
      ParamSpec::Int("try_number", d.try_number, 1, 10000, "tries", "prey attempts"),
      ParamSpec::Int("max_generations", d.max_generations, 1, 1000000, "iterations", "MAXGEN"),
      ParamSpec::Double("visual", d.visual, 0.0, 1e6, "cells", "visual (visual_max with eq 9)"),
      ParamSpec::Double("crowding", d.crowding, 0.0, 1.0, "", "δ, crowding factor"),
      ParamSpec::Double("step_min", d.step_min, 1.0, 1e6, "cells", "step_min of eq 10"),
      ParamSpec::Double("step_max", d.step_max, 1.0, 1e6, "cells", "step_max of eq 11"),
      ParamSpec::Double("feedback_gain", d.feedback_gain, 0.0, 1e6, "",
                        "m of eq 9 (paper: 17 on 10x10, 10 on 20x20)"),
  };
  for (ParamSpec& spec : GridSpaceParamSpecs(/*with_corner_cutting=*/false)) {
    specs.push_back(std::move(spec));
  }
  for (ParamSpec& spec : GridSeedingParams()) specs.push_back(std::move(spec));
  return specs;
}

FishSwarmParams FishSwarmParams::From(const ParamSet& set) {
  FishSwarmParams p;
  const std::string& n = set.Enum("neighbourhood");
  p.neighbourhood = n == "4"    ? Neighbourhood::k4
                    : n == "24" ? Neighbourhood::k24
                                : Neighbourhood::k8;
  p.segment_check = set.Bool("segment_check");
  p.feasible_solutions = set.Bool("feasible_solutions");
  p.dynamic_visual = set.Bool("dynamic_visual");
  p.adaptive_step = set.Bool("adaptive_step");
  p.move = set.Enum("move") == "random-closer" ? Move::kRandomCloser : Move::kDirection;
  p.prey_culling = set.Bool("prey_culling");
  p.population = static_cast<int>(set.Int("population"));
  p.try_number = static_cast<int>(set.Int("try_number"));
  p.max_generations = static_cast<int>(set.Int("max_generations"));
  p.visual = set.Double("visual");
  p.crowding = set.Double("crowding");
  p.step_min = set.Double("step_min");
  p.step_max = set.Double("step_max");
  p.feedback_gain = set.Double("feedback_gain");
  p.resolution = set.Double("resolution");
  p.seeding = GridSeedingFrom(set);
  return p;
}

absl::StatusOr<SearchResult> RunGridSearch(const FishSwarmParams& params, const Problem& problem,
                                           const GridSpace& space, const StopToken& stop,
                                           Observer& observer) {
  FishSwarmSearch search(params, problem, space);
  return search.Run(stop, observer);
}

PlannerInfo AfsaInfo() {
  return FishInfo(FishSwarmParams::Variant::kAfsa, "afsa",
                  "Traditional artificial fish swarm on a grid (prey, swarm, follow, random) with "
                  "a 4-, 8- or 24-cell neighbourhood; a move needs only a free target cell, so "
                  "paths may cut corners or jump obstacles (then they are reported as not "
                  "collision-free). The search ends when the first fish reaches the goal; its "
                  "trail, loops removed, is the answer. Ours: the fitness streamed before any "
                  "fish arrives is a bound on path lengths plus the best distance to the goal.");
}

PlannerInfo DafsaInfo() {
  return FishInfo(FishSwarmParams::Variant::kDafsa, "dafsa",
                  "Fish swarm with the 16-direction 24-cell neighbourhood whose moves are "
                  "segment-checked (touch no blocked cell, corners included), valid moves shared "
                  "per cell. Otherwise as `afsa`.");
}

PlannerInfo IdafsaInfo() {
  return FishInfo(
      FishSwarmParams::Variant::kIdafsa, "idafsa",
      "Improved fish swarm (IDAFSA-S16): `dafsa` plus a feasible-solution set (every "
      "fish reaching the goal records its trail and restarts; the answer is the "
      "shortest record), dynamic feedback visual visual_max*exp(-λt/T), "
      "λ = m(1 - dist/DistMin) (ours: λ clamped at 0 and the visual at step_min, so a fish "
      "near the goal still sees its neighbours), and adaptive step "
      "(2*step_min while visual >= step_max, else step_min). Runs MAXGEN "
      "iterations.");
}

}  // namespace swarmplan
