#include "bench/papers/as_bfo_islands_morris.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "bench/papers/as_bfo_islands_runs.h"
#include "bench/papers/as_bfo_islands_significance.h"
#include "bench/papers/markdown_table.h"
#include "bench/papers/parallel_jobs.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// The paper's finding (section 4.2, Fig. 11): Nre and Ned lie farthest from the origin.
const std::vector<std::string>& PaperMostImportant() {
  static const std::vector<std::string>* const symbols = new std::vector<std::string>{"Nre", "Ned"};
  return *symbols;
}

std::string Sample(const MorrisTrajectory& t, size_t point) {
  std::vector<int> values;
  for (size_t f = 0; f < MorrisFactors().size(); ++f) {
    values.push_back(MorrisValue(MorrisFactors()[f], t.points[point][f]));
  }
  return absl::StrCat("(", absl::StrJoin(values, ", "), ")");
}

std::string Interval(const std::vector<double>& effects, uint64_t seed) {
  const std::optional<MuStarInterval> ci = BootstrapMuStar(effects, 0.95, 10000, seed);
  return ci ? absl::StrCat("[", NumberCell(ci->low, 3), ", ", NumberCell(ci->high, 3), "]") : "–";
}

std::string Where(const MorrisAnalysis& a) {
  return absl::StrCat(a.world->environment, " ", SizeName(a.world->n));
}

}  // namespace

const std::vector<MorrisFactor>& MorrisFactors() {
  static const std::vector<MorrisFactor>* const factors = new std::vector<MorrisFactor>{
      {"population", "P", 10, 100},
      {"chemotactic_steps", "Nc", 2, 12},
      {"reproduction_steps", "Nre", 1, 8},
      {"elimination_steps", "Ned", 1, 10},
  };
  return *factors;
}

int MorrisValue(const MorrisFactor& factor, double x) {
  return static_cast<int>(std::lround(factor.low + x * (factor.high - factor.low)));
}

absl::StatusOr<MorrisAnalysis> RunMorris(const World& world, int trajectories, int runs,
                                         int max_iterations, uint64_t seed, int jobs) {
  const int factors = static_cast<int>(MorrisFactors().size());
  absl::StatusOr<std::vector<MorrisTrajectory>> design =
      MorrisTrajectories(factors, kMorrisLevels, trajectories, seed);
  if (!design.ok()) return design.status();
  MorrisAnalysis analysis;
  analysis.world = &world;
  analysis.design = *std::move(design);
  const int points = factors + 1;
  analysis.outcomes.assign(trajectories, std::vector<Outcome>(points));
  absl::Status status = RunJobs(trajectories * points, jobs, [&](int job) -> absl::Status {
    const MorrisTrajectory& t = analysis.design[job / points];
    const size_t point = static_cast<size_t>(job % points);
    PlanSpec spec{"as-bfo",
                  {{"init", std::string("paper")}, {"max_waypoints", int64_t{kWanderingVia}}}};
    spec.max_iterations = max_iterations;
    for (int f = 0; f < factors; ++f) {
      spec.params[MorrisFactors()[f].parameter] =
          static_cast<int64_t>(MorrisValue(MorrisFactors()[f], t.points[point][f]));
    }
    absl::StatusOr<Outcome> outcome = RunConfig(spec, world, runs, seed);
    if (!outcome.ok()) return outcome.status();
    analysis.outcomes[job / points][point] = *std::move(outcome);
    return absl::OkStatus();
  });
  if (!status.ok()) return status;
  std::vector<std::vector<double>> apl, ain;
  for (const std::vector<Outcome>& row : analysis.outcomes) {
    apl.emplace_back();
    ain.emplace_back();
    for (const Outcome& o : row) {
      apl.back().push_back(Mean(o.lengths).value_or(std::nan("")));
      ain.back().push_back(Mean(o.ains).value_or(std::nan("")));
    }
  }
  absl::StatusOr<MorrisIndices> apl_indices = MorrisElementaryEffects(analysis.design, apl);
  if (!apl_indices.ok()) return apl_indices.status();
  absl::StatusOr<MorrisIndices> ain_indices = MorrisElementaryEffects(analysis.design, ain);
  if (!ain_indices.ok()) return ain_indices.status();
  analysis.apl = *std::move(apl_indices);
  analysis.ain = *std::move(ain_indices);
  return analysis;
}

