#!/usr/bin/env bash
# Reproduces bench/results/movingai-grid-planners.md: the grid planners of issue 5 (as-bfo,
# idafsa, dafsa, afsa and the baselines ga, aco-grid, apf) on the Moving AI maps through
# swarmplan-bench, with the planners' default parameters, plus a few runs with one parameter
# changed that show which failures are limits of our defaults.
#
# Usage: bench/movingai-grid-planners.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  a configured build tree with swarmplan-bench built (default: build)
#   OUT_DIR    where the CSVs and per-run Markdown summaries go (default: /tmp/movingai-grid)
# At the end it writes OUT_DIR/summary.md: the tables of the report, computed from the CSVs.
#
# About 29 minutes on a 2-core machine under a load average of 11-14 (user time about 8
# minutes); the runs go one after another under nice.
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/movingai-grid}
HERE=$(cd "$(dirname "$0")" && pwd)
MAPS=${MOVINGAI_DIR:-$HERE/../../shared/benchmarks/movingai}
BENCH="nice -n 10 $BUILD_DIR/bench/swarmplan-bench"
PLANNERS=(--planner as-bfo --planner idafsa --planner dafsa --planner afsa --planner ga
  --planner aco-grid --planner apf)
mkdir -p "$OUT"

# run NAME MAP SELECTION... : every planner, defaults, on MAP; writes OUT/NAME.{csv,md}.
run() {
  local name=$1 map=$2
  shift 2
  echo "== $name" >&2
  $BENCH "${PLANNERS[@]}" --map "$MAPS/$map.map" --scen "$MAPS/$map.map.scen" "$@" \
    --csv "$OUT/$name.csv" --markdown "$OUT/$name.md"
}

# 1. Default parameters. Small maps: one scenario from every bucket (the whole difficulty
#    range); the larger maps: scenarios spread evenly over the file (every difficulty).
run arena arena --bucket-sample 1 --runs 5 --seed 1
run den312d den312d --bucket-sample 1 --runs 5 --seed 1
run den011d den011d --bucket-sample 1 --runs 3 --seed 1
run Berlin_0_256 Berlin_0_256 --scenarios 16 --runs 3 --seed 1
run Boston_0_256 Boston_0_256 --scenarios 16 --runs 3 --seed 1
run 8room_000 8room_000 --scenarios 8 --runs 3 --seed 1
run random512-10-0 random512-10-0 --scenarios 8 --runs 3 --seed 1
run maze512-32-9 maze512-32-9 --scenarios 4 --runs 1 --seed 1
run AcrosstheCape AcrosstheCape --scenarios 1 --runs 1 --seed 1

# 2. One parameter changed (a planner named with its changed parameter in the file name).
# extra NAME MAP PLANNER SELECTION_AND_PARAMS...
extra() {
  local name=$1 map=$2 planner=$3
  shift 3
  echo "== $name" >&2
  $BENCH --planner "$planner" --map "$MAPS/$map.map" --scen "$MAPS/$map.map.scen" "$@" \
    --csv "$OUT/extra-$name.csv" --markdown "$OUT/extra-$name.md"
}
# Fish: MAXGEN bounds how far a fish can swim (at most 2*sqrt(2) cells per iteration).
extra idafsa-maxgen1000-den312d den312d idafsa --bucket-sample 1 --runs 5 --seed 1 \
  --param idafsa.max_generations=1000
extra idafsa-maxgen1000-den011d den011d idafsa --bucket-sample 1 --runs 3 --seed 1 \
  --param idafsa.max_generations=1000
extra idafsa-maxgen10000-den312d den312d idafsa --scenarios 10 --runs 1 --seed 1 \
  --param idafsa.max_generations=10000
extra idafsa-maxgen100-den312d den312d idafsa --scenarios 10 --runs 1 --seed 1  # same problems
# ACO: a weaker pull toward the goal (beta) and more ants.
extra aco-grid-beta2-den312d den312d aco-grid --bucket-sample 1 --runs 5 --seed 1 \
  --param aco-grid.beta=2
extra aco-grid-ants50-den011d den011d aco-grid --scenarios 8 --runs 1 --seed 1
extra aco-grid-ants500-den011d den011d aco-grid --scenarios 8 --runs 1 --seed 1 \
  --param aco-grid.ants=500
