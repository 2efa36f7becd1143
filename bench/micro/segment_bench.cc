// CollisionChecker::SegmentFree, the check every sampling and swarm planner calls most.
#include <benchmark/benchmark.h>

#include "bench/micro/fixtures.h"
#include "core/geometry/collision.h"

namespace swarmplan::bench {
namespace {

constexpr int kSegments = 1024;

// Arg: the clearance in tenths of a world unit (0 takes the exact cell traversal on grids).
void RunSegmentFree(benchmark::State& state, const Map& map, double lo, double hi) {
  const double clearance = static_cast<double>(state.range(0)) / 10.0;
  const std::unique_ptr<const CollisionChecker> checker = MakeCollisionChecker(map);
  const std::vector<std::pair<Point3, Point3>> segments =
      RandomSegments(*checker, lo, hi, kSegments, 2);
  size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b] = segments[i++ % segments.size()];
    benchmark::DoNotOptimize(checker->SegmentFree(a, b, clearance));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SegmentFreeGrid512(benchmark::State& state) {
  RunSegmentFree(state, RandomGridMap(512), 0.0, 512.0);
}
BENCHMARK(BM_SegmentFreeGrid512)->Arg(0)->Arg(5);

void BM_SegmentFreeShapeWorld(benchmark::State& state) {
  RunSegmentFree(state, RandomShapeWorldMap(), 0.0, 100.0);
}
BENCHMARK(BM_SegmentFreeShapeWorld)->Arg(0)->Arg(5);

}  // namespace
}  // namespace swarmplan::bench
