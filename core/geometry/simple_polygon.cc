#include "core/geometry/simple_polygon.h"

#include <algorithm>
#include <numeric>

#include "absl/strings/str_cat.h"
#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

std::string Describe(const std::vector<Point2>& ring, size_t edge) {
  const Point2& a = ring[edge];
  const Point2& b = ring[(edge + 1) % ring.size()];
  return absl::StrCat("edge ", edge, " (", a.x(), ", ", a.y(), ")-(", b.x(), ", ", b.y(), ")");
}

absl::Status Crossing(const std::vector<Point2>& ring, size_t i, size_t j, const char* what) {
  return absl::InvalidArgumentError(absl::StrCat(
      "polygon is self-intersecting: ", Describe(ring, i), " and ", Describe(ring, j), " ", what));
}

}  // namespace

absl::Status CheckSimplePolygon(const std::vector<Point2>& ring) {
  const size_t n = ring.size();
  if (n > kMaxPolygonVertices) {
    return absl::ResourceExhaustedError(
        absl::StrCat("polygon has ", n, " vertices, more than the limit of ", kMaxPolygonVertices));
  }
  // Adjacent edges a-b and b-c overlap when one's far end lies on the other.
  for (size_t i = 0; i < n; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % n];
    const Point2& c = ring[(i + 2) % n];
    if (PointSegmentDistance(c, a, b) <= kGeometryEpsilon ||
        PointSegmentDistance(a, b, c) <= kGeometryEpsilon) {
      return Crossing(ring, i, (i + 1) % n, "overlap (the boundary turns back on itself)");
    }
  }
  // Non-adjacent edges, swept by their smallest x: only edges whose x ranges overlap are
  // compared.
  auto min_x = [&](size_t e) { return std::min(ring[e].x(), ring[(e + 1) % n].x()); };
  auto max_x = [&](size_t e) { return std::max(ring[e].x(), ring[(e + 1) % n].x()); };
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return min_x(a) < min_x(b) || (min_x(a) == min_x(b) && a < b);
  });
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    const double reach = max_x(i) + kGeometryEpsilon;
    for (size_t m = k + 1; m < n && min_x(order[m]) <= reach; ++m) {
      const size_t j = order[m];
      const size_t gap = i > j ? i - j : j - i;
      if (gap == 1 || gap == n - 1) continue;  // adjacent: checked above
      if (SegmentsIntersect(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) {
        return Crossing(ring, std::min(i, j), std::max(i, j), "cross or touch");
      }
    }
  }
  return absl::OkStatus();
}

}  // namespace swarmplan
