// AEM-BSO paper (seed 002), Table 1: the five optimisers on the ten test functions.

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "bench/papers/aem_bso_test_functions.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"
#include "core/algorithms/bso/swarm_options.h"
#include "core/planner.h"
#include "core/random.h"
#include "core/registry.h"
#include "core/stop_token.h"

namespace swarmplan::bench {
namespace {

constexpr int kDefaultRuns = 30;
// D = 60 as well costs about twice the time of D = 30 again; on the shared 2-core machine that
// does not fit the ~10 minute budget of a full run, so the default is D = 30 only. Add 60 here
// to run it: the paper's D = 60 column is below.
const std::vector<int> kFullDimensions = {30};

struct Algorithm {
  const char* planner_id;
  const char* paper_name;
};

// Table 1's column order.
constexpr std::array<Algorithm, 5> kAlgorithms = {{{"aem-bso", "AEM-BSO"},
                                                   {"aem-bso-linear", "AEM-BSO2"},
                                                   {"bso", "BSO"},
                                                   {"pso", "PSO"},
                                                   {"ba", "BA"}}};

// One function's row pair of Table 1 at one dimension, in kAlgorithms' order.
struct PaperRow {
  std::array<double, 5> best;
  std::array<double, 5> mean;
};

// Table 1, D = 30 (100 runs, population 100, 1000 iterations), f1..f10.
constexpr std::array<PaperRow, 10> kPaperD30 = {{
    {{2.68e-174, 4.91e-159, 6.76e-2, 3.15e0, 3.44e0},
     {1.98e-154, 1.99e-143, 4.82e0, 3.09e1, 5.03e0}},
    {{0, 0, 4.00e1, 5.20e1, 4.00e0}, {2.00e-2, 2.50e-1, 1.48e2, 1.94e2, 6.94e0}},
    {{2.91e-5, 1.07e-2, 9.54e1, 3.65e2, 5.22e2}, {1.29e-1, 3.66e-1, 5.97e2, 3.96e3, 1.57e3}},
    {{4.23e-170, 4.69e-157, 2.79e1, 1.36e2, 9.15e0},
     {2.00e-154, 2.32e-143, 1.67e2, 3.60e2, 1.54e1}},
    {{1.26e-179, 1.69e-166, 2.43e-3, 5.01e-2, 3.61e0},
     {3.52e-157, 1.88e-148, 7.29e-2, 4.30e-1, 1.60e2}},
    {{1.26e-163, 2.67e-156, 6.03e4, 1.20e5, 5.47e5},
     {7.38e-149, 2.48e-139, 2.74e5, 7.58e5, 2.57e6}},
    {{1.69e1, 3.08e1, 2.11e1, 2.23e1, 2.02e2}, {5.12e1, 6.12e1, 5.38e1, 5.26e1, 2.50e2}},
    {{0, 2.08e-1, 2.89e-1, 8.60e-1, 2.03e-1}, {1.77e-3, 2.66e-1, 9.35e-1, 1.27e0, 2.68e-1}},
    {{-4.44e-16, -4.44e-16, 2.53e0, 3.11e0, 3.01e0}, {2.58e-15, 2.58e-15, 5.66e0, 5.48e0, 5.19e0}},
    {{0, 0, 1.74e1, 2.70e1, 2.81e1}, {0, 1.10e-1, 4.03e1, 6.25e1, 3.39e1}},
}};

// Table 1, D = 60.
constexpr std::array<PaperRow, 10> kPaperD60 = {{
    {{1.94e-171, 9.95e-163, 2.00e2, 3.71e2, 1.53e1},
     {2.45e-156, 1.32e-145, 4.81e2, 8.32e2, 2.23e1}},
    {{0, 0, 6.20e2, 7.61e2, 2.30e1}, {0, 0, 1.11e3, 1.40e3, 3.30e1}},
    {{4.76e1, 4.81e1, 8.22e3, 3.92e4, 3.27e3}, {4.94e1, 4.96e1, 1.01e5, 2.09e5, 6.15e3}},
    {{2.08e-170, 1.81e-163, 6.01e2, 1.25e3, 2.19e2},
     {1.91e-152, 5.90e-142, 1.70e3, 2.57e3, 3.73e2}},
    {{1.52e-173, 1.52e-163, 1.84e0, 4.33e0, 1.98e1},
     {7.34e-132, 6.93e-127, 5.90e0, 9.55e0, 6.38e16}},
    {{1.98e-164, 1.01e-152, 1.07e6, 1.63e6, 4.30e6},
     {1.96e-149, 1.60e-140, 3.30e6, 6.68e6, 8.82e6}},
    {{3.48e1, 4.78e1, 1.13e2, 1.30e2, 5.35e2}, {1.08e2, 1.12e2, 1.68e2, 1.97e2, 6.39e2}},
    {{0, 0, 2.84e0, 3.63e0, 4.62e-1}, {1.75e-3, 2.44e-3, 5.19e0, 8.13e0, 5.60e-1}},
    {{-4.44e-16, -4.44e-16, 5.88e0, 6.03e0, 3.91e0}, {2.43e-15, 2.72e-15, 7.44e0, 7.54e0, 8.29e0}},
    {{0, 0, 1.81e2, 3.59e2, 9.06e1}, {0, 0, 4.57e2, 7.10e2, 1.08e2}},
}};

// Functions of the origin-bias check: optimum moved off the origin.
constexpr std::array<int, 3> kShiftedFunctions = {0, 6, 8};  // f1, f7, f9
constexpr double kShiftFraction = 0.2;  // shift_j = +-0.2 * upper, alternating in sign
constexpr int kShiftedRuns = 10;        // at most; a side check, kept cheap

struct Settings {
  std::vector<int> dims;
  int runs = kDefaultRuns;
  int iterations = 1000;
  int population = 100;
};

// Results of one algorithm on one function: the best value of every run.
struct Cell {
  std::vector<double> best_values;
  double seconds = 0.0;
};

std::string Sci(std::optional<double> value) {
  if (!value) return "–";
  return absl::StrFormat("%.3g", *value);
}

std::string PaperCell(double value) { return absl::StrCat("(", Sci(value), ")"); }

// The optimisers with each registered planner's default parameters, population overridden.
absl::StatusOr<std::vector<SwarmOptimiser>> MakeOptimisers(int population) {
  std::vector<SwarmOptimiser> optimisers;
  for (const Algorithm& algorithm : kAlgorithms) {
    absl::StatusOr<const PlannerInfo*> info = DefaultRegistry().Get(algorithm.planner_id);
    if (!info.ok()) return info.status();
    absl::StatusOr<ParamSet> params = ParamSet::Resolve(
        (*info)->params, ParamValues{{"population", static_cast<int64_t>(population)}});
    if (!params.ok()) return params.status();
    absl::StatusOr<SwarmOptimiser> optimiser = SwarmOptimiserFor(algorithm.planner_id, *params);
    if (!optimiser.ok()) return optimiser.status();
    optimisers.push_back(*std::move(optimiser));
  }
  return optimisers;
}

Eigen::VectorXd ShiftFor(const TestFunction& function, int dim) {
  Eigen::VectorXd shift(dim);
  for (int j = 0; j < dim; ++j) {
    shift[j] = (j % 2 == 0 ? 1.0 : -1.0) * kShiftFraction * function.upper;
  }
  return shift;
}

// Runs `optimiser` `settings.runs` times on the function (shifted when asked); run r uses seed
// `seed + r`. Every result is checked.
absl::StatusOr<Cell> RunCell(const SwarmOptimiser& optimiser, const TestFunction& function, int dim,
                             bool shifted, const Settings& settings, uint64_t seed) {
  Cell cell;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < settings.runs; ++r) {
    TestFunctionObjective objective =
        shifted ? TestFunctionObjective(function, dim, ShiftFor(function, dim))
                : TestFunctionObjective(function, dim);
    Rng rng(seed + static_cast<uint64_t>(r));
    NullObserver observer;
    const SearchOutcome outcome =
        optimiser(objective, settings.iterations, rng, StopToken(), observer);
    if (outcome.iterations != settings.iterations) {
      return absl::InternalError(absl::StrCat(function.id, ": ran ", outcome.iterations,
                                              " iterations instead of ", settings.iterations));
    }
    if (absl::Status status =
            CheckOptimiserResult(function, objective, outcome.best_x, outcome.best_fitness);
        !status.ok()) {
      return status;
    }
    cell.best_values.push_back(outcome.best_fitness);
  }
  cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return cell;
}

std::string ResultsTable(const std::vector<TestFunction>& functions,
                         const std::vector<std::vector<Cell>>& cells,
                         const std::array<PaperRow, 10>* paper) {
  std::vector<std::string> header = {"function", "statistic"};
  for (const Algorithm& algorithm : kAlgorithms) {
    header.push_back(algorithm.paper_name);
    if (paper) header.push_back("paper");
  }
  MarkdownTable table(header, 2);
  for (size_t f = 0; f < functions.size(); ++f) {
    const std::string label = absl::StrCat(functions[f].id, " ", functions[f].name);
    for (const char* statistic : {"best", "mean", "std"}) {
      std::vector<std::string> row = {std::string(statistic) == "best" ? label : "", statistic};
      for (size_t a = 0; a < kAlgorithms.size(); ++a) {
        const std::vector<double>& values = cells[f][a].best_values;
        const std::string s = statistic;
        row.push_back(Sci(s == "best" ? Min(values) : s == "mean" ? Mean(values) : StdDev(values)));
        if (paper) {
          row.push_back(s == "best"   ? PaperCell((*paper)[f].best[a])
                        : s == "mean" ? PaperCell((*paper)[f].mean[a])
                                      : "");
        }
      }
      table.AddRow(std::move(row));
    }
  }
  return table.ToString();
}

std::string TimeTable(const std::vector<std::pair<int, std::vector<std::vector<Cell>>>>& results,
                      int runs) {
  std::vector<std::string> header = {"D"};
  for (const Algorithm& algorithm : kAlgorithms) header.push_back(algorithm.paper_name);
  MarkdownTable table(header);
  for (const auto& [dim, cells] : results) {
    std::vector<std::string> row = {absl::StrCat(dim)};
    for (size_t a = 0; a < kAlgorithms.size(); ++a) {
      double seconds = 0.0;
      for (const auto& function_cells : cells) seconds += function_cells[a].seconds;
      row.push_back(NumberCell(1000.0 * seconds / (runs * static_cast<double>(cells.size())), 3));
    }
    table.AddRow(std::move(row));
  }
  return table.ToString();
}

std::string FunctionsTable() {
  MarkdownTable table({"id", "function", "kind", "range", "minimum", "at", "our reading"}, 7);
  for (const TestFunction& function : AemBsoTestFunctions()) {
    table.AddRow({function.id, function.name, function.unimodal ? "unimodal" : "multimodal",
                  absl::StrCat("[", function.lower, ", ", function.upper, "]"),
                  absl::StrCat(function.minimum),
                  absl::StrCat("(", function.minimiser_coordinate, ", ..., ",
                               function.minimiser_coordinate, ")"),
                  function.note.empty() ? "as printed" : function.note});
  }
  return table.ToString();
}

std::string ParameterLine(const std::string& planner_id) {
  const PlannerInfo* info = DefaultRegistry().Find(planner_id);
  if (!info) return "";
  std::vector<std::string> parts;
  for (const ParamSpec& spec : info->params) {
    static const std::vector<std::string> kOptimiserParams = {"inertia",
                                                              "w_max",
                                                              "w_min",
                                                              "c1",
                                                              "c2",
                                                              "c3",
                                                              "step_fraction",
                                                              "step_decay",
                                                              "velocity_fraction",
                                                              "k1",
                                                              "k2",
                                                              "k3",
                                                              "f_min",
                                                              "f_max",
                                                              "loudness0",
                                                              "pulse_rate0",
                                                              "alpha",
                                                              "gamma",
                                                              "walk_fraction"};
    if (std::find(kOptimiserParams.begin(), kOptimiserParams.end(), spec.name) ==
        kOptimiserParams.end()) {
      continue;
    }
    parts.push_back(absl::StrCat(spec.name, " = ", FormatParamValue(spec.default_value),
                                 spec.ours ? " (ours)" : ""));
  }
  std::string line = absl::StrCat("- `", planner_id, "`: ");
  for (size_t i = 0; i < parts.size(); ++i) absl::StrAppend(&line, i ? ", " : "", parts[i]);
  return line;
}

// Mean of the final best values of algorithm `a` in `cells`.
double CellMean(const std::vector<Cell>& cells, size_t a) {
  return Mean(cells[a].best_values).value_or(0.0);
}

std::string IdList(const std::vector<std::string>& ids) {
  return ids.empty() ? std::string("none") : absl::StrJoin(ids, ", ");
}

// The discussion's measured statements, from the D = 30 table and the shifted check.
std::string MeasuredFindings(const std::vector<TestFunction>& functions,
                             const std::vector<std::vector<Cell>>& cells,
                             const std::vector<TestFunction>& shifted_functions,
                             const std::vector<std::vector<Cell>>& shifted_cells) {
  std::vector<std::string> aem_best, aem_collapsed, bso_pso_beat_paper;
  for (size_t f = 0; f < functions.size(); ++f) {
    bool best = true;
    for (size_t a = 1; a < kAlgorithms.size(); ++a) {
      if (CellMean(cells[f], a) < CellMean(cells[f], 0)) best = false;
    }
    if (best) aem_best.push_back(functions[f].id);
    if (CellMean(cells[f], 0) < 1e-100) aem_collapsed.push_back(functions[f].id);
    if (CellMean(cells[f], 2) < kPaperD30[f].mean[2] &&
        CellMean(cells[f], 3) < kPaperD30[f].mean[3]) {
      bso_pso_beat_paper.push_back(functions[f].id);
    }
  }
  std::string text;
  absl::StrAppend(&text, "- D = 30: AEM-BSO has the lowest mean of the five on ", aem_best.size(),
                  " of 10 functions (", IdList(aem_best),
                  "; the paper: all 10). Its mean is below 1e-100 on ", IdList(aem_collapsed),
                  ".\n");
  absl::StrAppend(&text, "- Our BSO and PSO both have a lower mean than the paper's on ",
                  IdList(bso_pso_beat_paper), ".\n");
  absl::StrAppend(&text, "- f3 Rosenbrock (minimum at (1, ..., 1), not the origin): mean AEM-BSO ",
                  Sci(CellMean(cells[2], 0)), ", BSO ", Sci(CellMean(cells[2], 2)), ", PSO ",
                  Sci(CellMean(cells[2], 3)), " (paper: ", Sci(kPaperD30[2].mean[0]), ", ",
                  Sci(kPaperD30[2].mean[2]), ", ", Sci(kPaperD30[2].mean[3]), ").\n");
  absl::StrAppend(&text, "- BA on f9 Ackley: mean ", Sci(CellMean(cells[8], 4)), " (paper ",
                  Sci(kPaperD30[8].mean[4]), ").\n");
  for (size_t f = 0; f < shifted_functions.size(); ++f) {
    absl::StrAppend(&text, "- Shifted ", shifted_functions[f].id, ": mean AEM-BSO ",
                    Sci(CellMean(shifted_cells[f], 0)), ", BSO ",
                    Sci(CellMean(shifted_cells[f], 2)), ", PSO ",
                    Sci(CellMean(shifted_cells[f], 3)), ".\n");
  }
  return text;
}

constexpr char kDiscussion[] = R"(
**Where ours agree.** The paper's headline is reproduced: on the functions whose minimum is
the origin, AEM-BSO and AEM-BSO2 end at or within rounding of the optimum (the functions
listed above with a mean below 1e-100), many orders of magnitude below BSO, PSO and BA, as in
the paper's Table 1. Ackley's best value -4.44e-16 is the same rounding artefact as the
paper's (20 + e - 20 - e in floating point).

**Why: the elite mutation pulls towards the origin.** Eq 9 multiplies the whole Gbest vector by
1 +- (G1 + G2 + mu). With the minus sign (half of the iterations) the factor lies in
(-G1 - G2, 1 - G1 - G2], so Gbest is shrunk towards 0 by a random factor and the shrunk point
is kept whenever it is better, which it always is for a function with its minimum at 0
(Sphere, Quadric, Elliptic, Schwefel 2.22 are monotone in |x_i|). A few hundred such
contractions over 1000 iterations give the paper's 1e-150..1e-180, and in our runs often
exactly 0 (the product underflows) or subnormal numbers. That is not search ability: in the
shifted check, where the same functions have their minimum away from the origin, AEM-BSO's
advantage over BSO shrinks to the ordinary differences between swarm variants (the "Shifted"
lines above). Rosenbrock (f3), the one function with its minimum at (1, ..., 1), is where the
paper's own AEM-BSO is weakest, and where ours, like every swarm here, stays far from the
optimum (the f3 line above). The paper's conclusion that AEM-BSO "jumps out of local optima" on
f7-f10 should be read with this in mind: Rastrigin, Griewank, Ackley and Bohachevsky also
have their global minimum at the origin.

**Where ours differ, and why.**
- *How close AEM-BSO gets*: the paper gives no k1, k2, k3 (ALGORITHMS.md: choose them); ours
  are k1 = k2 = 0.1, k3 = -1. With them G1 + G2 is between 0 and about 0.2, so every
  minus-sign mutation contracts. Where f7 Rastrigin is in the below-1e-100 list above, ours
  collapse onto its global minimum while the paper's AEM-BSO ends at 17-51 on average: the
  paper's mutation is evidently weaker there (other k1, k2, k3, or fewer accepted
  contractions), which the text does not let us recover.