std::vector<size_t> RankByMuStar(const MorrisIndices& indices) {
  std::vector<size_t> order(indices.mu_star.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return indices.mu_star[a] > indices.mu_star[b]; });
  return order;
}

std::string MorrisSection(const std::vector<MorrisAnalysis>& analyses, int runs, uint64_t seed) {
  std::string text = "## Section 4.2: Morris sensitivity analysis\n\n";
  if (analyses.empty()) return text;
  std::string ranges;
  for (const MorrisFactor& f : MorrisFactors()) {
    std::vector<int> levels;
    for (int l = 0; l < kMorrisLevels; ++l) {
      levels.push_back(MorrisValue(f, static_cast<double>(l) / (kMorrisLevels - 1)));
    }
    AppendListItem(
        &ranges,
        absl::StrCat(f.symbol, " ∈ (", f.low, ", ", f.high, "): ", absl::StrJoin(levels, ", ")),
        "; ");
  }
  const int trajectories = static_cast<int>(analyses.front().design.size());
  absl::StrAppend(
      &text,
      "The paper's design (its Tables 1–3): the four parameters over the ranges of its "
      "Table 1, ",
      kPaperMorrisTrajectories,
      " trajectories of 5 samples, each sample run 10 "
      "times for its average path length; it plots μ* against σ (its Fig. 11) and finds Nre and "
      "Ned farthest from the origin, \"the most important\". Ours: the same ranges on a ",
      kMorrisLevels, "-level grid (", ranges, "), Δ = ", NumberCell(MorrisDelta(kMorrisLevels), 3),
      " of the range, ", trajectories,
      " trajectories (module bench/papers/morris.h, drawn from "
      "seed ",
      seed, "), each sample run ", runs, " times (seeds ", seed, "…", seed + runs - 1,
      ") with the main rows' wandering initial paths, on S3 of each environment (the size of "
      "the paper's Table 3, whose lengths are about 30; the smallest size in quick mode). "
      "Outputs: APL (the paper's) and AIN (ours). An elementary effect is the change of the "
      "output divided by the parameter's step as a fraction of its range (±Δ); μ* is the mean "
      "of their absolute values "
      "(overall importance), σ their standard deviation (non-linearity or interaction), and the "
      "interval of μ* is a percentile bootstrap over the trajectories (95%, 10000 resamples).\n\n");
  MarkdownTable table(
      {"environment", "output", "parameter", "μ", "μ* [95% CI]", "σ", "√(μ*² + σ²)", "rank by μ*"},
      3);
  for (const MorrisAnalysis& a : analyses) {
    for (const auto& [name, indices] :
         {std::pair<std::string, const MorrisIndices*>{"APL", &a.apl}, {"AIN", &a.ain}}) {
      const std::vector<size_t> order = RankByMuStar(*indices);
      for (size_t f = 0; f < MorrisFactors().size(); ++f) {
        const size_t rank = std::find(order.begin(), order.end(), f) - order.begin();
        table.AddRow({Where(a), name, MorrisFactors()[f].symbol, NumberCell(indices->mu[f], 3),
                      absl::StrCat(NumberCell(indices->mu_star[f], 3), " ",
                                   Interval(indices->effects[f], 1 + f)),
                      NumberCell(indices->sigma[f], 3),
                      NumberCell(std::hypot(indices->mu_star[f], indices->sigma[f]), 3),
                      absl::StrCat(rank + 1)});
      }
    }
  }
  absl::StrAppend(&text, table.ToString(), "\n");
  absl::StrAppend(&text,
                  "The samples (P, Nc, Nre, Ned) and their outputs, as the paper's Tables 2 and "
                  "3; the first sample of a trajectory changes nothing, each later one the "
                  "named parameter:\n\n");
  MarkdownTable samples({"environment", "trajectory", "sample", "(P, Nc, Nre, Ned)", "changed",
                         "APL", "AIN", "success"},
                        5);
  for (const MorrisAnalysis& a : analyses) {
    for (size_t t = 0; t < a.design.size(); ++t) {
      for (size_t i = 0; i < a.design[t].points.size(); ++i) {
        const Outcome& o = a.outcomes[t][i];
        samples.AddRow({Where(a), absl::StrCat(t + 1), absl::StrCat(i + 1), Sample(a.design[t], i),
                        i == 0 ? "–" : MorrisFactors()[a.design[t].changed[i - 1]].symbol,
                        NumberCell(Mean(o.lengths)), NumberCell(Mean(o.ains), 3),
                        PercentCell(o.success())});
      }
    }
  }
  absl::StrAppend(&text, samples.ToString(), "\n");
  return text;
}

