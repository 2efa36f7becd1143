#include "core/fitness/interpolation_basis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "absl/synchronization/mutex.h"

namespace swarmplan {
namespace {

std::vector<double> UniformParameters(int knots) {
  std::vector<double> t(knots);
  std::iota(t.begin(), t.end(), 0.0);
  return t;
}

}  // namespace

InterpolationBasis::InterpolationBasis(Interpolation interpolation, int waypoints, int samples)
    : InterpolationBasis(interpolation, UniformParameters(waypoints + 2), samples,
                         /*uniform=*/true) {}

InterpolationBasis::InterpolationBasis(Interpolation interpolation,
                                       const std::vector<double>& parameters, int samples)
    : InterpolationBasis(interpolation, parameters, samples, /*uniform=*/false) {}

InterpolationBasis::InterpolationBasis(Interpolation interpolation,
                                       const std::vector<double>& parameters, int samples,
                                       bool uniform)
    : knots_(static_cast<int>(parameters.size())),
      spline_(interpolation == Interpolation::kSpline) {
  const int n = knots_;
  std::vector<double> h(n - 1);
  for (int i = 0; i + 1 < n; ++i) h[i] = parameters[i + 1] - parameters[i];
  const double span = parameters.back() - parameters.front();
  first_.assign(n - 1, 0);
  // Point weights (a, b) of the piece's knots in both coordinates, c and d of its moments.
  auto add = [this](double ax, double bx, double ay, double by, double c = 0.0, double d = 0.0) {
    ax_.push_back(ax);
    bx_.push_back(bx);
    ay_.push_back(ay);
    by_.push_back(by);
    c_.push_back(c);
    d_.push_back(d);
  };
  auto start_piece = [this](int j) { first_[j] = points(); };
  switch (interpolation) {
    case Interpolation::kSpline: {
      // `count` points at equal parameter steps (WaypointPathBuilder: CubicSpline::Evaluate at
      // s = j (n - 1) / (count - 1)), the last exactly at the last knot.
      const int count = std::max(samples, 2);
      const double step = span / (count - 1);
      int piece = -1;
      for (int j = 0; j < count; ++j) {
        const double s = j == count - 1 ? parameters.back() : parameters.front() + j * step;
        int i = std::max(piece, 0);
        while (i < n - 2 && s >= parameters[i + 1]) ++i;
        while (piece < i) start_piece(++piece);
        const double b = std::clamp((s - parameters[i]) / h[i], 0.0, 1.0), a = 1.0 - b;
        const double scale = h[i] * h[i] / 6.0;
        add(a, b, a, b, (a * a * a - a) * scale, (b * b * b - b) * scale);
      }
      while (piece < n - 2) start_piece(++piece);
      break;
    }
    case Interpolation::kLinear:
      for (int j = 0; j + 1 < n; ++j) {
        start_piece(j);
        add(1, 0, 1, 0);
      }
      add(0, 1, 0, 1);
      break;
    case Interpolation::kPolyline: {
      // Evenly sampled pieces: (samples - 1) / (n - 1) points each, or with parameters their
      // share of the samples by parameter length; every knot among the points.
      for (int j = 0; j + 1 < n; ++j) {
        start_piece(j);
        const int pieces =
            uniform ? std::max(1, (samples - 1) / (n - 1))
                    : std::max(1, static_cast<int>(std::lround((samples - 1) * h[j] / span)));
        for (int i = 0; i < pieces; ++i) {
          const double t = static_cast<double>(i) / pieces;
          add(1.0 - t, t, 1.0 - t, t);
        }
      }
      add(0, 1, 0, 1);
      break;
    }
    case Interpolation::kNearest:
      // The staircase: x moves to the middle, y jumps there, then the next knot.
      for (int j = 0; j + 1 < n; ++j) {
        start_piece(j);
        if (j == 0) add(1, 0, 1, 0);
        add(0.5, 0.5, 1, 0);
        add(0.5, 0.5, 0, 1);
        add(0, 1, 0, 1);
      }
      break;
  }
  first_.push_back(points());
  if (spline_) FactorMomentSystem(h);
}

void InterpolationBasis::FactorMomentSystem(const std::vector<double>& h) {
  const int n = knots_;
  h_ = h;
  inverse_h_.resize(h.size());
  for (size_t i = 0; i < h.size(); ++i) inverse_h_[i] = 1.0 / h[i];
  if (n < 4) return;
  // Unknowns M_1..M_n-2. Interior row i:
  //   h_i-1 M_i-1 + 2 (h_i-1 + h_i) M_i + h_i M_i+1 = 6 ((y_i+1 - y_i) / h_i - (y_i - y_i-1) /
  //   h_i-1).
  // Not-a-knot ends (the third derivative continuous at the second and the second-to-last knot)
  // give M_0 = ((h_0 + h_1) M_1 - h_0 M_2) / h_1, and mirrored, which folds into the first and
  // last rows. The system is diagonally dominant: the Thomas sweep needs no pivoting.
  const int m = n - 2;
  sub_.assign(m, 0.0);
  pivot_.assign(m, 0.0);
  super_.assign(m, 0.0);
  std::vector<double> main(m), upper(m);
  for (int k = 0; k < m; ++k) {
    const int i = k + 1;
    sub_[k] = h[i - 1];
    main[k] = 2.0 * (h[i - 1] + h[i]);
    upper[k] = h[i];
  }
  main[0] += h[0] * (h[0] + h[1]) / h[1];
  upper[0] -= h[0] * h[0] / h[1];
  sub_[0] = 0.0;
  main[m - 1] += h[n - 2] * (h[n - 3] + h[n - 2]) / h[n - 3];
  sub_[m - 1] -= h[n - 2] * h[n - 2] / h[n - 3];
  upper[m - 1] = 0.0;
  for (int k = 0; k < m; ++k) {
    pivot_[k] = main[k] - (k > 0 ? sub_[k] * super_[k - 1] : 0.0);
    super_[k] = upper[k] / pivot_[k];
    pivot_[k] = 1.0 / pivot_[k];
  }
}

size_t InterpolationBasis::MemoryBytes() const {
  return sizeof(*this) + first_.size() * sizeof(int) +
         (6 * ax_.size() + 5 * h_.size()) * sizeof(double);
}

void InterpolationBasis::Moments(const double* v, double* out) const {
  const int n = knots_;
  const std::vector<double>& h = h_;
  if (n == 3) {
    // Not-a-knot through three knots is the parabola: one second derivative.
    const double second = 2.0 * ((v[2] - v[1]) / h[1] - (v[1] - v[0]) / h[0]) / (h[0] + h[1]);
    std::fill(out, out + n, second);
    return;
  }
  const int m = n - 2;
  double* r = out + 1;
  const double* inv = inverse_h_.data();
  for (int k = 0; k < m; ++k) {
    r[k] = 6.0 * ((v[k + 2] - v[k + 1]) * inv[k + 1] - (v[k + 1] - v[k]) * inv[k]);
    if (k > 0) r[k] -= sub_[k] * r[k - 1];
    r[k] *= pivot_[k];
  }
  for (int k = m - 2; k >= 0; --k) r[k] -= super_[k] * r[k + 1];
  out[0] = ((h[0] + h[1]) * out[1] - h[0] * out[2]) / h[1];
  out[n - 1] = ((h[n - 3] + h[n - 2]) * out[n - 2] - h[n - 2] * out[n - 3]) / h[n - 3];
}

void InterpolationBasis::ApplyCoordinate(const double* v, const double* m,
                                         const std::vector<double>& a, const std::vector<double>& b,
                                         double* p) const {
  for (int j = 0; j + 1 < knots_; ++j) {
    const double k0 = v[j], k1 = v[j + 1];
    const int begin = first_[j], end = first_[j + 1];
    if (spline_) {
      const double m0 = m[j], m1 = m[j + 1];
      for (int i = begin; i < end; ++i) p[i] = a[i] * k0 + b[i] * k1 + c_[i] * m0 + d_[i] * m1;
    } else {
      for (int i = begin; i < end; ++i) p[i] = a[i] * k0 + b[i] * k1;
    }
  }
}

void InterpolationBasis::Apply(const double* kx, const double* ky, double* px, double* py,
                               double* moments) const {
  double* mx = moments;
  double* my = moments + knots_;
  if (spline_) {
    Moments(kx, mx);
    Moments(ky, my);
  }
  ApplyCoordinate(kx, mx, ax_, bx_, px);
  ApplyCoordinate(ky, my, ay_, by_, py);
}

std::shared_ptr<const InterpolationBasis> CachedInterpolationBasis(Interpolation interpolation,
                                                                   int waypoints, int samples) {
  using Key = std::tuple<Interpolation, int, int>;
  static absl::Mutex mutex(absl::kConstInit);
  static auto* const cache = new std::map<Key, std::shared_ptr<const InterpolationBasis>>();
  static size_t cached_bytes = 0;
  const Key key(interpolation, waypoints, samples);
  {
    absl::MutexLock lock(&mutex);
    auto it = cache->find(key);
    if (it != cache->end()) return it->second;
  }
  auto built = std::make_shared<const InterpolationBasis>(interpolation, waypoints, samples);
  absl::MutexLock lock(&mutex);
  auto [it, inserted] = cache->try_emplace(key, nullptr);
  if (!inserted) return it->second;
  if (cached_bytes + built->MemoryBytes() > kMaxCachedBasisBytes) {
    cache->erase(it);
    return built;
  }
  cached_bytes += built->MemoryBytes();
  it->second = std::move(built);
  return it->second;
}

}  // namespace swarmplan