- *Rosenbrock*: the paper's AEM-BSO reaches 0.129 on average at D = 30 (but 49 at D = 60);
  ours stalls in the curved valley like the other swarms. The text gives nothing (no
  mutation constants, no step sizes) that would tell us what makes the difference.
- *BSO and PSO are much better than the paper's* on most functions. The paper gives no
  velocity clamp, no antennae step size and no step decay; ours clamp the velocity to 20% of
  the span and start the antennae step at 5% of the span decaying by 0.99 per iteration
  (ALGORITHMS.md). Unclamped velocities with w = 0.9 make a swarm oscillate over the whole
  box for much of the run, which fits the paper's BSO/PSO numbers of order 1-1e5 on
  Sphere-like functions. Our `pso` also uses c1 = c2 = 2 (ALGORITHMS.md's PSO baseline)
  where the paper's Table 1 used 1.49.
- *BA*: its frequency range, initial loudness, pulse rate and local-walk scale are ours
  (the paper gives only that it is Yang's BA). Our local walk is 1% of the span times the
  mean loudness, which decays by alpha = 0.9 per accepted move, so BA freezes early; where
  the BA line above shows about 20 on Ackley it has stayed on the flat outer plateau, where
  the paper's BA reaches 3-5.
- *Runs*: 30 per cell here against the paper's 100, so our best values are minima over fewer
  runs; the paper does not say how its runs were seeded.
- *D = 60* is not in the default run (time budget); the paper's D = 60 column is kept in the
  code for a run that enables it.
)";

}  // namespace

