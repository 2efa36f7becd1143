#pragma once

#include "absl/status/status.h"

namespace swarmplan {

// The objective a fleet manager asks for, on 2D maps: length, plus a weighted shortfall below a
// preferred clearance, plus a weighted excess of curvature over 1 / turning radius, plus a
// weighted violation of the problem's hard clearance. Each shortfall is integrated along the
// path:
//   J = L + w_c int max(0, c_pref - d) ds + w_k int max(0, kappa - 1/R) ds
//         + w_v (L xi + int max(0, c_hard - h - d) ds),
// d the distance to the nearest obstacle from the map's distance field (negative inside an
// obstacle; near an obstacle it may read low by up to about 1.5 field cells), h two field
// cells, kappa the discrete curvature at each sample, xi the number of obstacles the path comes
// closer to than c_hard (ObstacleProximity: exact segment distances on worlds; on grids the
// components whose cells it crosses, and 1 when there are none but the collision checker's exact
// test finds a segment closer than c_hard; feasible when xi = 0, the checker's verdict). The
// integral below c_hard - h keeps deeply infeasible paths comparable. A point outside the map adds
// its distance outside to it.
struct FleetObjective {
  double preferred_clearance = 0.0;  // world units; 0: no clearance term
  double clearance_weight = 1.0;     // per unit of length and unit of shortfall
  double turning_radius = 0.0;       // world units; 0: no curvature term
  double curvature_weight = 1.0;     // per unit of length and unit of curvature (1 / units)
  double violation_weight = 100.0;   // per unit of length and unit below the hard clearance
};

// Each term of J for one path, weighted as in J.
struct FleetTerms {
  double length = 0.0;
  double clearance = 0.0;  // w_c int max(0, c_pref - d) ds
  double curvature = 0.0;  // w_k int max(0, kappa - 1/R) ds
  double violation = 0.0;  // w_v (L xi + int max(0, c_hard - h - d) ds)
  double Total() const { return length + clearance + curvature + violation; }
};

// INVALID_ARGUMENT naming the field when a value is negative or not finite.
absl::Status ValidateFleetObjective(const FleetObjective& fleet);

}  // namespace swarmplan
