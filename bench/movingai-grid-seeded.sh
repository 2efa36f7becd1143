#!/usr/bin/env bash
# Reproduces bench/results/grid-seeded.md: the grid-node planners (as-bfo, afsa, dafsa, idafsa,
# ga, aco-grid) with init=seeded on every shared Moving AI map through swarmplan-bench: three
# scenarios spread over each .scen file, seeds 1-3, a time budget of 1 s per plan.
#
# Usage: bench/movingai-grid-seeded.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  a configured build tree with swarmplan-bench built (default: build)
#   OUT_DIR    where the CSVs go (default: /tmp/movingai-grid-seeded)
# At the end it writes OUT_DIR/summary.md, the report's table, computed from the CSVs.
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/movingai-grid-seeded}
HERE=$(cd "$(dirname "$0")" && pwd)
MAPS=${MOVINGAI_DIR:-$HERE/../../shared/benchmarks/movingai}
BENCH="nice -n 5 $BUILD_DIR/bench/swarmplan-bench"
PLANNERS=(as-bfo afsa dafsa idafsa ga aco-grid)
ARGS=()
for p in "${PLANNERS[@]}"; do ARGS+=(--planner "$p" --param "$p.init=seeded"); done
mkdir -p "$OUT"

for map in arena den312d den011d Berlin_0_256 Boston_0_256 8room_000 random512-10-0 \
  maze512-32-9 AcrosstheCape; do
  echo "== $map" >&2
  $BENCH "${ARGS[@]}" --map "$MAPS/$map.map" --scen "$MAPS/$map.map.scen" --scenarios 3 \
    --runs 3 --seed 1 --time-budget 1 --csv "$OUT/$map.csv"
done

python3 - "$OUT" >"$OUT/summary.md" <<'PY'
import csv, glob, os, statistics, sys

out = sys.argv[1]
ORDER = ["as-bfo", "afsa", "dafsa", "idafsa", "ga", "aco-grid"]
MAPS = ["arena", "den312d", "den011d", "Berlin_0_256", "Boston_0_256", "8room_000",
        "random512-10-0", "maze512-32-9", "AcrosstheCape"]
rows = []
for m in MAPS:
    if os.path.exists(f"{out}/{m}.csv"):
        with open(f"{out}/{m}.csv") as f:
            rows += list(csv.DictReader(f))


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}f}"


def line(label, rs):
    ok = [r for r in rs if r["success"] == "true"]
    ratios = [float(r["ratio"]) for r in ok if r["ratio"]]
    times = [float(r["wall_seconds"]) for r in rs]
    best0 = sum(1 for r in ok if r.get("best_iteration") == "0")
    print(f"| {label} | {len(rs)} | {100 * len(ok) / len(rs):.0f}% "
          f"| {fmt(statistics.median(ratios) if ratios else None)} "
          f"| {fmt(max(ratios) if ratios else None)} | {best0} "
          f"| {fmt(statistics.median(times), 3)} |")


print("| planner | map | runs | success | median ratio | worst ratio | best at iteration 0 "
      "| median time (s) |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for p in ORDER:
    for m in MAPS:
        g = [r for r in rows if r["planner"] == p and r["map"] == m + ".map"]
        if g:
            line(f"{p} | {m}", g)
print("\n| planner | runs | success | median ratio | worst ratio | best at iteration 0 "
      "| median time (s) |")
print("|---|---:|---:|---:|---:|---:|---:|")
for p in ORDER:
    g = [r for r in rows if r["planner"] == p]
    if g:
        line(p, g)
PY
echo "wrote $OUT/summary.md" >&2
