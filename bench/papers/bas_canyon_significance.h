#pragma once

// The tests behind the bas-canyon report's comparisons: for a pair of rows, rank-sum on the
// fitness of the found paths and Fisher on the found runs, against the paper's claim that the
// second row's fitness is the lower.

#include <optional>
#include <string>
#include <vector>

#include "bench/papers/bas_canyon_runs.h"

namespace swarmplan::bench::bas {

struct ClaimedPair {
  std::string reference;
  std::string other;  // the paper claims (or we ask) that its fitness is lower than reference's
  std::string claim;  // e.g. "paper: LFS-BAS beats ACO"
};

struct PairTest {
  ClaimedPair pair;
  RankComparison fitness;         // other against reference
  std::optional<double> found_p;  // Fisher on the found runs
  bool supported() const { return Significant(fitness.p) && !fitness.other_higher; }
  bool contradicted() const { return Significant(fitness.p) && fitness.other_higher; }
};

// Pairs whose rows are both in `set`, tested; other pairs are skipped.
std::vector<PairTest> TestPairs(const RowSet& set, const std::vector<ClaimedPair>& pairs);

// reference | other | claim | medians [95 % CI] | rank-sum p | Fisher p (found) | verdict.
std::string SignificanceTable(const RowSet& set, const std::vector<PairTest>& tests);

// "supported", "contradicted" or "not significant".
std::string Verdict(const PairTest& test);

}  // namespace swarmplan::bench::bas
