#include "core/smoothing/simplify.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace swarmplan {
namespace {

double DistanceToSegment(const Point3& p, const Point3& a, const Point3& b) {
  const Point3 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

}  // namespace

Path SimplifyWithin(const Path& path, double tolerance, const CollisionChecker& checker,
                    double clearance) {
  if (path.size() < 3) return path;
  std::vector<bool> keep(path.size(), false);
  keep.front() = keep.back() = true;
  std::vector<std::pair<size_t, size_t>> spans = {{0, path.size() - 1}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    if (b - a < 2) continue;
    size_t farthest = a + 1;
    double deviation = -1.0;
    for (size_t i = a + 1; i < b; ++i) {
      const double d = DistanceToSegment(path[i], path[a], path[b]);
      if (d > deviation) {
        deviation = d;
        farthest = i;
      }
    }
    if (deviation <= tolerance && checker.SegmentFree(path[a], path[b], clearance)) continue;
    keep[farthest] = true;
    spans.emplace_back(a, farthest);
    spans.emplace_back(farthest, b);
  }
  Path out;
  for (size_t i = 0; i < path.size(); ++i) {
    if (keep[i]) out.push_back(path[i]);
  }
  return out;
}

}  // namespace swarmplan
