#pragma once

#include "core/map/map.h"
#include "core/map/point.h"

namespace swarmplan {

// Whether two paths between the same start and goal certainly lie in different corridors
// (homotopy classes): the closed loop `a` then `b` reversed winds around an obstacle, tested at
// the centre of every blocked cell of a grid and at one interior point of every circle and
// polygon of a world. Paths that wind around no obstacle are in the same class. Not for terrain
// (false).
bool SeparatedByObstacle(const Map& map, const Path& a, const Path& b);

}  // namespace swarmplan
