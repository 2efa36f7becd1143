#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmplan::bench {

// One run of one planner on one problem: a row of the CSV. Optional fields are written empty.
struct RunRecord {
  std::string map;       // the map file's name
  std::string scenario;  // index of the scenario in its .scen file, or the start and goal
  std::string planner;
  uint64_t seed = 0;
  bool success = false;  // a path was found and it is collision-free
  std::optional<double> length;
  std::optional<double> optimal;       // the exact optimum (core/optimum.h)
  std::optional<double> ratio;         // length / optimal
  std::optional<double> scen_optimal;  // the .scen file's 8-connected length
  std::optional<double> min_clearance;
  std::optional<double> max_curvature;
  int iterations = 0;
  int64_t evaluations = 0;
  double wall_seconds = 0.0;
  // The planner's objective: its final best, its best after the initial population (for a
  // seeded planner, about its best seed's), and the iteration that reached the final best.
  std::optional<double> fitness;
  std::optional<double> initial_fitness;
  int best_iteration = 0;
  // On 2D maps, the fleet objective's total for the final path and for the best seed after the
  // same smoothing (PlanResult::objective, seed_objective).
  std::optional<double> objective;
  std::optional<double> seed_objective;
  // The seed's objective beyond its length (its clearance, curvature and violation terms): what
  // a search can gain on it. 0 when the seed is already the best path by the objective.
  std::optional<double> seed_penalty;
  // With --alternatives: the collision-free alternatives returned, and how many of the paths
  // (the result and those) lie pairwise in distinct corridors (SeparatedByObstacle).
  std::optional<int> alternatives;
  std::optional<int> distinct_corridors;
  // Seconds from the start of the plan (seed paths included) to the first iteration whose best
  // is feasible and, by the planner's fitness, within 1.05 and 1.02 of the optimum (the fitness
  // is the raw path's length only for feasible paths without preference terms).
  std::optional<double> seconds_to_1_05;
  std::optional<double> seconds_to_1_02;
  // Each iteration's best so far, at its seconds from the plan's start.
  struct Progress {
    double seconds = 0.0;
    double best_fitness = 0.0;
    bool feasible = false;
  };
  std::vector<Progress> convergence;
};

// The convergence CSV (--convergence-csv): one row per iteration of each run.
std::string ConvergenceCsvHeader();
std::string ConvergenceCsvRows(const RunRecord& record);

// length / optimal for a successful run with a known optimum; 1 when both are zero (start ==
// goal), nullopt otherwise.
std::optional<double> LengthRatio(bool success, std::optional<double> length,
                                  std::optional<double> optimal);

// A number as the reports print it: up to 9 significant digits, "inf", "-inf" or "nan".
std::string FormatNumber(double value);

// One CSV field per RFC 4180: quoted when it holds a comma, quote, CR or LF (quotes doubled).
std::string CsvField(const std::string& text);

// The header line and one line per record, each ending in "\n".
std::string CsvHeader();
std::string CsvRow(const RunRecord& record);

// The runs of one planner on one map.
struct SummaryRow {
  std::string planner;
  std::string map;
  int runs = 0;
  int successes = 0;
  std::optional<double> median_ratio;  // over successful runs with a known optimum
  std::optional<double> worst_ratio;
  std::optional<double> median_length;   // over successful runs
  std::optional<double> median_seconds;  // over all runs
};

// One row per (planner, map) pair, in the order the pairs first appear in the records.
std::vector<SummaryRow> Summarize(const std::vector<RunRecord>& records);

// A Markdown table of the summary rows (an empty string when there are none).
std::string MarkdownSummary(const std::vector<SummaryRow>& rows);

}  // namespace swarmplan::bench
