#pragma once

#include <vector>

#include "absl/status/statusor.h"
#include "core/map/map.h"
#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// Exact Euclidean shortest paths on a ShapeWorld by a visibility graph and Dijkstra.
//
// Obstacles are grown by `clearance` (GrowPolygon; circles become circumscribed polygons of
// radius + clearance): every path returned keeps at least `clearance` from every obstacle and is
// at most `circle_tolerance` per grown arc longer than the true optimum (the grown arcs and
// circles are replaced by circumscribed polygons whose vertices are at most
// `circle_tolerance` beyond the true offset curve). With no arcs (clearance 0 and no circles)
// the path is the exact shortest path. The bounds limit the map but are not obstacles.
//
// Errors: InvalidArgument for a negative or non-finite clearance, a non-positive or non-finite
// tolerance, or non-finite endpoints; FailedPrecondition when start or goal is outside the
// bounds or closer than `clearance` to an obstacle (exact distances, as the collision checker
// measures them); NotFound when no path exists. The path runs from start to goal (z = 0)
// through corners of the grown obstacles (GrowObstacles). Cost: builds the grown obstacles
// (O(corners x pieces)) and runs A* over the implicit visibility graph, testing an edge only
// when it would improve its end (milliseconds on parking worlds, ~0.3 s on warehouse2 with
// clearance).
absl::StatusOr<Path> ShortestPathVisibility(const ShapeWorld& world, const Point2& start,
                                            const Point2& goal, double clearance,
                                            double circle_tolerance);

// The same on a shape-world map, with the grown obstacles cached with the map per clearance
// and tolerance (Map::Derived), so that only the first plan of each pays for growing them.
// InvalidArgument when the map is not a shape world.
absl::StatusOr<Path> ShortestPathVisibility(const Map& map, const Point2& start, const Point2& goal,
                                            double clearance, double circle_tolerance);

}  // namespace swarmplan
