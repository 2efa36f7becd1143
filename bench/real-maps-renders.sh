#!/usr/bin/env bash
# The rendered fleet plans of bench/results/real-maps.md: aem-bso (seed 1, 5 s budget,
# clearance 0.5, preferred clearance 1.5, turning radius 2, bounded-curvature smoothing, three
# alternatives) beside the exact path with the same clearance, on Berlin_0_256 (its longest
# scenario), den312d (its longest) and the warehouse polygon world (its query in
# polygon-queries.sh), through a local swarmplan-server and the CLI.
#   bench/real-maps-renders.sh BUILD_DIR OUT_DIR     # about a minute; SVGs and summary.txt
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/real-maps-renders}
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${SHARED_DIR:-$HERE/../../shared/benchmarks}
swarmplan=$BUILD_DIR/client/swarmplan
mkdir -p "$OUT"
work=$(mktemp -d)
"$BUILD_DIR/server/swarmplan-server" --listen 127.0.0.1:0 --data-dir "$work/data" \
  --metrics-port 0 >"$work/server.log" 2>&1 &
server_pid=$!
trap 'kill "$server_pid" 2>/dev/null; wait "$server_pid" 2>/dev/null; rm -rf "$work"' EXIT
port=""
for _ in $(seq 1 300); do
  port=$(sed -n 's/.*listening on port \([0-9][0-9]*\).*/\1/p' "$work/server.log" | head -n 1)
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { cat "$work/server.log" >&2; exit 1; }
export SWARMPLAN_SERVER=127.0.0.1:$port

# The last (longest) scenario of a Moving AI .scen file as "x,y x,y" cell centres.
last_scenario() {
  tail -n 1 "$1" | awk '{ printf "%.1f,%.1f %.1f,%.1f\n", $5 + 0.5, $6 + 0.5, $7 + 0.5, $8 + 0.5 }'
}
source "$HERE/polygon-queries.sh"
warehouse_query=""
for q in "${POLYGON_QUERIES[@]}"; do
  read -r world start goal <<<"$q"
  [ "$world" = warehouse ] && warehouse_query="$start $goal"
done

: >"$OUT/summary.txt"
render() {  # NAME FILE START GOAL EXACT_PLANNER
  local name=$1 file=$2 start=$3 goal=$4 exact=$5
  local map ids
  map=$("$swarmplan" --json maps upload "$file" --name "$name" | /usr/bin/python3 -c \
    'import json, sys; print(json.load(sys.stdin)["map"]["id"])')
  "$swarmplan" --json plan "$map" --start "$start" --goal "$goal" --algorithm aem-bso \
    --seed 1 --time-budget 5s --clearance 0.5 --preferred-clearance 1.5 --turning-radius 2 \
    --smoothing bounded-curvature --alternatives 3 >"$work/fleet.json"
  "$swarmplan" --json plan "$map" --start "$start" --goal "$goal" --algorithm "$exact" \
    --clearance 0.5 >"$work/optimum.json"
  ids=$(/usr/bin/python3 -c '
import json, sys
for name in sys.argv[1:]:
    job = json.load(open(name))
    print("--job", job.get("job", job)["id"], end=" ")' "$work/fleet.json" "$work/optimum.json")
  # shellcheck disable=SC2086
  "$swarmplan" render $ids --output "$OUT/$name.svg" \
    --title "$name: aem-bso (fleet objective, bounded curvature) and the exact path"
  /usr/bin/python3 -c '
import json, sys
job = json.load(open(sys.argv[2]))
r = job.get("job", job)["result"]
o, s = r["objective"], r["seed_objective"]
m = r["smoothed_metrics"]
alts = ", ".join("%.3fx" % a.get("optimality_ratio", 0) for a in r.get("alternatives", []))
print("%s: %.3fx the exact optimum, clearance %.2f, largest curvature %.3f, objective %.2f "
      "against the smoothed seed %.2f, best at iteration %d of %d, alternatives: %s"
      % (sys.argv[1], r.get("optimality_ratio", 0), m["min_clearance"], m["max_curvature"],
         o["total"], s["total"], r.get("best_iteration", 0), r["iterations"], alts or "none"))
' "$name" "$work/fleet.json" >>"$OUT/summary.txt"
}

read -r s g <<<"$(last_scenario "$SHARED/movingai/Berlin_0_256.map.scen")"
render Berlin_0_256 "$SHARED/movingai/Berlin_0_256.map" "$s" "$g" exact-any-angle
read -r s g <<<"$(last_scenario "$SHARED/movingai/den312d.map.scen")"
render den312d "$SHARED/movingai/den312d.map" "$s" "$g" exact-any-angle
read -r s g <<<"$warehouse_query"
render warehouse "$SHARED/polygons/warehouse.geojson" "$s" "$g" visibility-graph
cat "$OUT/summary.txt"
