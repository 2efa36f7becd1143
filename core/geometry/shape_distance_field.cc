#include "core/geometry/shape_distance_field.h"

#include <algorithm>
#include <cmath>

namespace swarmplan {
namespace {

// v clamped to [lo, hi] and converted (no overflow for any v, NaN gives lo).
int ClampToInt(double v, int lo, int hi) {
  if (!(v > lo)) return lo;
  return v < hi ? static_cast<int>(v) : hi;
}

// Clips the segment [a, b] to the box (Liang-Barsky); false when it misses the box.
bool ClipToBox(const Point2& lo, const Point2& hi, Point2& a, Point2& b) {
  double t0 = 0.0, t1 = 1.0;
  const Point2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - a[axis]) / d[axis], tb = (hi[axis] - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  const Point2 start = a;
  a = start + t0 * d;
  b = start + t1 * d;
  return true;
}

}  // namespace

DistanceField ShapeDistanceField(const Bounds2& bounds, const std::vector<Circle>& circles,
                                 const std::vector<Polygon>& polygons) {
  const double h = std::max(bounds.Width(), bounds.Height()) / kShapeFieldCells;
  const int width = static_cast<int>(std::ceil(bounds.Width() / h - 1e-9)) + 2 * kShapeFieldRing;
  const int height = static_cast<int>(std::ceil(bounds.Height() / h - 1e-9)) + 2 * kShapeFieldRing;
  const Point2 origin = bounds.min - Point2::Constant(kShapeFieldRing * h);
  const Point2 field_max = origin + Point2(width, height) * h;
  std::vector<uint8_t> blocked(static_cast<size_t>(width) * height, 0);
  // Cell index along an axis, clamped to [0, count).
  auto index = [h](double v, double lo, int count) {
    return ClampToInt(std::floor((v - lo) / h), 0, count - 1);
  };
  auto mark_box = [&](const Point2& lo, const Point2& hi) {
    const int x0 = index(lo.x(), origin.x(), width), x1 = index(hi.x(), origin.x(), width);
    const int y0 = index(lo.y(), origin.y(), height), y1 = index(hi.y(), origin.y(), height);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) blocked[static_cast<size_t>(y) * width + x] = 1;
    }
  };
  const Point2 grow = Point2::Constant(1e-9 * h);
  for (const Circle& c : circles) {
    const int x0 = index(c.center.x() - c.radius, origin.x(), width);
    const int x1 = index(c.center.x() + c.radius, origin.x(), width);
    const int y0 = index(c.center.y() - c.radius, origin.y(), height);
    const int y1 = index(c.center.y() + c.radius, origin.y(), height);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Point2 lo = origin + Point2(x, y) * h;
        const Point2 nearest = c.center.cwiseMax(lo).cwiseMin(lo + Point2::Constant(h));
        if ((nearest - c.center).norm() <= c.radius * (1 + 1e-9)) {
          blocked[static_cast<size_t>(y) * width + x] = 1;
        }
      }
    }
  }
  std::vector<std::vector<double>> crossings(height);
  for (const Polygon& polygon : polygons) {
    const std::vector<Point2>& v = polygon.vertices;
    const size_t n = v.size();
    int row_lo = height, row_hi = -1;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      const Point2& a = v[j];
      const Point2& b = v[i];
      // The boundary: every cell the edge passes through, by boxes of pieces no longer than h.
      Point2 ca = a, cb = b;
      if (ClipToBox(origin, field_max, ca, cb)) {
        const int pieces = ClampToInt(std::ceil((cb - ca).norm() / h), 1, width + height + 1);
        for (int s = 0; s < pieces; ++s) {
          const Point2 p = ca + (cb - ca) * (static_cast<double>(s) / pieces);
          const Point2 q = ca + (cb - ca) * (static_cast<double>(s + 1) / pieces);
          mark_box(p.cwiseMin(q) - grow, p.cwiseMax(q) + grow);
        }
      }
      // The interior: crossings of the edge with the rows' centre lines (half-open in y).
      const double ylo = std::min(a.y(), b.y()), yhi = std::max(a.y(), b.y());
      const int r0 = ClampToInt(std::ceil((ylo - origin.y()) / h - 0.5), 0, height);
      const int r1 = ClampToInt(std::floor((yhi - origin.y()) / h - 0.5), -1, height - 1);
      for (int r = r0; r <= r1; ++r) {
        const double yc = origin.y() + (r + 0.5) * h;
        if (yc < ylo || yc >= yhi) continue;
        crossings[r].push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        row_lo = std::min(row_lo, r);
        row_hi = std::max(row_hi, r);
      }
    }
    for (int r = row_lo; r <= row_hi; ++r) {
      std::vector<double>& xs = crossings[r];
      std::sort(xs.begin(), xs.end());
      for (size_t k = 0; k + 1 < xs.size(); k += 2) {
        // Cells whose centres lie between the pair.
        const int c0 = ClampToInt(std::ceil((xs[k] - origin.x()) / h - 0.5), 0, width);
        const int c1 = ClampToInt(std::floor((xs[k + 1] - origin.x()) / h - 0.5), -1, width - 1);
        for (int c = c0; c <= c1; ++c) blocked[static_cast<size_t>(r) * width + c] = 1;
      }
      xs.clear();
    }
  }
  return DistanceField::FromBlockedCells(width, height, blocked, h, origin, /*cap_at_edge=*/true);
}

}  // namespace swarmplan
