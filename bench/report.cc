#include "bench/report.h"

#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "bench/statistics.h"

namespace swarmplan::bench {
namespace {

std::string FormatOptional(const std::optional<double>& value) {
  return value ? FormatNumber(*value) : std::string();
}

// A Markdown cell: pipes escaped, "–" for a missing value.
std::string MarkdownCell(const std::string& text) {
  return absl::StrReplaceAll(text, {{"|", "\\|"}});
}
std::string MarkdownNumber(const std::optional<double>& value, int decimals) {
  if (!value) return "–";
  if (!std::isfinite(*value)) return FormatNumber(*value);
  return absl::StrFormat("%.*f", decimals, *value);
}

}  // namespace

std::optional<double> LengthRatio(bool success, std::optional<double> length,
                                  std::optional<double> optimal) {
  if (!success || !length || !optimal) return std::nullopt;
  if (*optimal > 0) return *length / *optimal;
  if (*optimal == 0 && *length == 0) return 1.0;
  return std::nullopt;
}

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return absl::StrFormat("%.9g", value);
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  return absl::StrCat("\"", absl::StrReplaceAll(text, {{"\"", "\"\""}}), "\"");
}

std::string CsvHeader() {
  return "map,scenario,planner,seed,success,length,optimal,ratio,scen_optimal,min_clearance,"
         "max_curvature,iterations,evaluations,wall_seconds,fitness,initial_fitness,best_"
         "iteration,objective,seed_objective,seed_penalty,seconds_to_1.05,seconds_to_1.02,"
         "alternatives,distinct_corridors\n";
}

std::string CsvRow(const RunRecord& r) {
  const std::vector<std::string> fields = {
      CsvField(r.map),
      CsvField(r.scenario),
      CsvField(r.planner),
      absl::StrCat(r.seed),
      r.success ? "true" : "false",
      FormatOptional(r.length),
      FormatOptional(r.optimal),
      FormatOptional(r.ratio),
      FormatOptional(r.scen_optimal),
      FormatOptional(r.min_clearance),
      FormatOptional(r.max_curvature),
      absl::StrCat(r.iterations),
      absl::StrCat(r.evaluations),
      absl::StrFormat("%.6f", r.wall_seconds),
      FormatOptional(r.fitness),
      FormatOptional(r.initial_fitness),
      absl::StrCat(r.best_iteration),
      FormatOptional(r.objective),
      FormatOptional(r.seed_objective),
      FormatOptional(r.seed_penalty),
      FormatOptional(r.seconds_to_1_05),
      FormatOptional(r.seconds_to_1_02),
      r.alternatives ? absl::StrCat(*r.alternatives) : "",
      r.distinct_corridors ? absl::StrCat(*r.distinct_corridors) : "",
  };
  return absl::StrCat(absl::StrJoin(fields, ","), "\n");
}

std::string ConvergenceCsvHeader() {
  return "map,scenario,planner,seed,iteration,seconds,best_fitness,feasible\n";
}

std::string ConvergenceCsvRows(const RunRecord& r) {
  std::string out;
  for (size_t i = 0; i < r.convergence.size(); ++i) {
    const RunRecord::Progress& p = r.convergence[i];
    absl::StrAppend(&out, CsvField(r.map), ",", CsvField(r.scenario), ",", CsvField(r.planner), ",",
                    r.seed, ",", i, ",", absl::StrFormat("%.6f", p.seconds), ",",
                    FormatNumber(p.best_fitness), ",", p.feasible ? "true" : "false", "\n");
  }
  return out;
}

std::vector<SummaryRow> Summarize(const std::vector<RunRecord>& records) {
  struct Group {
    SummaryRow row;
    std::vector<double> ratios, lengths, seconds;
  };
  std::vector<Group> groups;
  for (const RunRecord& r : records) {
    Group* group = nullptr;
    for (Group& g : groups) {
      if (g.row.planner == r.planner && g.row.map == r.map) group = &g;
    }
    if (group == nullptr) {
      group = &groups.emplace_back();
      group->row.planner = r.planner;
      group->row.map = r.map;
    }
    ++group->row.runs;
    group->seconds.push_back(r.wall_seconds);
    if (!r.success) continue;
    ++group->row.successes;
    if (r.length) group->lengths.push_back(*r.length);
    if (r.ratio) group->ratios.push_back(*r.ratio);
  }
  std::vector<SummaryRow> rows;
  for (Group& g : groups) {
    g.row.median_ratio = Median(g.ratios);
    g.row.worst_ratio = Max(g.ratios);
    g.row.median_length = Median(g.lengths);
    g.row.median_seconds = Median(g.seconds);
    rows.push_back(std::move(g.row));
  }
  return rows;
}

std::string MarkdownSummary(const std::vector<SummaryRow>& rows) {
  if (rows.empty()) return "";
  std::string out =
      "| planner | map | runs | success | median ratio | worst ratio | median length | "
      "median time (s) |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const SummaryRow& r : rows) {
    const double rate = r.runs > 0 ? 100.0 * r.successes / r.runs : 0.0;
    absl::StrAppend(&out, "| ", MarkdownCell(r.planner), " | ", MarkdownCell(r.map), " | ", r.runs,
                    " | ", absl::StrFormat("%.1f%%", rate), " | ",
                    MarkdownNumber(r.median_ratio, 6), " | ", MarkdownNumber(r.worst_ratio, 6),
                    " | ", MarkdownNumber(r.median_length, 4), " | ",
                    MarkdownNumber(r.median_seconds, 6), " |\n");
  }
  return out;
}

}  // namespace swarmplan::bench
