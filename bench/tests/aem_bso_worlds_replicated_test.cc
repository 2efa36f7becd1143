#include "bench/papers/aem_bso_worlds_replicated.h"

#include <set>
#include <string>

#include "absl/strings/str_cat.h"
#include "bench/papers/experiments.h"
#include "bench/papers/markdown_table.h"
#include "core/graph/visibility_graph.h"
#include "core/map/io/map_writers.h"
#include "core/path_metrics.h"
#include "gtest/gtest.h"

namespace swarmplan::bench::aem_bso {
namespace {

TEST(AemBsoReplicatedWorldsTest, WorldZeroIsTheShippedWorld) {
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    absl::StatusOr<ShapeWorld> shipped = MakeAemBsoWorld(spec);
    absl::StatusOr<ShapeWorld> first = MakeAemBsoWorld(ReplicatedSpec(spec, 0));
    ASSERT_TRUE(shipped.ok() && first.ok()) << spec.name;
    EXPECT_EQ(FormatShapesJson(*shipped, "x"), FormatShapesJson(*first, "x")) << spec.name;
  }
}

// Every drawn world is a different, non-trivial and solvable world of its environment, and
// drawing it again gives the same world.
TEST(AemBsoReplicatedWorldsTest, WorldsAreDistinctSolvableAndDeterministic) {
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    std::set<std::string> seen;
    for (int index = 0; index < kReplicatedWorlds; ++index) {
      const AemBsoWorldSpec world_spec = ReplicatedSpec(spec, index);
      EXPECT_EQ(world_spec.seed, spec.seed + index * kWorldSeedStride);
      absl::StatusOr<ShapeWorld> world = MakeAemBsoWorld(world_spec);
      absl::StatusOr<ShapeWorld> again = MakeAemBsoWorld(world_spec);
      ASSERT_TRUE(world.ok() && again.ok()) << spec.name << " " << index;
      const std::string json = FormatShapesJson(*world, "x");
      EXPECT_EQ(json, FormatShapesJson(*again, "x"));
      EXPECT_TRUE(seen.insert(json).second) << spec.name << " world " << index << " repeats";
      EXPECT_EQ(world->circles().size(), static_cast<size_t>(spec.circles));
      EXPECT_TRUE(SegmentBlocked(*world, AemBsoStart(), AemBsoGoal(), kAemBsoSafeDistance));
      EXPECT_TRUE(
          ShortestPathVisibility(*world, AemBsoStart(), AemBsoGoal(), kAemBsoSafeDistance, 0.01)
              .ok());
    }
  }
}

// The quick report has the per-world and pooled tables, each world's row with its seed and its
// exact optimum.
TEST(AemBsoReplicatedWorldsTest, ReportHasPerWorldAndPooledTables) {
  ExperimentOptions options;
  options.quick = true;
  options.worlds_dir = std::string(SWARMPLAN_SOURCE_DIR) + "/bench/worlds";
  absl::StatusOr<std::string> report = RunAemBsoWorlds(options);
  ASSERT_TRUE(report.ok()) << report.status();
  for (const char* text : {"## Table 3 on 2 worlds per environment", "| signed-rank |",
                           "With every environment drawn 2 times"}) {
    EXPECT_NE(report->find(text), std::string::npos) << text;
  }
  for (const AemBsoWorldSpec& spec : AemBsoWorldSpecs()) {
    for (int index = 0; index < 2; ++index) {
      const AemBsoWorldSpec world_spec = ReplicatedSpec(spec, index);
      absl::StatusOr<ShapeWorld> world = MakeAemBsoWorld(world_spec);
      ASSERT_TRUE(world.ok());
      absl::StatusOr<Path> path =
          ShortestPathVisibility(*world, AemBsoStart(), AemBsoGoal(), kAemBsoSafeDistance, 0.01);
      ASSERT_TRUE(path.ok());
      const std::string row =
          absl::StrCat("| ", spec.name, " | ", index == 0 ? "0 (shipped)" : "1", " | ",
                       world_spec.seed, " | ", NumberCell(PathLength(*path)), " |");
      EXPECT_NE(report->find(row), std::string::npos) << row;
    }
  }
}

}  // namespace
}  // namespace swarmplan::bench::aem_bso
