#include "core/algorithms/afsa/fish_moves.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace swarmplan {
namespace {

// Draws the indices 0 .. count - 1 in random order, each once (Fisher-Yates on a sparse array:
// only the swapped entries are stored, so a large view costs nothing until it is drawn).
class DrawWithoutReplacement {
 public:
  explicit DrawWithoutReplacement(int64_t count) : remaining_(count) {}

  std::optional<int64_t> Next(Rng& rng) {
    if (remaining_ == 0) return std::nullopt;
    const int64_t k = rng.UniformInt(0, remaining_ - 1);
    const int64_t last = --remaining_;
    const int64_t drawn = At(k);
    swapped_[k] = At(last);
    return drawn;
  }

 private:
  int64_t At(int64_t i) const {
    const auto it = swapped_.find(i);
    return it == swapped_.end() ? i : it->second;
  }

  int64_t remaining_;
  std::unordered_map<int64_t, int64_t> swapped_;
};

}  // namespace

double FishDistance(Cell a, Cell b) { return std::hypot(a.x - b.x, a.y - b.y); }

FishAim DirectionAim(Cell from, Cell target, double length) {
  const double d = FishDistance(from, target);
  if (d == 0.0) return {static_cast<double>(from.x), static_cast<double>(from.y)};
  return {from.x + length * (target.x - from.x) / d, from.y + length * (target.y - from.y) / d};
}

std::optional<Cell> DirectionMove(Cell from, Cell target, double length,
                                  const std::vector<Cell>& moves) {
  const FishAim aim = DirectionAim(from, target, length);
  const double now = FishDistance(from, target);
  std::optional<Cell> best;
  double best_d2 = 0.0;
  for (const Cell& c : moves) {
    if (FishDistance(c, target) >= now - 1e-12) continue;
    const double d2 = (c.x - aim.x) * (c.x - aim.x) + (c.y - aim.y) * (c.y - aim.y);
    if (!best || d2 < best_d2 - 1e-12) {
      best = c;
      best_d2 = d2;
    }
  }
  return best;
}

std::optional<Cell> PreyTarget(Cell me, double food_here, const PreySearch& search,
                               const std::function<bool(Cell)>& usable,
                               const std::function<double(Cell)>& food, Rng& rng) {
  const int reach = static_cast<int>(std::floor(search.visual));
  if (reach < 1) return std::nullopt;
  const auto better = [&](Cell c) { return food(c) < food_here; };
  if (!search.culling) {
    for (int t = 0; t < search.try_number; ++t) {
      const Cell c{me.x + static_cast<int>(rng.UniformInt(-reach, reach)),
                   me.y + static_cast<int>(rng.UniformInt(-reach, reach))};
      if (FishDistance(me, c) > search.visual || !usable(c)) continue;
      if (better(c)) return c;
    }
    return std::nullopt;
  }
  const int64_t side = 2 * static_cast<int64_t>(reach) + 1;
  DrawWithoutReplacement draw(side * side);
  for (int tries = 0; tries < search.try_number;) {
    const std::optional<int64_t> index = draw.Next(rng);
    if (!index) break;
    const Cell c{me.x + static_cast<int>(*index % side) - reach,
                 me.y + static_cast<int>(*index / side) - reach};
    if (c == me || FishDistance(me, c) > search.visual || !usable(c)) continue;
    ++tries;
    if (better(c)) return c;
  }
  return std::nullopt;
}

}  // namespace swarmplan
