// swarmplan-bench: runs registered planners on benchmark maps; see bench/README.md.
#include <fstream>
#include <iostream>

#include "absl/strings/str_join.h"
#include "bench/bench_options.h"
#include "bench/bench_runner.h"
#include "bench/ompl_log.h"
#include "bench/report.h"
#include "core/registry.h"

namespace swarmplan::bench {
namespace {

constexpr int kExitFailure = 1;   // a file could not be read or written
constexpr int kExitBadUsage = 2;  // bad arguments

void ListPlanners(const Registry& registry) {
  for (const PlannerInfo& info : registry.planners()) {
    std::cout << info.id << "\t" << JoinMapKinds(info.map_kinds) << "\t" << info.description
              << "\n";
  }
}

int Main(int argc, char** argv) {
  absl::StatusOr<ParsedArgs> parsed = ParseBenchArgs(argc, argv);
  if (!parsed.ok()) {
    std::cerr << "swarmplan-bench: error: " << parsed.status().message()
              << "\nRun with --help for the options.\n";
    return kExitBadUsage;
  }
  if (!parsed->help.empty()) {
    std::cout << parsed->help;
    return 0;
  }
  const BenchOptions& options = parsed->options;
  const Registry& registry = DefaultRegistry();
  if (options.list_planners) {
    ListPlanners(registry);
    return 0;
  }
  absl::StatusOr<PlannerParams> params = ResolvePlannerParams(registry, options);
  if (!params.ok()) {
    std::cerr << "swarmplan-bench: error: " << params.status().message() << "\n";
    return kExitBadUsage;
  }
  absl::StatusOr<std::vector<BenchProblem>> problems = LoadProblems(options, std::cerr);
  if (!problems.ok()) {
    std::cerr << "swarmplan-bench: error: " << problems.status().message() << "\n";
    return kExitFailure;
  }

  AddOptima(registry, absl::Seconds(options.optimum_budget_seconds), options.clearance, *problems,
            std::cerr);

  std::ofstream csv_file;
  if (!options.csv_path.empty()) {
    csv_file.open(options.csv_path);
    if (!csv_file) {
      std::cerr << "swarmplan-bench: error: cannot write " << options.csv_path << "\n";
      return kExitFailure;
    }
  }
  std::ostream& csv = options.csv_path.empty() ? std::cout : csv_file;
  csv << CsvHeader() << std::flush;

  std::ofstream convergence;
  if (!options.convergence_csv_path.empty()) {
    convergence.open(options.convergence_csv_path);
    convergence << ConvergenceCsvHeader();
    if (!convergence) {
      std::cerr << "swarmplan-bench: error: cannot write " << options.convergence_csv_path << "\n";
      return kExitFailure;
    }
  }

  std::vector<RunRecord> records;
  const absl::Time started = absl::Now();
  RunBench(
      registry, *problems, options, *params,
      [&](RunRecord record) {
        csv << CsvRow(record) << std::flush;
        if (convergence.is_open()) convergence << ConvergenceCsvRows(record) << std::flush;
        if (options.ompl_log_path.empty()) record.convergence.clear();
        records.push_back(std::move(record));
      },
      std::cerr);
  if (convergence.is_open() && !convergence) {
    std::cerr << "swarmplan-bench: error: writing the convergence CSV failed\n";
    return kExitFailure;
  }

  int successes = 0;
  for (const RunRecord& r : records) successes += r.success ? 1 : 0;
  std::cerr << "swarmplan-bench: " << records.size() << " runs, " << successes << " succeeded\n";
  if (!csv) {
    std::cerr << "swarmplan-bench: error: writing the CSV failed\n";
    return kExitFailure;
  }
  if (!options.ompl_log_path.empty()) {
    absl::StatusOr<std::vector<std::string>> logs = WriteOmplLogs(
        options.ompl_log_path, *problems, records, options, started, absl::Now() - started);
    if (!logs.ok()) {
      std::cerr << "swarmplan-bench: error: " << logs.status().message() << "\n";
      return kExitFailure;
    }
    std::cerr << "swarmplan-bench: OMPL log: " << absl::StrJoin(*logs, ", ") << "\n";
  }
  if (!options.markdown_path.empty()) {
    std::ofstream markdown(options.markdown_path);
    markdown << MarkdownSummary(Summarize(records));
    if (!markdown) {
      std::cerr << "swarmplan-bench: error: cannot write " << options.markdown_path << "\n";
      return kExitFailure;
    }
  }
  return 0;
}

}  // namespace
}  // namespace swarmplan::bench

int main(int argc, char** argv) { return swarmplan::bench::Main(argc, argv); }
