#pragma once

// The "## Setup" section of the bas-canyon report: the map, start and goal, fitness, the paper's
// settings and ours, runs and seeds.

#include <cstdint>
#include <string>

#include "bench/papers/bas_canyon_world.h"

namespace swarmplan::bench::bas {

struct SetupFigures {
  int iterations = 0;             // Table A
  int population_iterations = 0;  // Table B
  int runs = 0;                   // Tables A-D
  int sweep_runs = 0;             // Table 3, Fig. 6
  int replicated_worlds = 0;
  int replicated_runs = 0;
  double map_step_fraction = 0.0;  // Table D
  uint64_t first_seed = 1;
};

std::string SetupSection(const CanyonWorld& world, const SetupFigures& figures);

// The yardstick's paragraph: the lattice, its fitness and where its path runs.
std::string YardstickParagraph(const CanyonWorld& world);

}  // namespace swarmplan::bench::bas
