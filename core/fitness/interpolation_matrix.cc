#include "core/fitness/interpolation_matrix.h"

#include <map>
#include <tuple>

#include "absl/synchronization/mutex.h"

namespace swarmplan {

InterpolationMatrix BuildInterpolationMatrix(Interpolation interpolation, int waypoints,
                                             int samples) {
  const int knots = waypoints + 2;
  // Knot j at (1, 1), every other knot at the origin: each coordinate is interpolated on its
  // own, so the path's x and y are knot j's weights in the two coordinates.
  InterpolationMatrix m;
  Eigen::VectorXd x(2 * waypoints);
  for (int j = 0; j < knots; ++j) {
    x.setZero();
    if (j > 0 && j < knots - 1) x[j - 1] = x[waypoints + j - 1] = 1.0;
    const Point3 start = j == 0 ? Point3(1, 1, 0) : Point3::Zero();
    const Point3 goal = j == knots - 1 ? Point3(1, 1, 0) : Point3::Zero();
    WaypointPathBuilder builder(start, goal, waypoints, interpolation, samples);
    const Path& path = builder.Build(x);
    if (j == 0) {
      m.x.resize(static_cast<int>(path.size()), knots);
      m.y.resize(static_cast<int>(path.size()), knots);
    }
    for (int i = 0; i < m.x.rows(); ++i) {
      m.x(i, j) = path[i].x();
      m.y(i, j) = path[i].y();
    }
  }
  return m;
}

std::shared_ptr<const InterpolationMatrix> CachedInterpolationMatrix(Interpolation interpolation,
                                                                     int waypoints, int samples) {
  using Key = std::tuple<Interpolation, int, int>;
  static absl::Mutex mutex(absl::kConstInit);
  static auto* const cache = new std::map<Key, std::shared_ptr<const InterpolationMatrix>>();
  const Key key(interpolation, waypoints, samples);
  {
    absl::MutexLock lock(&mutex);
    auto it = cache->find(key);
    if (it != cache->end()) return it->second;
  }
  auto built = std::make_shared<const InterpolationMatrix>(
      BuildInterpolationMatrix(interpolation, waypoints, samples));
  if (built->x.size() > kMaxCachedEntries) return built;
  absl::MutexLock lock(&mutex);
  if (static_cast<int>(cache->size()) >= kMaxCachedMatrices) return built;
  return cache->emplace(key, std::move(built)).first->second;
}

}  // namespace swarmplan
