#pragma once

#include <Eigen/Core>

#include "core/operators/objective.h"

namespace swarmplan {

// One antennae probe (BAS eqs 5 and 8, BSO eq 1): the antennae sit at x +- d*b (bounded as the
// optimiser's positions are); the step moves toward the antenna with the lower fitness: -step * b *
// sign(f_r - f_l).
struct AntennaeProbe {
  double f_right = 0.0;
  double f_left = 0.0;
  // +1 when the right antenna (x + d b) is better, -1 when the left one is, 0 on a tie.
  double toward_right = 0.0;
};

// Evaluates both antennae, using `scratch` as the antenna buffer (no allocation once sized).
AntennaeProbe ProbeAntennae(Objective& objective, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& b, double d, Eigen::VectorXd& scratch,
                            PositionBound bound = PositionBound::kBox);

// The antennae step -step * b * sign(f_r - f_l) = step * b * toward_right.
inline void AddAntennaeStep(const AntennaeProbe& probe, const Eigen::VectorXd& b, double step,
                            Eigen::VectorXd& out) {
  out.noalias() += (step * probe.toward_right) * b;
}

}  // namespace swarmplan
