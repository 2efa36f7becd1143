#pragma once

#include <cstddef>
#include <vector>

#include "core/map/io/map_io.h"

namespace swarmplan::bench {

// Which problems of a .scen file to run.
struct ScenarioSelection {
  enum class Mode {
    kPerBucket,  // `count` problems from every bucket, spread evenly inside the bucket
    kEvenly,     // `count` problems spread evenly over the whole file
    kAll,        // every problem
  };
  Mode mode = Mode::kPerBucket;
  int count = 1;
};

// Indices into `scenarios`, in file order, without repeats. Buckets are taken as the file
// groups them (consecutive records with the same bucket number).
std::vector<size_t> SelectScenarios(const std::vector<Scenario>& scenarios,
                                    const ScenarioSelection& selection);

}  // namespace swarmplan::bench
