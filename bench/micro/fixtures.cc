#include "bench/micro/fixtures.h"

#include <cstdlib>
#include <map>
#include <memory>

#include "core/map/generate.h"
#include "core/random.h"

namespace swarmplan::bench {

std::string MovingAiDir() {
  const char* dir = std::getenv("SWARMPLAN_MOVINGAI_DIR");
  return dir != nullptr ? dir : "../shared/benchmarks/movingai";
}

const Map& RandomGridMap(int size) {
  static auto* const maps = new std::map<int, std::unique_ptr<const Map>>();
  std::unique_ptr<const Map>& map = (*maps)[size];
  if (map == nullptr) {
    map = std::make_unique<const Map>(ValueOrDie(RandomGrid(size, size, 0.2, 1)));
  }
  return *map;
}

const Map& RandomShapeWorldMap() {
  static const Map* const map = new Map(ValueOrDie(RandomShapeWorld(RandomWorldOptions{}, 1)));
  return *map;
}

std::vector<std::pair<Point3, Point3>> RandomSegments(const CollisionChecker& checker, double lo,
                                                      double hi, int count, uint64_t seed) {
  Rng rng(seed);
  auto free_point = [&] {
    while (true) {
      const Point3 p(rng.Uniform(lo, hi), rng.Uniform(lo, hi), 0.0);
      if (checker.PointFree(p, 0.0)) return p;
    }
  };
  std::vector<std::pair<Point3, Point3>> segments;
  for (int i = 0; i < count; ++i) segments.emplace_back(free_point(), free_point());
  return segments;
}

std::vector<std::pair<Cell, Cell>> RandomFreeCellPairs(const OccupancyGrid& grid, int count,
                                                       uint64_t seed) {
  Rng rng(seed);
  auto free_cell = [&] {
    while (true) {
      const Cell c{static_cast<int>(rng.UniformInt(0, grid.width() - 1)),
                   static_cast<int>(rng.UniformInt(0, grid.height() - 1))};
      if (grid.IsFree(c)) return c;
    }
  };
  std::vector<std::pair<Cell, Cell>> pairs;
  for (int i = 0; i < count; ++i) pairs.emplace_back(free_cell(), free_cell());
  return pairs;
}

}  // namespace swarmplan::bench
