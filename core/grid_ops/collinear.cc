#include "core/grid_ops/collinear.h"

#include <Eigen/Geometry>
#include <cmath>

namespace swarmplan {

Path PruneCollinear(const Path& path, double tolerance) {
  Path out;
  out.reserve(path.size());
  for (const Point3& p : path) {
    if (!out.empty() && (p - out.back()).norm() <= tolerance) continue;
    while (out.size() >= 2) {
      const Point3 u = out.back() - out[out.size() - 2];
      const Point3 v = p - out.back();
      const double scale = u.norm() * v.norm();
      if (u.cross(v).norm() > tolerance * std::max(scale, 1.0)) break;
      out.pop_back();
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace swarmplan
