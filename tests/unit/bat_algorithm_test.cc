// The bat algorithm's velocity bound and pulse rate schedules, replayed from the candidates it
// evaluates.

#include <algorithm>
#include <limits>
#include <vector>

#include "core/algorithms/baselines/ba.h"
#include "core/planner.h"
#include "core/random.h"
#include "core/stop_token.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

// f(x) = |x - (30, -20)|^2 on [-100, 100]^2, remembering every point it evaluates.
class RecordingBowl final : public Objective {
 public:
  int dim() const override { return 2; }
  const Eigen::VectorXd& lower() const override { return lo_; }
  const Eigen::VectorXd& upper() const override { return hi_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override {
    points.push_back(x);
    return {(x - Eigen::Vector2d(30, -20)).squaredNorm(), true};
  }
  double Fitness(const Eigen::VectorXd& x) const {
    return (x - Eigen::Vector2d(30, -20)).squaredNorm();
  }

  std::vector<Eigen::VectorXd> points;

 private:
  Eigen::VectorXd lo_ = Eigen::Vector2d(-100, -100), hi_ = Eigen::Vector2d(100, 100);
};

constexpr int kBats = 8;
constexpr int kIterations = 40;
constexpr double kSpan = 200.0;

// Every bat flies (r0 = 1: no local walk) and accepts every candidate no worse than itself
// (A = 1 throughout).
BatOptions FlyingBats(double velocity_fraction) {
  BatOptions options;
  options.population = kBats;
  options.pulse_rate0 = 1.0;
  options.loudness0 = 1.0;
  options.alpha = 1.0;
  options.velocity_fraction = velocity_fraction;
  return options;
}

// The largest coordinate step from a bat's position to its candidate over the whole run,
// replaying the acceptance rule (A = 1: a candidate no worse than the bat replaces it).
double LargestStep(const RecordingBowl& bowl) {
  std::vector<Eigen::VectorXd> x(bowl.points.begin(), bowl.points.begin() + kBats);
  double largest = 0.0;
  for (size_t k = kBats; k < bowl.points.size(); ++k) {
    const int i = static_cast<int>((k - kBats) % kBats);
    const Eigen::VectorXd& candidate = bowl.points[k];
    largest = std::max(largest, (candidate - x[i]).cwiseAbs().maxCoeff());
    if (bowl.Fitness(candidate) <= bowl.Fitness(x[i])) x[i] = candidate;
  }
  return largest;
}

SearchOutcome RunBats(const BatOptions& options, RecordingBowl& bowl) {
  Rng rng(7);
  NullObserver observer;
  return RunBatAlgorithm(bowl, options, kIterations, rng, StopToken(), observer);
}

TEST(BatAlgorithmTest, VelocityBoundLimitsEveryFlight) {
  RecordingBowl bounded_bowl;
  RunBats(FlyingBats(0.01), bounded_bowl);
  ASSERT_EQ(bounded_bowl.points.size(), static_cast<size_t>(kBats * (kIterations + 1)));
  EXPECT_LE(LargestStep(bounded_bowl), 0.01 * kSpan + 1e-9);

  RecordingBowl free_bowl;
  RunBats(FlyingBats(0.0), free_bowl);
  EXPECT_GT(LargestStep(free_bowl), 0.01 * kSpan);
}

// The largest coordinate distance from a candidate to the best point evaluated before it.
double LargestDistanceFromBest(const RecordingBowl& bowl) {
  Eigen::VectorXd best = bowl.points[0];
  for (int i = 1; i < kBats; ++i) {
    if (bowl.Fitness(bowl.points[i]) < bowl.Fitness(best)) best = bowl.points[i];
  }
  double largest = 0.0;
  for (size_t k = kBats; k < bowl.points.size(); ++k) {
    largest = std::max(largest, (bowl.points[k] - best).cwiseAbs().maxCoeff());
    if (bowl.Fitness(bowl.points[k]) <= bowl.Fitness(best)) best = bowl.points[k];
  }
  return largest;
}

TEST(BatAlgorithmTest, PerIterationScheduleStartsWithLocalWalks) {
  // gamma = 0 keeps the per-iteration schedule at r = 0: every candidate is a local walk within
  // walk_fraction of the span around the best so far. On accept, r starts at r0 = 1: bats fly.
  BatOptions options = FlyingBats(0.0);
  options.gamma = 0.0;
  options.walk_fraction = 0.01;
  options.pulse_schedule = PulseSchedule::kPerIteration;
  RecordingBowl walking;
  RunBats(options, walking);
  EXPECT_LE(LargestDistanceFromBest(walking), 0.01 * kSpan + 1e-9);

  options.pulse_schedule = PulseSchedule::kOnAccept;
  RecordingBowl flying;
  RunBats(options, flying);
  EXPECT_GT(LargestDistanceFromBest(flying), 0.01 * kSpan);
}

TEST(BatAlgorithmTest, ParsesPulseSchedules) {
  EXPECT_EQ(*ParsePulseSchedule("on-accept"), PulseSchedule::kOnAccept);
  EXPECT_EQ(*ParsePulseSchedule("per-iteration"), PulseSchedule::kPerIteration);
  const absl::StatusOr<PulseSchedule> unknown = ParsePulseSchedule("sometimes");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("pulse_schedule"), std::string::npos);
}

}  // namespace
}  // namespace swarmplan
