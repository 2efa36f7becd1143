#include "core/grid_ops/shortcut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/grid_ops/collinear.h"

namespace swarmplan {
namespace {

// Greedy string pulling: from each kept point the path goes straight to the last later point
// that `visible(anchor, j)` accepts; `visible` is only asked after SegmentFree holds. Without
// the collinear pruning.
template <typename Visible>
std::optional<Path> PullString(const GridSpace& space, const Path& path, Visible visible) {
  if (path.size() < 2) return path;
  if (!space.SegmentFree(path[0], path[1])) return std::nullopt;
  Path out{path.front()};
  size_t anchor = 0;
  // Invariant: the segment from path[anchor] to path[i] is collision-free.
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    if (space.SegmentFree(path[anchor], path[i + 1]) && visible(anchor, i + 1)) continue;
    if (!space.SegmentFree(path[i], path[i + 1])) return std::nullopt;
    out.push_back(path[i]);
    anchor = i;
  }
  out.push_back(path.back());
  return out;
}

std::optional<Path> PullString(const GridSpace& space, const Path& path) {
  return PullString(space, path, [](size_t, size_t) { return true; });
}

// Where a bend may move within its cell, in half cells from the centre. On a grid the shortest
// path bends at obstacle corners, which are cell corners; the centres a cell path runs through
// lie half a cell off them. A bend that trades clearance for length may rest between them.
using CellOffsets = std::vector<std::array<int, 2>>;
const CellOffsets& CellCorners() {
  static const CellOffsets offsets{{-1, -1}, {-1, 1}, {1, -1}, {1, 1}};
  return offsets;
}
const CellOffsets& CornersAndEdgeMidpoints() {
  static const CellOffsets offsets{{-1, -1}, {-1, 0}, {-1, 1}, {0, -1},
                                   {0, 1},   {1, -1}, {1, 0},  {1, 1}};
  return offsets;
}

// Moves each interior point to the point of its cell at one of `offsets` where
// `cost(before, point, after)` of its two segments is least, while both stay free; it stays
// unless such a point costs less.
template <typename Cost>
void MoveBendsWithinCells(const GridSpace& space, Path& path, const CellOffsets& offsets,
                          Cost cost) {
  const double half = space.grid->resolution() / 2.0;
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    const Point3& before = path[i - 1];
    const Point3& after = path[i + 1];
    double best = cost(before, path[i], after);
    Point3 chosen = path[i];
    for (const std::array<int, 2>& offset : offsets) {
      const Point3 moved = path[i] + Point3(half * offset[0], half * offset[1], 0.0);
      const double c = cost(before, moved, after);
      if (c < best - 1e-12 && space.SegmentFree(before, moved) && space.SegmentFree(moved, after)) {
        best = c;
        chosen = moved;
      }
    }
    path[i] = chosen;
  }
}

double TwoSegmentLength(const Point3& before, const Point3& point, const Point3& after) {
  return (point - before).norm() + (after - point).norm();
}

}  // namespace

std::optional<Path> ShortcutPath(const GridSpace& space, const Path& path) {
  std::optional<Path> pulled = PullString(space, path);
  if (!pulled) return std::nullopt;
  MoveBendsWithinCells(space, *pulled, CellCorners(), TwoSegmentLength);
  pulled = PullString(space, *pulled);
  if (!pulled) return std::nullopt;
  return PruneCollinear(*pulled);
}

std::optional<Path> ShortcutKeepingClearance(const GridSpace& space, const Path& path,
                                             const DistanceField& field, double preferred_clearance,
                                             double clearance_weight) {
  std::vector<double> vertex_clearance(path.size());
  for (size_t i = 0; i < path.size(); ++i) {
    vertex_clearance[i] = std::min(preferred_clearance, field.Bilinear(path[i].x(), path[i].y()));
  }
  // The nearest vertex of the stretch anchor..j, extended as j grows from the anchor.
  size_t stretch_anchor = 0, stretch_end = 0;
  double stretch_floor = path.empty() ? 0.0 : vertex_clearance[0];
  std::optional<Path> pulled = PullString(space, path, [&](size_t anchor, size_t j) {
    if (anchor != stretch_anchor) {
      stretch_anchor = stretch_end = anchor;
      stretch_floor = vertex_clearance[anchor];
    }
    while (stretch_end < j)
      stretch_floor = std::min(stretch_floor, vertex_clearance[++stretch_end]);
    return field.SegmentKeeps(path[anchor].head<2>(), path[j].head<2>(), stretch_floor);
  });
  if (!pulled) return std::nullopt;
  MoveBendsWithinCells(
      space, *pulled, CornersAndEdgeMidpoints(),
      [&](const Point3& before, const Point3& point, const Point3& after) {
        const double shortfall =
            field.ShortfallAlong(before.head<2>(), point.head<2>(), preferred_clearance) +
            field.ShortfallAlong(point.head<2>(), after.head<2>(), preferred_clearance);
        return TwoSegmentLength(before, point, after) + clearance_weight * shortfall;
      });
  return PruneCollinear(*pulled);
}

std::optional<Path> AnyAnglePath(const GridSpace& space, const std::vector<Cell>& cells) {
  if (cells.empty()) return std::nullopt;
  return ShortcutPath(space, space.WorldPath(cells));
}

}  // namespace swarmplan
