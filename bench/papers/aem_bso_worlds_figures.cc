#include "bench/papers/aem_bso_worlds_figures.h"

#include <optional>

#include "absl/strings/str_cat.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::aem_bso {
namespace {

std::string FoundCell(const CellStats& cell) { return absl::StrCat(cell.found(), "/", cell.runs); }

std::vector<int> Checkpoints(int iterations) {
  std::vector<int> out;
  for (int t : {1, iterations / 50, iterations / 10, iterations / 5, iterations / 2, iterations}) {
    if (t >= 1 && (out.empty() || t > out.back())) out.push_back(t);
  }
  return out;
}

// The median over runs of the best z after `iteration` iterations (1-based).
std::optional<double> MedianBestAfter(const CellStats& cell, int iteration) {
  std::vector<double> values;
  for (const std::vector<double>& curve : cell.convergence) {
    if (static_cast<int>(curve.size()) >= iteration) values.push_back(curve[iteration - 1]);
  }
  return Median(values);
}

}  // namespace

std::string InterpolationTestsSection(const std::vector<std::string>& environments,
                                      const CellOf& cell, std::string* summary) {
  std::string out = absl::StrCat(
      "## Table 2: tests\n\n",
      "aem-bso with the spline (the paper's choice) against the other interpolations: Fisher on "
      "found runs, rank-sum on the lengths of the found runs, medians with bootstrap 95 % "
      "intervals.\n\n");
  MarkdownTable table({"environment", "interpolation", "found", "Fisher (found)",
                       "median length [95 % CI]", "rank-sum (length)"},
                      2);
  std::string differences;
  for (const std::string& environment : environments) {
    const CellStats& spline = cell(environment, "aem-bso", "spline");
    table.AddRow(
        {environment, "spline", FoundCell(spline), "", MedianWithInterval(spline.lengths), ""});
    for (const char* other : {"linear", "nearest"}) {
      const CellStats& c = cell(environment, "aem-bso", other);
      const std::optional<double> found_p = SuccessP(c.Found(), spline.Found());
      const std::optional<double> length_p = RankSumP(c.lengths, spline.lengths);
      table.AddRow({environment, other, FoundCell(c), PValueCell(found_p),
                    MedianWithInterval(c.lengths), PValueCell(length_p)});
      const std::string label = absl::StrCat(environment, " ", other);
      std::string found = SuccessDifference(label, spline.Found(), c.Found(), found_p);
      std::string length = ValueDifference(label, "length", spline.lengths, c.lengths, length_p);
      if (found.empty() && length.empty()) {
        found = absl::StrCat(label, ": no significant difference from the spline");
      }
      AppendListItem(&differences, found, "; ");
      AppendListItem(&differences, length, "; ");
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  absl::StrAppend(summary, differences);
  return out;
}

std::string ConvergenceSection(const std::vector<std::string>& environments,
                               const std::vector<std::string>& planners, int iterations,
                               const CellOf& cell, std::string* summary) {
  std::string out = absl::StrCat(
      "## Fig. 4: convergence\n\n",
      "The paper plots each planner's best fitness against the iteration (one run, Fig. 4). "
      "Here: the median over the runs of the best z so far (penalty included) after k "
      "iterations, with the spline, and the iteration at which each run found its final best, "
      "against aem-bso's (rank-sum).\n\n");
  std::vector<std::string> header = {"environment", "planner"};
  const std::vector<int> checkpoints = Checkpoints(iterations);
  for (int t : checkpoints) header.push_back(absl::StrCat("after ", t));
  header.push_back("median iteration of the final best");
  header.push_back("rank-sum (iteration)");
  MarkdownTable table(header, 2);
  std::string differences;
  for (const std::string& environment : environments) {
    const CellStats& reference = cell(environment, "aem-bso", "spline");
    for (const std::string& planner : planners) {
      const CellStats& c = cell(environment, planner, "spline");
      std::vector<std::string> row = {environment, planner};
      for (int t : checkpoints) row.push_back(NumberCell(MedianBestAfter(c, t)));
      const bool is_reference = planner == "aem-bso";
      const std::optional<double> p =
          is_reference ? std::nullopt : RankSumP(c.best_iterations, reference.best_iterations);
      row.push_back(NumberCell(Median(c.best_iterations), 3));
      row.push_back(is_reference ? "" : PValueCell(p));
      table.AddRow(std::move(row));
      if (!is_reference) {
        AppendListItem(
            &differences,
            ValueDifference(absl::StrCat(environment, " ", planner), "iteration of the final best",
                            reference.best_iterations, c.best_iterations, p),
            "; ");
      }
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  absl::StrAppend(summary, differences.empty() ? "none" : differences);
  return out;
}

}  // namespace swarmplan::bench::aem_bso
