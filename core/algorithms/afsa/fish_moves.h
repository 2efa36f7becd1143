#pragma once

// The fish's two grid moves of the fish swarm paper (seed 003) that take a random draw: the step
// toward a chosen cell (eqs 3-5) and the prey search for that cell (with its culled factor).

#include <functional>
#include <optional>
#include <vector>

#include "core/map/point.h"
#include "core/random.h"

namespace swarmplan {

// The Euclidean distance between two cells, in cells: the fish's food and step measure.
double FishDistance(Cell a, Cell b);

// Where eqs 3-5 put a fish at `from` that swims toward `target`:
// from + length * (target - from) / ||target - from||, in cell coordinates.
struct FishAim {
  double x = 0.0;
  double y = 0.0;
};
FishAim DirectionAim(Cell from, Cell target, double length);

// The move of eqs 3-5 on a grid (our reading): among the `moves` from `from` that bring the fish
// closer to `target` (the paper's Fig. 9; the others are eliminated), the one nearest to
// DirectionAim(from, target, length), the first of them on a tie. nullopt when no move gets
// closer.
std::optional<Cell> DirectionMove(Cell from, Cell target, double length,
                                  const std::vector<Cell>& moves);

// The prey behaviour's search for X_j: up to `try_number` cells drawn uniformly from the square
// of half-side floor(visual) around `me`; the first that is in view (within `visual`), usable and
// has food below `food_here` is returned. Without culling every draw is a try, repeats and
// unusable cells included (the traditional AFSA). With culling (the paper's culled factor) a
// drawn cell is never drawn again, and a cell that cannot be a target (out of view, unusable, the
// fish's own) is removed without using a try.
struct PreySearch {
  int try_number = 8;
  double visual = 5.0;
  bool culling = false;
};
std::optional<Cell> PreyTarget(Cell me, double food_here, const PreySearch& search,
                               const std::function<bool(Cell)>& usable,
                               const std::function<double(Cell)>& food, Rng& rng);

}  // namespace swarmplan
