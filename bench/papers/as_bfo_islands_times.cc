#include "bench/papers/as_bfo_islands_times.h"

#include <optional>

#include "absl/strings/str_cat.h"
#include "bench/papers/as_bfo_islands_significance.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::as_bfo_islands {
namespace {

// "a–b×", or "a×" when both print the same.
std::string RatioRange(const std::vector<double>& ratios) {
  if (ratios.empty()) return "–";
  const std::string low = NumberCell(Min(ratios), 3);
  const std::string high = NumberCell(Max(ratios), 3);
  return low == high ? low + "×" : absl::StrCat(low, "–", high, "×");
}

std::string TimeTables(const std::vector<std::vector<World>>& worlds, const Table4& outcomes) {
  std::string text;
  for (size_t e = 0; e < worlds.size(); ++e) {
    absl::StrAppend(&text, "### Environment ", e + 1, "\n\n");
    std::vector<std::string> header{"metric", "method"};
    for (const World& w : worlds[e]) header.push_back(SizeName(w.n));
    MarkdownTable table(header, 2);
    for (size_t m = 0; m < Methods().size(); ++m) {
      std::vector<std::string> row{"time ms (mean)", Methods()[m].label};
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        row.push_back(NumberCell(Mean(outcomes[e][m][s].millis), 3));
      }
      table.AddRow(row);
    }
    for (size_t m : TestedMethods()) {
      std::vector<std::string> row{"rank-sum against " + Methods()[kReferenceMethod].label,
                                   Methods()[m].label};
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        row.push_back(PValueCell(
            CompareRanks(outcomes[e][kReferenceMethod][s].millis, outcomes[e][m][s].millis).p));
      }
      table.AddRow(row);
    }
    absl::StrAppend(&text, table.ToString(), "\n");
  }
  return text;
}

std::string RatiosParagraph(const std::vector<std::vector<World>>& worlds, const Table4& outcomes) {
  const std::string& ref = Methods()[kReferenceMethod].label;
  int cells = 0;
  for (const std::vector<World>& e : worlds) cells += static_cast<int>(e.size());
  std::string text;
  for (size_t m : TestedMethods()) {
    std::vector<double> ratios;
    int slower = 0, faster = 0;
    for (size_t e = 0; e < worlds.size(); ++e) {
      for (size_t s = 0; s < worlds[e].size(); ++s) {
        const Outcome& base = outcomes[e][kReferenceMethod][s];
        const Outcome& other = outcomes[e][m][s];
        const std::optional<double> a = Mean(base.millis), b = Mean(other.millis);
        if (a && b && *a > 0.0) ratios.push_back(*b / *a);
        const RankComparison test = CompareRanks(base.millis, other.millis);
        if (Significant(test.p)) ++(test.other_higher ? slower : faster);
      }
    }
    absl::StrAppend(&text, Methods()[m].label, "'s mean run time is ", RatioRange(ratios), " ", ref,
                    "'s (slower in ", slower, "/", cells, " cells and faster in ", faster,
                    " by the rank-sum test on the run times). ");
  }
  std::vector<int> slowest_in(Methods().size(), 0);
  for (size_t e = 0; e < worlds.size(); ++e) {
    for (size_t s = 0; s < worlds[e].size(); ++s) {
      size_t slowest = kReferenceMethod;
      for (size_t m : TestedMethods()) {
        if (Mean(outcomes[e][m][s].millis).value_or(0.0) >
            Mean(outcomes[e][slowest][s].millis).value_or(0.0)) {
          slowest = m;
        }
      }
      ++slowest_in[slowest];
    }
  }
  std::string slowest;
  for (size_t m = 0; m < Methods().size(); ++m) {
    if (slowest_in[m] > 0) {
      AppendListItem(&slowest, absl::StrCat(Methods()[m].label, " in ", slowest_in[m], "/", cells));
    }
  }
  absl::StrAppend(&text, "The slowest of the three by mean run time: ", slowest, ".\n\n");
  return text;
}

std::string SweepTimes(const std::vector<SweepRow>& rows) {
  if (rows.empty()) return "";
  MarkdownTable table({"parameter", "value", "time ms (mean), near-A* initial paths",
                       absl::StrCat("time ms (mean), ≤", kWanderingVia, " via")},
                      2);
  for (const SweepRow& row : rows) {
    table.AddRow({row.sweep->symbol, absl::StrCat(row.value),
                  NumberCell(Mean(row.outcome.millis), 3),
                  NumberCell(Mean(row.wandering.millis), 3)});
  }
  return absl::StrCat("The sweeps of section 4.1, per value:\n\n", table.ToString(), "\n");
}

}  // namespace

std::string RunTimesSection(const std::vector<std::vector<World>>& worlds, const Table4& outcomes,
                            const std::vector<SweepRow>& sweep_rows) {
  std::string text = absl::StrCat(kTimesHeading, "\n\n");
  absl::StrAppend(&text,
                  "The paper reports no run times. Ours: wall time per run of Table 4's "
                  "configurations, with the rank-sum test of each of the paper's other methods "
                  "against ",
                  Methods()[kReferenceMethod].label, ".\n\n", TimeTables(worlds, outcomes),
                  RatiosParagraph(worlds, outcomes), SweepTimes(sweep_rows),
                  "Times are wall-clock times from a shared, loaded 2-core machine: compare "
                  "ratios between planners, not absolute values.\n");
  return text;
}

}  // namespace swarmplan::bench::as_bfo_islands
