#pragma once

#include "core/geometry/collision.h"
#include "core/map/point.h"

namespace swarmplan {

// Douglas-Peucker simplification that keeps the path usable: the result's vertices are points
// of `path` (start and goal kept), every point of `path` lies within `tolerance` of the result's
// segment that spans it, and every segment of the result keeps `clearance` by `checker` (a
// segment that does not is split at the point farthest from it, whatever the tolerance). When
// `path` itself does not keep the clearance, the result keeps the offending pieces as they are.
Path SimplifyWithin(const Path& path, double tolerance, const CollisionChecker& checker,
                    double clearance);

}  // namespace swarmplan
