#include "bench/papers/bpso_vertices_worlds.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "core/random.h"

namespace swarmplan::bench {
namespace {

constexpr double kMargin = 5.0;      // obstacles stay this far inside the bounds
constexpr double kGap = 8.0;         // between the circumcircles of two rectangles
constexpr double kEndClear = 25.0;   // between an obstacle's circumcircle and start or goal
constexpr double kMaxOffset = 70.0;  // perpendicular distance of a centre from the diagonal
constexpr int kMaxAttempts = 100000;

struct Placed {
  Point2 center;
  double radius;
};

double RoundToHalf(double v) { return std::round(v * 2.0) / 2.0; }

}  // namespace

absl::StatusOr<ShapeWorld> GenerateBpsoVerticesWorld(int rectangles, uint64_t seed) {
  const Bounds2 bounds{Point2(0, 0), Point2(300, 300)};
  const Point2 start = BpsoVerticesStart(), goal = BpsoVerticesGoal();
  const Point2 along = (goal - start).normalized();
  const Point2 across(-along.y(), along.x());
  Rng rng(seed);
  std::vector<Placed> placed;
  std::vector<Polygon> polygons;
  for (int attempt = 0; attempt < kMaxAttempts && static_cast<int>(polygons.size()) < rectangles;
       ++attempt) {
    const bool first = polygons.empty();
    // The first rectangle is large and lies across the diagonal: the detour matters.
    const double t = rng.Uniform(first ? 0.3 : 0.1, first ? 0.7 : 0.9) * (goal - start).norm();
    const double offset = first ? rng.Uniform(-5.0, 5.0) : rng.Uniform(-kMaxOffset, kMaxOffset);
    const Point2 center = start + t * along + offset * across;
    const double low = first ? 25.0 : 8.0, high = first ? 40.0 : 26.0;
    const double half_w = rng.Uniform(low, high), half_h = rng.Uniform(low, high);
    const double angle = rng.Uniform(0.0, std::numbers::pi / 2.0);
    const double radius = std::hypot(half_w, half_h) + 0.5;  // + the rounding
    bool fits =
        (center - start).norm() > radius + kEndClear && (center - goal).norm() > radius + kEndClear;
    for (const Placed& other : placed) {
      if ((center - other.center).norm() < radius + other.radius + kGap) fits = false;
    }
    const Point2 u(std::cos(angle), std::sin(angle)), v(-std::sin(angle), std::cos(angle));
    Polygon polygon;
    for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      const Point2 p = center + su * half_w * u + sv * half_h * v;
      const Point2 rounded(RoundToHalf(p.x()), RoundToHalf(p.y()));
      if (rounded.x() < kMargin || rounded.y() < kMargin || rounded.x() > 300 - kMargin ||
          rounded.y() > 300 - kMargin) {
        fits = false;
      }
      polygon.vertices.push_back(rounded);
    }
    if (!fits) continue;
    placed.push_back({center, radius});
    polygons.push_back(std::move(polygon));
  }
  if (static_cast<int>(polygons.size()) < rectangles) {
    return absl::InternalError(
        absl::StrFormat("bpso-vertices: could not place %d rectangles (seed %d)", rectangles,
                        static_cast<int64_t>(seed)));
  }
  return ShapeWorld::Create(bounds, {}, std::move(polygons));
}

}  // namespace swarmplan::bench
