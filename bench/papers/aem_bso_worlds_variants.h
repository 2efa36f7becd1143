#pragma once

// The settings of the AEM-BSO paper's baselines that it does not state (velocity bounds, BA's
// pulse rate schedule), and its planners at equal evaluation budgets: runs against our
// settings, with the rank-sum and Fisher tests. Positions that leave the map are among them:
// their runs use a world without a boundary near the map.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "bench/papers/aem_bso_worlds_runs.h"
#include "bench/papers/experiment.h"
#include "core/map/map.h"

namespace swarmplan::bench::aem_bso {

// A baseline with one setting the paper leaves open changed from ours.
struct BaselineVariant {
  std::string planner;  // bso, pso or ba, with the spline as in Table 3
  std::string ours;     // our setting, e.g. "velocity bound 20 %"
  std::string changed;  // the variant's, e.g. "no velocity bound"
  ParamValues params;   // what the variant sets on top of PaperPlan
  // Runs on OpenWorld: the paper's worlds have no boundary.
  bool open_world = false;
};
const std::vector<BaselineVariant>& BaselineVariants();

// How far OpenWorld grows the map beyond each edge: as far as positions=far lets positions go
// from the search box, the paper's 100 x 100 region.
inline constexpr double kOpenWorldMargin = 1000.0;
// The map with the same obstacles and its bounds grown by kOpenWorldMargin on each side; the
// variants that run on it search the original rectangle (`box_inset`).
absl::StatusOr<MapPtr> OpenWorld(const Map& map);

// The planners that make one evaluation per member and iteration, run with this many times
// aem-bso's iterations (a beetle evaluates itself and both antennae).
inline constexpr int kEqualBudgetFactor = 3;
const std::vector<std::string>& EqualBudgetPlanners();

// What one environment's variant and equal-budget runs gave, in the orders above.
struct VariantRuns {
  std::string environment;
  std::vector<CellStats> variants;
  std::vector<CellStats> equal_budget;
};

absl::StatusOr<VariantRuns> RunVariants(const std::string& environment, const MapPtr& map,
                                        const ExperimentOptions& options, int runs, int iterations);

// The cell of `planner` with the spline at our settings in `environment`.
using OurCell =
    std::function<const CellStats&(const std::string& environment, const std::string& planner)>;
// The paper's Table 3 standard deviation of `planner`'s lengths in `environment`.
using PaperStdDev = std::function<std::optional<double>(const std::string& environment,
                                                        const std::string& planner)>;

// "## The baselines' unstated settings": each variant against ours; `summary` gets one
// sentence for the discussion (does any variant's spread of lengths approach the paper's?).
std::string UnstatedSettingsSection(const std::vector<VariantRuns>& runs, const OurCell& ours,
                                    const PaperStdDev& paper_std, std::string* summary);

// The waypoint-count variants against ours, per environment, for the discussion.
std::string WaypointCountSentence(const std::vector<VariantRuns>& runs, const OurCell& ours);

// "## Equal evaluation budgets": pso and ba at kEqualBudgetFactor times the iterations against
// aem-bso; `summary` gets one sentence for the discussion.
std::string EqualBudgetSection(const std::vector<VariantRuns>& runs, const OurCell& ours,
                               int iterations, std::string* summary);

}  // namespace swarmplan::bench::aem_bso
