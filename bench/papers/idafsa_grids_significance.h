#pragma once

// The IDAFSA reproduction's tests of idafsa against the other configurations: success by
// Fisher's exact test, lengths and turning points of the successful runs by rank-sum, medians
// with bootstrap 95 % intervals, and the paper's headline held against them.

#include <optional>
#include <string>
#include <vector>

#include "bench/papers/comparison.h"
#include "bench/papers/idafsa_grids_runs.h"

namespace swarmplan::bench {

// What one configuration's runs give to the comparisons.
struct ComparedRuns {
  std::string label;
  SuccessCount success;
  std::vector<double> lengths;         // of the successful runs, raw or over the world's optimum
  std::vector<double> turning_points;  // of the successful runs
};

ComparedRuns CompareRunsOf(const std::string& label, const FishRunStats& stats);

// The tests of `other` against `reference`; nullopt where a sample is empty.
struct ComparisonTests {
  std::optional<double> success_p;
  std::optional<double> length_p;
  std::optional<double> turning_p;
};
ComparisonTests TestAgainst(const ComparedRuns& reference, const ComparedRuns& other);

// A table with a row per configuration, `reference` first: success and Fisher's p, median length
// and median turning points with their intervals and rank-sum p against `reference`.
std::string ComparisonTable(const ComparedRuns& reference, const std::vector<ComparedRuns>& others,
                            const std::string& length_heading);

// The differences from `reference` that the tests support, e.g. "dafsa's length higher
// (p = 0.003), afsa-8 found fewer (p = 1e-08)"; "none" when there are none.
std::string SupportedDifferences(const ComparedRuns& reference,
                                 const std::vector<ComparedRuns>& others);

// One claim for idafsa tested against one baseline: p nullopt when the runs allow no test.
struct ClaimTest {
  std::string baseline;
  std::optional<double> p;
  bool idafsa_better = false;  // the direction of the difference, meaningful when p is small
};
// "Shorter paths: supported against dafsa (p = 0.002); not significant against afsa-4
// (p = 0.41); untestable against afsa-8 (...)."
std::string ClaimVerdict(const std::string& claim, const std::vector<ClaimTest>& tests,
                         const std::string& why_untestable);

// What the tests say about one claim against one baseline.
enum class ClaimOutcome { kSupported, kReversed, kNotSignificant, kUntestable };
ClaimOutcome OutcomeOf(const ClaimTest& test);
// "supported", "reversed", "not significant" or "untestable".
std::string OutcomeName(ClaimOutcome outcome);

// One of the paper's claims for idafsa tested against every baseline.
struct ClaimTests {
  std::string claim;           // e.g. "Shorter paths"
  std::string why_untestable;  // when a test has no p
  std::vector<ClaimTest> tests;
};
std::string ClaimVerdict(const ClaimTests& claim);

// The paper's claims for idafsa (shorter paths, fewer turning points, higher success) tested
// against each of `baselines`.
std::vector<ClaimTests> HeadlineClaims(const ComparedRuns& idafsa,
                                       const std::vector<ComparedRuns>& baselines);

// Which of the paper's claims for idafsa (shorter paths, fewer turning points, higher success)
// the tests support against each of `baselines`: per claim the configurations where idafsa is
// significantly better, where it is significantly worse, and where the runs do not tell.
std::string HeadlineVerdict(const ComparedRuns& idafsa, const std::vector<ComparedRuns>& baselines);

}  // namespace swarmplan::bench
