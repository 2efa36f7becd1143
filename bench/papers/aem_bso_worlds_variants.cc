#include "bench/papers/aem_bso_worlds_variants.h"

#include <memory>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"
#include "core/map/shape_world.h"

namespace swarmplan::bench::aem_bso {
namespace {

// A variant's spread of lengths "comes close" to the paper's from this fraction of its standard
// deviation on.
constexpr double kCloseSpread = 0.5;
// velocity_fraction of the runs without a velocity bound: ten times the span of the box, more
// than any step can use.
constexpr double kUnboundedVelocity = 10.0;
constexpr double kOurVelocityBound = 0.2;

// Positions may leave the map (up to kOpenWorldMargin beyond it) in a world without a boundary
// there; the search box stays the map.
ParamValues FreePositions() {
  return {{"positions", std::string("far")}, {"box_inset", kOpenWorldMargin}};
}
ParamValues FreePositionsWithoutVelocityBound() {
  ParamValues values = FreePositions();
  values["velocity_fraction"] = kUnboundedVelocity;
  return values;
}

std::string FoundCell(const CellStats& cell) { return absl::StrCat(cell.found(), "/", cell.runs); }

std::string MeanEvaluations(const CellStats& cell) { return NumberCell(Mean(cell.evaluations), 4); }

}  // namespace

const std::vector<BaselineVariant>& BaselineVariants() {
  static const std::vector<BaselineVariant>* const variants = new std::vector<BaselineVariant>{
      {"bso",
       "velocity bound 20 %",
       "no velocity bound",
       {{"velocity_fraction", kUnboundedVelocity}}},
      {"pso",
       "velocity bound 20 %",
       "no velocity bound",
       {{"velocity_fraction", kUnboundedVelocity}}},
      {"ba",
       "no velocity bound",
       "velocity bound 20 %",
       {{"velocity_fraction", kOurVelocityBound}}},
      {"ba",
       "pulse rate set on accept",
       "pulse rate per iteration from 0",
       {{"pulse_schedule", std::string("per-iteration")}}},
      {"aem-bso", "3 waypoints", "6 waypoints", {{"waypoints", int64_t{6}}}},
      {"bso", "positions in the map", "positions free, no boundary", FreePositions(), true},
      {"pso", "positions in the map", "positions free, no boundary", FreePositions(), true},
      {"ba", "positions in the map", "positions free, no boundary", FreePositions(), true},
      {"bso", "velocity bound 20 %, positions in the map", "neither, no boundary",
       FreePositionsWithoutVelocityBound(), true},
      {"pso", "velocity bound 20 %, positions in the map", "neither, no boundary",
       FreePositionsWithoutVelocityBound(), true},
  };
  return *variants;
}

absl::StatusOr<MapPtr> OpenWorld(const Map& map) {
  const ShapeWorld* world = map.world();
  if (world == nullptr) return absl::InvalidArgumentError("OpenWorld: not a shape world");
  const Point2 margin(kOpenWorldMargin, kOpenWorldMargin);
  const Bounds2 bounds{world->bounds().min - margin, world->bounds().max + margin};
  absl::StatusOr<ShapeWorld> open = ShapeWorld::Create(bounds, world->circles(), world->polygons());
  if (!open.ok()) return open.status();
  return std::make_shared<const Map>(Map::Data(*std::move(open)));
}

const std::vector<std::string>& EqualBudgetPlanners() {
  static const std::vector<std::string>* const planners = new std::vector<std::string>{"pso", "ba"};
  return *planners;
}

absl::StatusOr<VariantRuns> RunVariants(const std::string& environment, const MapPtr& map,
                                        const ExperimentOptions& options, int runs,
                                        int iterations) {
  VariantRuns out;
  out.environment = environment;
  absl::StatusOr<MapPtr> open_map = OpenWorld(*map);
  if (!open_map.ok()) return open_map.status();
  for (const BaselineVariant& variant : BaselineVariants()) {
    PlanSpec plan = PaperPlan(variant.planner, "spline", iterations);
    for (const auto& [name, value] : variant.params) plan.params[name] = value;
    absl::StatusOr<CellStats> cell =
        RunCell(plan, variant.open_world ? *open_map : map, options, runs,
                absl::StrCat(environment, " ", variant.planner, " ", variant.changed));
    if (!cell.ok()) return cell.status();
    out.variants.push_back(*std::move(cell));
  }
  for (const std::string& planner : EqualBudgetPlanners()) {
    absl::StatusOr<CellStats> cell =
        RunCell(PaperPlan(planner, "spline", kEqualBudgetFactor * iterations), map, options, runs,
                absl::StrCat(environment, " ", planner, " x", kEqualBudgetFactor, " iterations"));
    if (!cell.ok()) return cell.status();
    out.equal_budget.push_back(*std::move(cell));
  }
  return out;
}

std::string UnstatedSettingsSection(const std::vector<VariantRuns>& runs, const OurCell& ours,
                                    const PaperStdDev& paper_std, std::string* summary) {
  std::string out = "## The baselines' unstated settings\n\n";
  absl::StrAppend(
      &out,
      "The paper gives no velocity bound for BSO and PSO, no parameters for BA and no number "
      "of waypoints. Each row pair runs one planner with the spline as in Table 3, at our setting "
      "and with one "
      "setting changed (`velocity_fraction` = ",
      kUnboundedVelocity,
      ": a bound of ten times the box's span, none in effect; BA's `pulse_schedule`). "
      "*Positions free, no boundary*: `positions=far` lets positions leave the map, and the "
      "runs use the same circles in a world grown by ",
      kOpenWorldMargin,
      " on each side (`box_inset` keeps the search box, which draws the initial population and "
      "bounds the velocities, the paper's 100 x 100); a path that leaves the map is then no "
      "collision. *Fisher*: found, changed against ours; *rank-sum*: the lengths of the found "
      "runs.\n\n");
  MarkdownTable table({"environment", "planner", "setting", "found", "Fisher (found)", "shortest",
                       "median [95 % CI]", "mean", "std", "rank-sum (length)", "paper std"},
                      3);
  std::string differences, spreads;
  int compared = 0, close = 0;
  for (const VariantRuns& environment : runs) {
    const std::string& name = environment.environment;
    for (size_t v = 0; v < BaselineVariants().size(); ++v) {
      const BaselineVariant& variant = BaselineVariants()[v];
      const CellStats& base = ours(name, variant.planner);
      const CellStats& changed = environment.variants[v];
      const std::optional<double> found_p = SuccessP(changed.Found(), base.Found());
      const std::optional<double> length_p = RankSumP(changed.lengths, base.lengths);
      const std::optional<double> paper = paper_std(name, variant.planner);
      for (const bool is_changed : {false, true}) {
        const CellStats& c = is_changed ? changed : base;
        table.AddRow({name, variant.planner, is_changed ? variant.changed : variant.ours,
                      FoundCell(c), is_changed ? PValueCell(found_p) : "",
                      NumberCell(Min(c.lengths)), MedianWithInterval(c.lengths),
                      NumberCell(Mean(c.lengths)), NumberCell(StdDev(c.lengths)),
                      is_changed ? PValueCell(length_p) : "",
                      paper.has_value() ? NumberCell(*paper) : "–"});
      }
      const std::string label = absl::StrCat(name, " ", variant.planner, " with ", variant.changed);
      AppendListItem(&differences, SuccessDifference(label, base.Found(), changed.Found(), found_p),
                     "; ");
      AppendListItem(&differences,
                     ValueDifference(label, "length", base.lengths, changed.lengths, length_p),
                     "; ");
      AppendListItem(&spreads,
                     absl::StrCat(label, " std ", NumberCell(StdDev(changed.lengths)), " (",
                                  variant.ours, " ", NumberCell(StdDev(base.lengths)), ", paper ",
                                  paper.has_value() ? NumberCell(*paper) : "–", ")"),
                     "; ");
      if (paper.has_value() && *paper > 0) {
        ++compared;
        if (StdDev(changed.lengths).value_or(0.0) >= kCloseSpread * *paper) ++close;
      }
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  const char* verdict = close == 0 ? "so none of these settings explains the paper's spread"
                        : close < compared
                            ? "so these settings explain part of the paper's spread at most"
                            : "so these settings come close to the paper's spread";
  absl::StrAppend(
      summary,
      "differences that the tests support (p < 0.05): ", differences.empty() ? "none" : differences,
      ". The lengths' standard deviations: ", spreads,
      absl::StrFormat(": in %d of %d cases the changed setting's standard deviation reaches half "
                      "the paper's, ",
                      close, compared),
      verdict);
  return out;
}

std::string WaypointCountSentence(const std::vector<VariantRuns>& runs, const OurCell& ours) {
  std::string out;
  for (const VariantRuns& environment : runs) {
    for (size_t v = 0; v < BaselineVariants().size(); ++v) {
      const BaselineVariant& variant = BaselineVariants()[v];
      if (variant.params.count("waypoints") == 0) continue;
      const CellStats& base = ours(environment.environment, variant.planner);
      const CellStats& changed = environment.variants[v];
      AppendListItem(
          &out,
          absl::StrCat(environment.environment, ": ", variant.planner, " with ", variant.changed,
                       " found ", FoundCell(changed), " (", variant.ours, ": ", FoundCell(base),
                       ", Fisher ", PValueCell(SuccessP(changed.Found(), base.Found())),
                       "), median length ", MedianWithInterval(changed.lengths), " against ",
                       MedianWithInterval(base.lengths), " (rank-sum ",
                       PValueCell(RankSumP(changed.lengths, base.lengths)), ")"),
          "; ");
    }
  }
  return out;
}

std::string EqualBudgetSection(const std::vector<VariantRuns>& runs, const OurCell& ours,
                               int iterations, std::string* summary) {
  std::string out = "## Equal evaluation budgets\n\n";
  absl::StrAppend(
      &out,
      absl::StrFormat(
          "A beetle evaluates its new position and both antennae, so aem-bso's %d iterations "
          "cost about %d times the evaluations of PSO's and BA's (the paper compares them at "
          "equal iterations). Here pso and ba also run %d iterations, with the spline as in "
          "Table 3. *evaluations*: mean fitness evaluations per run. *Fisher* and *rank-sum*: "
          "against aem-bso.\n\n",
          iterations, kEqualBudgetFactor, kEqualBudgetFactor * iterations));
  MarkdownTable table({"environment", "planner", "iterations", "evaluations", "found",
                       "Fisher (found)", "median [95 % CI]", "mean", "rank-sum (length)"},
                      2);
  std::string differences;
  for (const VariantRuns& environment : runs) {
    const std::string& name = environment.environment;
    const CellStats& reference = ours(name, "aem-bso");
    table.AddRow({name, "aem-bso", absl::StrCat(iterations), MeanEvaluations(reference),
                  FoundCell(reference), "", MedianWithInterval(reference.lengths),
                  NumberCell(Mean(reference.lengths)), ""});
    for (size_t i = 0; i < EqualBudgetPlanners().size(); ++i) {
      const std::string& planner = EqualBudgetPlanners()[i];
      for (const bool equal : {false, true}) {
        const CellStats& c = equal ? environment.equal_budget[i] : ours(name, planner);
        const std::optional<double> found_p = SuccessP(c.Found(), reference.Found());
        const std::optional<double> length_p = RankSumP(c.lengths, reference.lengths);
        table.AddRow({name, planner, absl::StrCat((equal ? kEqualBudgetFactor : 1) * iterations),
                      MeanEvaluations(c), FoundCell(c), PValueCell(found_p),
                      MedianWithInterval(c.lengths), NumberCell(Mean(c.lengths)),
                      PValueCell(length_p)});
        if (!equal) continue;
        const std::string label = absl::StrCat(name, " ", planner, " at equal evaluations");
        std::string found = SuccessDifference(label, reference.Found(), c.Found(), found_p);
        std::string length =
            ValueDifference(label, "length", reference.lengths, c.lengths, length_p);
        if (found.empty() && length.empty()) {
          found = absl::StrCat(label, ": no significant difference");
        }
        AppendListItem(&differences, found, "; ");
        AppendListItem(&differences, length, "; ");
      }
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  absl::StrAppend(summary, differences);
  return out;
}

}  // namespace swarmplan::bench::aem_bso
