"""Draws one map's convergence (bench/convergence-plots.sh) as SVG on standard output.

Each line is the median over a planner's runs of best fitness / exact optimum against seconds
from the plan's start; a run counts from its first collision-free best. Solid: init=seeded
under the fleet objective; dashed: init=paper (its fitness is the length once feasible).
"""
import csv
import os
import statistics
import sys

COLOURS = {"bso": "#1b9e77", "aem-bso": "#d95f02", "aem-bso-linear": "#7570b3",
           "pso": "#e7298a", "ba": "#66a61e"}
WIDTH, HEIGHT, LEFT, RIGHT, TOP, BOTTOM = 640, 400, 60, 150, 50, 45
T_HIGH = 1.0
Y_LOW, Y_HIGH = 0.99, 1.5  # set from the lines by main()
TIMES = [T_HIGH * i / 100 for i in range(101)]


def runs(out, mode, name):
    optimal = {}
    with open(os.path.join(out, f"{mode}-{name}.csv")) as f:
        for r in csv.DictReader(f):
            if r["optimal"]:
                optimal[(r["scenario"], r["planner"], r["seed"])] = float(r["optimal"])
    series = {}
    with open(os.path.join(out, f"{mode}-{name}-convergence.csv")) as f:
        for r in csv.DictReader(f):
            key = (r["scenario"], r["planner"], r["seed"])
            if key not in optimal:
                continue
            value = float(r["best_fitness"]) / optimal[key] if r["feasible"] == "true" else None
            series.setdefault(key, []).append((float(r["seconds"]), value))
    return series


def median_line(series, planner):
    own = [s for (scenario, p, seed), s in series.items() if p == planner]
    points = []
    for t in TIMES:
        values = []
        for s in own:
            current = None
            for seconds, value in s:
                if seconds > t:
                    break
                current = value
            values.append(current)
        known = [v for v in values if v is not None]
        if own and len(known) * 2 > len(own):
            # Runs without a feasible best yet count as worse than every feasible one.
            values = sorted(known) + [float("inf")] * (len(values) - len(known))
            points.append((t, statistics.median(values)))
    return points


def x_of(t):
    return LEFT + (WIDTH - LEFT - RIGHT) * t / T_HIGH


def y_of(v):
    v = min(max(v, Y_LOW), Y_HIGH)
    return TOP + (HEIGHT - TOP - BOTTOM) * (Y_HIGH - v) / (Y_HIGH - Y_LOW)


def main():
    global Y_LOW, Y_HIGH
    name, out = sys.argv[1], sys.argv[2]
    drawn = []
    for mode, dash in (("fleet", ""), ("paper", ' stroke-dasharray="5,4"')):
        series = runs(out, mode, name)
        for planner, colour in COLOURS.items():
            points = median_line(series, planner)
            if len(points) >= 2:
                drawn.append((points, colour, dash))
    values = [v for points, _, _ in drawn for _, v in points if v != float("inf")]
    if values:
        Y_LOW = min(0.99, min(values))
        Y_HIGH = min(1.5, max(1.02, max(values) * 1.01))
    ticks = [Y_LOW + (Y_HIGH - Y_LOW) * i / 5 for i in range(6)]
    lines = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
             f'font-family="sans-serif" font-size="12">',
             f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
             f'<text x="{LEFT}" y="18">{name}: median best / exact optimum over the runs</text>',
             f'<text x="{LEFT}" y="34">solid: init=seeded, fleet objective; dashed: '
             f'init=paper, length (when most runs are feasible)</text>']
    for v in ticks:
        y = y_of(v)
        lines.append(f'<line x1="{LEFT}" x2="{WIDTH - RIGHT}" y1="{y:.1f}" y2="{y:.1f}" '
                     f'stroke="#ddd"/><text x="{LEFT - 8}" y="{y + 4:.1f}" '
                     f'text-anchor="end">{v:.3f}</text>')
    for t in (0.0, 0.25, 0.5, 0.75, 1.0):
        x = x_of(t)
        lines.append(f'<text x="{x:.1f}" y="{HEIGHT - BOTTOM + 16}" text-anchor="middle">'
                     f'{t:g}</text>')
    lines.append(f'<text x="{(LEFT + WIDTH - RIGHT) / 2}" y="{HEIGHT - 8}" '
                 f'text-anchor="middle">seconds from the plan\'s start</text>')
    for points, colour, dash in drawn:
        path = " ".join(f"{x_of(t):.1f},{y_of(v):.1f}" for t, v in points)
        lines.append(f'<polyline points="{path}" fill="none" stroke="{colour}" '
                     f'stroke-width="1.5"{dash}/>')
    for i, (planner, colour) in enumerate(COLOURS.items()):
        y = TOP + 16 * i + 10
        lines.append(f'<line x1="{WIDTH - RIGHT + 10}" x2="{WIDTH - RIGHT + 30}" y1="{y}" '
                     f'y2="{y}" stroke="{colour}" stroke-width="2"/><text '
                     f'x="{WIDTH - RIGHT + 36}" y="{y + 4}">{planner}</text>')
    lines.append("</svg>")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
