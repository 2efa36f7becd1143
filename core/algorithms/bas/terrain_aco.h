#pragma once

#include <Eigen/Core>
#include <vector>

#include "absl/status/statusor.h"
#include "core/algorithms/bas/terrain_objective.h"
#include "core/operators/search_loop.h"
#include "core/random.h"

namespace swarmplan {

// The column-by-column ant colony of seed 000 (the `aco` baseline and the ACO-BAS initialiser).
// Ants move from (Y, Z) at one column to the 5 x 5 candidates Y + {-2..2} rows, Z + {-2..2}
// height levels (levels one cell size apart, from the lowest ground: the paper's unit cells) at
// the next, with weight tau^alpha * S * D * M: S = 1 when the step keeps the clearance, else 0;
// D = 1 / (step length + |Y - Y_goal| / (columns left + 1)) favours short steps toward the
// goal; M = s / (s + height above ground), s the cell size, favours low flight (D and M are
// ours; the paper only names them). When no candidate is valid
// the ant takes the best one by D * M. After a generation, tau <- local_keep * tau on every cell
// an ant visited, then tau <- global_keep * tau + (1 - global_keep) * q * s / f_best along the
// best path so far (s the cell size: f_best is in world units); tau stays >= tau_min.
struct TerrainAcoOptions {
  int ants = 20;
  double alpha = 1.0;
  double local_keep = 0.5;
  double global_keep = 0.8;
  double q = 100.0;
  double tau_min = 1e-3;
};

class TerrainAco {
 public:
  // RESOURCE_EXHAUSTED when the pheromone table would exceed 32M cells.
  static absl::StatusOr<TerrainAco> Create(TerrainObjective& objective,
                                           const TerrainAcoOptions& options);

  // One generation: every ant builds a path; returns the best ant's decision vector (its
  // evaluation in `best`, the ants' mean fitness in `mean`) and updates the pheromone.
  // `evaluations` counts fitness evaluations.
  Eigen::VectorXd Generation(Rng& rng, Evaluation& best, double& mean, int64_t& evaluations);

  // The full search for t_max generations.
  SearchOutcome Run(int t_max, Rng& rng, const StopToken& stop, Observer& observer);

 private:
  TerrainAco(TerrainObjective& objective, const TerrainAcoOptions& options, int levels);
  size_t Index(int column, int y, int level) const {
    return (static_cast<size_t>(column) * depth_ + y) * levels_ + level;
  }
  double LevelZ(int level) const { return base_ + level * step_; }
  double RowY(int row) const { return objective_->terrain().CellCentre(0, row).y(); }

  TerrainObjective* objective_;
  TerrainAcoOptions options_;
  int depth_ = 0;
  int levels_ = 0;
  double base_ = 0.0;
  double step_ = 1.0;  // between height levels: the cell size
  std::vector<double> tau_;
  Eigen::VectorXd best_x_;
  double best_f_ = 0.0;
  bool has_best_ = false;
};

}  // namespace swarmplan
