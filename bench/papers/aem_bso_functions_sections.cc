#include "bench/papers/aem_bso_functions_sections.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/comparison.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"
#include "core/registry.h"

namespace swarmplan::bench::aem_bso {
namespace {

std::string PaperValue(double value) { return absl::StrCat("(", Sci(value), ")"); }

std::string FunctionLabel(const TestFunction& function) {
  return absl::StrCat(function.id, " ", function.name);
}

// "lower, p = 1.2e-11 *": whether `a`'s median is below `b`'s, and the rank-sum p.
std::string VersusCell(const std::vector<double>& a, const std::vector<double>& b,
                       std::optional<double> p) {
  const double median_a = Median(a).value_or(0.0), median_b = Median(b).value_or(0.0);
  const char* direction = median_a < median_b ? "lower" : median_a > median_b ? "higher" : "equal";
  return absl::StrCat(direction, ", ", PValueCell(p));
}

}  // namespace

bool SignificantlyLower(const std::vector<double>& a, const std::vector<double>& b) {
  const std::optional<double> p = RankSumP(a, b);
  return p.has_value() && *p < kSignificanceLevel &&
         Median(a).value_or(0.0) < Median(b).value_or(0.0);
}

std::string Sci(std::optional<double> value) {
  if (!value) return "–";
  return absl::StrFormat("%.3g", *value);
}

std::string ResultsTable(const std::vector<const TestFunction*>& functions,
                         const std::vector<std::string>& labels, const CellGrid& cells,
                         const std::array<PaperRow, 10>* paper) {
  std::vector<std::string> header = {"function", "statistic"};
  for (const std::string& label : labels) {
    header.push_back(label);
    if (paper) header.push_back("paper");
  }
  MarkdownTable table(header, 2);
  const std::vector<TestFunction>& all = AemBsoTestFunctions();
  for (size_t f = 0; f < functions.size(); ++f) {
    const size_t paper_row = static_cast<size_t>(functions[f] - all.data());
    for (const std::string statistic : {"best", "mean", "std"}) {
      std::vector<std::string> row = {statistic == "best" ? FunctionLabel(*functions[f]) : "",
                                      statistic};
      for (size_t c = 0; c < labels.size(); ++c) {
        const std::vector<double>& values = cells[f][c].best_values;
        row.push_back(Sci(statistic == "best"   ? Min(values)
                          : statistic == "mean" ? Mean(values)
                                                : StdDev(values)));
        if (paper) {
          row.push_back(statistic == "best"   ? PaperValue((*paper)[paper_row].best[c])
                        : statistic == "mean" ? PaperValue((*paper)[paper_row].mean[c])
                                              : "");
        }
      }
      table.AddRow(std::move(row));
    }
  }
  return table.ToString();
}

std::string SignificanceTable(const std::vector<const TestFunction*>& functions,
                              const std::vector<std::string>& labels, const CellGrid& cells,
                              std::vector<std::string>* lower_than_all,
                              std::vector<std::string>* lower_than_baselines) {
  std::vector<std::string> header = {"function", absl::StrCat("median ", labels[0])};
  for (size_t c = 1; c < labels.size(); ++c) {
    header.push_back(absl::StrCat("median ", labels[c]));
    header.push_back(absl::StrCat(labels[0], " vs ", labels[c]));
  }
  MarkdownTable table(header);
  for (size_t f = 0; f < functions.size(); ++f) {
    const std::vector<double>& reference = cells[f][0].best_values;
    std::vector<std::string> row = {FunctionLabel(*functions[f]), Sci(Median(reference))};
    bool all = true, baselines = true;
    for (size_t c = 1; c < labels.size(); ++c) {
      const std::vector<double>& other = cells[f][c].best_values;
      row.push_back(Sci(Median(other)));
      row.push_back(VersusCell(reference, other, RankSumP(reference, other)));
      const bool lower = SignificantlyLower(reference, other);
      all = all && lower;
      if (c >= 2) baselines = baselines && lower;
    }
    if (all) lower_than_all->push_back(functions[f]->id);
    if (baselines) lower_than_baselines->push_back(functions[f]->id);
    table.AddRow(std::move(row));
  }
  return table.ToString();
}

std::string MeansTable(const std::vector<const TestFunction*>& functions,
                       const std::vector<std::string>& labels, const CellGrid& cells,
                       const std::vector<int>& tested) {
  std::vector<std::string> header = {"function"};
  for (const std::string& label : labels) header.push_back(absl::StrCat("mean ", label));
  for (int c : tested) header.push_back(absl::StrCat(labels[0], " vs ", labels[c]));
  MarkdownTable table(header);
  for (size_t f = 0; f < functions.size(); ++f) {
    std::vector<std::string> row = {FunctionLabel(*functions[f])};
    for (size_t c = 0; c < labels.size(); ++c) row.push_back(Sci(Mean(cells[f][c].best_values)));
    for (int c : tested) {
      const std::vector<double>& a = cells[f][0].best_values;
      const std::vector<double>& b = cells[f][c].best_values;
      row.push_back(VersusCell(a, b, RankSumP(a, b)));
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
                                                              "pulse_schedule",
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

}  // namespace swarmplan::bench::aem_bso
