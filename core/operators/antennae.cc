#include "core/operators/antennae.h"

namespace swarmplan {

AntennaeProbe ProbeAntennae(Objective& objective, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& b, double d, Eigen::VectorXd& scratch,
                            PositionBound bound) {
  AntennaeProbe probe;
  scratch = x + d * b;
  objective.Bound(bound, scratch);
  probe.f_right = objective.Evaluate(scratch).fitness;
  scratch = x - d * b;
  objective.Bound(bound, scratch);
  probe.f_left = objective.Evaluate(scratch).fitness;
  probe.toward_right =
      probe.f_right < probe.f_left ? 1.0 : (probe.f_left < probe.f_right ? -1.0 : 0.0);
  return probe;
}

}  // namespace swarmplan
