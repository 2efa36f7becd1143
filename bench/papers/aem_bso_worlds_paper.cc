#include "bench/papers/aem_bso_worlds_paper.h"

#include <algorithm>
#include <map>
#include <utility>

namespace swarmplan::bench::aem_bso {

const std::vector<std::string>& Planners() {
  static const std::vector<std::string>* const planners =
      new std::vector<std::string>{"aem-bso", "aem-bso-linear", "bso", "pso", "ba"};
  return *planners;
}
const std::vector<std::string>& Interpolations() {
  static const std::vector<std::string>* const names =
      new std::vector<std::string>{"spline", "linear", "nearest"};
  return *names;
}

// Table 2: aem-bso with each interpolation. Keys: environment, interpolation.
std::optional<PaperCell> PaperTable2(const std::string& world, const std::string& interpolation) {
  static const std::map<std::pair<std::string, std::string>, PaperCell>* const table =
      new std::map<std::pair<std::string, std::string>, PaperCell>{
          {{"simple", "linear"}, {120.68, 121.08, std::nullopt, 2.62}},
          {{"simple", "nearest"}, {158.81, 159.28, std::nullopt, 2.60}},
          {{"simple", "spline"}, {114.86, 146.29, std::nullopt, 2.64}},
          {{"complex", "linear"}, {115.24, 139.67, std::nullopt, 5.20}},
          {{"complex", "nearest"}, {159.01, 159.76, std::nullopt, 4.89}},
          {{"complex", "spline"}, {116.17, 160.19, std::nullopt, 4.94}},
      };
  auto it = table->find({world, interpolation});
  if (it == table->end()) return std::nullopt;
  return it->second;
}

// Table 3: the four planners with the spline. Keys: environment, planner.
std::optional<PaperCell> PaperTable3(const std::string& world, const std::string& planner) {
  static const std::map<std::pair<std::string, std::string>, PaperCell>* const table =
      new std::map<std::pair<std::string, std::string>, PaperCell>{
          {{"simple", "aem-bso"}, {114.11, 121.65, 1.50, 2.35}},
          {{"simple", "bso"}, {115.00, 209.06, 99.04, 2.35}},
          {{"simple", "pso"}, {121.67, 361.94, 247.32, 0.78}},
          {{"simple", "ba"}, {115.48, 310.81, 609.00, 0.79}},
          {{"complex", "aem-bso"}, {115.94, 158.51, 8.57, 4.60}},
          {{"complex", "bso"}, {116.22, 162.20, 11.55, 4.62}},
          {{"complex", "pso"}, {141.59, 279.31, 262.14, 1.54}},
          {{"complex", "ba"}, {126.59, 165.53, 9.98, 1.58}},
      };
  auto it = table->find({world, planner});
  if (it == table->end()) return std::nullopt;
  return it->second;
}

std::optional<double> PaperShortest(const std::string& world) {
  std::optional<double> shortest;
  auto consider = [&](const std::optional<PaperCell>& cell) {
    if (!cell.has_value() || !cell->shortest.has_value()) return;
    shortest = std::min(shortest.value_or(*cell->shortest), *cell->shortest);
  };
  for (const std::string& interpolation : Interpolations()) {
    consider(PaperTable2(world, interpolation));
  }
  for (const std::string& planner : Planners()) consider(PaperTable3(world, planner));
  return shortest;
}

}  // namespace swarmplan::bench::aem_bso
