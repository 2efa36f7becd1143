#include "core/smoothing/cubic_spline.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace swarmplan {

void CubicSpline::Fit(const std::vector<Point3>& knots, SplineEnd end) {
  knots_.assign(knots.begin(), knots.end());
  const int n = static_cast<int>(knots_.size());
  second_.assign(n, Point3::Zero());
  if (n < 3) return;  // a point or a straight segment
  if (n == 3 && end == SplineEnd::kNotAKnot) {
    // Not-a-knot through three points is the single parabola: constant second derivative.
    const Point3 m = knots_[0] - 2.0 * knots_[1] + knots_[2];
    std::fill(second_.begin(), second_.end(), m);
    return;
  }
  // Unknowns M_1..M_{n-2}; with unit knot spacing the interior rows read
  // M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i-1} - 2 y_i + y_{i+1}). Natural ends set M_0 = M_{n-1} = 0.
  // Not-a-knot ends set M_0 = 2 M_1 - M_2 (and mirrored), which turns the first and last rows
  // into 6 M_1 = r_1 and 6 M_{n-2} = r_{n-2}.
  const int m = n - 2;
  const bool not_a_knot = end == SplineEnd::kNotAKnot;
  diag_.resize(m);
  rhs_.resize(m);
  rhs_scratch_.resize(m);  // modified super-diagonal of the Thomas sweep
  for (int k = 0; k < m; ++k) {
    const int i = k + 1;
    rhs_[k] = 6.0 * (knots_[i - 1] - 2.0 * knots_[i] + knots_[i + 1]);
  }
  auto sub = [&](int k) { return (k == 0 || (not_a_knot && k == m - 1)) ? 0.0 : 1.0; };
  auto super = [&](int k) { return (k == m - 1 || (not_a_knot && k == 0)) ? 0.0 : 1.0; };
  auto main = [&](int k) { return (not_a_knot && (k == 0 || k == m - 1)) ? 6.0 : 4.0; };
  // Thomas algorithm (the system is diagonally dominant).
  for (int k = 0; k < m; ++k) {
    const double denom = main(k) - (k > 0 ? sub(k) * rhs_scratch_[k - 1] : 0.0);
    rhs_scratch_[k] = super(k) / denom;
    if (k > 0) rhs_[k] -= sub(k) * rhs_[k - 1];
    rhs_[k] /= denom;
  }
  for (int k = m - 2; k >= 0; --k) rhs_[k] -= rhs_scratch_[k] * rhs_[k + 1];
  for (int k = 0; k < m; ++k) second_[k + 1] = rhs_[k];
  if (not_a_knot) {
    second_[0] = 2.0 * second_[1] - second_[2];
    second_[n - 1] = 2.0 * second_[n - 2] - second_[n - 3];
  }
}

Point3 CubicSpline::Evaluate(double s) const {
  const int n = static_cast<int>(knots_.size());
  if (n == 0) return Point3::Zero();
  if (n == 1) return knots_[0];
  s = std::clamp(s, 0.0, static_cast<double>(n - 1));
  const int i = std::min(static_cast<int>(s), n - 2);  // s >= 0: truncation is floor
  const double t = s - i;
  const double u = 1.0 - t;
  return u * knots_[i] + t * knots_[i + 1] +
         ((u * u * u - u) * second_[i] + (t * t * t - t) * second_[i + 1]) * (1.0 / 6.0);
}

void CubicSpline::SampleByCount(int count, std::vector<Point3>& out) const {
  out.clear();
  const int n = static_cast<int>(knots_.size());
  if (n == 0) return;
  count = std::max(count, 2);
  const double step = static_cast<double>(n - 1) / (count - 1);
  for (int j = 0; j < count; ++j) out.push_back(Evaluate(j == count - 1 ? n - 1 : j * step));
}

void CubicSpline::SampleBySpacing(double spacing, std::vector<Point3>& out) const {
  out.clear();
  const int n = static_cast<int>(knots_.size());
  if (n == 0) return;
  out.push_back(knots_[0]);
  // Each piece is tabulated at kProbe parameter steps; samples are placed at equal arc length
  // by linear interpolation of the parameter in that table.
  constexpr int kProbe = 64;
  std::array<double, kProbe + 1> arc;
  for (int i = 0; i + 1 < n; ++i) {
    arc[0] = 0.0;
    Point3 prev = knots_[i];
    for (int j = 1; j <= kProbe; ++j) {
      const Point3 p = Evaluate(i + static_cast<double>(j) / kProbe);
      arc[j] = arc[j - 1] + (p - prev).norm();
      prev = p;
    }
    const int pieces = std::max(1, static_cast<int>(std::ceil(arc[kProbe] / spacing)));
    int j = 0;
    for (int k = 1; k < pieces; ++k) {
      const double target = arc[kProbe] * k / pieces;
      while (j + 1 < kProbe && arc[j + 1] < target) ++j;
      const double span = arc[j + 1] - arc[j];
      const double frac = span > 0.0 ? (target - arc[j]) / span : 0.0;
      out.push_back(Evaluate(i + (j + frac) / kProbe));
    }
    out.push_back(knots_[i + 1]);
  }
}

std::vector<Point3> SplineThrough(const std::vector<Point3>& knots, int count, SplineEnd end) {
  CubicSpline spline;
  spline.Fit(knots, end);
  std::vector<Point3> out;
  spline.SampleByCount(count, out);
  return out;
}

}  // namespace swarmplan
