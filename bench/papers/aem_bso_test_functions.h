#pragma once

// The ten test functions of the AEM-BSO paper (seed 002, eqs 10-19), with the paper's search
// ranges and known minima, and an Objective over them for the swarm optimisers.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "core/operators/objective.h"

namespace swarmplan::bench {

struct TestFunction {
  std::string id;    // "f1" .. "f10"
  std::string name;  // "Sphere", ...
  bool unimodal = true;
  double lower = 0.0;  // every coordinate lies in [lower, upper]
  double upper = 0.0;
  double minimum = 0.0;               // the known global minimum
  double minimiser_coordinate = 0.0;  // the minimum is at (c, c, ..., c)
  std::string note;                   // where we read the printed formula differently, or ""
  double (*value)(const Eigen::VectorXd& x) = nullptr;

  Eigen::VectorXd Minimiser(int dim) const {
    return Eigen::VectorXd::Constant(dim, minimiser_coordinate);
  }
};

// f1..f10 in the paper's order.
const std::vector<TestFunction>& AemBsoTestFunctions();

double Sphere(const Eigen::VectorXd& x);
double Step(const Eigen::VectorXd& x);
double Rosenbrock(const Eigen::VectorXd& x);
double Quadric(const Eigen::VectorXd& x);
double SchwefelP222(const Eigen::VectorXd& x);
double Elliptic(const Eigen::VectorXd& x);
double Rastrigin(const Eigen::VectorXd& x);
double Griewank(const Eigen::VectorXd& x);
double Ackley(const Eigen::VectorXd& x);
double Bohachevsky(const Eigen::VectorXd& x);

// A test function over [lower, upper]^dim as a minimisation problem, optionally shifted:
// Evaluate(x) = value(x - shift), so the minimiser moves to the function's minimiser + shift
// (the shift must keep it inside the box). Every point is feasible.
class TestFunctionObjective final : public Objective {
 public:
  TestFunctionObjective(const TestFunction& function, int dim);
  TestFunctionObjective(const TestFunction& function, int dim, Eigen::VectorXd shift);

  int dim() const override { return static_cast<int>(lower_.size()); }
  const Eigen::VectorXd& lower() const override { return lower_; }
  const Eigen::VectorXd& upper() const override { return upper_; }
  Evaluation Evaluate(const Eigen::VectorXd& x) override;

 private:
  double (*value_)(const Eigen::VectorXd& x);
  Eigen::VectorXd lower_, upper_, shift_, shifted_;
};

// What an optimiser reports for `function` must be a real result: `value` finite, not below the
// known minimum (minus 1e-9 for rounding), `x` inside the box and `value` what `objective`
// gives at `x`. INTERNAL naming the function and the value otherwise.
absl::Status CheckOptimiserResult(const TestFunction& function, TestFunctionObjective& objective,
                                  const Eigen::VectorXd& x, double value);

}  // namespace swarmplan::bench
