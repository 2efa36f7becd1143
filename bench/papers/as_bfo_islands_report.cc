#include "bench/papers/as_bfo_islands_report.h"

#include <algorithm>
#include <functional>
#include <limits>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "bench/papers/as_bfo_islands_paper.h"
#include "bench/papers/as_bfo_islands_world.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// "ours (paper)", or "ours" when the paper has no number.
std::string WithPaper(std::optional<double> ours, std::optional<double> paper,
                      int significant = 4) {
  if (!paper) return NumberCell(ours, significant);
  return absl::StrCat(NumberCell(ours, significant), " (", NumberCell(paper, significant), ")");
}

// A ratio with three decimals (NumberCell would print 0.99999... as "1.0000").
std::string RatioCell(double ratio) { return absl::StrFormat("%.3f", ratio); }

std::string SizeLabel(int n) { return absl::StrCat(n, "×", n); }

}  // namespace

std::string SettingsSection(const ExperimentOptions& options, int table_runs, int sweep_runs,
                            const std::vector<int>& sizes) {
  std::string text;
  absl::StrAppend(&text, "## Settings\n\n");
  MarkdownTable table({"setting", "paper", "ours"}, 3);
  table.AddRow(
      {"worlds",
       "two island environments (their Fig. 5), partitioned at 10×10 … 30×30, equal "
       "obstacle ratio",
       absl::StrCat("two generated island environments (bench/worlds/", kName,
                    "/), partitioned at ", SizeLabel(sizes.front()), " … ", SizeLabel(sizes.back()),
                    ", exactly ", PercentCell(AsBfoEnvironments().front().obstacle_ratio),
                    " blocked at every size")});
  table.AddRow({"start, goal", "opposite corners (S, G in their Fig. 5)",
                "cells (0, 0) and (n−1, n−1): the first and last character of the ASCII file"});
  table.AddRow({"moves", "8 neighbours (their nine-square graph)",
                "8 neighbours, no corner cutting (every planner and A*)"});
  table.AddRow({"AS-BFO", "P = 50, Nc = 5, Nre = 2, Ned = 2 (Ns, Ped not given)",
                "`as-bfo` defaults: P = 50, Nc = 5, Nre = 2, Ned = 2, Ns = 4, Ped = 0.25; "
                "Nc·Nre·Ned = 20 iterations"});
  table.AddRow({"ACO", "tuned on S3, values not published",
                "`aco-grid` defaults: 50 ants, α = 1, β = 7, ρ = 0.3, Q = 1, 100 iterations"});
  table.AddRow({"GA", "tuned on S3, values not published",
                "`ga` defaults: 50 individuals, 100 generations, crossover 0.8, mutation 0.2"});
  table.AddRow(
      {"initial paths",
       "\"randomly generated without infeasible paths\" (section 3.3); variable length (3.1); "
       "how they are drawn is not stated",
       absl::StrCat(
           "AS-BFO and GA (Table 4's main rows, the drawn worlds): start → 1 to ", kWanderingVia,
           " random reachable cells → goal, joined by A*, loops removed (`max_waypoints = ",
           kWanderingVia,
           "`), so they wander like random paths while staying feasible. The experiment's choice, "
           "not `init=paper`'s default: the paper states no construction, ALGORITHMS.md reads it "
           "as 1–",
           kDefaultVia,
           " random cells, and `ga` shares that initialisation, so changing one planner's default "
           "would make the comparison unequal")});
  table.AddRow({"ablation rows", "–",
                absl::StrCat("AS-BFO near-A* and GA near-A*: the planners' default initial paths "
                             "(1–",
                             kDefaultVia,
                             " random cells joined by A*), each leg already optimal, so the "
                             "search has almost nothing left to do")});
  table.AddRow(
      {"runs", "20 per cell",
       absl::StrCat(table_runs, " per cell (Table 4), ", sweep_runs, " per value (sweeps)")});
  table.AddRow({"AIN", "average iteration number",
                "mean over found paths of best_iteration + 1: the iteration (counted from 1; "
                "the initial population is in iteration 1) in which the final best was first "
                "reached"});
  table.AddRow({"seeds", "–",
                absl::StrCat("run i uses seed ", options.seed,
                             " + i, the same for every "
                             "planner and configuration")});
  absl::StrAppend(&text, table.ToString(), "\n");
  if (options.quick) {
    absl::StrAppend(&text, "**Quick mode**: ", kQuickRuns, " runs, ", kQuickIterations,
                    " iterations per planner, only ", SizeLabel(sizes.front()),
                    " and the first value of each sweep. The numbers say nothing about the "
                    "planners.\n\n");
  }
  return text;
}

