// `positions` (box or far) in every waypoint swarm optimiser, on bowls whose minimum lies outside
// the box, and `box_inset`, the search box of the paper's initialisation inside a larger map.

#include <memory>
#include <string>
#include <vector>

#include "core/algorithms/bso/swarm_options.h"
#include "core/map/map.h"
#include "core/map/shape_world.h"
#include "core/operators/waypoint_objective.h"
#include "core/planner.h"
#include "core/random.h"
#include "core/registry.h"
#include "core/stop_token.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

// f(x) = |x - minimum|^2 on the box [0, 10]^2, remembering every point it evaluates.
class RecordingBowl final : public Objective {
 public:
  explicit RecordingBowl(Eigen::Vector2d minimum) : minimum_(std::move(minimum)) {}
  int dim() const override { return 2; }
  const Eigen::VectorXd& lower() const override { return lo_; }
  const Eigen::VectorXd& upper() const override { return hi_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override {
    points.push_back(x);
    return {(x - minimum_).squaredNorm(), true};
  }

  std::vector<Eigen::VectorXd> points;

 private:
  Eigen::Vector2d minimum_;
  Eigen::VectorXd lo_ = Eigen::Vector2d(0, 0), hi_ = Eigen::Vector2d(10, 10);
};

const std::vector<std::string>& SwarmPlanners() {
  static const std::vector<std::string>* const ids =
      new std::vector<std::string>{"bso", "aem-bso", "aem-bso-linear", "pso", "ba"};
  return *ids;
}

SearchOutcome RunOptimiser(const std::string& planner, const std::string& positions,
                           RecordingBowl& bowl) {
  const PlannerInfo* info = DefaultRegistry().Find(planner);
  EXPECT_NE(info, nullptr) << planner;
  absl::StatusOr<ParamSet> params =
      ParamSet::Resolve(info->params, {{"positions", positions}, {"population", int64_t{20}}});
  EXPECT_TRUE(params.ok()) << params.status();
  absl::StatusOr<SwarmOptimiser> optimiser = SwarmOptimiserFor(planner, *params);
  EXPECT_TRUE(optimiser.ok()) << optimiser.status();
  Rng rng(7);
  NullObserver observer;
  return (*optimiser)(bowl, 60, rng, StopToken(), observer);
}

bool Within(const Eigen::VectorXd& x, double lo, double hi) {
  return x.minCoeff() >= lo && x.maxCoeff() <= hi;
}

TEST(PositionBoundTest, BoxKeepsEveryEvaluatedPointInTheBox) {
  for (const std::string& planner : SwarmPlanners()) {
    RecordingBowl bowl(Eigen::Vector2d(25, -5));
    RunOptimiser(planner, "box", bowl);
    ASSERT_FALSE(bowl.points.empty());
    for (const Eigen::VectorXd& x : bowl.points) {
      ASSERT_TRUE(Within(x, 0.0, 10.0)) << planner << ": " << x.transpose();
    }
  }
}

TEST(PositionBoundTest, FarLeavesTheBoxForAMinimumOutsideIt) {
  // The best point of the box is its corner (10, 0), at fitness 15^2 + 5^2 = 250.
  for (const std::string& planner : SwarmPlanners()) {
    RecordingBowl bowl(Eigen::Vector2d(25, -5));
    const SearchOutcome outcome = RunOptimiser(planner, "far", bowl);
    EXPECT_LT(outcome.best_fitness, 200.0) << planner;
    EXPECT_FALSE(Within(outcome.best_x, 0.0, 10.0)) << planner;
  }
}

TEST(PositionBoundTest, FarStopsTenSpansBeyondTheBox) {
  for (const std::string& planner : SwarmPlanners()) {
    RecordingBowl bowl(Eigen::Vector2d(1e6, -1e6));
    RunOptimiser(planner, "far", bowl);
    for (const Eigen::VectorXd& x : bowl.points) {
      ASSERT_TRUE(Within(x, -100.0, 110.0)) << planner << ": " << x.transpose();
    }
  }
}

TEST(PositionBoundTest, FarClampsToTheGrownBox) {
  const RecordingBowl bowl(Eigen::Vector2d(0, 0));
  Eigen::VectorXd x = Eigen::Vector2d(-500, 50);
  bowl.Bound(PositionBound::kFar, x);
  EXPECT_EQ(x, Eigen::Vector2d(-100, 50));
  bowl.Bound(PositionBound::kBox, x);
  EXPECT_EQ(x, Eigen::Vector2d(0, 10));
}

Problem WorldProblem() {
  Problem problem;
  problem.map = std::make_shared<Map>(*ShapeWorld::Create({{0, 0}, {100, 60}}, {}, {}));
  problem.start = {40, 30, 0};
  problem.goal = {60, 30, 0};
  return problem;
}

TEST(BoxInsetTest, ShrinksTheSearchBoxOnEachSide) {
  WaypointFitnessOptions options;
  options.waypoints = 2;
  absl::StatusOr<std::unique_ptr<WaypointObjective>> objective =
      WaypointObjective::Create(WorldProblem(), options, 20.0);
  ASSERT_TRUE(objective.ok()) << objective.status();
  EXPECT_EQ((*objective)->lower(), Eigen::Vector4d(20, 20, 20, 20));
  EXPECT_EQ((*objective)->upper(), Eigen::Vector4d(80, 80, 40, 40));
}

TEST(BoxInsetTest, RejectsAnInsetThatLeavesNoBox) {
  WaypointFitnessOptions options;
  absl::StatusOr<std::unique_ptr<WaypointObjective>> objective =
      WaypointObjective::Create(WorldProblem(), options, 30.0);
  ASSERT_FALSE(objective.ok());
  EXPECT_EQ(objective.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(objective.status().message().find("box_inset"), std::string::npos);
}

TEST(BoxInsetTest, PlannersSearchInsideTheInsetBox) {
  // With straight segments the raw path is start, the two waypoints, goal: the best position.
  for (const std::string& planner : SwarmPlanners()) {
    const PlannerInfo* info = DefaultRegistry().Find(planner);
    ASSERT_NE(info, nullptr);
    absl::StatusOr<ParamSet> params =
        ParamSet::Resolve(info->params, {{"init", std::string("paper")},
                                         {"box_inset", 20.0},
                                         {"waypoints", int64_t{2}},
                                         {"interpolation", std::string("linear")},
                                         {"iterations", int64_t{5}},
                                         {"population", int64_t{10}}});
    ASSERT_TRUE(params.ok()) << params.status();
    std::unique_ptr<Planner> p = info->factory(*params);
    NullObserver observer;
    absl::StatusOr<SearchResult> result = p->Solve(WorldProblem(), StopToken(), observer);
    ASSERT_TRUE(result.ok()) << planner << ": " << result.status();
    ASSERT_EQ(result->path.size(), 4u) << planner;
    for (size_t i = 1; i <= 2; ++i) {
      const Point3& q = result->path[i];
      EXPECT_TRUE(q.x() >= 20 && q.x() <= 80 && q.y() >= 20 && q.y() <= 40)
          << planner << ": " << q.transpose();
    }
  }
}

}  // namespace
}  // namespace swarmplan
