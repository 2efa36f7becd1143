#include "bench/papers/idafsa_grids_moves.h"

#include <string>
#include <variant>
#include <vector>

#include "gtest/gtest.h"

namespace swarmplan::bench {
namespace {

TEST(IdafsaGridsMovesTest, RandomCloserMovesAreTheOldMovesWithoutCulling) {
  const FishConfig config{"dafsa", "dafsa", {{"population", int64_t{10}}}};
  const FishConfig old = WithRandomCloserMoves(config);
  EXPECT_EQ(old.label, "dafsa");
  EXPECT_EQ(old.algorithm, "dafsa");
  EXPECT_EQ(std::get<std::string>(old.params.at("move")), "random-closer");
  EXPECT_FALSE(std::get<bool>(old.params.at("prey_culling")));
  EXPECT_EQ(std::get<int64_t>(old.params.at("population")), 10);
}

TEST(IdafsaGridsMovesTest, OutcomesFollowTheSignificanceLevelAndDirection) {
  EXPECT_EQ(OutcomeOf({"dafsa", std::nullopt, true}), ClaimOutcome::kUntestable);
  EXPECT_EQ(OutcomeOf({"dafsa", 0.2, true}), ClaimOutcome::kNotSignificant);
  EXPECT_EQ(OutcomeOf({"dafsa", 0.01, true}), ClaimOutcome::kSupported);
  EXPECT_EQ(OutcomeOf({"dafsa", 0.01, false}), ClaimOutcome::kReversed);
}

TEST(IdafsaGridsMovesTest, CountsTheVerdictsThatChange) {
  const std::vector<VerdictScope> paper = {
      {"10 x 10, shipped world",
       {{"Shorter paths", "", {{"dafsa", 0.01, true}, {"afsa-4", 0.3, true}}},
        {"Higher success", "", {{"dafsa", std::nullopt, false}, {"afsa-4", 0.02, false}}}}}};
  const std::vector<VerdictScope> before = {
      {"10 x 10, shipped world",
       {{"Shorter paths", "", {{"dafsa", 0.2, true}, {"afsa-4", 0.5, false}}},
        {"Higher success", "", {{"dafsa", std::nullopt, false}, {"afsa-4", 0.01, false}}}}}};
  std::string summary;
  const std::string section = MovesVerdictSection(paper, before, &summary);
  EXPECT_EQ(summary,
            "the paper's moves change 1 of the 4 per-claim verdicts, 1 to supported and 0 from "
            "supported (10 x 10, shipped world, "
            "shorter paths against dafsa: supported, was not significant)");
  EXPECT_NE(section.find("| 10 x 10, shipped world | Shorter paths | dafsa | supported (p = "
                         "0.010) | not significant (p = 0.200) | **yes** |"),
            std::string::npos)
      << section;
  MovesVerdictSection(paper, paper, &summary);
  EXPECT_EQ(summary, "the paper's moves change none of the 4 per-claim verdicts");
}

}  // namespace
}  // namespace swarmplan::bench
