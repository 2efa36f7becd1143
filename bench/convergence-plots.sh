#!/usr/bin/env bash
# Convergence of the waypoint swarms on three shared maps, from benchmark runs: the fleet
# objective with init=seeded and the length with init=paper, each run's best over the exact
# optimum against seconds from the plan's start (seed paths included), median over the runs.
#   bench/convergence-plots.sh BUILD_DIR OUT_DIR     # about 5 minutes; SVGs in OUT_DIR
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/convergence}
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${SHARED_DIR:-$HERE/../../shared/benchmarks}
BENCH="nice -n 10 $BUILD_DIR/bench/swarmplan-bench"
source "$HERE/waypoint-swarm-settings.sh"
mkdir -p "$OUT"

source "$HERE/polygon-queries.sh"
for m in den312d Berlin_0_256 warehouse; do
  if [ "$m" = warehouse ]; then
    for q in "${POLYGON_QUERIES[@]}"; do
      read -r world start goal <<<"$q"
      [ "$world" = warehouse ] && SEL=(--map "$SHARED/polygons/$world.geojson" --start "$start"
        --goal "$goal")
    done
  else
    SEL=(--map "$SHARED/movingai/$m.map" --scen "$SHARED/movingai/$m.map.scen" --scenarios 3)
  fi
  echo "== $m" >&2
  $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" "${FLEET[@]}" --csv "$OUT/fleet-$m.csv" \
    --convergence-csv "$OUT/fleet-$m-convergence.csv" 2>>"$OUT/notes.txt"
  $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" "${PAPER[@]}" --csv "$OUT/paper-$m.csv" \
    --convergence-csv "$OUT/paper-$m-convergence.csv" 2>>"$OUT/notes.txt"
  python3 "$HERE/plot_convergence.py" "$m" "$OUT" >"$OUT/$m.svg"
done
