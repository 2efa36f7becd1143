#pragma once

// The reproductions, one file each. Each Run* returns its Markdown report; each Generate* writes
// the worlds the experiment ships under bench/worlds/<experiment>/.

#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "bench/papers/experiment.h"

namespace swarmplan::bench {

// AEM-BSO paper, Table 1: the ten test functions (aem_bso_functions.cc).
absl::StatusOr<std::string> RunAemBsoFunctions(const ExperimentOptions& options);

// AEM-BSO paper, Tables 2-3: 100 x 100 worlds with 10 and 30 circles (aem_bso_worlds.cc).
absl::StatusOr<std::string> RunAemBsoWorlds(const ExperimentOptions& options);
absl::Status GenerateAemBsoWorlds(const std::string& dir);

// BAS paper: canyon terrain, ACO/BAS/LFS-BAS/ACO-BAS and SIO-BAS vs multi-BAS (bas_canyon.cc).
absl::StatusOr<std::string> RunBasCanyon(const ExperimentOptions& options);
absl::Status GenerateBasCanyon(const std::string& dir);

// The terrain section of exact-yardsticks.md: the terrain-lattice optimum on the shared DEMs
// and the terrain planners against it (terrain_yardsticks.cc).
absl::StatusOr<std::string> RunTerrainYardsticks(const ExperimentOptions& options);

// AS-BFO paper, Table 4 and the parameter sweeps of its section 4.1 (as_bfo_islands.cc).
absl::StatusOr<std::string> RunAsBfoIslands(const ExperimentOptions& options);
absl::Status GenerateAsBfoIslands(const std::string& dir);

// IDAFSA paper, Tables 2-3: 10 x 10 and 20 x 20 grids (idafsa_grids.cc).
absl::StatusOr<std::string> RunIdafsaGrids(const ExperimentOptions& options);
absl::Status GenerateIdafsaGrids(const std::string& dir);

// Binary PSO paper, Table 1, Fig. 4 and Fig. 5 (bpso_vertices.cc).
absl::StatusOr<std::string> RunBpsoVertices(const ExperimentOptions& options);
absl::Status GenerateBpsoVertices(const std::string& dir);

}  // namespace swarmplan::bench
