#pragma once

#include <cstddef>
#include <vector>

#include "absl/status/status.h"
#include "core/map/point.h"

namespace swarmplan {

// The most vertices one polygon may have: the self-intersection check compares pairs of edges
// whose bounding boxes overlap, O(n^2) at worst.
inline constexpr size_t kMaxPolygonVertices = 10000;

// OK when the ring (not closed, no repeated consecutive vertices, at least 3 vertices) is
// simple: no two non-adjacent edges meet, and no two adjacent edges overlap beyond their
// common vertex (a spike). "Meet" is SegmentIntersection's rule, so edges within
// kGeometryEpsilon of each other count as touching, as they do for the collision checks.
// INVALID_ARGUMENT naming the two edges by their vertices; RESOURCE_EXHAUSTED beyond
// kMaxPolygonVertices. The message has no path: callers prefix theirs.
absl::Status CheckSimplePolygon(const std::vector<Point2>& ring);

}  // namespace swarmplan
