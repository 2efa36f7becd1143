#pragma once

// What the binary PSO encoding can express at best: the particle picks a subset of the obstacle
// vertices and the path visits them in a fixed order (projection on the start-goal line), so its
// best fitness may exceed the visibility graph's optimum. Used to tell the search's losses from
// the encoding's in the bpso-vertices report.

#include <optional>

#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan::bench {

// The shortest collision-free path start -> ordered subset of the vertices -> goal, with the
// vertices and the order the `bpso` planner uses (GrowObstacles corners for `clearance`,
// stable-sorted by their projection on the start-goal line), by dynamic programming over that
// order (exact: O(D^2) segment tests). nullopt when no subset gives a free path.
std::optional<double> BestOrderedVertexPath(const ShapeWorld& world, const Point2& start,
                                            const Point2& goal, double clearance = 0.0,
                                            double circle_tolerance = 0.002);

}  // namespace swarmplan::bench
