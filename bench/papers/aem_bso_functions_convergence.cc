#include "bench/papers/aem_bso_functions_convergence.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "bench/papers/markdown_table.h"
#include "bench/statistics.h"

namespace swarmplan::bench::aem_bso {
namespace {

// The indices of the checkpoints where `a` is significantly below `b`.
std::vector<size_t> CheckpointsBelow(const FunctionCell& a, const FunctionCell& b) {
  std::vector<size_t> out;
  for (size_t k = 0; k < a.best_so_far.size() && k < b.best_so_far.size(); ++k) {
    if (SignificantlyLower(a.best_so_far[k], b.best_so_far[k])) out.push_back(k);
  }
  return out;
}

// "all", "–" or the iteration counts of `indices`.
std::string CheckpointList(const std::vector<size_t>& indices,
                           const std::vector<int>& checkpoints) {
  if (indices.empty()) return "–";
  if (indices.size() == checkpoints.size()) return "all";
  std::vector<int> iterations;
  for (size_t k : indices) iterations.push_back(checkpoints[k]);
  return absl::StrJoin(iterations, ", ");
}

}  // namespace

std::string ConvergenceSection(const std::vector<const TestFunction*>& functions,
                               const std::vector<std::string>& labels, const CellGrid& cells,
                               size_t first_baseline, int dim, int iterations,
                               std::string* summary) {
  const std::vector<int> checkpoints = ConvergenceCheckpoints(iterations);
  std::string out = absl::StrCat(
      "## Fig. 2: convergence on the test functions (D = ", dim, ")\n\n",
      "The paper plots one iteration curve per optimiser and function (Fig. 2) and reads them "
      "as AEM-BSO converging fastest. Here, from the runs of the D = ",
      dim,
      " table: the median over the runs of the best value so far after k iterations, and the "
      "checkpoints at which ",
      labels.front(),
      " is significantly below (or above) the optimiser of the row (rank-sum per checkpoint, "
      "p < 0.05, medians compared).\n\n");
  std::vector<std::string> header = {"function", "optimiser"};
  for (int t : checkpoints) header.push_back(absl::StrCat("after ", t));
  header.push_back(absl::StrCat(labels.front(), " below at"));
  header.push_back(absl::StrCat(labels.front(), " above at"));
  MarkdownTable table(header, 2);
  std::vector<std::string> below_throughout, below_baselines_throughout, below_baselines_at_end,
      above_somewhere;
  for (size_t f = 0; f < functions.size(); ++f) {
    bool throughout = true, baselines_throughout = true, baselines_at_end = true;
    std::vector<std::string> above_labels;
    for (size_t c = 0; c < labels.size(); ++c) {
      const FunctionCell& cell = cells[f][c];
      std::vector<std::string> row = {functions[f]->id, labels[c]};
      for (const std::vector<double>& values : cell.best_so_far) row.push_back(Sci(Median(values)));
      if (c == 0) {
        row.insert(row.end(), {"", ""});
        table.AddRow(std::move(row));
        continue;
      }
      const std::vector<size_t> below = CheckpointsBelow(cells[f][0], cell);
      const std::vector<size_t> above = CheckpointsBelow(cell, cells[f][0]);
      row.push_back(CheckpointList(below, checkpoints));
      row.push_back(CheckpointList(above, checkpoints));
      table.AddRow(std::move(row));
      const bool all = below.size() == checkpoints.size();
      throughout = throughout && all;
      if (c >= first_baseline) {
        baselines_throughout = baselines_throughout && all;
        baselines_at_end =
            baselines_at_end && !below.empty() && below.back() + 1 == checkpoints.size();
      }
      if (!above.empty()) above_labels.push_back(labels[c]);
    }
    const std::string& id = functions[f]->id;
    if (throughout) below_throughout.push_back(id);
    if (baselines_throughout) below_baselines_throughout.push_back(id);
    if (baselines_at_end) below_baselines_at_end.push_back(id);
    if (!above_labels.empty()) {
      above_somewhere.push_back(absl::StrCat(id, " (", absl::StrJoin(above_labels, ", "), ")"));
    }
  }
  absl::StrAppend(&out, table.ToString(), "\n");
  auto list = [](const std::vector<std::string>& ids) {
    return ids.empty() ? std::string("none") : absl::StrJoin(ids, ", ");
  };
  const std::vector<std::string> baselines(labels.begin() + first_baseline, labels.end());
  const std::string finding = absl::StrCat(
      labels.front(), " is significantly below ", absl::StrJoin(baselines, ", "),
      " at every checkpoint on ", below_baselines_throughout.size(), " of ", functions.size(),
      " functions (", list(below_baselines_throughout), ") and at the last one on ",
      below_baselines_at_end.size(), " (", list(below_baselines_at_end), "); below all ",
      labels.size() - 1, " others at every checkpoint on ", below_throughout.size(), " (",
      list(below_throughout), "); another optimiser is significantly below ", labels.front(),
      " at some checkpoint on ", above_somewhere.size(), " (", list(above_somewhere), ")");
  absl::StrAppend(&out, finding, ".\n\n");
  absl::StrAppend(summary, finding);
  return out;
}

}  // namespace swarmplan::bench::aem_bso
