#include "core/geometry/distance_transform.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace swarmplan {
namespace {

// One-dimensional transform of f (length n) into d: d[q] = min_p (q - p)^2 + f[p], by the lower
// envelope of parabolas. v and z are scratch buffers of size n and n + 1.
void Transform1D(const double* f, int n, double* d, int* v, double* z) {
  int k = 0;
  int first = 0;
  while (first < n && f[first] == kInf) ++first;
  if (first == n) {
    for (int q = 0; q < n; ++q) d[q] = kInf;
    return;
  }
  v[0] = first;
  z[0] = -kInf;
  z[1] = kInf;
  for (int q = first + 1; q < n; ++q) {
    if (f[q] == kInf) continue;
    double s;
    while (true) {
      const int p = v[k];
      s = ((f[q] + static_cast<double>(q) * q) - (f[p] + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s <= z[k] && k > 0) {
        --k;
      } else {
        break;
      }
    }
    if (s <= z[k]) {  // k == 0 and the new parabola dominates everywhere
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
}

}  // namespace

std::vector<double> SquaredDistanceTransform(int width, int height,
                                             const std::vector<uint8_t>& blocked) {
  const size_t cells = static_cast<size_t>(width) * height;
  std::vector<double> out(cells);
  for (size_t i = 0; i < cells; ++i) out[i] = blocked[i] ? 0.0 : kInf;
  const int n = std::max(width, height);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  // Columns first, then rows.
  for (int x = 0; x < width; ++x) {
    for (int y = 0; y < height; ++y) f[y] = out[static_cast<size_t>(y) * width + x];
    Transform1D(f.data(), height, d.data(), v.data(), z.data());
    for (int y = 0; y < height; ++y) out[static_cast<size_t>(y) * width + x] = d[y];
  }
  for (int y = 0; y < height; ++y) {
    double* row = out.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) f[x] = row[x];
    Transform1D(f.data(), width, d.data(), v.data(), z.data());
    for (int x = 0; x < width; ++x) row[x] = d[x];
  }
  return out;
}

}  // namespace swarmplan
