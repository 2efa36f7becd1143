#pragma once

#include <vector>

#include "core/map/point.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// The obstacles of a ShapeWorld grown by a radius, as the visibility graph and the
// vertex-based planners see them. Circles become circumscribed polygons of radius
// r + radius (CircleToPolygon with `circle_tolerance`); polygons are grown by GrowPolygon.
// Everything is grown by a further kGrowMargin so paths along the grown boundaries pass the
// exact collision checks despite rounding.
struct GrownObstacles {
  static constexpr double kGrowMargin = 1e-8;

  // A vertex of a piece where a shortest path may bend.
  struct Corner {
    Point2 point = Point2::Zero();
    int piece = 0;  // index in `pieces`
    int index = 0;  // index of the vertex in pieces[piece].vertices
  };

  // Counter-clockwise; convex, except polygons grown by radius 0, which stay as they are.
  std::vector<Polygon> pieces;
  std::vector<Bounds2> boxes;  // bounding box of each piece
  std::vector<char> convex;    // whether each piece is convex
  // Convex vertices of the pieces that are inside the world's bounds and not strictly inside
  // another piece, sorted by x then y (the vertex numbering of the vertex-based planners).
  std::vector<Corner> corners;

  // True when p lies strictly inside some piece.
  bool Contains(const Point2& p) const;
  // True when the segment enters the interior of some piece (running along edges and touching
  // vertices is allowed).
  bool Blocks(const Point2& a, const Point2& b) const;
  // True when the line through `from` and the corner leaves the corner's piece on one side
  // locally (the segment is tangent to the piece there), a necessary condition for a
  // shortest path to bend at the corner.
  bool Tangent(const Point2& from, const Corner& corner) const;
};

GrownObstacles GrowObstacles(const ShapeWorld& world, double radius, double circle_tolerance);

// The corners' points of GrowObstacles, numbered by x then y.
std::vector<Point2> ObstacleVertices(const ShapeWorld& world, double radius,
                                     double circle_tolerance);

}  // namespace swarmplan
