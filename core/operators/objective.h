#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/map/point.h"

namespace swarmplan {

class Rng;

// How far an optimiser's positions may go.
enum class PositionBound {
  kBox,  // every new position is clamped to the objective's box
  // Positions may leave the box, up to kFarBoxSpans times its span on each side (which keeps
  // coordinates finite); the box then bounds the initial population and the velocities only.
  kFar,
};
inline constexpr double kFarBoxSpans = 10.0;

struct Evaluation {
  double fitness = 0.0;
  bool feasible = false;  // the decoded path keeps the safety distance (always true off maps)
};

// A box-bounded minimisation problem over R^dim, the common ground of every swarm optimiser:
// waypoint paths on 2D maps, column paths on terrain, and the test functions. Evaluate reuses
// the objective's own buffers, so it is not const and one objective serves one search.
class Objective {
 public:
  virtual ~Objective() = default;
  virtual int dim() const = 0;
  virtual const Eigen::VectorXd& lower() const = 0;
  virtual const Eigen::VectorXd& upper() const = 0;
  virtual Evaluation Evaluate(const Eigen::VectorXd& x) = 0;
  // out[j] = Evaluate(xs.col(j)) for the columns of xs (dim rows): a whole population in one
  // call. The default evaluates column by column.
  virtual void EvaluateColumns(const Eigen::MatrixXd& xs, Evaluation* out);

  // A path objective's decision vector drawn inside a band of half-width `band` (map units)
  // around the straight start-goal path (the initial space C_ini of BAS eq 12). The default,
  // for objectives without a path, draws uniformly in the box.
  virtual void SampleAroundStraightPath(double band, Rng& rng, Eigen::VectorXd& x) const;
  // A hook applied after each BAS move (the terrain path rationality check, eq 13); `theta` is
  // the current rationality step. The default does nothing.
  virtual void Repair(double /*theta*/, Eigen::VectorXd& /*x*/) const {}
  // Decision vectors an optimiser puts in its initial population in place of as many drawn
  // members (PlaceInitialGuesses): a seeded objective's seeds. None by default, which leaves
  // the paper's initialisation alone.
  virtual std::vector<Eigen::VectorXd> InitialGuesses() const { return {}; }
  // A decision vector for a member of the initial population after the guesses, drawn near
  // them by a seeded objective; false (the default) keeps the optimiser's own draw.
  virtual bool SampleNearGuesses(Rng& /*rng*/, Eigen::VectorXd& /*x*/) const { return false; }

  void Clamp(Eigen::VectorXd& x) const { x = x.cwiseMax(lower()).cwiseMin(upper()); }
  // Clamp for PositionBound::kBox; for kFar, the clamp to the box grown by kFarBoxSpans spans.
  void Bound(PositionBound bound, Eigen::VectorXd& x) const;
};

// An objective whose decision vectors are paths on a map.
class PathObjective : public Objective {
 public:
  struct KnownPath {
    Path path;
    double fitness = 0.0;
  };
  // The path a decision vector stands for, start first and goal last, as evaluated.
  virtual Path Decode(const Eigen::VectorXd& x) = 0;
  // A collision-free path known before the search and its fitness by this objective (a seeded
  // objective's best seed): the planner returns it when the search ends on nothing better.
  virtual std::optional<KnownPath> BestKnownPath() { return std::nullopt; }
  // The corridors of a seeded objective: how many, the one a decision vector lies in, and the
  // corridor of BestKnownPath. One corridor (0) by default.
  virtual int Corridors() const { return 1; }
  virtual int CorridorOf(const Eigen::VectorXd& /*x*/) const { return 0; }
  virtual int BestKnownCorridor() const { return 0; }
  // The known path of a corridor (a seed) and its fitness; none by default.
  virtual std::optional<KnownPath> KnownPathIn(int /*corridor*/) { return std::nullopt; }
};

// Overwrites the first members of `population` with the objective's initial guesses (as many
// as fit), clamped to the box, and the rest with its draws near them where it makes some.
void PlaceInitialGuesses(const Objective& objective, Rng& rng,
                         std::vector<Eigen::VectorXd>& population);

}  // namespace swarmplan
