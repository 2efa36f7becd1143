# The settings bench/real-maps.sh and bench/convergence-plots.sh share (sourced): the five
# waypoint swarms, their paper initialisation, seeds and budget, and the fleet request.
PLANNERS=(--planner bso --planner aem-bso --planner aem-bso-linear --planner pso --planner ba)
PAPER=()
for p in bso aem-bso aem-bso-linear pso ba; do PAPER+=(--param "$p.init=paper"); done
COMMON=(--seed 1 --runs 3 --time-budget 1)
FLEET=(--clearance 0.5 --preferred-clearance 1.5 --turning-radius 2 --smoothing bounded-curvature)
