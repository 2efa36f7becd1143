#pragma once

// The pieces of the AS-BFO islands reproduction (as_bfo_islands.cc): what it runs and the sections
// of its report (as_bfo_islands_report.cc).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bench/papers/experiment.h"
#include "core/map/map.h"
#include "core/params.h"

namespace swarmplan::bench::as_bfo_islands {

inline constexpr char kName[] = "as-bfo-islands";
inline constexpr int kQuickRuns = 2;
inline constexpr int kQuickIterations = 10;
// A world of the experiment, loaded from its shipped file, with A*'s optimum.
struct World {
  std::string environment;
  int n = 0;
  MapPtr map;
  Cell start;
  Cell goal;
  double optimum = 0.0;
  int64_t blocked = 0;
  int islands = 0;
};

// The runs of one planner configuration on one world.
struct Outcome {
  int runs = 0;
  std::vector<double> lengths;  // found paths only
  std::vector<double> ains;     // best_iteration + 1, found paths only
  std::vector<double> millis;   // every run
  std::vector<double> evaluations;

  double success() const { return runs == 0 ? 0.0 : static_cast<double>(lengths.size()) / runs; }
};

// Initial paths through up to this many random cells (the planners' max_waypoints, at most 100):
// Table 4's main rows, closer to the paper's random initial paths than our default of 3.
inline constexpr int kWanderingVia = 100;
// The planners' default: initial paths through 1 to this many random cells.
inline constexpr int kDefaultVia = 3;

struct Method {
  std::string label;
  std::string algorithm;
  ParamValues params;
  int paper_row = -1;  // row of as_bfo_paper's tables; -1: an ablation row, not the paper's
};

// The rows of Table 4: the paper's three methods (AS-BFO and GA with wandering initial paths),
// then the ablation: AS-BFO and GA with near-A* initial paths (through 1 to kDefaultVia cells).
const std::vector<Method>& Methods();

struct Sweep {
  std::string parameter;  // registered name
  std::string symbol;     // the paper's
  std::vector<int> values;
  std::string paper_env1;  // the paper's findings (Figs. 6-9), environment 1
  std::string paper_env2;
  // The values the paper's text names best in environment 2 (the sweep world's); 0: none named.
  int paper_shortest_env2 = 0;
  int paper_fewest_env2 = 0;
};

// The sweeps of the paper's section 4.1, with what its text says of them.
const std::vector<Sweep>& Sweeps();

struct SweepRow {
  const Sweep* sweep;
  int value;
  Outcome outcome;    // default initial paths (through 1-3 random cells)
  Outcome wandering;  // initial paths through up to kWanderingVia random cells
};

// outcomes[environment][method][size].
using Table4 = std::vector<std::vector<std::vector<Outcome>>>;

std::string SettingsSection(const ExperimentOptions& options, int table_runs, int sweep_runs,
                            const std::vector<int>& sizes);
std::string WorldsSection(const std::vector<std::vector<World>>& worlds);
std::string Table4Section(const std::vector<std::vector<World>>& worlds, const Table4& outcomes);
// How many worlds each method has the lowest APL (ties count for all) and reaches the optimum.
std::string Table4Summary(const std::vector<std::vector<World>>& worlds, const Table4& outcomes);
std::string SweepSection(const World& world, const std::vector<SweepRow>& rows, int runs);

}  // namespace swarmplan::bench::as_bfo_islands
