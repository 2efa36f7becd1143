#include "core/smoothing/bezier.h"

#include <algorithm>
#include <cmath>

#include "core/grid_ops/collinear.h"

namespace swarmplan {

const double BezierConstants::c2 = 2.0 * (std::sqrt(6.0) - 1.0) / 5.0;
const double BezierConstants::c3 = (BezierConstants::c2 + 4.0) / (BezierConstants::c1 + 6.0);
const double BezierConstants::c4 =
    (BezierConstants::c2 + 4.0) * (BezierConstants::c2 + 4.0) / (54.0 * BezierConstants::c3);

namespace {

using C = BezierConstants;

}  // namespace

double HalfHeadingChange(const Point2& u1, const Point2& u2) {
  // u1 points back along the incoming line, u2 along the outgoing one: the interior angle is
  // acos(u1·u2) and the heading change its supplement.
  const double cos_interior = std::clamp(u1.dot(u2), -1.0, 1.0);
  return 0.5 * (M_PI - std::acos(cos_interior));
}

namespace {

void AppendCurve(const Point2 p[4], bool reversed, int samples, Path& out) {
  for (int i = 0; i <= samples; ++i) {
    double s = static_cast<double>(i) / samples;
    if (reversed) s = 1.0 - s;
    const Point2 q = CubicBezierPoint(p, s);
    const Point3 q3(q.x(), q.y(), 0.0);
    if (!out.empty() && (out.back() - q3).norm() < 1e-12) continue;
    out.push_back(q3);
  }
}

}  // namespace

Path CornerPolyline(const BezierCorner& c, int samples) {
  Path out;
  AppendCurve(c.b, false, samples, out);
  AppendCurve(c.e, true, samples, out);
  return out;
}

BezierOptions DefaultBezierOptions(const Map& map, double clearance) {
  BezierOptions options;
  options.clearance = clearance;
  if (const OccupancyGrid* grid = map.grid()) {
    options.min_turning_radius = grid->resolution();
  } else if (const ShapeWorld* world = map.world()) {
    options.min_turning_radius =
        std::max(world->bounds().Width(), world->bounds().Height()) / 100.0;
  }
  return options;
}

double BezierCornerCurvature(double beta, double d) {
  const double cb = std::cos(beta);
  return C::c4 * std::sin(beta) / (d * cb * cb);
}

double BezierDistanceForCurvature(double beta, double curvature) {
  const double cb = std::cos(beta);
  return C::c4 * std::sin(beta) / (curvature * cb * cb);
}

BezierCorner MakeBezierCorner(const Point2& prev, const Point2& w, const Point2& next, double d) {
  BezierCorner c;
  const Point2 u1 = (prev - w).normalized();
  const Point2 u2 = (next - w).normalized();
  c.d = d;
  c.beta = HalfHeadingChange(u1, u2);
  const double h = C::c3 * d;
  const double g = C::c2 * C::c3 * d;
  c.b[0] = w + d * u1;
  c.b[1] = c.b[0] - g * u1;
  c.b[2] = c.b[1] - h * u1;
  c.e[0] = w + d * u2;
  c.e[1] = c.e[0] - g * u2;
  c.e[2] = c.e[1] - h * u2;
  // With the published c1 = 7.2364, B2 + k·u_d and E2 − k·u_d differ by about 2e-4·d; the joint
  // is their common midpoint, which keeps position, tangent and curvature continuous exactly.
  const Point2 joint = 0.5 * (c.b[2] + c.e[2]);
  c.b[3] = joint;
  c.e[3] = joint;
  c.max_curvature = BezierCornerCurvature(c.beta, d);
  return c;
}

Point2 CubicBezierPoint(const Point2 p[4], double s) {
  const double t = 1.0 - s;
  return t * t * t * p[0] + 3.0 * t * t * s * p[1] + 3.0 * t * s * s * p[2] + s * s * s * p[3];
}

double CubicBezierCurvature(const Point2 p[4], double s) {
  const double t = 1.0 - s;
  const Point2 d1 =
      3.0 * (t * t * (p[1] - p[0]) + 2.0 * t * s * (p[2] - p[1]) + s * s * (p[3] - p[2]));
  const Point2 d2 = 6.0 * (t * (p[2] - 2.0 * p[1] + p[0]) + s * (p[3] - 2.0 * p[2] + p[1]));
  const double speed = d1.norm();
  if (speed == 0.0) return 0.0;
  return (d1.x() * d2.y() - d1.y() * d2.x()) / (speed * speed * speed);
}

std::vector<double> FitCornerDistances(const std::vector<double>& wanted,
                                       const std::vector<double>& segments) {
  std::vector<double> d = wanted;
  FitCornerDistances(d.data(), segments.data(), d.size());
  return d;
}

void FitCornerDistances(double* d, const double* segments, size_t corners) {
  for (size_t i = 0; i < corners; ++i) d[i] = std::min({d[i], segments[i], segments[i + 1]});
  // Neighbouring corners share segment i + 1: d_i + d_(i+1) <= its length.
  for (size_t i = 0; i + 1 < corners; ++i) {
    const double length = segments[i + 1];
    if (d[i] + d[i + 1] <= length) continue;
    double& small = d[i] <= d[i + 1] ? d[i] : d[i + 1];
    double& large = d[i] <= d[i + 1] ? d[i + 1] : d[i];
    if (small <= 0.5 * length) {
      large = length - small;
    } else {
      small = large = 0.5 * length;
    }
  }
}

BezierResult SmoothWithBezier(const Path& raw, const BezierOptions& options,
                              const CollisionChecker* checker) {
  BezierResult result;
  Path flat;
  flat.reserve(raw.size());
  for (const Point3& p : raw) flat.emplace_back(p.x(), p.y(), 0.0);
  const Path pruned = PruneCollinear(flat);
  if (pruned.size() < 3) {
    result.path = pruned;
    result.collision_free = checker == nullptr || checker->PathFree(result.path, options.clearance);
    return result;
  }
  std::vector<Point2> pts;
  for (const Point3& p : pruned) pts.emplace_back(p.x(), p.y());
  const size_t corners = pts.size() - 2;  // corner i sits at pts[i + 1]
  result.corners = static_cast<int>(corners);
  std::vector<double> seg(pts.size() - 1);
  for (size_t j = 0; j + 1 < pts.size(); ++j) seg[j] = (pts[j + 1] - pts[j]).norm();

  const double wanted_curvature = 1.0 / std::max(options.min_turning_radius, 1e-12);
  std::vector<double> needed(corners);
  for (size_t i = 0; i < corners; ++i) {
    const Point2 u1 = (pts[i] - pts[i + 1]).normalized();
    const Point2 u2 = (pts[i + 2] - pts[i + 1]).normalized();
    needed[i] = BezierDistanceForCurvature(HalfHeadingChange(u1, u2), wanted_curvature);
  }
  const std::vector<double> d = FitCornerDistances(needed, seg);

  std::vector<BezierCorner> built(corners);
  std::vector<bool> sharp(corners, false);
  for (size_t i = 0; i < corners; ++i) {
    if (d[i] < needed[i] * (1.0 - 1e-12)) ++result.corners_limited;
    built[i] = MakeBezierCorner(pts[i], pts[i + 1], pts[i + 2], d[i]);
    if (checker == nullptr) continue;
    int shrinks = 0;
    while (!checker->PathFree(CornerPolyline(built[i], options.samples_per_curve),
                              options.clearance)) {
      if (shrinks == options.max_shrinks) {
        sharp[i] = true;
        break;
      }
      ++shrinks;
      built[i] = MakeBezierCorner(pts[i], pts[i + 1], pts[i + 2], built[i].d * 0.5);
    }
    if (sharp[i]) {
      ++result.corners_sharp;
    } else if (shrinks > 0) {
      ++result.corners_shrunk;
    }
  }

  Path& out = result.path;
  out.push_back(pruned.front());
  for (size_t i = 0; i < corners; ++i) {
    if (sharp[i]) {
      out.push_back(pruned[i + 1]);
      continue;
    }
    const Path curve = CornerPolyline(built[i], options.samples_per_curve);
    for (const Point3& q : curve) {
      if ((out.back() - q).norm() < 1e-12) continue;
      out.push_back(q);
    }
    result.max_curvature = std::max(result.max_curvature, built[i].max_curvature);
  }
  if ((out.back() - pruned.back()).norm() >= 1e-12) out.push_back(pruned.back());
  result.collision_free = checker == nullptr || checker->PathFree(out, options.clearance);
  return result;
}

}  // namespace swarmplan
