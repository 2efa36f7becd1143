#include "bench/papers/bas_canyon_significance.h"

#include "bench/papers/markdown_table.h"

namespace swarmplan::bench::bas {

std::vector<PairTest> TestPairs(const RowSet& set, const std::vector<ClaimedPair>& pairs) {
  std::vector<PairTest> out;
  for (const ClaimedPair& pair : pairs) {
    const RowRuns* reference = set.Find(pair.reference);
    const RowRuns* other = set.Find(pair.other);
    if (reference == nullptr || other == nullptr) continue;
    PairTest test;
    test.pair = pair;
    test.fitness = CompareRanks(reference->fitness, other->fitness);
    test.found_p = SuccessP(reference->found(), other->found());
    out.push_back(test);
  }
  return out;
}

std::string Verdict(const PairTest& test) {
  if (test.supported()) return "supported";
  if (test.contradicted()) return "contradicted";
  return "not significant";
}

std::string SignificanceTable(const RowSet& set, const std::vector<PairTest>& tests) {
  MarkdownTable table({"reference", "other", "claim (other's fitness lower)",
                       "reference median [95 % CI]", "other median [95 % CI]",
                       "rank-sum p (fitness)", "Fisher p (found)", "verdict"});
  for (const PairTest& test : tests) {
    table.AddRow({test.pair.reference, test.pair.other, test.pair.claim,
                  MedianWithInterval(set.Find(test.pair.reference)->fitness),
                  MedianWithInterval(set.Find(test.pair.other)->fitness),
                  PValueCell(test.fitness.p), PValueCell(test.found_p), Verdict(test)});
  }
  return table.ToString();
}

}  // namespace swarmplan::bench::bas
