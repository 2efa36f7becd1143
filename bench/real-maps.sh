#!/usr/bin/env bash
# The waypoint swarms on real maps, bench/results/real-maps.md: bso, aem-bso, aem-bso-linear,
# pso and ba with init=seeded (the default) and init=paper side by side, through swarmplan-bench,
# on every shared Moving AI map (3 scenarios spread over the .scen file: short, middle, long) and
# every shared polygon world (one long query), seeds 1-3, a time budget of 1 s per plan:
#   length: no preferences (the fleet objective is the length; clearance 0 on grids);
#   fleet:  clearance 0.5, preferred clearance 1.5, turning radius 2 (world units = cells on
#           the Moving AI maps), init=seeded only, bounded-curvature smoothing; compared with
#           the best seed after the same smoothing;
#   alternatives: the length settings with PlanRequest.alternatives = 3 (--alternatives 2):
#           how many of the three paths lie in distinct corridors.
# Writes OUT_DIR/{length,paper,fleet,alternatives}-MAP.csv; prints the report's tables (stdout).
#
# With PLANNER_SET=grid the same runs and tables for the six grid-node planners.
#
# Usage: [MODES="length paper fleet alternatives"] bench/real-maps.sh [BUILD_DIR] [OUT_DIR]
# One run after another on one core, about 35 minutes (two MODES side by side: about 18);
# MODES=none prints the tables of the CSVs already in OUT_DIR.
set -euo pipefail

BUILD_DIR=${1:-build}
OUT=${2:-/tmp/real-maps}
HERE=$(cd "$(dirname "$0")" && pwd)
SHARED=${SHARED_DIR:-$HERE/../../shared/benchmarks}
BENCH="nice -n 10 $BUILD_DIR/bench/swarmplan-bench"
source "$HERE/waypoint-swarm-settings.sh"
MODES=${MODES:-length paper fleet alternatives}
mkdir -p "$OUT"
# mode NAME: whether NAME is among the MODES to run.
mode() { [[ " $MODES " == *" $1 "* ]]; }

# run_modes: the selected modes on SEL, files named after $m.
run_modes() {
  if mode length; then
    $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" --csv "$OUT/length-$m.csv" 2>>"$OUT/notes.txt"
  fi
  if mode paper; then
    $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" "${PAPER[@]}" --csv "$OUT/paper-$m.csv" \
      2>>"$OUT/notes.txt"
  fi
  if mode fleet; then
    $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" "${FLEET[@]}" --csv "$OUT/fleet-$m.csv" \
      2>>"$OUT/notes.txt"
  fi
  if mode alternatives; then
    $BENCH "${PLANNERS[@]}" "${SEL[@]}" "${COMMON[@]}" --alternatives 2 \
      --csv "$OUT/alternatives-$m.csv" 2>>"$OUT/notes.txt"
  fi
}

MAPS=(arena den312d den011d Berlin_0_256 Boston_0_256 8room_000 random512-10-0 maze512-32-9
  AcrosstheCape)
for m in "${MAPS[@]}"; do
  echo "== $m" >&2
  SEL=(--map "$SHARED/movingai/$m.map" --scen "$SHARED/movingai/$m.map.scen" --scenarios 3)
  run_modes
done

source "$HERE/polygon-queries.sh"
for q in "${POLYGON_QUERIES[@]}"; do
  read -r world start goal <<<"$q"
  echo "== $world" >&2
  SEL=(--map "$SHARED/polygons/$world.geojson" --start "$start" --goal "$goal")
  m=$world run_modes
done

PLANNER_NAMES="${PLANNER_NAMES[*]}" python3 - "$OUT" "${MAPS[@]}" parking1 parking3 warehouse warehouse2 <<'PY'
import csv, os, statistics, sys
out, maps = sys.argv[1], sys.argv[2:]
planners = os.environ["PLANNER_NAMES"].split()

