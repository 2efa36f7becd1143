#include <regex>
#include <set>
#include <string>
#include <vector>

#include "core/algorithms/register.h"
#include "core/registry.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

TEST(CatalogueTest, RegistersEveryPlannerOnceAndRefusesASecondCatalogue) {
  Registry registry;
  ASSERT_TRUE(RegisterAllPlanners(registry).ok());
  EXPECT_EQ(registry.Ids(), DefaultRegistry().Ids());
  const std::vector<std::string> ids = registry.Ids();
  const std::set<std::string> unique(ids.begin(), ids.end());
  EXPECT_EQ(unique.size(), ids.size());

  const absl::Status again = RegisterAllPlanners(registry);
  EXPECT_EQ(again.code(), absl::StatusCode::kAlreadyExists) << again;
  EXPECT_EQ(registry.Ids().size(), unique.size());
}

TEST(CatalogueTest, EveryPlannerCitesItsPaperNotAFile) {
  const std::regex file_name(R"(\.(txt|pdf|md)\b|seed \d{3})");
  const std::regex year_or_reason(R"((19|20)\d\d|not named)");
  for (const PlannerInfo& info : DefaultRegistry().planners()) {
    SCOPED_TRACE(info.id);
    EXPECT_FALSE(info.seed_paper.empty());
    EXPECT_FALSE(std::regex_search(info.seed_paper, file_name)) << info.seed_paper;
    EXPECT_TRUE(std::regex_search(info.seed_paper, year_or_reason)) << info.seed_paper;
  }
}

// The server caps population sizes by --max-population through this flag alone; a population
// parameter without it would escape the cap.
TEST(CatalogueTest, PopulationParametersSayTheySizeAPopulation) {
  const std::set<std::string> population_names = {"population", "ants", "particles",
                                                  "bacteria",   "fish", "beetles"};
  int flagged = 0;
  for (const PlannerInfo& info : DefaultRegistry().planners()) {
    for (const ParamSpec& spec : info.params) {
      SCOPED_TRACE(info.id + "." + spec.name);
      if (population_names.count(spec.name) > 0) {
        EXPECT_TRUE(spec.population_size);
      }
      if (spec.population_size) {
        EXPECT_EQ(spec.type, ParamType::kInt);
        ++flagged;
      }
    }
  }
  EXPECT_GT(flagged, 10);
}

}  // namespace
}  // namespace swarmplan
