// The exact Euclidean distance field, computed when an OccupancyGrid is built.
#include <benchmark/benchmark.h>

#include "bench/micro/fixtures.h"
#include "core/map/occupancy_grid.h"

namespace swarmplan::bench {
namespace {

// Arg: the grid's side in cells; the cells are RandomGridMap's (20% blocked).
void BM_OccupancyGridCreate(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const std::vector<int8_t>& cells = RandomGridMap(size).grid()->cells();
  for (auto _ : state) {
    absl::StatusOr<OccupancyGrid> grid = OccupancyGrid::Create(size, size, cells);
    benchmark::DoNotOptimize(grid);
  }
  state.SetItemsProcessed(state.iterations() * size * size);
}
BENCHMARK(BM_OccupancyGridCreate)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace swarmplan::bench
