#include "bench/papers/bas_canyon_tables.h"

#include <optional>

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_paper.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::bas {
namespace {

std::string CountCell(const SuccessCount& count) {
  return absl::StrCat(count.successes, "/", count.runs);
}

std::string PaperCell(const PaperRow* paper, std::optional<double> PaperRow::*field) {
  return paper != nullptr && (paper->*field).has_value() ? NumberCell(paper->*field) : "–";
}

}  // namespace

std::string FitnessTable(const RowSet& set, double yardstick) {
  MarkdownTable table({"planner", "found", "improved on first path", "best", "median [95 % CI]",
                       "mean", "std", "median / yardstick", "deep branch",
                       "best found at iteration (mean)", "paper best", "paper mean", "paper std"});
  for (size_t r = 0; r < set.rows.size(); ++r) {
    const RowRuns& runs = set.runs[r];
    const PaperRow* paper = FindPaperRow(set.rows[r].label);
    const std::optional<double> median = Median(runs.fitness);
    table.AddRow({set.rows[r].label, CountCell(runs.found()), CountCell(runs.improved_count()),
                  NumberCell(Min(runs.fitness)), MedianWithInterval(runs.fitness),
                  NumberCell(Mean(runs.fitness)), NumberCell(StdDev(runs.fitness)),
                  median ? NumberCell(*median / yardstick) : "–",
                  absl::StrCat(runs.right_branch, "/", runs.fitness.size()),
                  NumberCell(Mean(runs.best_iteration)), PaperCell(paper, &PaperRow::best),
                  PaperCell(paper, &PaperRow::mean), PaperCell(paper, &PaperRow::std)});
  }
  return table.ToString();
}

std::string TimeTable(const RowSet& set) {
  MarkdownTable table({"planner", "mean time (s)", "paper time (s)", "paper / ours"});
  for (size_t r = 0; r < set.rows.size(); ++r) {
    const PaperRow* paper = FindPaperRow(set.rows[r].label);
    const std::optional<double> ours = Mean(set.runs[r].seconds);
    const bool ratio = paper != nullptr && paper->seconds && ours && *ours > 0.0;
    table.AddRow({set.rows[r].label, NumberCell(ours), PaperCell(paper, &PaperRow::seconds),
                  ratio ? NumberCell(*paper->seconds / *ours) : "–"});
  }
  return table.ToString();
}

std::string TimeRatioSentence(const RowSet& set, const std::string& slow, const std::string& fast) {
  const PaperRow* paper_slow = FindPaperRow(slow);
  const PaperRow* paper_fast = FindPaperRow(fast);
  const RowRuns* ours_slow = set.Find(slow);
  const RowRuns* ours_fast = set.Find(fast);
  if (paper_slow == nullptr || paper_fast == nullptr || ours_slow == nullptr ||
      ours_fast == nullptr || !paper_slow->seconds || !paper_fast->seconds) {
    return "";
  }
  const std::optional<double> a = Mean(ours_slow->seconds), b = Mean(ours_fast->seconds);
  if (!a || !b || *b <= 0.0) return "";
  return absl::StrCat("The paper's ", slow, " took ",
                      NumberCell(*paper_slow->seconds / *paper_fast->seconds, 3),
                      "x as long as its ", fast, "; ours ", NumberCell(*a / *b, 3),
                      "x (our ACO checks 25 candidate segments per ant per column; a beetle "
                      "evaluates 3 paths per iteration).\n");
}

}  // namespace swarmplan::bench::bas
