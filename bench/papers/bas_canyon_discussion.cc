#include "bench/papers/bas_canyon_discussion.h"

#include <cmath>
#include <optional>

#include "absl/strings/str_cat.h"
#include "bench/papers/bas_canyon_paper.h"
#include "bench/papers/markdown_table.h"
#include "bench/significance.h"
#include "bench/statistics.h"

namespace swarmplan::bench::bas {
namespace {

std::string MedianText(const RowSet& set, const std::string& label) {
  const RowRuns* runs = set.Find(label);
  return runs == nullptr ? "–" : NumberCell(Median(runs->fitness));
}

std::string PText(std::optional<double> p) {
  return p.has_value() ? FormatPValue(*p, /*mark_significant=*/false) : "no test";
}

// "lfs-bas (median 177.8) against aco (103.7): contradicted, rank-sum p = 2e-11".
std::string PairSentence(const RowSet& set, const PairTest& test) {
  return absl::StrCat(test.pair.other, " (median ", MedianText(set, test.pair.other), ") against ",
                      test.pair.reference, " (", MedianText(set, test.pair.reference),
                      "): ", Verdict(test), ", rank-sum ", PText(test.fitness.p));
}

std::string ReplicatedSentence(const ReplicatedPairTest& test) {
  return absl::StrCat(test.pair.other, " against ", test.pair.reference, ": lower in ",
                      test.worlds_other_lower, " of ", test.worlds, " worlds, signed-rank ",
                      PText(test.signed_rank_p), "; found ", test.other_found.successes, "/",
                      test.other_found.runs, " against ", test.reference_found.successes, "/",
                      test.reference_found.runs, " (Fisher ", PText(test.pooled_found_p), "), ",
                      test.supported()      ? "supported"
                      : test.contradicted() ? "contradicted"
                                            : "not significant");
}

bool AllSupported(const std::vector<PairTest>& tests) {
  for (const PairTest& test : tests) {
    if (!test.supported()) return false;
  }
  return !tests.empty();
}

std::string HeadlineItems(const DiscussionInputs& in) {
  std::string out;
  for (const PairTest& test : in.headline) {
    absl::StrAppend(&out, "- ", test.pair.claim, ": ", PairSentence(in.shipped, test), ".\n");
  }
  return out;
}

// Table C: how often smaller initial steps improve on the first path, and the best median.
std::string StepItem(const DiscussionInputs& in) {
  std::string counts;
  std::string best_label;
  std::optional<double> best_median;
  for (const std::string& label : in.step_labels) {
    const RowRuns* row = in.shipped.Find(label);
    if (row == nullptr) continue;
    AppendListItem(&counts, absl::StrCat(label, ": ", row->improved, "/", row->runs));
    const std::optional<double> median = Median(row->fitness);
    if (median && (!best_median || *median < *best_median)) {
      best_median = median;
      best_label = label;
    }
  }
  if (counts.empty()) return "";
  return absl::StrCat("- Table C, runs that improve on their first path: ", counts,
                      ". Lowest median: ", best_label, ", ", NumberCell(best_median), " = ",
                      best_median ? NumberCell(*best_median / in.yardstick) : "–",
                      " x the lattice yardstick.\n");
}

std::string FirstPathItem(const DiscussionInputs& in) {
  int runs = 0, improved = 0;
  std::string never;
  for (const std::string& label : in.paper_setting_labels) {
    const RowRuns* row = in.shipped.Find(label);
    if (row == nullptr) continue;
    runs += row->found().successes;
    improved += row->improved;
    if (row->improved == 0) AppendListItem(&never, label);
  }
  return absl::StrCat(
      "- At the paper's step (δ0 = ", kPaperStep0, " cells, every move taken) ", improved, " of ",
      runs, " found runs of the beetle rows (", in.paper_setting_labels.size(),
      " rows) end better than their first path", never.empty() ? "" : "; never: ", never,
      ". A move δ·b with a random unit b shifts each of the ", in.dimensions, " coordinates by δ/√",
      in.dimensions, " = ",
      NumberCell(kPaperStep0 / std::sqrt(static_cast<double>(in.dimensions)), 3),
      " cells (rms) at the start, and the first path hugs the ground, so about half of the "
      "waypoints go under it and pay the penalty.\n",
      StepItem(in));
}

// The ACO baseline's rows ("aco", "aco (200 iterations)"), not ACO-BAS's.
bool IsAco(const std::string& label) { return label == "aco" || label.rfind("aco (", 0) == 0; }

std::string OptionItems(const DiscussionInputs& in) {
  std::string out;
  for (const PairTest& test : in.options) {
    const RowRuns* other = in.shipped.Find(test.pair.other);
    const RowRuns* reference = in.shipped.Find(test.pair.reference);
    if (other == nullptr || reference == nullptr) continue;
    const std::optional<double> median = Median(other->fitness);
    const std::string against =
        absl::StrCat("against ", test.pair.reference, " (median ",
                     MedianText(in.shipped, test.pair.reference), "): ", Verdict(test),
                     " (claim: ", test.pair.claim, "; rank-sum ", PText(test.fitness.p), ")");
    if (IsAco(test.pair.reference)) {
      absl::StrAppend(&out, "- ", test.pair.other, " ", against, ".\n");
      continue;
    }
    absl::StrAppend(&out, "- ", test.pair.other, ": improves on its first path in ",
                    other->improved, "/", other->runs, " runs (", test.pair.reference, ": ",
                    reference->improved, "/", reference->runs, ", Fisher ",
                    PText(SuccessP(reference->improved_count(), other->improved_count())),
                    "); median ", NumberCell(median), " = ",
                    median ? NumberCell(*median / in.yardstick) : "–", " x the lattice yardstick; ",
                    against, ".\n");
  }
  return out;
}

std::string SweepItems(const DiscussionInputs& in) {
  std::string out;
  for (const PairTest& test : in.sweep) {
    absl::StrAppend(&out, "- ", test.pair.other, " (median ",
                    MedianText(in.sweep_set, test.pair.other), ") against ", test.pair.reference,
                    " (", MedianText(in.sweep_set, test.pair.reference), "): ",
                    test.supported()      ? "lower"
                    : test.contradicted() ? "higher"
                                          : "no significant difference",
                    ", rank-sum ", PText(test.fitness.p), ".\n");
  }
  return out;
}

std::string MovedStartVerdict(const MovedStartTest& t) {
  if (t.supported()) return "reproduced";
  if (Significant(t.p) && t.lfs_right.rate() < t.aco_bas_right.rate()) return "contradicted";
  return "not reproduced";
}

std::string MovedStartItem(const DiscussionInputs& in) {
  const MovedStartTest& t = in.moved_start;
  return absl::StrCat(
      "- Fig. 6 (start moved toward the shallow left side): the paper's LFS-BAS still finds the "
      "deep right branch where its ACO-BAS falls into the left one. Ours: lfs-bas ends in the "
      "right branch in ",
      t.lfs_right.successes, "/", t.lfs_right.runs, " runs, aco-bas in ", t.aco_bas_right.successes,
      "/", t.aco_bas_right.runs, " (Fisher ", PText(t.p), "): ", MovedStartVerdict(t), ".\n");
}

}  // namespace

std::string Discussion(const DiscussionInputs& in) {
  std::vector<PairTest> family_vs_aco;
  for (const PairTest& test : in.headline) {
    if (test.pair.reference == "aco") family_vs_aco.push_back(test);
  }
  int replicated_supported = 0;
  std::string replicated;
  for (const ReplicatedPairTest& test : in.replicated) {
    if (test.supported()) ++replicated_supported;
    absl::StrAppend(&replicated, "- ", ReplicatedSentence(test), ".\n");
  }
  return absl::StrCat(
      "## Discussion\n\n"
      "Computed from this run; a difference counts only at p < ",
      kSignificanceLevel, " (rank-sum on the fitness of found paths, Fisher on counts).\n\n",
      "**The paper's claims on the shipped canyon (Tables A and B).** The headline that the BAS "
      "family beats ACO is ",
      AllSupported(family_vs_aco) ? "reproduced" : "not reproduced", ".\n", HeadlineItems(in),
      "\n**Why the beetles stay where they start.**\n", FirstPathItem(in),
      "\n**Two options of ours (Table D): init=paper with infeasible moves undone and/or steps "
      "scaled to the map.**\n",
      OptionItems(in),
      "\n**Table 3 (iterations).** Run i of every iteration count has the same seed, so a shorter "
      "run is the start of a longer one: equal rows mean no improvement after the shorter "
      "count.\n",
      SweepItems(in), "\n**Fig. 6 (moved start).**\n", MovedStartItem(in), "\n**Replication over ",
      in.replicated_worlds, " canyons** (", replicated_supported, " of ", in.replicated.size(),
      " pairs supported):\n", replicated,
      "\n**Caveats.** The paper's canyon is not published, so ours is an analogue: absolute "
      "fitness values cannot be compared, only rankings and the qualitative behaviour. The "
      "paper does not say what its beetle does with an invalid move (init=paper penalises it "
      "and keeps moving unless reject_infeasible is set).\n");
}

}  // namespace swarmplan::bench::bas
