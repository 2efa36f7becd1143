#pragma once

// What the runs of the AEM-BSO path-planning reproduction gave on one environment.

#include <map>
#include <string>
#include <utility>

#include "bench/papers/aem_bso_worlds_generate.h"
#include "bench/papers/aem_bso_worlds_runs.h"
#include "bench/papers/aem_bso_worlds_variants.h"

namespace swarmplan::bench::aem_bso {

struct WorldRun {
  AemBsoWorldSpec spec;
  double optimum = 0.0;
  double straight = 0.0;
  std::map<std::pair<std::string, std::string>, CellStats> cells;  // (planner, interpolation)
  VariantRuns variants;  // the baselines' unstated settings, equal budgets
};

}  // namespace swarmplan::bench::aem_bso