def rows(kind, m):
    path = os.path.join(out, f"{kind}-{m}.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []

def num(r, k):
    return float(r[k]) if r.get(k) not in (None, "") else None

def cell(rs):
    if not rs:
        return "–", "–", "–", "–"
    ok = [r for r in rs if r["success"] == "true"]
    ratios = sorted(num(r, "ratio") for r in ok if num(r, "ratio") is not None)
    times = [float(r["wall_seconds"]) for r in rs]
    succ = f"{len(ok)}/{len(rs)}"
    med = f"{statistics.median(ratios):.3f}" if ratios else "–"
    worst = f"{max(ratios):.3f}" if ratios else "–"
    return succ, med, worst, f"{statistics.median(times):.2f}"

print("## Length: init=seeded against init=paper\n")
print("Success, median and worst length / exact optimum, median seconds per plan.\n")
print("| map | planner | seeded success | seeded median | seeded worst | seeded s | paper success | paper median | paper worst | paper s |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for m in maps:
    L, P = rows("length", m), rows("paper", m)
    for p in planners:
        s = cell([r for r in L if r["planner"] == p])
        q = cell([r for r in P if r["planner"] == p])
        print(f"| {m} | {p} | " + " | ".join(s) + " | " + " | ".join(q) + " |")

def seconds(rs, key):
    reached = sorted(num(r, key) for r in rs if num(r, key) is not None)
    if not reached:
        return f"0/{len(rs)}", "–"
    return f"{len(reached)}/{len(rs)}", f"{statistics.median(reached):.3f}"

print("\n## Length: time to quality\n")
print("Runs whose best came within 1.05 and 1.02 of the exact optimum, and the median seconds from")
print("the plan's start (seed paths included) to get there, over the runs that did.\n")
print("| map | planner | seeded 1.05 | seeded s | seeded 1.02 | seeded s | paper 1.05 | paper s | paper 1.02 | paper s |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
for m in maps:
    L, P = rows("length", m), rows("paper", m)
    for p in planners:
        ls = [r for r in L if r["planner"] == p]
        ps = [r for r in P if r["planner"] == p]
        cells = [*seconds(ls, "seconds_to_1.05"), *seconds(ls, "seconds_to_1.02"),
                 *seconds(ps, "seconds_to_1.05"), *seconds(ps, "seconds_to_1.02")]
        print(f"| {m} | {p} | " + " | ".join(cells) + " |")

print("\n## Fleet: clearance 0.5, preferred clearance 1.5, turning radius 2, bounded-curvature smoothing (init=seeded)\n")
print("Success; median and worst length / exact optimum (with the clearance); runs whose best")
print("seed leaves something to gain (`seed_penalty` > 0: its smoothed objective is more than its")
print("length), and among them the runs whose final objective (after the smoothing) is below the")
print("best seed's after the same smoothing, with the median improvement; successful runs whose")
print("largest discrete curvature is at most 1 / R; median seconds per plan.\n")
print("| map | planner | success | median ratio | worst ratio | improvable | below the seed | median improvement | curvature <= 1/R | s |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
totals = dict(runs=0, ok=0, improvable=0, better=0, bounded=0, within=0, gains=[], ratios=[])

def improvable(r):
    f0, pen = num(r, "seed_objective"), num(r, "seed_penalty")
    return f0 is not None and pen is not None and pen > 1e-6 * f0

def groups(kind):
    """(map, planner, rows, successful rows) of every planner with rows in the kind's CSVs."""
    for m in maps:
        every = rows(kind, m)
        for p in planners:
            rs = [r for r in every if r["planner"] == p]
            if rs:
                yield m, p, rs, [r for r in rs if r["success"] == "true"]

for m, p, rs, ok in groups("fleet"):
    succ, med, worst, sec = cell(rs)
    room = [r for r in ok if improvable(r)]
    gains = [1 - num(r, "objective") / num(r, "seed_objective") for r in room]
    better = sum(1 for r in room if num(r, "objective") < num(r, "seed_objective") * (1 - 1e-9))
    gain = f"{100 * statistics.median(gains):.1f} %" if gains else "–"
    bounded = sum(1 for r in ok if num(r, "max_curvature") is not None
                  and num(r, "max_curvature") <= 0.5 * (1 + 1e-6))
    totals["runs"] += len(rs)
    totals["ok"] += len(ok)
    totals["improvable"] += len(room)
    totals["better"] += better
    totals["bounded"] += bounded
    totals["gains"] += gains
    ratios = [num(r, "ratio") for r in ok if num(r, "ratio") is not None]
    totals["ratios"] += ratios
    totals["within"] += sum(1 for x in ratios if x <= 1.10)
    print(f"| {m} | {p} | {succ} | {med} | {worst} | {len(room)}/{len(ok)} | {better}/{len(room)} | "
          f"{gain} | {bounded}/{len(ok)} | {sec} |")

t = totals
if t["runs"]:
    pct = lambda a, b: f"{100 * a / b:.1f} %" if b else "–"
    print(f"\nFleet totals: {t['ok']} of {t['runs']} runs found a path (the others have no path that keeps")
    print(f"the clearance); {t['improvable']} of those {t['ok']} have a best seed with something to gain;")
    print(f"the final objective is below the smoothed seed's in {t['better']} of them ({pct(t['better'], t['improvable'])}),")
    if t["gains"]:
        print(f"by a median {100 * statistics.median(t['gains']):.2f} %; ", end="")
    print(f"curvature within 1 / R in {t['bounded']} of {t['ok']} ({pct(t['bounded'], t['ok'])}); length within")
    worst = f"{max(t['ratios']):.3f}" if t["ratios"] else "–"
    print(f"1.10 of the optimum in {t['within']} of {len(t['ratios'])}, the worst {worst}.")

print("\n## Alternatives: PlanRequest.alternatives = 3, the length settings (init=seeded)\n")
print("Successful runs; among them the runs that returned 2 collision-free alternatives, and the")
print("runs whose 3 paths (the result and the alternatives) lie pairwise in distinct corridors by")
print("the independent test (`distinct_corridors`), at least 2 of them; median length / exact")
print("optimum of the result.\n")
print("| map | planner | success | 2 alternatives | 3 corridors | >= 2 corridors | median ratio |")
print("|---|---|---:|---:|---:|---:|---:|")
alt = dict(ok=0, two=0, three=0, several=0)
for m, p, rs, ok in groups("alternatives"):
    succ, med, _, _ = cell(rs)
    two = sum(1 for r in ok if num(r, "alternatives") == 2)
    three = sum(1 for r in ok if num(r, "distinct_corridors") == 3)
    several = sum(1 for r in ok if (num(r, "distinct_corridors") or 0) >= 2)
    for k, v in (("ok", len(ok)), ("two", two), ("three", three), ("several", several)):
        alt[k] += v
    print(f"| {m} | {p} | {succ} | {two}/{len(ok)} | {three}/{len(ok)} | {several}/{len(ok)} | {med} |")
if alt["ok"]:
    print(f"\nAlternatives totals: of {alt['ok']} successful runs, {alt['two']} returned two alternatives,")
    print(f"{alt['three']} three paths in pairwise distinct corridors, {alt['several']} at least two.")
PY
