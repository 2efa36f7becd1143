#include "core/algorithms/bas/terrain_aco.h"

#include <cmath>
#include <limits>

#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::StatusOr<TerrainAco> TerrainAco::Create(TerrainObjective& objective,
                                              const TerrainAcoOptions& options) {
  const Terrain& terrain = objective.terrain();
  const double span = (terrain.ceiling() - terrain.min_height()) / terrain.cell_size();
  const double cells = static_cast<double>(objective.columns()) * terrain.depth() * (span + 1);
  if (cells > 32.0 * 1024 * 1024) {
    return absl::ResourceExhaustedError(
        absl::StrCat("terrain aco: the pheromone table would hold ", cells,
                     " cells (columns x rows x height levels one cell size apart); the limit "
                     "is 32M"));
  }
  return TerrainAco(objective, options, static_cast<int>(std::floor(span)) + 1);
}

TerrainAco::TerrainAco(TerrainObjective& objective, const TerrainAcoOptions& options, int levels)
    : objective_(&objective),
      options_(options),
      depth_(objective.terrain().depth()),
      levels_(levels),
      base_(objective.terrain().min_height()),
      step_(objective.terrain().cell_size()),
      tau_(static_cast<size_t>(objective.columns()) * depth_ * levels, 1.0) {}

Eigen::VectorXd TerrainAco::Generation(Rng& rng, Evaluation& best, double& mean,
                                       int64_t& evaluations) {
  mean = 0.0;
  const TerrainObjective& obj = *objective_;
  const Terrain& terrain = obj.terrain();
  const int columns = obj.columns();
  Eigen::VectorXd ant(obj.dim()), generation_best;
  std::vector<size_t> visited;
  visited.reserve(static_cast<size_t>(options_.ants) * columns);
  best.fitness = std::numeric_limits<double>::infinity();
  struct Candidate {
    int y, level;
    double weight, fallback;
  };
  std::vector<Candidate> candidates;
  for (int a = 0; a < options_.ants; ++a) {
    int y = std::clamp(static_cast<int>(std::lround(terrain.ToCell(obj.start().head<2>()).y())), 0,
                       depth_ - 1);
    int level = std::clamp(static_cast<int>(std::lround((obj.start().z() - base_) / step_)), 0,
                           levels_ - 1);
    Point3 prev = obj.start();
    for (int k = 0; k < columns; ++k) {
      const double x = obj.ColumnX(k);
      const int left = columns - k;
      candidates.clear();
      double total = 0.0;
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dz = -2; dz <= 2; ++dz) {
          const int ny = y + dy, nl = level + dz;
          if (ny < 0 || ny >= depth_ || nl < 0 || nl >= levels_) continue;
          const Point3 p(x, RowY(ny), LevelZ(nl));
          const double ground = terrain.GroundAt(p.head<2>());
          const double step = (p - prev).norm();
          const double d = 1.0 / (step + std::abs(p.y() - obj.goal().y()) / (left + 1));
          const double m =
              std::isnan(ground) ? 0.0 : step_ / (step_ + std::max(0.0, p.z() - ground));
          const bool valid = obj.SegmentViolation(prev, p) == 0.0;
          const double w = valid ? std::pow(tau_[Index(k, ny, nl)], options_.alpha) * d * m : 0.0;
          candidates.push_back({ny, nl, w, d * m});
          total += w;
        }
      }
      size_t pick = 0;
      if (total > 0.0) {
        double r = rng.Uniform() * total;
        for (pick = 0; pick + 1 < candidates.size(); ++pick) {
          r -= candidates[pick].weight;
          if (r < 0.0) break;
        }
        while (candidates[pick].weight == 0.0 && pick > 0) --pick;
      } else {
        for (size_t i = 1; i < candidates.size(); ++i) {
          if (candidates[i].fallback > candidates[pick].fallback) pick = i;
        }
      }
      y = candidates[pick].y;
      level = candidates[pick].level;
      ant[2 * k] = RowY(y);
      ant[2 * k + 1] = LevelZ(level);
      visited.push_back(Index(k, y, level));
      prev = Point3(x, RowY(y), LevelZ(level));
    }
    const Evaluation e = objective_->Evaluate(ant);
    ++evaluations;
    mean += e.fitness / options_.ants;
    if (a == 0 || e.fitness < best.fitness) {
      best = e;
      generation_best = ant;
    }
  }
  for (size_t i : visited) tau_[i] = std::max(options_.tau_min, options_.local_keep * tau_[i]);
  if (!has_best_ || best.fitness < best_f_) {
    best_f_ = best.fitness;
    best_x_ = generation_best;
    has_best_ = true;
  }
  // q per cell size of fitness: the same pheromone on a terrain scaled in every length.
  const double deposit =
      (1.0 - options_.global_keep) * options_.q * step_ / std::max(best_f_, 1e-9);
  for (int k = 0; k < columns; ++k) {
    const int yy =
        static_cast<int>(std::lround(terrain.ToCell(Point2(obj.ColumnX(k), best_x_[2 * k])).y()));
    const int ll = static_cast<int>(std::lround((best_x_[2 * k + 1] - base_) / step_));
    double& t = tau_[Index(k, yy, ll)];
    t = std::max(options_.tau_min, options_.global_keep * t + deposit);
  }
  return generation_best;
}

SearchOutcome TerrainAco::Run(int t_max, Rng& rng, const StopToken& stop, Observer& observer) {
  SearchOutcome out;
  out.best_fitness = std::numeric_limits<double>::infinity();
  RunIterations(t_max, stop, observer, out, [&](const Iteration&) {
    Evaluation best;
    double mean = 0.0;
    Eigen::VectorXd x = Generation(rng, best, mean, out.evaluations);
    if (out.best_x.size() == 0 || best.fitness < out.best_fitness) {
      out.best_fitness = best.fitness;
      out.best_x = std::move(x);
      out.best_feasible = best.feasible;
    }
    return IterationSummary{mean};
  });
  return out;
}

}  // namespace swarmplan
