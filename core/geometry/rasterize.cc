#include "core/geometry/rasterize.h"

#include <algorithm>
#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

// Cells along one axis: whole cells inside `extent`, as a double (it may exceed any int).
double CellCount(double extent, double resolution) {
  const double cells = extent / resolution;
  const double rounded = std::round(cells);
  return std::abs(cells - rounded) <= 1e-9 * std::max(1.0, cells) ? rounded : std::floor(cells);
}

// True when the segment passes through the open box.
bool SegmentEntersOpenBox(const Point2& a, const Point2& b, const Bounds2& box) {
  double t0 = 0.0, t1 = 1.0;
  const Point2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = box.min[axis], hi = box.max[axis];
    if (d[axis] == 0.0) {
      if (a[axis] <= lo || a[axis] >= hi) return false;
      continue;
    }
    double ta = (lo - a[axis]) / d[axis];
    double tb = (hi - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 >= t1) return false;
  }
  const Point2 mid = a + 0.5 * (t0 + t1) * d;
  return mid.x() > box.min.x() && mid.x() < box.max.x() && mid.y() > box.min.y() &&
         mid.y() < box.max.y();
}

bool PolygonOverlapsOpenBox(const std::vector<Point2>& polygon, const Bounds2& box) {
  if (LocatePoint(0.5 * (box.min + box.max), polygon) == PointLocation::kInside) return true;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    if (SegmentEntersOpenBox(polygon[j], polygon[i], box)) return true;
  }
  return false;
}

double PointBoxDistance(const Point2& p, const Bounds2& box) {
  const double dx = std::max({0.0, box.min.x() - p.x(), p.x() - box.max.x()});
  const double dy = std::max({0.0, box.min.y() - p.y(), p.y() - box.max.y()});
  return std::hypot(dx, dy);
}

}  // namespace

absl::StatusOr<OccupancyGrid> RasterizeShapeWorld(const ShapeWorld& world, double resolution,
                                                  const MapLimits& limits) {
  if (!std::isfinite(resolution) || resolution <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("resolution must be a positive number, got ", resolution));
  }
  const Bounds2& bounds = world.bounds();
  const double wide = CellCount(bounds.Width(), resolution);
  const double high = CellCount(bounds.Height(), resolution);
  if (wide < 1 || high < 1) {
    return absl::InvalidArgumentError(absl::StrCat("resolution ", resolution,
                                                   " is coarser than the world (", bounds.Width(),
                                                   " x ", bounds.Height(), ")"));
  }
  if (wide * high > static_cast<double>(limits.max_cells)) {
    return absl::ResourceExhaustedError(
        absl::StrCat("rasterising at resolution ", resolution, " needs ", wide * high,
                     " cells, over the limit of ", limits.max_cells));
  }
  const int width = static_cast<int>(wide);
  const int height = static_cast<int>(high);
  std::vector<int8_t> cells(static_cast<size_t>(width) * height, OccupancyGrid::kFree);
  auto cell_box = [&](int x, int y) {
    const Point2 lo = bounds.min + Point2(x, y) * resolution;
    return Bounds2{lo, lo + Point2(resolution, resolution)};
  };
  // Visits the cells whose squares meet the box, calling mark(x, y, cell square).
  auto for_cells_in = [&](const Bounds2& box, auto&& mark) {
    const int x0 =
        std::max(0, static_cast<int>(std::floor((box.min.x() - bounds.min.x()) / resolution)) - 1);
    const int y0 =
        std::max(0, static_cast<int>(std::floor((box.min.y() - bounds.min.y()) / resolution)) - 1);
    const int x1 = std::min(
        width - 1, static_cast<int>(std::floor((box.max.x() - bounds.min.x()) / resolution)) + 1);
    const int y1 = std::min(
        height - 1, static_cast<int>(std::floor((box.max.y() - bounds.min.y()) / resolution)) + 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        int8_t& cell = cells[static_cast<size_t>(y) * width + x];
        if (cell == OccupancyGrid::kFree && mark(cell_box(x, y))) cell = OccupancyGrid::kOccupied;
      }
    }
  };
  for (const Circle& c : world.circles()) {
    const Point2 r(c.radius, c.radius);
    for_cells_in(Bounds2{c.center - r, c.center + r}, [&](const Bounds2& square) {
      return PointBoxDistance(c.center, square) < c.radius;
    });
  }
  for (const Polygon& p : world.polygons()) {
    for_cells_in(BoundingBox(p.vertices),
                 [&](const Bounds2& square) { return PolygonOverlapsOpenBox(p.vertices, square); });
  }
  return OccupancyGrid::Create(width, height, std::move(cells), resolution, bounds.min, limits);
}

}  // namespace swarmplan
