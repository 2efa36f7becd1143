// Exact grid search (A* and Dijkstra) on a 512 × 512 random grid, with a reused context.
#include <benchmark/benchmark.h>

#include "bench/micro/fixtures.h"
#include "core/graph/grid_search.h"

namespace swarmplan::bench {
namespace {

void RunGridSearch(benchmark::State& state, bool use_heuristic) {
  const OccupancyGrid& grid = *RandomGridMap(512).grid();
  const std::vector<std::pair<Cell, Cell>> pairs = RandomFreeCellPairs(grid, 64, 3);
  GridSearchOptions options;
  options.use_heuristic = use_heuristic;
  GridSearchContext context;
  size_t i = 0;
  int64_t expanded = 0;
  for (auto _ : state) {
    const auto& [from, to] = pairs[i++ % pairs.size()];
    GridSearchResult result = SearchGrid(grid, from, to, options, &context);
    expanded += result.expanded;
    benchmark::DoNotOptimize(result);
  }
  state.counters["expanded/search"] =
      benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kAvgIterations);
}

void BM_AStarGrid512(benchmark::State& state) { RunGridSearch(state, true); }
BENCHMARK(BM_AStarGrid512)->Unit(benchmark::kMillisecond);

void BM_DijkstraGrid512(benchmark::State& state) { RunGridSearch(state, false); }
BENCHMARK(BM_DijkstraGrid512)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace swarmplan::bench
