#include "core/grid_ops/shortcut.h"

#include <limits>

#include "core/grid_ops/collinear.h"
#include "core/path_metrics.h"

namespace swarmplan {

std::optional<Path> ShortcutPath(const GridSpace& space, const Path& path) {
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
  return PruneCollinear(out);
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
