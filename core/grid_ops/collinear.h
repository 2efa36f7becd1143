#pragma once

#include "core/map/point.h"

namespace swarmplan {

// Drops repeated points and every interior point collinear with its kept predecessor and its
// successor (the rank test of the fish swarm paper's eq 24, with a relative tolerance). The
// result runs along the input polyline; start and goal are kept.
Path PruneCollinear(const Path& path, double tolerance = 1e-9);

}  // namespace swarmplan
