#include "core/algorithms/bas/seeded_terrain_objective.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace swarmplan {

SeededTerrainObjective::SeededTerrainObjective(std::unique_ptr<TerrainObjective> inner, Path seed,
                                               int vertices_per_control)
    : inner_(std::move(inner)), seed_(std::move(seed)) {
  known_ = KnownPath{seed_, inner_->EvaluatePath(seed_).fitness};
  const int interior = std::max(static_cast<int>(seed_.size()) - 2, 1);
  k_ = std::clamp(interior / std::max(vertices_per_control, 1), 1, interior);
  // The inner box: Y over the cell centres' rows, Z from the lowest ground to the ceiling.
  y_min_ = inner_->lower()[0];
  y_max_ = inner_->upper()[0];
  z_min_ = inner_->lower()[1];
  z_max_ = inner_->upper()[1];
  y_range_ = y_max_ - y_min_;
  z_range_ = z_max_ - z_min_;
  // Vertex v sits at v of [0, n - 1] (start 0, goal n - 1); control point i at (i + 1) of k + 1
  // equal parts.
  const int n = static_cast<int>(seed_.size());
  const double spacing = (n - 1.0) / (k_ + 1.0);
  left_.assign(n, -1);
  weight_.assign(n, 0.0);
  for (int v = 1; v + 1 < n; ++v) {
    const double position = v / spacing;  // point i at i + 1
    const int left = std::min(static_cast<int>(std::floor(position)), k_);
    left_[v] = left - 1;
    weight_[v] = position - left;
  }
  lower_ = Eigen::VectorXd::Constant(2 * k_, -0.5);
  upper_ = Eigen::VectorXd::Constant(2 * k_, 0.5);
}

void SeededTerrainObjective::Move(const Eigen::VectorXd& u, Path& path) const {
  path = seed_;
  for (size_t v = 1; v + 1 < path.size(); ++v) {
    const int left = left_[v];
    const double w = weight_[v];
    const auto offset = [&](int axis) {
      const double a = left >= 0 ? u[2 * left + axis] : 0.0;
      const double b = left + 1 < k_ ? u[2 * (left + 1) + axis] : 0.0;
      return (1.0 - w) * a + w * b;
    };
    path[v].y() = std::clamp(path[v].y() + offset(0) * y_range_, y_min_, y_max_);
    path[v].z() = std::clamp(path[v].z() + offset(1) * z_range_, z_min_, z_max_);
  }
}

Evaluation SeededTerrainObjective::Evaluate(const Eigen::VectorXd& u) {
  Move(u, moved_);
  return inner_->EvaluatePath(moved_);
}

Path SeededTerrainObjective::Decode(const Eigen::VectorXd& u) {
  Path path;
  Move(u, path);
  return path;
}

void SeededTerrainObjective::SampleAroundStraightPath(double band, Rng& rng,
                                                      Eigen::VectorXd& u) const {
  u.resize(dim());
  for (int i = 0; i < dim(); ++i) {
    const double range = i % 2 == 0 ? y_range_ : z_range_;
    u[i] = range > 0.0 ? rng.Uniform(-band, band) / range : 0.0;
  }
  Clamp(u);
}

}  // namespace swarmplan
