#include "core/fitness/rounded_corner_path.h"

#include <algorithm>
#include <cmath>

#include "core/map/point.h"
#include "core/smoothing/bezier.h"

namespace swarmplan {
namespace {

// Corners are designed for a radius 1 % larger, so the sampled curves' discrete curvature stays
// within 1 / radius (as the bounded-curvature smoothing's).
constexpr double kRadiusMargin = 1.01;
constexpr double kNearCurveInRadii = 0.2;
// Chords per cubic: a multiple of the bounded-curvature smoothing's 16, so that the points of
// the smoothing's curves are among ours and the smoothed seed keeps its clearance here too.
constexpr int kSmoothingChordsPerCubic = 16;
constexpr int kMaxChordsPerCubic = 4 * kSmoothingChordsPerCubic;
// Points a path may need beyond its straight parts' spacing: per corner two cubics, and per
// straight part the rounding up of its pieces, the points beside the curves and its end.
constexpr int kPointsPerCorner = 2 * kMaxChordsPerCubic + 5;

// Appends the points of the straight line from a (excluded) to b (included).
struct StraightWriter {
  double* px;
  double* py;
  int n = 0;
  double near_curve = 0.0;

  void Point(const Point2& p) {
    px[n] = p.x();
    py[n] = p.y();
    ++n;
  }
  void Line(const Point2& a, const Point2& b, bool from_curve, bool to_curve, double spacing) {
    const double length = (b - a).norm();
    if (length == 0.0) return;
    const Point2 u = (b - a) / length;
    double lo = 0.0, hi = length;
    if ((from_curve || to_curve) && length <= 2.0 * near_curve) {
      spacing = std::min(spacing, near_curve);
    } else {
      if (from_curve) {
        lo = near_curve;
        Point(a + lo * u);
      }
      if (to_curve) hi = length - near_curve;
    }
    const int pieces = std::max(1, static_cast<int>(std::ceil((hi - lo) / spacing)));
    for (int p = 1; p < pieces; ++p) Point(a + (lo + (hi - lo) * p / pieces) * u);
    if (hi < length) Point(a + hi * u);
    Point(b);
  }
  // One cubic, its first point excluded (it ends the line before it).
  void Cubic(const Point2 c[4], bool reversed) {
    const double polygon = (c[1] - c[0]).norm() + (c[2] - c[1]).norm() + (c[3] - c[2]).norm();
    // Clamped before the conversion: a tiny radius makes the quotient huge.
    const double rounds = std::clamp(std::ceil(polygon / (kSmoothingChordsPerCubic * near_curve)),
                                     1.0, double{kMaxChordsPerCubic / kSmoothingChordsPerCubic});
    const int chords = kSmoothingChordsPerCubic * static_cast<int>(rounds);
    for (int i = 1; i <= chords; ++i) {
      const double s = static_cast<double>(i) / chords;
      Point(CubicBezierPoint(c, reversed ? 1.0 - s : s));
    }
  }
};

}  // namespace

RoundedCornerPath::RoundedCornerPath(int knots, double turning_radius, double spacing,
                                     int max_points)
    : knots_(knots),
      curvature_(1.0 / (kRadiusMargin * turning_radius)),
      near_curve_(kNearCurveInRadii * turning_radius),
      smallest_curve_(kSmallestCurveInRadii * turning_radius),
      spacing_(spacing),
      max_points_(std::max(max_points, 2) + kPointsPerCorner * knots) {}

double RoundedCornerPath::CornerDistances(const double* kx, const double* ky, double* segment,
                                          double* distance) const {
  const int n = knots_;
  double total = 0.0;
  for (int j = 0; j + 1 < n; ++j) {
    segment[j] = std::hypot(kx[j + 1] - kx[j], ky[j + 1] - ky[j]);
    total += segment[j];
  }
  distance[0] = distance[n - 1] = 0.0;
  for (int i = 1; i + 1 < n; ++i) {
    distance[i] = 0.0;
    if (segment[i - 1] == 0.0 || segment[i] == 0.0) continue;
    const Point2 w(kx[i], ky[i]);
    const Point2 u1 = (Point2(kx[i - 1], ky[i - 1]) - w) / segment[i - 1];
    const Point2 u2 = (Point2(kx[i + 1], ky[i + 1]) - w) / segment[i];
    const double beta = HalfHeadingChange(u1, u2);
    // A reversal (beta = pi / 2) has no curve: it stays a cusp, which the curvature term prices.
    if (beta > 0.0 && beta < 0.5 * M_PI - 1e-9) {
      distance[i] = BezierDistanceForCurvature(beta, curvature_);
    }
  }
  if (n > 2) FitCornerDistances(distance + 1, segment, n - 2);
  for (int i = 1; i + 1 < n; ++i) {
    if (distance[i] < smallest_curve_) distance[i] = 0.0;
  }
  return total;
}

int RoundedCornerPath::Apply(const double* kx, const double* ky, double* px, double* py,
                             double* scratch) const {
  const int n = knots_;
  double* segment = scratch;       // n - 1 lengths
  double* distance = scratch + n;  // corner i's d at index i
  const double straight = CornerDistances(kx, ky, segment, distance);

  // The straight parts share what the curves leave of max_points_.
  const int straight_points = max_points_ - kPointsPerCorner * n;
  const double spacing = std::max(spacing_, straight / straight_points);
  StraightWriter out{px, py, 0, near_curve_};
  out.Point(Point2(kx[0], ky[0]));
  Point2 from(kx[0], ky[0]);
  bool from_curve = false;
  for (int i = 1; i + 1 < n; ++i) {
    const Point2 w(kx[i], ky[i]);
    if (distance[i] <= 0.0) {
      // A sharp corner gets the short pieces of a curve beside it.
      out.Line(from, w, from_curve, true, spacing);
      from = w;
      from_curve = true;
      continue;
    }
    const BezierCorner c = MakeBezierCorner(Point2(kx[i - 1], ky[i - 1]), w,
                                            Point2(kx[i + 1], ky[i + 1]), distance[i]);
    out.Line(from, c.b[0], from_curve, true, spacing);
    out.Cubic(c.b, false);
    out.Cubic(c.e, true);
    from = c.e[0];
    from_curve = true;
  }
  out.Line(from, Point2(kx[n - 1], ky[n - 1]), from_curve, false, spacing);
  return out.n;
}

}  // namespace swarmplan
