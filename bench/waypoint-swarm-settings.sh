# The settings bench/real-maps.sh and bench/convergence-plots.sh share (sourced): the planners
# (the five waypoint swarms, or with PLANNER_SET=grid the six grid-node planners), their paper
# initialisation, seeds and budget, and the fleet request.
if [ "${PLANNER_SET:-waypoint}" = grid ]; then
  PLANNER_NAMES=(as-bfo afsa dafsa idafsa ga aco-grid)
else
  PLANNER_NAMES=(bso aem-bso aem-bso-linear pso ba)
fi
PLANNERS=()
PAPER=()
for p in "${PLANNER_NAMES[@]}"; do
  PLANNERS+=(--planner "$p")
  PAPER+=(--param "$p.init=paper")
done
COMMON=(--seed 1 --runs 3 --time-budget 1)
FLEET=(--clearance 0.5 --preferred-clearance 1.5 --turning-radius 2 --smoothing bounded-curvature)