# APF: a narrower, weaker repulsion does not remove the local minima of the attraction.
extra apf-influence1-den312d den312d apf --bucket-sample 1 --runs 1 --seed 1 \
  --param apf.influence=1 --param apf.k_rep=1
# Reference: exact A* on the same maze problems (its time is the floor for the A*-based planners).
extra astar-maze512 maze512-32-9 astar --scenarios 4 --runs 1 --seed 1
# AS-BFO: fewer bacteria, fewer whole-map A* searches for initial and dispersed paths.
extra as-bfo-pop10-maze512 maze512-32-9 as-bfo --scenarios 4 --runs 1 --seed 1 \
  --param as-bfo.population=10

# 3. The report's tables from the CSVs (written to OUT/summary.md).
python3 - "$OUT" >"$OUT/summary.md" <<'PY'
import csv, glob, os, statistics, sys

out = sys.argv[1]
ORDER = ["as-bfo", "idafsa", "dafsa", "afsa", "ga", "aco-grid", "apf"]
MAPS = ["arena", "den312d", "den011d", "Berlin_0_256", "Boston_0_256", "8room_000",
        "random512-10-0", "maze512-32-9", "AcrosstheCape"]
BANDS = [(0, 32), (32, 64), (64, 128), (128, 256), (256, 512), (512, 1e9)]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def med(xs):
    return statistics.median(xs) if xs else None


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}f}"


def table(groups, key_names):
    print("| " + " | ".join(key_names) + " | runs | success | no path | path not collision-free "
          "| median ratio | worst ratio | median time (s) |")
    print("|" + "---|" * len(key_names) + "---:|---:|---:|---:|---:|---:|---:|")
    for key, rs in groups:
        ok = [r for r in rs if r["success"] == "true"]
        hit = [r for r in rs if r["success"] != "true" and r["length"]]
        ratios = [float(r["ratio"]) for r in ok if r["ratio"]]
        times = [float(r["wall_seconds"]) for r in rs]
        print("| " + " | ".join(key) + f" | {len(rs)} | {100 * len(ok) / len(rs):.0f}% "
              f"| {len(rs) - len(ok) - len(hit)} | {len(hit)} | {fmt(med(ratios))} "
              f"| {fmt(max(ratios) if ratios else None)} | {fmt(med(times), 4)} |")


def by_planner_map(rs):
    groups = []
    for m in MAPS:
        for p in ORDER:
            g = [r for r in rs if r["map"] == m + ".map" and r["planner"] == p]
            if g:
                groups.append(((p, m), g))
    return groups


main = []
for m in MAPS:
    if os.path.exists(f"{out}/{m}.csv"):
        main += rows(f"{out}/{m}.csv")
print("## Default parameters, planner x map\n")
table(by_planner_map(main), ["planner", "map"])

print("\n## Default parameters, success by the .scen file's octile length (cells), all maps\n")
print("| planner | " + " | ".join(f"{a}–{b if b < 1e9 else '∞'}" for a, b in BANDS) + " |")
print("|---|" + "---:|" * len(BANDS))
for p in ORDER:
    cells = []
    for a, b in BANDS:
        g = [r for r in main if r["planner"] == p and a <= float(r["scen_optimal"]) < b]
        ok = sum(r["success"] == "true" for r in g)
        cells.append(f"{100 * ok / len(g):.0f}% ({len(g)})" if g else "–")
    print(f"| {p} | " + " | ".join(cells) + " |")

print("\n## One parameter changed\n")
extra = []
for path in sorted(glob.glob(f"{out}/extra-*.csv")):
    name = os.path.basename(path)[len("extra-"):-len(".csv")]
    extra.append(((name,), rows(path)))
table(extra, ["run"])

# Moves of 16 directions (dafsa, idafsa, afsa with 24 cells) can beat the 8-connected optimum
# of the .scen file; 8-connected planners cannot, so a ratio < 0.999 there would be a bug.
print("\nSuccessful runs shorter than the 8-connected optimum (ratio < 0.999), per planner:")
for p in ORDER:
    n = sum(r["planner"] == p and r["success"] == "true" and r["ratio"] != ""
            and float(r["ratio"]) < 0.999 for r in main + [r for _, g in extra for r in g])
    print(f"- {p}: {n}")
PY
echo "wrote $OUT/summary.md" >&2