std::string WorldsSection(const std::vector<std::vector<World>>& worlds) {
  std::string text = "## Worlds\n\n";
  absl::StrAppend(
      &text,
      "Each environment is one set of islands in the unit square, each island a disc with 2–4 "
      "overlapping lobes (",
      absl::StrJoin(AsBfoEnvironments(), "; ",
                    [](std::string* out, const IslandEnvironmentSpec& spec) {
                      absl::StrAppend(out, spec.name, ": ", spec.islands, " islands, main radius ",
                                      spec.min_radius, "–", spec.max_radius);
                    }),
      "), partitioned into n × n cells: the ",
      PercentCell(AsBfoEnvironments().front().obstacle_ratio),
      " of cells whose centres lie deepest inside the islands are blocked, so the obstacle ratio "
      "is equal at every size as in the paper (islands that touch merge, so there are fewer "
      "blobs than drawn islands). The seed is the first from the environment's own that keeps "
      "start and goal connected and blocks the straight diagonal at every size. The paper's own "
      "maps are not published, so the lengths below are not comparable number for number with "
      "its Table 4: compare each method's distance to A*'s optimum and the ranking.\n\n");
  MarkdownTable table({"environment", "size", "file", "blocked", "islands", "A* optimum"}, 3);
  for (const std::vector<World>& environment : worlds) {
    for (const World& w : environment) {
      table.AddRow({w.environment, SizeLabel(w.n), IslandWorldFile(w.environment, w.n),
                    absl::StrCat(w.blocked, " (", PercentCell(w.blocked / double(w.n * w.n)), ")"),
                    absl::StrCat(w.islands), NumberCell(w.optimum)});
    }
  }
  absl::StrAppend(&text, table.ToString(), "\n");
  return text;
}

std::string Table4Section(const std::vector<std::vector<World>>& worlds, const Table4& outcomes) {
  namespace paper = as_bfo_paper;
  std::string text = "## Table 4: AS-BFO vs ACO vs GA\n\n";
  absl::StrAppend(&text,
                  "Cells: ours (paper). Lengths in cells; our worlds differ from the paper's, "
                  "so compare against the A* row and the ranking, not number for number. Run "
                  "times are in section \"Run times\".\n\n");
  for (size_t e = 0; e < worlds.size(); ++e) {
    absl::StrAppend(&text, "### Environment ", e + 1, "\n\n");
    std::vector<std::string> header{"metric", "method"};
    for (const World& w : worlds[e])
      header.push_back(absl::StrCat("S", w.n / 5 - 1, " ", SizeLabel(w.n)));
    MarkdownTable table(header, 2);
    std::vector<std::string> optimum{"A* optimum", "astar"};
    for (const World& w : worlds[e]) optimum.push_back(NumberCell(w.optimum));
    table.AddRow(optimum);
    struct Metric {
      std::string name;
      const paper::Table* paper;
      std::function<std::optional<double>(const Outcome&)> ours;
    };
    const std::vector<Metric> metrics{
        {"AIN", &paper::kAin, [](const Outcome& o) { return Mean(o.ains); }},
        {"MaxPL", &paper::kMaxLength, [](const Outcome& o) { return Max(o.lengths); }},
        {"MinPL", &paper::kMinLength, [](const Outcome& o) { return Min(o.lengths); }},
        {"APL", &paper::kMeanLength, [](const Outcome& o) { return Mean(o.lengths); }},
    };
    for (const Metric& metric : metrics) {
      for (size_t m = 0; m < Methods().size(); ++m) {
        std::vector<std::string> row{metric.name, Methods()[m].label};
        for (size_t s = 0; s < worlds[e].size(); ++s) {
          // The paper's sizes are S1..S5 = 10, 15, ..., 30: index by n.
          const int paper_size = worlds[e][s].n / 5 - 2;
          const int r = Methods()[m].paper_row;
          row.push_back(WithPaper(
              metric.ours(outcomes[e][m][s]),
              r < 0 ? std::nullopt : std::optional<double>((*metric.paper)[e][r][paper_size]),
              metric.name == "AIN" ? 2 : 4));
        }
        table.AddRow(row);
      }
    }
    for (size_t m = 0; m < Methods().size(); ++m) {
      std::vector<std::string> row{"APL / A*", Methods()[m].label};
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        const int paper_size = worlds[e][s].n / 5 - 2;
        const std::optional<double> mean = Mean(outcomes[e][m][s].lengths);
        const int r = Methods()[m].paper_row;
        std::string cell = mean ? RatioCell(*mean / worlds[e][s].optimum) : "–";
        if (r >= 0) {
          absl::StrAppend(
              &cell, " (",
              RatioCell(paper::kMeanLength[e][r][paper_size] / paper::kMinLength[e][0][paper_size]),
              ")");
        }
        row.push_back(cell);
      }
      table.AddRow(row);
    }
    for (size_t m = 0; m < Methods().size(); ++m) {
      std::vector<std::string> row{"final best in iteration 1", Methods()[m].label};
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        const Outcome& o = outcomes[e][m][s];
        const int first = static_cast<int>(std::count(o.ains.begin(), o.ains.end(), 1.0));
        row.push_back(absl::StrCat(first, "/", o.ains.size()));
      }
      table.AddRow(row);
    }
    for (size_t m = 0; m < Methods().size(); ++m) {
      std::vector<std::string> row{"success", Methods()[m].label};
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        row.push_back(PercentCell(outcomes[e][m][s].success()));
      }
      table.AddRow(row);
    }
    absl::StrAppend(&text, table.ToString(), "\n");
  }
  absl::StrAppend(&text,
                  "APL / A*: ours divides by A*'s optimum; the paper's column (in brackets) "
                  "divides by the shortest length any method found on that map (AS-BFO's MinPL), "
                  "since the paper gives no optimum.\n\n");
  return text;
}

