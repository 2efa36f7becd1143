#include "bench/papers/experiment.h"

#include "bench/papers/experiments.h"

namespace swarmplan::bench {

const std::vector<Experiment>& Experiments() {
  static const std::vector<Experiment>* const experiments = new std::vector<Experiment>{
      {"aem-bso-functions", "AEM-BSO Table 1", "aem-bso-functions.md", RunAemBsoFunctions, nullptr},
      {"aem-bso-worlds", "AEM-BSO Tables 2-3, Fig. 4", "aem-bso-worlds.md", RunAemBsoWorlds,
       GenerateAemBsoWorlds},
      {"bas-canyon", "BAS Tables 2-4, Figs. 6, 10-11", "bas-canyon.md", RunBasCanyon,
       GenerateBasCanyon},
      {"terrain-yardsticks", "terrain section of exact-yardsticks.md (lattice optimum on DEMs)",
       "exact-yardsticks-terrain.md", RunTerrainYardsticks, nullptr},
      {"as-bfo-islands", "AS-BFO Table 4, sections 4.1-4.2", "as-bfo-islands.md", RunAsBfoIslands,
       GenerateAsBfoIslands},
      {"idafsa-grids", "IDAFSA Tables 2-3", "idafsa-grids.md", RunIdafsaGrids, GenerateIdafsaGrids},
      {"bpso-vertices", "Binary PSO Table 1, Figs. 4-5", "bpso-vertices.md", RunBpsoVertices,
       GenerateBpsoVertices},
  };
  return *experiments;
}

const Experiment* FindExperiment(const std::string& name) {
  for (const Experiment& experiment : Experiments()) {
    if (experiment.name == name) return &experiment;
  }
  return nullptr;
}

}  // namespace swarmplan::bench
