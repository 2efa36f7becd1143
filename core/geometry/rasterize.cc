#include "core/geometry/rasterize.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/geometry/box_overlap.h"

namespace swarmplan {
namespace {

// Cells along one axis: whole cells inside `extent`, as a double (it may exceed any int).
double CellCount(double extent, double resolution) {
  const double cells = extent / resolution;
  const double rounded = std::round(cells);
  return std::abs(cells - rounded) <= 1e-9 * std::max(1.0, cells) ? rounded : std::floor(cells);
}

// The raster being filled, with index arithmetic that stays in range for any coordinate.
struct CellRaster {
  Point2 origin;
  double resolution;
  int width;
  int height;
  std::vector<int8_t> cells;

  Bounds2 Square(int x, int y) const {
    const Point2 lo = origin + Point2(x, y) * resolution;
    return Bounds2{lo, lo + Point2(resolution, resolution)};
  }
  double Center(int i, int axis) const { return origin[axis] + (i + 0.5) * resolution; }
  int Size(int axis) const { return axis == 0 ? width : height; }
  // The column (axis 0) or row (axis 1) holding coordinate v, clamped to [-1, size].
  int IndexOf(double v, int axis) const {
    const double i = std::floor((v - origin[axis]) / resolution);
    return static_cast<int>(std::clamp(i, -1.0, static_cast<double>(Size(axis))));
  }
  // Indices lo..hi (clamped to the raster) of the cells along `axis` that hold [a, b], and one
  // more on each side for rounding.
  std::pair<int, int> Span(double a, double b, int axis) const {
    return {std::max(0, IndexOf(std::min(a, b), axis) - 1),
            std::min(Size(axis) - 1, IndexOf(std::max(a, b), axis) + 1)};
  }
  int8_t& At(int x, int y) { return cells[static_cast<size_t>(y) * width + x]; }
  void BlockRun(int x0, int x1, int y) {
    if (x0 <= x1) std::fill(&At(x0, y), &At(x1, y) + 1, OccupancyGrid::kOccupied);
  }
};

// The cells of one row that overlap a disc form a run around the column nearest its centre:
// its ends come from the chord and are settled with the exact per-cell rule.
void BlockCircle(const Circle& c, CellRaster& raster) {
  const auto [y0, y1] = raster.Span(c.center.y() - c.radius, c.center.y() + c.radius, 1);
  const int nearest = std::clamp(raster.IndexOf(c.center.x(), 0), 0, raster.width - 1);
  for (int y = y0; y <= y1; ++y) {
    auto hits = [&](int x) { return CircleOverlapsOpenBox(c, raster.Square(x, y)); };
    int seed = -1;
    for (int x : {nearest, nearest - 1, nearest + 1}) {
      if (x >= 0 && x < raster.width && hits(x)) {
        seed = x;
        break;
      }
    }
    if (seed < 0) continue;
    const Bounds2 square = raster.Square(seed, y);
    const double dy = std::max({0.0, square.min.y() - c.center.y(), c.center.y() - square.max.y()});
    const double half_chord = std::sqrt(std::max(0.0, c.radius * c.radius - dy * dy));
    int left = std::clamp(raster.IndexOf(c.center.x() - half_chord, 0), 0, seed);
    while (left > 0 && hits(left - 1)) --left;
    while (!hits(left)) ++left;
    int right = std::clamp(raster.IndexOf(c.center.x() + half_chord, 0), seed, raster.width - 1);
    while (right < raster.width - 1 && hits(right + 1)) ++right;
    while (!hits(right)) --right;
    raster.BlockRun(left, right, y);
  }
}

// Blocks the cells whose open squares the segment enters, visiting only the cells along it.
void BlockEdgeCells(const Point2& a, const Point2& b, CellRaster& raster) {
  const auto [y0, y1] = raster.Span(a.y(), b.y(), 1);
  for (int y = y0; y <= y1; ++y) {
    // The part of a-b inside the row's band (a point near an end when it misses the band).
    double t0 = 0.0, t1 = 1.0;
    if (b.y() != a.y()) {
      const double lo = raster.origin.y() + y * raster.resolution;
      t0 = std::clamp((lo - a.y()) / (b.y() - a.y()), 0.0, 1.0);
      t1 = std::clamp((lo + raster.resolution - a.y()) / (b.y() - a.y()), 0.0, 1.0);
    }
    const auto [x0, x1] =
        raster.Span(a.x() + t0 * (b.x() - a.x()), a.x() + t1 * (b.x() - a.x()), 0);
    for (int x = x0; x <= x1; ++x) {
      int8_t& cell = raster.At(x, y);
      if (cell == OccupancyGrid::kFree && SegmentEntersOpenBox(a, b, raster.Square(x, y))) {
        cell = OccupancyGrid::kOccupied;
      }
    }
  }
}

// Reusable buffers of BlockInterior: the crossings of each row's centre line, grouped by row.
struct RowCrossings {
  std::vector<int> row_start;  // crossings of row y0 + i are xs[row_start[i]..row_start[i + 1])
  std::vector<double> xs;
};

// Calls visit(y, x) for each crossing of an edge with the centre line of a row in [y0, y1], by
// LocatePoint's half-open rule.
template <typename Visit>
void ForEachCrossing(const std::vector<Point2>& polygon, const CellRaster& raster, Visit visit) {
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[j];
    const Point2& b = polygon[i];
    if (a.y() == b.y()) continue;
    const auto [y0, y1] = raster.Span(a.y(), b.y(), 1);
    for (int y = y0; y <= y1; ++y) {
      const double yc = raster.Center(y, 1);
      if ((a.y() > yc) != (b.y() > yc)) {
        visit(y, a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
  }
}

// The first column whose centre lies right of x.
int FirstColumnAfter(double x, const CellRaster& raster) {
  const double guess = std::floor((x - raster.origin.x()) / raster.resolution - 0.5) + 1;
  int c = static_cast<int>(std::clamp(guess, 0.0, static_cast<double>(raster.width)));
  while (c > 0 && raster.Center(c - 1, 0) > x) --c;
  while (c < raster.width && raster.Center(c, 0) <= x) ++c;
  return c;
}

// Blocks the cells whose centres lie inside the polygon: per row, the centre line's crossings
// with the edges, filled pairwise. A centre on the boundary is left to BlockEdgeCells, as every
// cell whose square an edge enters is. Crossings are bucketed by row (a counting pass, then a
// filling pass), so the work is linear in the polygon's rows and crossings.
void BlockInterior(const std::vector<Point2>& polygon, CellRaster& raster, RowCrossings& rows) {
  double lo = polygon[0].y(), hi = polygon[0].y();
  for (const Point2& v : polygon) {
    lo = std::min(lo, v.y());
    hi = std::max(hi, v.y());
  }
  const auto [first_row, last_row] = raster.Span(lo, hi, 1);
  const int y0 = first_row, y1 = last_row;  // lambdas cannot capture structured bindings
  if (y0 > y1) return;
  rows.row_start.assign(static_cast<size_t>(y1 - y0) + 2, 0);
  ForEachCrossing(polygon, raster, [&](int y, double) { ++rows.row_start[y - y0 + 1]; });
  for (size_t i = 1; i < rows.row_start.size(); ++i) rows.row_start[i] += rows.row_start[i - 1];
  rows.xs.resize(static_cast<size_t>(rows.row_start.back()));
  std::vector<int>& next = rows.row_start;  // shifted down by one row while filling
  ForEachCrossing(polygon, raster, [&](int y, double x) { rows.xs[next[y - y0]++] = x; });
  for (int y = y1; y >= y0; --y) {
    const size_t end = static_cast<size_t>(next[y - y0]);
    const size_t begin = y > y0 ? static_cast<size_t>(next[y - y0 - 1]) : 0;
    std::sort(rows.xs.begin() + begin, rows.xs.begin() + end);
    // A closed ring crosses each line an even number of times; an odd last crossing (rounding)
    // is left out.
    for (size_t k = begin; k + 1 < end; k += 2) {
      const int first = FirstColumnAfter(rows.xs[k], raster);
      int last = FirstColumnAfter(rows.xs[k + 1], raster) - 1;
      if (last >= 0 && raster.Center(last, 0) >= rows.xs[k + 1]) --last;
      raster.BlockRun(first, last, y);
    }
  }
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
  CellRaster raster{bounds.min, resolution, width, height,
                    std::vector<int8_t>(static_cast<size_t>(width) * height, OccupancyGrid::kFree)};
  for (const Circle& c : world.circles()) BlockCircle(c, raster);
  RowCrossings rows;
  for (const Polygon& p : world.polygons()) {
    BlockInterior(p.vertices, raster, rows);
    const size_t n = p.vertices.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      BlockEdgeCells(p.vertices[j], p.vertices[i], raster);
    }
  }
  return OccupancyGrid::Create(width, height, std::move(raster.cells), resolution, bounds.min,
                               limits);
}

}  // namespace swarmplan
