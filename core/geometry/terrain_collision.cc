#include "core/geometry/terrain_collision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace swarmplan {
namespace {

// The parameters t in (0, 1) where the line from p0 to p0 + d crosses an integer coordinate.
void AddCrossings(double p0, double d, std::vector<double>& ts) {
  if (d == 0.0) return;
  const double p1 = p0 + d;
  const double lo = std::min(p0, p1), hi = std::max(p0, p1);
  for (double k = std::floor(lo) + 1.0; k < hi; k += 1.0) {
    const double t = (k - p0) / d;
    if (t > 0.0 && t < 1.0) ts.push_back(t);
  }
}

}  // namespace

double TerrainCollisionChecker::Clearance(const Point3& p) const {
  if (!(p.z() <= terrain_.ceiling())) return -kInf;
  const double ground = terrain_.GroundAt(p.head<2>());
  if (std::isnan(ground)) return -kInf;
  return p.z() - ground;
}

double TerrainCollisionChecker::SegmentClearance(const Point3& a, const Point3& b) const {
  // z is linear along the segment: the ceiling and the map's (convex) bounds are checked at the
  // ends.
  const double ca = Clearance(a);
  const double cb = Clearance(b);
  double best = std::min(ca, cb);
  if (best == -kInf) return best;
  const Point2 c0 = terrain_.ToCell(a.head<2>());
  const Point2 d = terrain_.ToCell(b.head<2>()) - c0;
  const double dz = b.z() - a.z();
  std::vector<double> ts = {0.0, 1.0};
  AddCrossings(c0.x(), d.x(), ts);
  AddCrossings(c0.y(), d.y(), ts);
  std::sort(ts.begin(), ts.end());
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    const double t0 = ts[i], t1 = ts[i + 1];
    if (t1 <= t0) continue;
    // The cell-centre square of this piece, found from its middle.
    const double tm = 0.5 * (t0 + t1);
    const int x0 =
        std::clamp(static_cast<int>(std::floor(c0.x() + tm * d.x())), 0, terrain_.width() - 2);
    const int y0 =
        std::clamp(static_cast<int>(std::floor(c0.y() + tm * d.y())), 0, terrain_.depth() - 2);
    const double h00 = terrain_.HeightAt(x0, y0), h10 = terrain_.HeightAt(x0 + 1, y0);
    const double h01 = terrain_.HeightAt(x0, y0 + 1), h11 = terrain_.HeightAt(x0 + 1, y0 + 1);
    if (std::isnan(h00) || std::isnan(h10) || std::isnan(h01) || std::isnan(h11)) return -kInf;
    // u = fx(t), v = fy(t) in the square; ground g = h00 + (h10-h00) u + (h01-h00) v + e u v
    // with e = h00 - h10 - h01 + h11; clearance(t) = z(t) - g(t) = q2 t^2 + q1 t + q0.
    const double u0 = c0.x() - x0, v0 = c0.y() - y0;
    const double gx = h10 - h00, gy = h01 - h00, e = h00 - h10 - h01 + h11;
    const double q2 = -e * d.x() * d.y();
    const double q1 = dz - (gx * d.x() + gy * d.y() + e * (u0 * d.y() + v0 * d.x()));
    const double q0 = a.z() - (h00 + gx * u0 + gy * v0 + e * u0 * v0);
    const auto clearance_at = [&](double t) { return (q2 * t + q1) * t + q0; };
    best = std::min({best, clearance_at(t0), clearance_at(t1)});
    if (q2 > 0.0) {
      const double t = -q1 / (2.0 * q2);
      if (t > t0 && t < t1) best = std::min(best, clearance_at(t));
    }
  }
  return best;
}

}  // namespace swarmplan
