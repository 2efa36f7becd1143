#include "core/grid_ops/shortcut.h"

#include <limits>

#include "core/grid_ops/collinear.h"
#include "core/path_metrics.h"

namespace swarmplan {
namespace {

// Greedy string pulling of ShortcutPath, without the collinear pruning.
std::optional<Path> PullString(const GridSpace& space, const Path& path) {
  if (path.size() < 2) return path;
  if (!space.SegmentFree(path[0], path[1])) return std::nullopt;
  Path out{path.front()};
  size_t anchor = 0;
  // Invariant: the segment from path[anchor] to path[i] is collision-free.
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    if (space.SegmentFree(path[anchor], path[i + 1])) continue;
    if (!space.SegmentFree(path[i], path[i + 1])) return std::nullopt;
    out.push_back(path[i]);
    anchor = i;
  }
  out.push_back(path.back());
  return out;
}

// Moves each interior point to the corner of its cell that shortens the path most while both
// its segments stay free. On a grid the shortest path bends at obstacle corners, which are cell
// corners; the centres a cell path runs through lie half a cell off them.
void PullToCellCorners(const GridSpace& space, Path& path) {
  const double half = space.grid->resolution() / 2.0;
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    const Point3& before = path[i - 1];
    const Point3& after = path[i + 1];
    double best = (path[i] - before).norm() + (after - path[i]).norm();
    Point3 chosen = path[i];
    for (const double dx : {-half, half}) {
      for (const double dy : {-half, half}) {
        const Point3 corner = path[i] + Point3(dx, dy, 0.0);
        const double length = (corner - before).norm() + (after - corner).norm();
        if (length < best - 1e-12 && space.SegmentFree(before, corner) &&
            space.SegmentFree(corner, after)) {
          best = length;
          chosen = corner;
        }
      }
    }
    path[i] = chosen;
  }
}

}  // namespace

std::optional<Path> ShortcutPath(const GridSpace& space, const Path& path) {
  std::optional<Path> pulled = PullString(space, path);
  if (!pulled) return std::nullopt;
  PullToCellCorners(space, *pulled);
  pulled = PullString(space, *pulled);
  if (!pulled) return std::nullopt;
  return PruneCollinear(*pulled);
}

std::optional<Path> AnyAnglePath(const GridSpace& space, const std::vector<Cell>& cells) {
  if (cells.empty()) return std::nullopt;
  return ShortcutPath(space, space.WorldPath(cells));
}

double AnyAngleLength(const GridSpace& space, const std::vector<Cell>& cells) {
  const std::optional<Path> path = AnyAnglePath(space, cells);
  return path ? PathLength(*path) : std::numeric_limits<double>::infinity();
}

}  // namespace swarmplan