absl::StatusOr<std::string> RunAemBsoFunctions(const ExperimentOptions& options) {
  Settings settings;
  if (options.quick) {
    settings = {{30}, 2, 20, 20};
  } else {
    settings = {kFullDimensions, kDefaultRuns, 1000, 100};
  }
  if (options.runs > 0) settings.runs = options.runs;
  absl::StatusOr<std::vector<SwarmOptimiser>> optimisers = MakeOptimisers(settings.population);
  if (!optimisers.ok()) return optimisers.status();
  const std::vector<TestFunction>& functions = AemBsoTestFunctions();

  std::vector<std::pair<int, std::vector<std::vector<Cell>>>> results;
  for (int dim : settings.dims) {
    std::vector<std::vector<Cell>> cells(functions.size());
    for (size_t f = 0; f < functions.size(); ++f) {
      for (size_t a = 0; a < kAlgorithms.size(); ++a) {
        absl::StatusOr<Cell> cell =
            RunCell((*optimisers)[a], functions[f], dim, false, settings, options.seed);
        if (!cell.ok()) {
          return absl::InternalError(absl::StrCat(kAlgorithms[a].planner_id, ", D = ", dim, ", ",
                                                  cell.status().message()));
        }
        if (options.log) {
          *options.log << "D=" << dim << " " << functions[f].id << " " << kAlgorithms[a].planner_id
                       << ": mean " << *Mean(cell->best_values) << " (" << cell->seconds << " s)\n";
        }
        cells[f].push_back(*std::move(cell));
      }
    }
    results.emplace_back(dim, std::move(cells));
  }

  Settings shifted_settings = settings;
  shifted_settings.runs = std::min(settings.runs, kShiftedRuns);
  std::vector<TestFunction> shifted_functions;
  std::vector<std::vector<Cell>> shifted_cells;
  for (int f : kShiftedFunctions) {
    shifted_functions.push_back(functions[f]);
    shifted_cells.emplace_back();
    for (size_t a = 0; a < kAlgorithms.size(); ++a) {
      absl::StatusOr<Cell> cell =
          RunCell((*optimisers)[a], functions[f], 30, true, shifted_settings, options.seed);
      if (!cell.ok()) {
        return absl::InternalError(
            absl::StrCat(kAlgorithms[a].planner_id, ", shifted, ", cell.status().message()));
      }
      shifted_cells.back().push_back(*std::move(cell));
    }
  }

  std::string report = "# AEM-BSO Table 1: five optimisers on ten test functions\n\n";
  absl::StrAppend(
      &report,
      "Reproduces Table 1 of Ouyang, Kuang, Ye, *Path planning based on improved beetle swarm "
      "optimization algorithm and cubic spline interpolation* (seed 002): the best and mean of "
      "the final best value over repeated runs of AEM-BSO, AEM-BSO2 (linear inertia), BSO, PSO "
      "and BA on f1-f10.\n\n");
  if (options.quick) {
    absl::StrAppend(&report,
                    "**Quick mode**: 2 runs of 20 iterations with 20 individuals; the numbers "
                    "say nothing about the optimisers.\n\n");
  }
  absl::StrAppend(&report, "## Settings\n\n");
  absl::StrAppend(&report, "| | paper | ours |\n|---|---|---|\n");
  absl::StrAppend(&report, "| dimensions | 30, 60 | ", absl::StrJoin(settings.dims, ", "), " |\n");
  absl::StrAppend(&report, "| population | 100 | ", settings.population, " |\n");
  absl::StrAppend(&report, "| iterations | 1000 | ", settings.iterations, " |\n");
  absl::StrAppend(&report, "| runs per cell | 100 | ", settings.runs, " (seeds ", options.seed,
                  "..", options.seed + settings.runs - 1, ", the same for every cell) |\n");
  absl::StrAppend(&report,
                  "| PSO c1, c2 | 1.49 | the registered `pso` planner's defaults (c1 = c2 = 2, "
                  "as ALGORITHMS.md gives for the PSO baseline) |\n");
  absl::StrAppend(&report,
                  "| extra | – | an origin-bias check: f1, f7, f9 with the optimum moved off "
                  "the origin (ours, see below) |\n\n");
  absl::StrAppend(
      &report,
      "Each optimiser is the very loop its registered planner runs (`SwarmOptimiserFor` in "
      "core/algorithms/bso/swarm_options.h, with the planner's default parameters), here "
      "minimising the test function instead of a path fitness:\n\n");
  for (const Algorithm& algorithm : kAlgorithms) {
    absl::StrAppend(&report, ParameterLine(algorithm.planner_id), "\n");
  }
  absl::StrAppend(&report,
                  "\nA statistic is over runs of the best value a run found. The paper's numbers "
                  "are in parentheses next to ours.\n\n");
  absl::StrAppend(&report, "## The test functions\n\n", FunctionsTable(), "\n");

  for (const auto& [dim, cells] : results) {
    absl::StrAppend(&report, "## D = ", dim, "\n\n",
                    ResultsTable(functions, cells,
                                 dim == 30   ? &kPaperD30
                                 : dim == 60 ? &kPaperD60
                                             : nullptr),
                    "\n");
  }

  absl::StrAppend(
      &report, "## Origin-bias check: the same functions with the optimum moved\n\n",
      "Every function of Table 1 has its minimum at the origin (f3 at (1, ..., 1)). Elite "
      "mutation (eq 9) multiplies Gbest by 1 - (G1 + G2 + mu) half of the time, a factor in "
      "(-G1 - G2, 1 - G1 - G2]: it pulls the best point towards the origin, whatever the "
      "function. Here f1, f7 and f9 are shifted, f(x - o) with o_j = +-",
      kShiftFraction, " * upper (alternating signs), D = 30, the other settings as above:\n\n",
      ResultsTable(shifted_functions, shifted_cells, nullptr), "\n");

  absl::StrAppend(&report, "## Discussion\n\n");
  if (results.front().first == 30) {
    absl::StrAppend(
        &report, "Measured in this run:\n\n",
        MeasuredFindings(functions, results.front().second, shifted_functions, shifted_cells));
  }
  absl::StrAppend(&report, kDiscussion, "\n");
  absl::StrAppend(&report, "## Time per run (ms)\n\n", TimeTable(results, settings.runs),
                  "\nTimes are from a shared, loaded 2-core machine; compare ratios, not "
                  "absolute values. AEM-BSO and BSO evaluate 3 points per beetle and iteration "
                  "(two antennae and the move), PSO and BA one.\n\n");
  return report;
}

}  // namespace swarmplan::bench
