#include "bench/scenario_selection.h"

namespace swarmplan::bench {
namespace {

// `count` indices spread evenly over [begin, end): the middle of each of `count` equal parts.
void SpreadEvenly(size_t begin, size_t end, size_t count, std::vector<size_t>& out) {
  const size_t n = end - begin;
  if (count >= n) {
    for (size_t i = begin; i < end; ++i) out.push_back(i);
    return;
  }
  for (size_t k = 0; k < count; ++k) out.push_back(begin + (2 * k + 1) * n / (2 * count));
}

}  // namespace

std::vector<size_t> SelectScenarios(const std::vector<Scenario>& scenarios,
                                    const ScenarioSelection& selection) {
  std::vector<size_t> out;
  const size_t count = selection.count > 0 ? static_cast<size_t>(selection.count) : 0;
  switch (selection.mode) {
    case ScenarioSelection::Mode::kAll:
      SpreadEvenly(0, scenarios.size(), scenarios.size(), out);
      break;
    case ScenarioSelection::Mode::kEvenly:
      SpreadEvenly(0, scenarios.size(), count, out);
      break;
    case ScenarioSelection::Mode::kPerBucket:
      for (size_t begin = 0; begin < scenarios.size();) {
        size_t end = begin;
        while (end < scenarios.size() && scenarios[end].bucket == scenarios[begin].bucket) ++end;
        SpreadEvenly(begin, end, count, out);
        begin = end;
      }
      break;
  }
  return out;
}

}  // namespace swarmplan::bench
