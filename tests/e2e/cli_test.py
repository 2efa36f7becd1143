"""End-to-end test of the swarmplan CLI against the real swarmplan-server binary.

Starts the server on a free loopback port with a temporary data directory, drives every
command group through the client binary (uploads, listings, planning with streamed progress,
jobs, rendering, health), checks the documented exit codes for bad input, and stops the server.
Standard library only; run by ctest (label e2e).
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_fixture import ServerFixture  # noqa: E402

START = (2.5, 2.5)   # warehouse.ascii: free cells (2, 2) and (45, 27)
GOAL = (45.5, 27.5)
BLOCKED = (0.5, 0.5)  # the border wall


class Cli:
    def __init__(self, binary, server, timeout="20"):
        self.binary = binary
        self.server = server
        self.timeout = timeout
        self.failures = []

    def run(self, *args, expect=0, stdin=None):
        command = [self.binary, "--server", self.server, "--timeout", self.timeout] + list(args)
        env = dict(os.environ)
        env.pop("SWARMPLAN_SERVER", None)
        result = subprocess.run(command, capture_output=True, text=True, env=env, timeout=300)
        shown = " ".join(command[1:])
        allowed = expect if isinstance(expect, (tuple, list)) else (expect,)
        if result.returncode not in allowed:
            self.fail("`swarmplan %s` exited %d, expected %s\nstdout:\n%s\nstderr:\n%s"
                      % (shown, result.returncode, expect, result.stdout, result.stderr))
        else:
            print("ok   [exit %d] swarmplan %s" % (result.returncode, shown))
        return result

    def json(self, *args, expect=0):
        result = self.run("--json", *args, expect=expect)
        try:
            return json.loads(result.stdout)
        except ValueError:
            self.fail("`swarmplan --json %s` printed no JSON:\n%s" % (" ".join(args), result.stdout))
            return {}

    def check(self, condition, message):
        if condition:
            print("ok   " + message)
        else:
            self.fail(message)

    def fail(self, message):
        print("FAIL " + message)
        self.failures.append(message)


def close(point, expected, tolerance=1e-6):
    return (math.isclose(point.get("x", 0.0), expected[0], abs_tol=tolerance) and
            math.isclose(point.get("y", 0.0), expected[1], abs_tol=tolerance))


def largest_curvature(points):
    """The largest curvature of the circle through each three consecutive points."""
    largest = 0.0
    for (ax, ay), (bx, by), (cx, cy) in zip(points, points[1:], points[2:]):
        twice_area = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
        product = (math.hypot(bx - ax, by - ay) * math.hypot(cx - bx, cy - by) *
                   math.hypot(cx - ax, cy - ay))
        if product > 0:
            largest = max(largest, 2 * twice_area / product)
    return largest


def pick_swarm_planner(algorithms):
    """A swarm planner (not an exact one) that plans on occupancy grids, if the server has one."""
    for algorithm in algorithms:
        if (algorithm.get("encoding") != "exact" and
                "MAP_KIND_OCCUPANCY_GRID" in algorithm.get("map_kinds", [])):
            return algorithm["id"]
    return None


def check_vda5050_order(cli, work, standards, timed_args, map_id):
    """plan --output-format vda5050: a VDA 5050 order valid by the published schema, its nodes
    the timed path's points, edge speeds within the vehicle's top speed."""
    order_file = os.path.join(work, "order.json")
    cli.run(*timed_args, "--label", "manufacturer=ACME", "--label", "serial_number=agv-7",
            "--output", order_file, "--output-format", "vda5050")
    with open(order_file) as f:
        order = json.load(f)
    nodes, edges = order.get("nodes", []), order.get("edges", [])
    cli.check(order.get("version") == "3.0.0" and order.get("manufacturer") == "ACME" and
              order.get("serialNumber") == "agv-7" and len(nodes) >= 2 and
              len(edges) == len(nodes) - 1 and
              all(n["nodePosition"]["mapId"] == map_id for n in nodes) and
              [n["sequenceId"] for n in nodes] == list(range(0, 2 * len(nodes), 2)) and
              all(0 < e.get("maximumSpeed", 0) <= 1.5 + 1e-9 for e in edges),
              "the VDA 5050 order has a node per point, edges between them within the top speed")
    schema_file = os.path.join(standards, "vda5050", "order.schema")
    if not os.path.exists(schema_file):
        print("skip the VDA 5050 schema check: %s is absent" % schema_file)
        return
    try:
        import jsonschema
    except ImportError:
        cli.fail("python3-jsonschema is missing (scripts/install-deps installs it)")
        return
    with open(schema_file) as f:
        schema = json.load(f)
    errors = sorted(jsonschema.Draft202012Validator(schema).iter_errors(order), key=str)
    cli.check(not errors, "the order validates against VDA 5050 order.schema 3.0.0%s"
              % ("" if not errors else ": " + "; ".join(e.message for e in errors[:3])))
    broken = dict(order, nodes=[dict(nodes[0], sequenceId=-1)] + nodes[1:])
    cli.check(any(True for _ in jsonschema.Draft202012Validator(schema).iter_errors(broken)),
              "the schema check rejects a negative sequenceId")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--client", required=True)
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--samples", required=True)
    parser.add_argument("--standards", default="",
                        help="../shared/standards: the VDA 5050 order schema")
    args = parser.parse_args()
    warehouse = os.path.join(args.samples, "warehouse.ascii")
    circles = os.path.join(args.samples, "circles.json")
    work = tempfile.mkdtemp(prefix="swarmplan-cli-e2e-")

    # Before the server runs: usage errors and an unreachable server.
    offline = Cli(args.client, "127.0.0.1:1", timeout="2")
    help_text = offline.run("--help").stdout
    offline.check("Exit codes" in help_text and "unauthenticated" in help_text,
                  "--help documents the exit codes")
    offline.run("no-such-command", expect=1)
    offline.run("plan", expect=1)  # missing map and --start/--goal
    offline.run("health", expect=2)
    offline.run("maps", "list", expect=2)
    offline.run("--server", "127.0.0.1:2", "health", expect=2)  # the last --server wins
    failures = list(offline.failures)

    with ServerFixture(args.server_binary) as server:
        cli = Cli(args.client, server.address)
        cli.failures = failures
        health = cli.run("health")
        cli.check("SERVING" in health.stdout, "health says SERVING")
        cli.check(cli.json("health").get("status") == "SERVING", "health --json")

        # Maps.
        uploaded = cli.json("maps", "upload", warehouse)
        grid = uploaded.get("map", {})
        grid_id = grid.get("id", "")
        cli.check(grid.get("kind") == "MAP_KIND_OCCUPANCY_GRID" and grid.get("width") == 48 and
                  grid.get("height") == 30, "warehouse.ascii uploaded as a 48x30 grid")
        again = cli.json("maps", "upload", warehouse)
        cli.check(again.get("map", {}).get("id") == grid_id and not again.get("created"),
                  "re-uploading the same map is idempotent")
        world = cli.json("maps", "upload", circles, "--name", "circles").get("map", {})
        world_id = world.get("id", "")
        cli.check(world.get("kind") == "MAP_KIND_SHAPE_WORLD", "circles.json is a shape world")
        listed = [m["id"] for m in cli.json("maps", "list").get("maps", [])]
        cli.check(grid_id in listed and world_id in listed, "maps list --json has both maps")
        cli.check("warehouse" in cli.run("maps", "list").stdout, "maps list table names the map")
        cli.run("maps", "get", grid_id)
        cli.run("maps", "get", grid_id, "--save", os.path.join(work, "saved"))
        cli.check(os.path.exists(os.path.join(work, "saved", "warehouse.ascii")),
                  "maps get --save downloads the uploaded file")

        # Map versions: new content under a name is its next version; NAME@VERSION names one.
        dock = os.path.join(work, "dock.ascii")
        dock_ids = []
        for art in ("....\n....\n", "....\n.#..\n"):
            with open(dock, "w") as f:
                f.write(art)
            dock_ids.append(cli.json("maps", "upload", dock).get("map", {}).get("id", ""))
        first = cli.json("maps", "get", "dock@1").get("map", {})
        latest = cli.json("maps", "get", "dock@latest").get("map", {})
        cli.check(first.get("id") == dock_ids[0] and int(first.get("version", 0)) == 1,
                  "maps get dock@1 is the first upload")
        cli.check(latest.get("id") == dock_ids[1] and int(latest.get("version", 0)) == 2,
                  "maps get dock@latest is the second upload, version 2")
        versions = [int(m.get("version", 0))
                    for m in cli.json("maps", "list", "--name", "dock").get("maps", [])]
        cli.check(versions == [1, 2], "maps list --name dock lists versions 1 and 2")
        cli.check("VERSION" in cli.run("maps", "list").stdout, "maps list shows the version")
        cli.run("maps", "get", "dock@first", expect=1)
        cli.run("maps", "get", "dock@9", expect=3)
        on_first = cli.json("plan", "dock@1", "--start", "0.5,0.5", "--goal", "3.5,1.5")
        cli.check(on_first.get("request", {}).get("map_id") == dock_ids[0] and
                  on_first.get("map_name") == "dock" and
                  int(on_first.get("map_version", 0)) == 1,
                  "plan dock@1 plans on the first version and the job records it")
        cli.check("(dock@1)" in cli.run("jobs", "get", on_first.get("id", "")).stdout,
                  "jobs get shows the map's name and version")
        cli.run("maps", "delete", "dock@latest")
        cli.check(cli.json("maps", "get", "dock@latest").get("map", {}).get("id") == dock_ids[0],
                  "after deleting version 2, dock@latest is version 1")

        # Algorithms.
        table = cli.run("algorithms").stdout
        cli.check("astar" in table, "algorithms lists astar")
        algorithms = cli.json("algorithms").get("algorithms", [])
        cli.check(any(a["id"] == "astar" for a in algorithms), "algorithms --json lists astar")
        cli.run("algorithms", "astar")
        cli.run("algorithms", "no-such-planner", expect=3)

        # Plan: JSON result, path file, the path from start to goal.
        path_json = os.path.join(work, "path.json")
        start, goal = "%g,%g" % START, "%g,%g" % GOAL
        job = cli.json("plan", grid_id, "--start", start, "--goal", goal, "--algorithm", "astar",
                       "--seed", "7", "--label", "robot=agv-7", "--output", path_json)
        job_id = job.get("id", "")
        result = job.get("result", {})
        raw = result.get("raw_path", [])
        cli.check(job.get("state") == "JOB_STATE_SUCCEEDED", "plan --json: job succeeded")
        cli.check(len(raw) >= 2 and close(raw[0], START) and close(raw[-1], GOAL),
                  "plan --json: the path runs from start to goal")
        cli.check(job.get("request", {}).get("labels", {}).get("robot") == "agv-7",
                  "plan --label is stored with the job")
        with open(path_json) as f:
            written = json.load(f)
        cli.check(written.get("job_id") == job_id and written["path"][0][:2] == list(START),
                  "plan --output writes the path as JSON")

        # Plan for people: progress lines on stderr (not a TTY), a summary table on stdout.
        path_csv = os.path.join(work, "path.csv")
        human = cli.run("plan", grid_id, "--start", start, "--goal", goal, "--output", path_csv)
        cli.check("iteration" in human.stderr and "accepted" in human.stderr,
                  "plan streams progress lines on stderr")
        cli.check("PATH" in human.stdout and "raw" in human.stdout and "succeeded" in human.stdout,
                  "plan ends with a summary table")
        with open(path_csv) as f:
            cli.check(f.readline().strip() == "x,y", "plan --output writes CSV")
        path_geojson = os.path.join(work, "path.geojson")
        cli.run("plan", grid_id, "--start", start, "--goal", goal, "--output", path_geojson)
        with open(path_geojson) as f:
            feature = json.load(f)["features"][0]
        cli.check(feature["geometry"]["type"] == "LineString", "plan --output writes GeoJSON")

        swarm = pick_swarm_planner(algorithms)
        if swarm:
            swarm_job = cli.json("plan", grid_id, "--start", start, "--goal", goal,
                                 "--algorithm", swarm, "--seed", "3", "--max-iterations", "20",
                                 "--time-budget", "60s", expect=(0, 5))
            cli.check(swarm_job.get("result", {}).get("algorithm", swarm) == swarm and
                      len(swarm_job.get("result", {}).get("convergence", [])) > 0,
                      "plan with seed-paper planner %s reports its convergence" % swarm)
        else:
            print("note no seed-paper planner for grids is registered yet; planned with astar only")

        # The fleet objective: a turning radius kept by bounded-curvature smoothing, each term of
        # the objective reported for the path and for the best seed after the same smoothing.
        fleet = cli.json("plan", grid_id, "--start", start, "--goal", goal, "--algorithm",
                         "aem-bso", "--seed", "3", "--max-iterations", "30", "--clearance", "0.5",
                         "--preferred-clearance", "1.5", "--turning-radius", "2", "--smoothing",
                         "bounded-curvature", "--time-budget", "60s").get("result", {})
        smoothed = [(p.get("x", 0.0), p.get("y", 0.0)) for p in fleet.get("smoothed_path", [])]
        cli.check(fleet.get("found") and smoothed[:1] == [START] and smoothed[-1:] == [GOAL],
                  "a fleet plan joins start and goal after bounded-curvature smoothing")
        cli.check(largest_curvature(smoothed) <= 0.5 * (1 + 1e-9),
                  "bounded-curvature smoothing keeps the curvature within 1 / turning radius")
        for key in ("objective", "seed_objective"):
            terms = fleet.get(key, {})
            parts = sum(terms.get(k, 0.0) for k in ("length", "clearance", "curvature",
                                                    "violation"))
            cli.check(terms.get("length", 0.0) > 0 and
                      math.isclose(terms.get("total", -1.0), parts, rel_tol=1e-9),
                      "the result's %s lists its terms and their total" % key)
        cli.check(fleet.get("objective", {}).get("total", 1e9) <=
                  fleet.get("seed_objective", {}).get("total", 0.0) + 1e-9,
                  "on the warehouse the fleet plan is no worse by its objective than its best seed")
        # The summary says whether the path keeps the turning radius: the fleet plan does; in the
        # warehouse's aisles no path can turn no tighter than a radius of 50.
        fleet_args = ("plan", grid_id, "--start", start, "--goal", goal, "--algorithm", "aem-bso",
                      "--seed", "3", "--max-iterations", "30", "--clearance", "0.5",
                      "--preferred-clearance", "1.5", "--smoothing", "bounded-curvature")
        cli.check(re.search(r"turning radius:\s+kept \(tightest turn radius",
                            cli.run(*fleet_args, "--turning-radius", "2").stdout),
                  "plan says the turning radius is kept when the smoothed path keeps it")
        cli.check(re.search(r"turning radius:\s+NOT kept: tightest turn radius",
                            cli.run(*fleet_args, "--turning-radius", "50").stdout),
                  "plan says when the path cannot keep the turning radius")

        # A timed path: the smoothed path timed for a vehicle, its duration printed.
        timed_args = ("plan", grid_id, "--start", start, "--goal", goal, "--algorithm",
                      "theta-star", "--smoothing", "bounded-curvature", "--turning-radius", "2",
                      "--max-speed", "1.5", "--max-acceleration", "0.5", "--max-yaw-rate", "1")
        timed = cli.json(*timed_args).get("result", {})
        points = timed.get("timed_path", {}).get("points", [])
        duration = timed.get("timed_path", {}).get("duration", 0.0)
        cli.check(len(points) == len(timed.get("smoothed_path", [])) and points and
                  points[-1].get("time") == duration and
                  duration > timed.get("smoothed_metrics", {}).get("length", 1e9) / 1.5,
                  "plan --max-speed returns the smoothed path timed, slower than its top speed")
        cli.check("duration" in cli.run(*timed_args).stdout, "plan --max-speed prints the duration")
        check_vda5050_order(cli, work, args.standards, timed_args, grid_id)
        # Via-points: the path passes each, in order; the legs are reported.
        via = cli.json("plan", grid_id, "--start", start, "--goal", goal, "--algorithm",
                       "theta-star", "--via", "20.5,2.5", "--via", "20.5,27.5").get("result", {})
        via_path = [(p.get("x", 0.0), p.get("y", 0.0)) for p in via.get("raw_path", [])]
        cli.check(via.get("found") and via.get("via_points_reached") == 2 and
                  len(via.get("legs", [])) == 3 and via_path[:1] == [START] and
                  via_path[-1:] == [GOAL] and (20.5, 2.5) in via_path and
                  (20.5, 27.5) in via_path and
                  via_path.index((20.5, 2.5)) < via_path.index((20.5, 27.5)),
                  "plan --via passes each via-point in order and reports the legs")
        cli.check("via points" in cli.run("plan", grid_id, "--start", start, "--goal", goal,
                                          "--algorithm", "theta-star", "--via",
                                          "20.5,2.5").stdout,
                  "plan --via prints the via-points reached")
        rejected = cli.run("plan", grid_id, "--start", start, "--goal", goal, "--max-speed", "1",
                           expect=(1, 2, 4))
        cli.check("vehicle.max_acceleration" in rejected.stdout + rejected.stderr,
                  "a top speed without an acceleration is refused naming the field")

        # Jobs.
        jobs = [j["id"] for j in cli.json("jobs", "list").get("jobs", [])]
        cli.check(job_id in jobs, "jobs list --json has the job")
        cli.check(job_id in cli.run("jobs", "list").stdout, "jobs list table has the job")
        cli.json("jobs", "list", "--state", "succeeded")
        cli.run("jobs", "list", "--state", "bogus", expect=1)
        got = cli.json("jobs", "get", job_id)
        cli.check(got.get("id") == job_id and got.get("result", {}).get("found"),
                  "jobs get --json returns the result")
        cli.check("collision" in cli.run("jobs", "get", job_id).stdout.lower(),
                  "jobs get shows the metrics")
        cli.run("jobs", "get", "no-such-job", expect=3)
        submitted = cli.json("plan", grid_id, "--start", start, "--goal", goal, "--detach")
        detached_id = submitted.get("job", {}).get("id", "")
        cli.check(bool(detached_id), "plan --detach returns a job id at once")
        watched = cli.run("jobs", "watch", detached_id)
        cli.check("succeeded" in watched.stdout, "jobs watch follows the job to its end")
        cancelled = cli.json("jobs", "cancel", detached_id)
        cli.check(cancelled.get("state") == "JOB_STATE_SUCCEEDED",
                  "cancelling a finished job changes nothing")
        cli.run("jobs", "cancel", "no-such-job", expect=3)

        # Render.
        svg = os.path.join(work, "map.svg")
        cli.run("render", "--job", job_id, "--output", svg)
        with open(svg) as f:
            content = f.read()
        cli.check(content.startswith("<?xml") and "<svg" in content and "<polyline" in content
                  and "<rect" in content, "render draws the grid and the path as SVG")
        try:
            ElementTree.parse(svg)
            cli.check(True, "the SVG is well-formed XML")
        except ElementTree.ParseError as error:
            cli.fail("the SVG is not well-formed XML: %s" % error)
        world_svg = os.path.join(work, "world.svg")
        cli.run("render", "--map", world_id, "--path", path_json, "--output", world_svg,
                "--convergence", "file")
        with open(world_svg) as f:
            cli.check("<circle" in f.read(), "render draws a shape world's circles")
        file_svg = os.path.join(work, "file.svg")
        rendered = cli.json("render", "--map-file", warehouse, "--path", path_csv, "--job", job_id,
                            "--convergence", "file", "--png", "--output", file_svg)
        cli.check(os.path.exists(file_svg) and
                  os.path.exists(os.path.join(work, "file-convergence.svg")),
                  "render --convergence file writes a second SVG")
        cli.check(rendered.get("png") or rendered.get("png_message"),
                  "render --png writes a PNG or says why not")
        cli.run("render", "--map", "no-such-map", "--output", svg, expect=3)

        # Bad input: the documented exit codes.
        cli.run("plan", grid_id, "--start", start, "--goal", goal, "--algorithm", "no-such-planner",
                expect=3)
        cli.run("plan", "no-such-map", "--start", start, "--goal", goal, expect=3)
        # The API answers FAILED_PRECONDITION (4) for a blocked start; a server that accepts the
        # job and fails it instead gives 5. Either way the job must not succeed.
        blocked = cli.run("plan", grid_id, "--start", "%g,%g" % BLOCKED, "--goal", goal,
                          expect=(4, 5))
        if blocked.returncode == 5:
            print("note the server accepted a blocked start and failed the job (API: "
                  "FAILED_PRECONDITION at submission)")
        cli.run("plan", grid_id, "--start", "-50,-50", "--goal", goal, expect=4)
        cli.run("plan", grid_id, "--start", "abc", "--goal", goal, expect=1)
        cli.run("plan", grid_id, "--start", start, "--goal", goal, "--param", "novalue", expect=1)
        cli.run("plan", grid_id, "--start", start, "--goal", goal, "--output", "path.txt",
                expect=1)
        cli.run("maps", "upload", os.path.join(work, "missing.ascii"), expect=1)
        cli.run("maps", "upload", os.path.join(work, "map.unknown-extension"), expect=1)
        malformed = os.path.join(work, "bad.ascii")
        with open(malformed, "w") as f:
            f.write("..#\n.x.\n")
        error = cli.json("maps", "upload", malformed, expect=4).get("error", {})
        cli.check(error.get("code") == "INVALID_ARGUMENT", "a malformed map is INVALID_ARGUMENT")
        cli.run("maps", "get", "no-such-map", expect=3)
        cli.run("maps", "delete", "no-such-map", expect=3)

        cli.run("maps", "delete", world_id)
        listed = [m["id"] for m in cli.json("maps", "list").get("maps", [])]
        cli.check(world_id not in listed and grid_id in listed, "maps delete removes only that map")
        cli.run("health")
        failures = cli.failures

    # Bearer-token authentication: health stays open, everything else needs --token-file.
    token = os.path.join(work, "token")
    with open(token, "w") as f:
        f.write("e2e-secret\n")
    wrong = os.path.join(work, "wrong-token")
    with open(wrong, "w") as f:
        f.write("not-the-secret\n")
    # A token file others can read is served, with a warning naming the file and its mode.
    os.chmod(token, 0o644)
    with ServerFixture(args.server_binary, ["--token-file", token]) as server:
        cli = Cli(args.client, server.address)
        cli.failures = failures
        cli.check("--token-file %s has mode 0644" % token in server.log(),
                  "a world-readable token file is warned about")
        cli.run("health")
        error = cli.json("maps", "list", expect=7).get("error", {})
        cli.check(error.get("code") == "UNAUTHENTICATED", "no token: UNAUTHENTICATED")
        cli.run("--token-file", wrong, "algorithms", expect=7)
        cli.run("--token-file", token, "maps", "upload", warehouse)
        cli.run("--token-file", os.path.join(work, "no-such-token"), "algorithms", expect=1)
        failures = cli.failures
    os.chmod(token, 0o600)
    with ServerFixture(args.server_binary, ["--token-file", token]) as server:
        cli = Cli(args.client, server.address)
        cli.failures = failures
        cli.check("has mode" not in server.log(), "a token file only its owner reads: no warning")
        cli.run("--token-file", token, "algorithms")
        failures = cli.failures

    shutil.rmtree(work, ignore_errors=True)
    if failures:
        print("\n%d check(s) failed" % len(failures))
        return 1
    print("\nall CLI end-to-end checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
