#include "core/map/generate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "core/random.h"

namespace swarmplan {
namespace {

constexpr int kCoverageSamples = 256;
constexpr int kMaxAttemptsPerObstacle = 1000;

bool InsidePolygon(const std::vector<Point2>& v, const Point2& p) {
  bool inside = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Lattice of sample points over the bounds, marking which are covered by some obstacle.
class CoverageLattice {
 public:
  CoverageLattice(const Bounds2& bounds, int samples)
      : bounds_(bounds), samples_(samples), covered_(static_cast<size_t>(samples) * samples) {}

  Point2 Sample(int i, int j) const {
    return bounds_.min +
           Point2((i + 0.5) / samples_ * bounds_.Width(), (j + 0.5) / samples_ * bounds_.Height());
  }

  // Marks the samples inside a shape given by its bounding box and an inside test.
  template <typename Inside>
  void Add(const Point2& box_min, const Point2& box_max, Inside inside) {
    const auto index = [&](double v, double lo, double size) {
      return std::clamp(static_cast<int>(std::floor((v - lo) / size * samples_ - 0.5)), 0,
                        samples_ - 1);
    };
    const int i0 = index(box_min.x(), bounds_.min.x(), bounds_.Width());
    const int i1 = index(box_max.x(), bounds_.min.x(), bounds_.Width()) + 1;
    const int j0 = index(box_min.y(), bounds_.min.y(), bounds_.Height());
    const int j1 = index(box_max.y(), bounds_.min.y(), bounds_.Height()) + 1;
    for (int j = j0; j <= std::min(j1, samples_ - 1); ++j) {
      for (int i = i0; i <= std::min(i1, samples_ - 1); ++i) {
        uint8_t& c = covered_[static_cast<size_t>(j) * samples_ + i];
        if (!c && inside(Sample(i, j))) {
          c = 1;
          ++count_;
        }
      }
    }
  }
  void Add(const Circle& circle) {
    const Point2 r(circle.radius, circle.radius);
    Add(circle.center - r, circle.center + r, [&](const Point2& p) {
      return (p - circle.center).squaredNorm() <= circle.radius * circle.radius;
    });
  }
  void Add(const Polygon& polygon) {
    Point2 lo = polygon.vertices.front(), hi = lo;
    for (const Point2& v : polygon.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    Add(lo, hi, [&](const Point2& p) { return InsidePolygon(polygon.vertices, p); });
  }
  double Share() const { return static_cast<double>(count_) / covered_.size(); }

 private:
  Bounds2 bounds_;
  int samples_;
  std::vector<uint8_t> covered_;
  int64_t count_ = 0;
};

// A convex polygon inscribed in the circle (center, radius): vertices at jittered, evenly
// spaced angles, counter-clockwise.
Polygon RandomConvexPolygon(Rng& rng, const Point2& center, double radius, int vertices) {
  const double step = 2 * std::numbers::pi / vertices;
  const double rotation = rng.Uniform(0, 2 * std::numbers::pi);
  Polygon polygon;
  for (int k = 0; k < vertices; ++k) {
    const double angle = rotation + k * step + rng.Uniform(-0.4, 0.4) * step;
    polygon.vertices.push_back(center + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  return polygon;
}

bool KeepsClear(const Point2& center, double radius, const std::vector<Point2>& keep_clear,
                double keep_clear_radius) {
  for (const Point2& p : keep_clear) {
    if ((p - center).norm() <= radius + keep_clear_radius) return false;
  }
  return true;
}

absl::Status CheckWorldOptions(const Bounds2& bounds, double min_radius, double max_radius,
                               double keep_clear_radius) {
  if (!bounds.min.allFinite() || !bounds.max.allFinite() || bounds.Width() <= 0 ||
      bounds.Height() <= 0) {
    return absl::InvalidArgumentError("bounds: must be finite with max > min in x and y");
  }
  if (!(min_radius > 0 && max_radius >= min_radius && std::isfinite(max_radius))) {
    return absl::InvalidArgumentError(absl::StrCat("radii: need 0 < min_radius <= max_radius, got ",
                                                   min_radius, " and ", max_radius));
  }
  if (!(keep_clear_radius >= 0 && std::isfinite(keep_clear_radius))) {
    return absl::InvalidArgumentError("keep_clear_radius: must be a non-negative number");
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<OccupancyGrid> RandomGrid(const RandomGridOptions& options, uint64_t seed) {
  const int w = options.width;
  const int h = options.height;
  if (w <= 0 || h <= 0) {
    return absl::InvalidArgumentError(absl::StrCat("grid size ", w, " x ", h, " must be positive"));
  }
  if (static_cast<int64_t>(w) * h > MapLimits{}.max_cells) {
    return absl::ResourceExhaustedError(absl::StrCat(
        "grid of ", w, " x ", h, " exceeds the limit of ", MapLimits{}.max_cells, " cells"));
  }
  if (!(options.obstacle_ratio >= 0 && options.obstacle_ratio <= 0.95)) {
    return absl::InvalidArgumentError(
        absl::StrCat("obstacle_ratio must be in [0, 0.95], got ", options.obstacle_ratio));
  }
  if (options.block_size < 1 || options.block_size > std::min(w, h)) {
    return absl::InvalidArgumentError(
        absl::StrCat("block_size must be in 1..", std::min(w, h), ", got ", options.block_size));
  }
  const size_t count = static_cast<size_t>(w) * h;
  std::vector<uint8_t> keep(count, 0);
  for (const Cell& c : options.keep_free) {
    if (c.x < 0 || c.y < 0 || c.x >= w || c.y >= h) {
      return absl::InvalidArgumentError(
          absl::StrCat("keep_free cell ", c.x, ",", c.y, " lies outside the grid"));
    }
    keep[static_cast<size_t>(c.y) * w + c.x] = 1;
  }
  const int64_t eligible = static_cast<int64_t>(std::count(keep.begin(), keep.end(), 0));
  const int64_t target = std::llround(options.obstacle_ratio * static_cast<double>(count));
  if (target > eligible) {
    return absl::InvalidArgumentError(absl::StrCat("obstacle_ratio ", options.obstacle_ratio,
                                                   " needs ", target, " blocked cells but only ",
                                                   eligible, " may be blocked"));
  }
  Rng rng(seed);
  std::vector<int8_t> cells(count, OccupancyGrid::kFree);
  int64_t blocked = 0;
  const auto block = [&](size_t i) {
    if (blocked < target && !keep[i] && cells[i] == OccupancyGrid::kFree) {
      cells[i] = OccupancyGrid::kOccupied;
      ++blocked;
    }
  };
  const int b = options.block_size;
  if (b > 1) {
    const int64_t attempts = 100 * (target / (static_cast<int64_t>(b) * b) + 1);
    for (int64_t a = 0; a < attempts && blocked < target; ++a) {
      const int x0 = static_cast<int>(rng.UniformInt(0, w - b));
      const int y0 = static_cast<int>(rng.UniformInt(0, h - b));
      for (int y = y0; y < y0 + b; ++y) {
        for (int x = x0; x < x0 + b; ++x) block(static_cast<size_t>(y) * w + x);
      }
    }
  }
  // Single cells (or the remainder after blocks): a partial Fisher-Yates shuffle of the cells
  // that may still be blocked, so the count is exact.
  if (blocked < target) {
    std::vector<size_t> candidates;
    for (size_t i = 0; i < count; ++i) {
      if (!keep[i] && cells[i] == OccupancyGrid::kFree) candidates.push_back(i);
    }
    for (size_t k = 0; blocked < target; ++k) {
      const size_t pick = static_cast<size_t>(
          rng.UniformInt(static_cast<int64_t>(k), static_cast<int64_t>(candidates.size()) - 1));
      std::swap(candidates[k], candidates[pick]);
      block(candidates[k]);
    }
  }
  return OccupancyGrid::Create(w, h, std::move(cells), options.resolution);
}

absl::StatusOr<OccupancyGrid> RandomGrid(int width, int height, double obstacle_ratio,
                                         uint64_t seed) {
  RandomGridOptions options;
  options.width = width;
  options.height = height;
  options.obstacle_ratio = obstacle_ratio;
  return RandomGrid(options, seed);
}

absl::StatusOr<ShapeWorld> RandomShapeWorld(const RandomWorldOptions& options, uint64_t seed) {
  if (auto s = CheckWorldOptions(options.bounds, options.min_radius, options.max_radius,
                                 options.keep_clear_radius);
      !s.ok()) {
    return s;
  }
  if (!(options.obstacle_ratio >= 0 && options.obstacle_ratio <= 0.9)) {
    return absl::InvalidArgumentError(
        absl::StrCat("obstacle_ratio must be in [0, 0.9], got ", options.obstacle_ratio));
  }
  if (!(options.polygon_share >= 0 && options.polygon_share <= 1)) {
    return absl::InvalidArgumentError("polygon_share must be in [0, 1]");
  }
  if (options.min_vertices < 3 || options.max_vertices < options.min_vertices ||
      options.max_vertices > 64) {
    return absl::InvalidArgumentError("vertices: need 3 <= min_vertices <= max_vertices <= 64");
  }
  Rng rng(seed);
  CoverageLattice lattice(options.bounds, kCoverageSamples);
  std::vector<Circle> circles;
  std::vector<Polygon> polygons;
  int failures = 0;
  while (lattice.Share() < options.obstacle_ratio) {
    const Point2 center(rng.Uniform(options.bounds.min.x(), options.bounds.max.x()),
                        rng.Uniform(options.bounds.min.y(), options.bounds.max.y()));
    const double radius = rng.Uniform(options.min_radius, options.max_radius);
    const bool polygon = rng.Bernoulli(options.polygon_share);
    const int vertices =
        static_cast<int>(rng.UniformInt(options.min_vertices, options.max_vertices));
    if (!KeepsClear(center, radius, options.keep_clear, options.keep_clear_radius)) {
      if (++failures > kMaxAttemptsPerObstacle) {
        return absl::InvalidArgumentError(
            absl::StrCat("cannot reach obstacle_ratio ", options.obstacle_ratio, " (reached ",
                         lattice.Share(), "): the keep-clear points leave too little room"));
      }
      continue;
    }
    failures = 0;
    if (polygon) {
      polygons.push_back(RandomConvexPolygon(rng, center, radius, vertices));
      lattice.Add(polygons.back());
    } else {
      circles.push_back(Circle{center, radius});
      lattice.Add(circles.back());
    }
  }
  return ShapeWorld::Create(options.bounds, std::move(circles), std::move(polygons));
}

absl::StatusOr<ShapeWorld> RandomShapeWorld(const Bounds2& bounds, int circles, double min_radius,
                                            double max_radius, uint64_t seed,
                                            const std::vector<Point2>& keep_clear,
                                            double keep_clear_radius) {
  if (auto s = CheckWorldOptions(bounds, min_radius, max_radius, keep_clear_radius); !s.ok()) {
    return s;
  }
  if (circles < 0 || circles > MapLimits{}.max_obstacles) {
    return absl::InvalidArgumentError(
        absl::StrCat("circles must be in 0..", MapLimits{}.max_obstacles, ", got ", circles));
  }
  Rng rng(seed);
  std::vector<Circle> out;
  int failures = 0;
  while (static_cast<int>(out.size()) < circles) {
    const Point2 center(rng.Uniform(bounds.min.x(), bounds.max.x()),
                        rng.Uniform(bounds.min.y(), bounds.max.y()));
    const double radius = rng.Uniform(min_radius, max_radius);
    if (!KeepsClear(center, radius, keep_clear, keep_clear_radius)) {
      if (++failures > kMaxAttemptsPerObstacle) {
        return absl::InvalidArgumentError(
            absl::StrCat("cannot place ", circles, " circles (placed ", out.size(),
                         "): the keep-clear points leave too little room"));
      }
      continue;
    }
    failures = 0;
    out.push_back(Circle{center, radius});
  }
  return ShapeWorld::Create(bounds, std::move(out), {});
}

double CoveredShare(const ShapeWorld& world, int samples) {
  CoverageLattice lattice(world.bounds(), std::max(1, samples));
  for (const Circle& c : world.circles()) lattice.Add(c);
  for (const Polygon& p : world.polygons()) lattice.Add(p);
  return lattice.Share();
}

}  // namespace swarmplan
