#include "core/geometry/terrain_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmplan {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

double TerrainCollisionChecker::Clearance(const Point3& p) const {
  if (!(p.z() <= terrain_.ceiling())) return -kInf;
  const double ground = terrain_.GroundAt(p.x(), p.y());
  if (std::isnan(ground)) return -kInf;
  return p.z() - ground;
}

// Calls visit(clearance) at samples from a to b, at most kSampleStep apart horizontally;
// stops when visit returns false.
template <typename Visit>
void TerrainCollisionChecker::ForEachSample(const Point3& a, const Point3& b, Visit&& visit) const {
  const double horizontal = (b.head<2>() - a.head<2>()).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(horizontal / kSampleStep)));
  if (!visit(Clearance(a))) return;
  for (int i = 1; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    if (!visit(Clearance(i == steps ? b : Point3(a + t * (b - a))))) return;
  }
}

double TerrainCollisionChecker::SegmentClearance(const Point3& a, const Point3& b) const {
  double best = kInf;
  ForEachSample(a, b, [&best](double c) {
    best = std::min(best, c);
    return best > -kInf;
  });
  return best;
}

bool TerrainCollisionChecker::SegmentFree(const Point3& a, const Point3& b,
                                          double clearance) const {
  bool free = true;
  ForEachSample(a, b, [&free, clearance](double c) {
    free = c >= clearance;
    return free;
  });
  return free;
}

}  // namespace swarmplan