// How many worlds each method has the lowest APL (ties count for all).
std::string Table4Summary(const std::vector<std::vector<World>>& worlds, const Table4& outcomes) {
  std::vector<int> wins(Methods().size(), 0);
  std::vector<int> optimal_min(Methods().size(), 0);
  int cells = 0;
  for (size_t e = 0; e < worlds.size(); ++e) {
    for (size_t s = 0; s < worlds[e].size(); ++s) {
      ++cells;
      double best = std::numeric_limits<double>::infinity();
      for (size_t m = 0; m < Methods().size(); ++m) {
        if (auto mean = Mean(outcomes[e][m][s].lengths)) best = std::min(best, *mean);
      }
      for (size_t m = 0; m < Methods().size(); ++m) {
        auto mean = Mean(outcomes[e][m][s].lengths);
        if (mean && *mean <= best + 1e-9) ++wins[m];
        auto min = Min(outcomes[e][m][s].lengths);
        if (min && *min <= worlds[e][s].optimum + 1e-9) ++optimal_min[m];
      }
    }
  }
  std::string text = "Measured summary: lowest APL (ties count for each) in ";
  for (size_t m = 0; m < Methods().size(); ++m) {
    absl::StrAppend(&text, m == 0 ? "" : ", ", Methods()[m].label, " ", wins[m], "/", cells);
  }
  absl::StrAppend(&text, " worlds; MinPL equal to A*'s optimum in ");
  for (size_t m = 0; m < Methods().size(); ++m) {
    absl::StrAppend(&text, m == 0 ? "" : ", ", Methods()[m].label, " ", optimal_min[m], "/", cells);
  }
  absl::StrAppend(&text, " worlds.\n\n");
  return text;
}

std::string SweepSection(const World& world, const std::vector<SweepRow>& rows, int runs) {
  std::string text = "## Section 4.1: parameter sweeps of AS-BFO\n\n";
  absl::StrAppend(&text, "On ", world.environment, " ", SizeLabel(world.n),
                  " (the paper sweeps on S3 = 20×20), A* optimum ", NumberCell(world.optimum), ", ",
                  runs,
                  " runs per value. As in the paper, the other three parameters stay at P = 50, "
                  "Nc = 5, Nre = 2, Ned = 2. Iterations = Nc·Nre·Ned, so the Nc, Nre and Ned "
                  "sweeps also change the budget. Each value runs twice: with near-A* initial "
                  "paths (the planner's default, through 1–",
                  kDefaultVia,
                  " random cells joined by A*) and with wandering ones (through "
                  "up to ",
                  kWanderingVia,
                  " random cells, `max_waypoints`), which leave the operators more to do. Success "
                  "was 100% in every cell unless a row says otherwise.\n\n");
  const std::string w = absl::StrCat(" ≤", kWanderingVia, " via");
  MarkdownTable table({"parameter", "value", "iterations", "success", "AIN", "APL", "optimal runs",
                       "AIN" + w, "APL" + w, "MaxPL" + w, "optimal runs" + w},
                      1);
  for (const SweepRow& row : rows) {
    auto optimal = [&](const Outcome& o) {
      int count = 0;
      for (double l : o.lengths) count += l <= world.optimum + 1e-9 ? 1 : 0;
      return absl::StrCat(count, "/", o.runs);
    };
    auto param = [&](const std::string& name, int fallback) {
      return row.sweep->parameter == name ? row.value : fallback;
    };
    const int iterations = param("chemotactic_steps", 5) * param("reproduction_steps", 2) *
                           param("elimination_steps", 2);
    const Outcome& o = row.outcome;
    const Outcome& v = row.wandering;
    const std::string success =
        o.success() == v.success()
            ? PercentCell(o.success())
            : absl::StrCat(PercentCell(o.success()), " / ", PercentCell(v.success()));
    table.AddRow({absl::StrCat(row.sweep->symbol, " (", row.sweep->parameter, ")"),
                  absl::StrCat(row.value), absl::StrCat(iterations), success,
                  NumberCell(Mean(o.ains), 3), NumberCell(Mean(o.lengths)), optimal(o),
                  NumberCell(Mean(v.ains), 3), NumberCell(Mean(v.lengths)),
                  NumberCell(Max(v.lengths)), optimal(v)});
  }
  absl::StrAppend(&text, table.ToString(), "\n");
  MarkdownTable paper({"parameter", "paper, environment 1", "paper, environment 2"}, 3);
  for (const Sweep& sweep : Sweeps()) {
    paper.AddRow({sweep.symbol, sweep.paper_env1, sweep.paper_env2});
  }
  absl::StrAppend(&text,
                  "The paper gives its sweeps only as plots (Figs. 6–9, path length and "
                  "iteration number per value); what its text says of them:\n\n",
                  paper.ToString(), "\n");
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
