#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace swarmplan::bench {

// How `swarmplan-papers` runs one reproduction.
struct ExperimentOptions {
  int runs = 0;       // runs per cell of the table; 0: the experiment's default
  uint64_t seed = 1;  // first seed; run i uses seed + i
  // A few runs of a few iterations: checks that every row of the report is produced and every
  // path is valid, quickly. Its numbers say nothing about the planners.
  bool quick = false;
  // Threads an experiment may spread its independent runs over; the report does not depend on
  // it (only its times do).
  int jobs = 1;
  std::string worlds_dir;       // bench/worlds of the source tree: the shipped, generated worlds
  std::ostream* log = nullptr;  // progress lines; may be null
};

// One table (or group of tables) of a paper, reproduced with our planners.
struct Experiment {
  std::string name;          // command-line name, e.g. "aem-bso-functions"
  std::string reproduces;    // what of which paper, e.g. "AEM-BSO Table 1"
  std::string results_file;  // where its report is kept, relative to bench/results/
  // Runs the experiment and returns its report as Markdown.
  std::function<absl::StatusOr<std::string>(const ExperimentOptions&)> run;
  // Writes the experiment's generated worlds into `dir` (a subfolder of bench/worlds named after
  // the experiment); null when it needs none. The shipped files are what this writes.
  std::function<absl::Status(const std::string& dir)> generate;
};

// Every reproduction, in the order of bench/README.md.
const std::vector<Experiment>& Experiments();

// nullptr when no experiment has this name.
const Experiment* FindExperiment(const std::string& name);

}  // namespace swarmplan::bench