std::string MorrisParagraph(const std::vector<MorrisAnalysis>& analyses) {
  std::string text =
      "**Section 4.2, the Morris analysis.** The paper finds Nre and Ned the most important "
      "parameters for the path length. We count that as reproduced on a world when Nre and Ned "
      "rank first and second by μ* of the APL and the lower end of each one's bootstrap interval "
      "lies above the upper ends of the intervals of P and Nc.";
  for (const MorrisAnalysis& a : analyses) {
    const std::vector<size_t> order = RankByMuStar(a.apl);
    std::vector<std::string> ranking, ain_ranking;
    for (size_t f : order) {
      ranking.push_back(absl::StrCat(MorrisFactors()[f].symbol, " (μ* ",
                                     NumberCell(a.apl.mu_star[f], 3), ", σ ",
                                     NumberCell(a.apl.sigma[f], 3), ")"));
    }
    for (size_t f : RankByMuStar(a.ain)) ain_ranking.push_back(MorrisFactors()[f].symbol);
    std::vector<std::optional<MuStarInterval>> ci;
    for (size_t f = 0; f < MorrisFactors().size(); ++f) {
      ci.push_back(BootstrapMuStar(a.apl.effects[f], 0.95, 10000, 1 + f));
    }
    auto index_of = [](const std::string& symbol) {
      for (size_t f = 0; f < MorrisFactors().size(); ++f) {
        if (MorrisFactors()[f].symbol == symbol) return f;
      }
      return size_t{0};
    };
    bool top_two = true, separated = true;
    for (size_t k = 0; k < PaperMostImportant().size(); ++k) {
      const size_t important = index_of(PaperMostImportant()[k]);
      top_two =
          top_two && std::find(order.begin(), order.begin() + 2, important) != order.begin() + 2;
      for (size_t other = 0; other < MorrisFactors().size(); ++other) {
        const bool paper_important =
            std::find(PaperMostImportant().begin(), PaperMostImportant().end(),
                      MorrisFactors()[other].symbol) != PaperMostImportant().end();
        if (paper_important) continue;
        separated = separated && ci[important] && ci[other] && ci[important]->low > ci[other]->high;
      }
    }
    absl::StrAppend(&text, " On ", Where(a), " the APL ranks ", absl::StrJoin(ranking, " > "), ": ",
                    top_two && separated ? "reproduced"
                    : top_two ? "Nre and Ned rank first and second, but their intervals overlap "
                                "those of P or Nc, so not reproduced"
                              : "not reproduced",
                    "; by μ* of the AIN the order is ", absl::StrJoin(ain_ranking, " > "), ".");
  }
  absl::StrAppend(&text,
                  " Nc, Nre and Ned each multiply the iteration budget Nc·Nre·Ned, and P sets the "
                  "number of paths per iteration, so every parameter also changes the work "
                  "done.\n\n");
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
