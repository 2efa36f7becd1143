#!/usr/bin/env bash
# The polygon-world part of bench/results/exact-yardsticks.md: the visibility-graph optimum of a
# long query on every shared polygon world, with clearance 0 and 0.5, through swarmplan-bench,
# 5 runs each (the exact planner is deterministic: the runs time it).
#
# Usage: bench/exact-yardsticks-polygons.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/exact-yardsticks-polygons}
HERE=$(cd "$(dirname "$0")" && pwd)
WORLDS=${POLYGONS_DIR:-$HERE/../../shared/benchmarks/polygons}
BENCH="$BUILD_DIR/bench/swarmplan-bench"
mkdir -p "$OUT"

source "$HERE/polygon-queries.sh"
for q in "${POLYGON_QUERIES[@]}"; do
  read -r world start goal <<<"$q"
  for clearance in 0 0.5; do
    "$BENCH" --planner visibility-graph --map "$WORLDS/$world.geojson" --start "$start" \
      --goal "$goal" --clearance "$clearance" --runs 5 --optimum-budget 0 \
      --csv "$OUT/$world-$clearance.csv" 2>/dev/null
  done
done

python3 - "$OUT" <<'PY'
import csv, statistics, sys
out = sys.argv[1]
worlds = ["parking1", "parking3", "warehouse", "warehouse2"]
print("| world | query (start -> goal) | optimum, clearance 0 | ms per query | optimum, clearance 0.5 | ms per query |")
print("|---|---|---:|---:|---:|---:|")
for w in worlds:
    cells = []
    query = ""
    for c in ["0", "0.5"]:
        rows = list(csv.DictReader(open(f"{out}/{w}-{c}.csv")))
        query = rows[0]["scenario"]
        ok = [r for r in rows if r["success"] == "true"]
        length = f"{float(ok[0]['length']):.4f}" if ok else "no path"
        ms = statistics.median(float(r["wall_seconds"]) for r in rows) * 1000
        cells += [length, f"{ms:.2f}"]
    print(f"| {w} | {query} | " + " | ".join(cells) + " |")
PY
