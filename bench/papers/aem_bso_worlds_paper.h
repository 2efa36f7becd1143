#pragma once

// The AEM-BSO paper's path-planning numbers (Tables 2-3) and the planners and interpolations they
// cover.

#include <optional>
#include <string>
#include <vector>

namespace swarmplan::bench::aem_bso {

// Table 3's planners with aem-bso-linear (the paper's AEM-BSO2), and Table 2's interpolations.
const std::vector<std::string>& Planners();
const std::vector<std::string>& Interpolations();

// The paper's numbers for one row of an environment; nullopt where it gives none.
struct PaperCell {
  std::optional<double> shortest, mean, std_dev, seconds;
};

// Table 2: aem-bso with each interpolation. Keys: environment, interpolation.
std::optional<PaperCell> PaperTable2(const std::string& world, const std::string& interpolation);
// Table 3: the four planners with the spline. Keys: environment, planner.
std::optional<PaperCell> PaperTable3(const std::string& world, const std::string& planner);
// The shortest path of any row of the paper's Tables 2 and 3 for the environment.
std::optional<double> PaperShortest(const std::string& world);

}  // namespace swarmplan::bench::aem_bso
