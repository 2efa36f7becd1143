#pragma once

#include "core/operators/elite_mutation.h"
#include "core/operators/inertia.h"
#include "core/operators/objective.h"
#include "core/operators/search_loop.h"
#include "core/random.h"

namespace swarmplan {

// The beetle swarm optimiser of AEM-BSO section 1-2 and its relatives, as options of one loop:
//   BSO       antennae on, random init, linear inertia, no mutation;
//   AEM-BSO   antennae on, good point set init, cosine inertia, elite mutation;
//   PSO       antennae off (c3 unused), random init, linear inertia.
// Per iteration and beetle: antennae at x +- (delta/2) b give vb = -delta b sign(f_r - f_l);
// v <- w v + c1 r1 (pbest - x) + c2 r2 (gbest - x) + c3 r3 vb (r per dimension), clamped to
// velocity_fraction of the span; x <- x + v bounded by `positions`. delta starts at
// step_fraction of the mean span and decays by step_decay per iteration.
struct BeetleSwarmOptions {
  int population = 100;
  bool good_point_init = false;
  InertiaSchedule inertia = InertiaSchedule::kLinear;
  double w_max = 0.9;
  double w_min = 0.4;
  double c1 = 1.49;
  double c2 = 1.49;
  double c3 = 1.49;
  bool antennae = true;
  double step_fraction = 0.05;
  double step_decay = 0.99;
  double velocity_fraction = 0.2;
  PositionBound positions = PositionBound::kBox;
  bool elite_mutation = false;
  EliteMutation mutation;
};

SearchOutcome RunBeetleSwarm(Objective& objective, const BeetleSwarmOptions& options, int t_max,
                             Rng& rng, const StopToken& stop, Observer& observer);

}  // namespace swarmplan
