#include "bench/papers/bas_canyon_setup.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "bench/papers/bas_canyon_paper.h"
#include "bench/papers/bas_canyon_sweeps.h"
#include "bench/papers/bas_canyon_terrain.h"
#include "bench/papers/markdown_table.h"

namespace swarmplan::bench::bas {
namespace {

std::string PointText(const Point3& p) {
  return absl::StrFormat("(%g, %g, %g)", p.x(), p.y(), p.z());
}

}  // namespace

std::string SetupSection(const CanyonWorld& world, const SetupFigures& f) {
  const CanyonShape shape;
  return absl::StrCat(
      "## Setup\n\n",
      "- **Map.** The paper's canyon is not published; ours is generated "
      "(`bench/worlds/bas-canyon/canyon.asc`, ESRI ASCII, `swarmplan-papers generate bas-canyon`,"
      " seed ",
      kCanyonSeed, "). ", shape.width, " columns x ", shape.depth,
      " rows (the paper's path has 21 columns, i = 1..21), unit cells with the centre of cell (0, "
      "0) at the origin, so world coordinates are the paper's grid units. Height "
      "h(x, y) = P - max((P - F_r) g(y - c_r(x)), (P - F_l) g(y - c_l(x))) + rocks(x, y) with "
      "g(d) = exp(-(d / w)^2), plateau P = ",
      shape.plateau, ", a deep winding right valley c_r(x) = ", shape.mouth_y, " + ",
      shape.right_bulge, " sin(pi u) + ", shape.right_wiggle, " sin(3 pi u), u = x / ",
      shape.width - 1, ", floor F_r = ", shape.right_floor,
      ", and a shallow left side c_l(x) = ", shape.mouth_y, " - ", shape.left_bulge,
      " sin(pi u), floor F_l = ", shape.left_floor, ", w = ", shape.half_width, "; rocks are ",
      shape.rocks, " seeded Gaussian bumps of height U[", shape.rock_min, ", ", shape.rock_max,
      "] and radius U[1, 2.5] (bench/papers/bas_canyon_terrain.h). Ceiling: the loader's "
      "default, highest ground + relief.\n",
      "- **Start and goal.** ", PointText(world.start), " and ", PointText(world.goal),
      ": the canyon's mouth at the first and last column, ", kStartHeightAboveGround,
      " above the ground; the optimum follows the curved deep valley on the right (y > ",
      shape.mouth_y,
      "), as in the paper (\"the optimal path ... is along the curved area on the right side of "
      "the canyon\"). Fig. 6's moved start: first column, y = ",
      MovedStartY(), ". Clearance 0 (a path must stay above the bilinear ground).\n",
      "- **Fitness.** The planners' own, eq. 3: sum over the 20 segments of (segment length + Z "
      "of its end), in grid units (= world units here). Absolute values depend on the map, so "
      "only rankings and ratios can be compared with the paper.\n",
      "- **Paper's settings, passed explicitly**: `init=paper` (the paper's initial space C_ini "
      "or ACO path), `step_units=cells` (δ0 in cells) and `reject_infeasible=false` (every move "
      "taken; the planners' defaults are the seeded service settings), ",
      f.iterations, " iterations, δ0 = ", kPaperStep0, ", λ1 = ", kPaperDecay,
      ", c = 2, θ0 = ", kPaperTheta0, ", λ2 = ", kPaperDecay,
      ", ACO population 20 (also the one ACO generation that seeds ACO-BAS). Table B: "
      "population ",
      kPaperPopulation, ", ", f.population_iterations,
      " iterations. The paper's μ = 0.998 is not defined anywhere in it and is not used.\n",
      "- **Two options of ours (Table D)**: `reject_infeasible=true` (an infeasible move "
      "is undone) and `step_units=map` with `step_fraction=",
      f.map_step_fraction,
      "` (the initial step is that fraction of each coordinate's range: the map's extent in Y, "
      "its height range in Z).\n",
      "- **Our choices where the paper is silent** (planner defaults, see "
      "`swarmplan algorithms`): penalty 100 per unit of depth below ground, C_ini widening "
      "c' = 0.5 cells, LFS m = 10, λ = 0.95, a = b = γ = 1; SIO-BAS η = (0.6, 0.2, 0.2); ACO's "
      "D and M heuristic terms.\n",
      "- **Runs and seeds.** ", f.runs, " runs per row of Tables A-D, ", f.sweep_runs,
      " per row of Table 3 and Fig. 6 (the paper: ", kPaperRuns, "), ", f.replicated_runs,
      " per row and world of the replication over ", f.replicated_worlds,
      " canyons; run i = 0, 1, ... with seed ", f.first_seed,
      " + i. Fitness statistics over the runs that found a collision-free path (`found`), "
      "medians with bootstrap 95 % intervals. `improved on first path`: found runs whose best "
      "path came after iteration 0. `deep branch`: runs whose middle waypoint lies in the right "
      "valley.\n",
      "- **Paper's numbers.** Its Tables 2-4 are images missing from our copy; `paper best` in "
      "Table A is the single run of its Fig. 4 caption, Fig. 6's from its caption; Table B's are "
      "from Figs. 7-8 and the text (std: Fig. 8's normal fit; the text's \"22.03\" is "
      "inconsistent with it); ACO at 200 iterations: the text's mean 115.82.\n\n");
}

std::string YardstickParagraph(const CanyonWorld& world) {
  const Point3& middle = world.lattice.path[world.lattice.path.size() / 2];
  return absl::StrCat(
      "Yardstick: the `terrain-lattice` optimum (core/algorithms/exact/terrain_lattice.h), the "
      "least-cost path of the same objective (each segment: its length + the Z of its end per "
      "cell of x-advance, which is eq. 3 on one-waypoint-per-column paths) over the voxel "
      "lattice of cell centres x heights Z = lowest ground + 0, ",
      world.lattice.levels.step, ", ... (", world.lattice.levels.count,
      " levels, 26-neighbourhood, A*), has fitness **", NumberCell(world.lattice.cost),
      "**. It bounds the optimum over all paths from above, not the optimum of the paper's "
      "one-waypoint-per-column model: a lattice path may climb inside a column and pay the "
      "lower height for the column, so the model's optimum can lie above it. Its path is "
      "collision-free; its middle point ",
      PointText(middle),
      InRightBranch(world.lattice.path) ? " is in the deep right valley"
                                        : " is not in the right valley",
      ".\n\n");
}

}  // namespace swarmplan::bench::bas
