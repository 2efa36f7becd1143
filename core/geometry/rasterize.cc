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

// Blocks the cells whose centres lie inside the polygon: per row, the centre line's crossings
// with the edges (LocatePoint's half-open rule), filled pairwise. A centre on the boundary is
// left to BlockEdgeCells, as every cell whose square an edge enters is.
void BlockInterior(const std::vector<Point2>& polygon, CellRaster& raster,
                   std::vector<std::pair<int, double>>& crossings) {
  crossings.clear();
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[j];
    const Point2& b = polygon[i];
    if (a.y() == b.y()) continue;
    const auto [y0, y1] = raster.Span(a.y(), b.y(), 1);
    for (int y = y0; y <= y1; ++y) {
      const double yc = raster.Center(y, 1);
      if ((a.y() > yc) != (b.y() > yc)) {
        crossings.emplace_back(y, a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
  }
  std::sort(crossings.begin(), crossings.end());
  for (size_t k = 0; k + 1 < crossings.size();) {
    const auto [y, enter] = crossings[k];
    const auto [next_y, leave] = crossings[k + 1];
    // A closed ring crosses each line an even number of times; a lone crossing is skipped
    // rather than paired with the next row's.
    if (next_y != y) {
      ++k;
      continue;
    }
    auto first_after = [&](double x) {
      const double guess = std::floor((x - raster.origin.x()) / raster.resolution - 0.5) + 1;
      int c = static_cast<int>(std::clamp(guess, 0.0, static_cast<double>(raster.width)));
      while (c > 0 && raster.Center(c - 1, 0) > x) --c;
      while (c < raster.width && raster.Center(c, 0) <= x) ++c;
      return c;
    };
    const int first = first_after(enter);
    int last = first_after(leave) - 1;
    if (last >= 0 && raster.Center(last, 0) >= leave) --last;
    raster.BlockRun(first, last, y);
    k += 2;
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
  std::vector<std::pair<int, double>> crossings;
  for (const Polygon& p : world.polygons()) {
    BlockInterior(p.vertices, raster, crossings);
    const size_t n = p.vertices.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      BlockEdgeCells(p.vertices[j], p.vertices[i], raster);
    }
  }
  return OccupancyGrid::Create(width, height, std::move(raster.cells), resolution, bounds.min,
                               limits);
}

}  // namespace swarmplan
