// swarmplan-papers: reproduces the tables of the papers behind the planners; see bench/README.md.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "CLI/CLI.hpp"
#include "absl/strings/str_join.h"
#include "bench/papers/experiment.h"
#include "bench/papers/report_stamp.h"

#ifndef SWARMPLAN_SOURCE_DIR
#error "SWARMPLAN_SOURCE_DIR must name the source tree"
#endif
#ifndef SWARMPLAN_BUILD_TYPE
#error "SWARMPLAN_BUILD_TYPE must name the build type"
#endif

namespace swarmplan::bench {
namespace {

constexpr int kExitFailure = 1;
constexpr int kExitBadUsage = 2;

int ListExperiments() {
  for (const Experiment& experiment : Experiments()) {
    std::cout << experiment.name << "\t" << experiment.reproduces << "\t" << experiment.results_file
              << "\n";
  }
  return 0;
}

int Generate(const std::vector<const Experiment*>& experiments, const std::string& worlds_dir) {
  for (const Experiment* experiment : experiments) {
    if (!experiment->generate) continue;
    const std::filesystem::path dir = std::filesystem::path(worlds_dir) / experiment->name;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) {
      std::cerr << "swarmplan-papers: error: cannot create " << dir << ": " << error.message()
                << "\n";
      return kExitFailure;
    }
    if (absl::Status status = experiment->generate(dir.string()); !status.ok()) {
      std::cerr << "swarmplan-papers: error: " << experiment->name << ": " << status.message()
                << "\n";
      return kExitFailure;
    }
    std::cerr << "wrote the worlds of " << experiment->name << " to " << dir.string() << "\n";
  }
  return 0;
}

int Run(const std::vector<const Experiment*>& experiments, const ExperimentOptions& options,
        const std::string& output_dir, const std::string& command) {
  const std::string stamp = ReportStamp(command, SWARMPLAN_SOURCE_DIR, SWARMPLAN_BUILD_TYPE);
  for (const Experiment* experiment : experiments) {
    std::cerr << "running " << experiment->name << " (" << experiment->reproduces << ")\n";
    absl::StatusOr<std::string> report = experiment->run(options);
    if (!report.ok()) {
      std::cerr << "swarmplan-papers: error: " << experiment->name << ": "
                << report.status().message() << "\n";
      return kExitFailure;
    }
    *report = InsertStamp(*report, stamp);
    if (output_dir.empty()) {
      std::cout << *report;
      continue;
    }
    const std::filesystem::path path = std::filesystem::path(output_dir) / experiment->results_file;
    std::ofstream out(path);
    out << *report;
    if (!out) {
      std::cerr << "swarmplan-papers: error: cannot write " << path.string() << "\n";
      return kExitFailure;
    }
    std::cerr << "wrote " << path.string() << "\n";
  }
  return 0;
}

int Main(int argc, char** argv) {
  CLI::App app{"Reproduces the tables of the papers behind swarmplan's planners."};
  app.require_subcommand(1);

  app.add_subcommand("list", "List the experiments: name, what it reproduces, results file.");

  std::vector<std::string> names;
  ExperimentOptions options;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  options.log = &std::cerr;
  std::string output_dir;
  CLI::App* run = app.add_subcommand("run", "Run experiments and print or write their reports.");
  run->add_option("experiments", names, "Experiment names, or `all`.")->required();
  run->add_option("--runs", options.runs, "Runs per table cell (default: each experiment's own).")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--seed", options.seed, "First seed; run i uses seed + i.")
      ->check(CLI::PositiveNumber);
  run->add_flag("--quick", options.quick,
                "A few short runs: checks the pipeline; the numbers mean nothing.");
  run->add_option("--jobs", options.jobs,
                  "Threads for an experiment's independent runs (those that support it); the "
                  "report is the same for any number.")
      ->check(CLI::Range(1, 64));
  run->add_option("--worlds-dir", options.worlds_dir, "Where the shipped worlds are.");
  run->add_option("--output-dir", output_dir,
                  "Write each report to DIR/<results file> instead of standard output.");

  std::string generate_dir = options.worlds_dir;
  std::vector<std::string> generate_names;
  CLI::App* generate =
      app.add_subcommand("generate", "Write the generated worlds of experiments (seeded).");
  generate->add_option("experiments", generate_names, "Experiment names, or `all`.")->required();
  generate->add_option("--worlds-dir", generate_dir, "Where to write them (one folder each).");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitBadUsage;
  }

  if (app.got_subcommand("list")) return ListExperiments();
  const std::vector<std::string>& chosen = app.got_subcommand("run") ? names : generate_names;
  std::vector<const Experiment*> experiments;
  for (const std::string& name : chosen) {
    if (name == "all") {
      for (const Experiment& experiment : Experiments()) experiments.push_back(&experiment);
      continue;
    }
    const Experiment* experiment = FindExperiment(name);
    if (experiment == nullptr) {
      std::cerr << "swarmplan-papers: error: unknown experiment '" << name
                << "'; `swarmplan-papers list` names them\n";
      return kExitBadUsage;
    }
    experiments.push_back(experiment);
  }
  if (app.got_subcommand("generate")) return Generate(experiments, generate_dir);
  std::vector<std::string> words = {"swarmplan-papers"};
  for (int i = 1; i < argc; ++i) words.push_back(argv[i]);
  return Run(experiments, options, output_dir, absl::StrJoin(words, " "));
}

}  // namespace
}  // namespace swarmplan::bench

int main(int argc, char** argv) { return swarmplan::bench::Main(argc, argv); }
