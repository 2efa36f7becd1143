"""End-to-end test of the Python client package (client/python, swarmplan-client).

Outside (run by ctest with /usr/bin/python3):
  - the committed stubs under client/python/swarmplan_client/_proto equal the output of a fresh
    client/python/generate-stubs run (protoc + grpc_python_plugin), so they follow the .proto;
  - a copy of client/python is pip-installed into a new venv that sees Debian's grpcio and
    protobuf (python3 -m venv --system-site-packages; pip install --no-index
    --no-build-isolation), so the install needs no package index;
  - the real swarmplan-server is started twice (one with --token-file) and this file runs again
    inside the venv (--inside) against them.
Inside (the venv's python): uploads the sample maps and maps of every other format the client
detects, plans with seeded planners and a progress callback, and checks paths, determinism,
errors (SwarmplanError with the status code and a message naming the field), jobs, map
deletion and the bearer token.

Everything is written under a temporary folder in /tmp, removed at the end. Exits 77 (ctest
SKIP_RETURN_CODE) when Debian's Python gRPC modules are missing.
"""

import argparse
import filecmp
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

SKIP = 77
START = (2.5, 2.5)
GOAL = (45.5, 27.5)
TOKEN = "python-client-test-token"


class Checks:
    def __init__(self):
        self.failures = []

    def __call__(self, condition, message):
        print(("ok   " if condition else "FAIL ") + message, flush=True)
        if not condition:
            self.failures.append(message)
        return condition


# ---- outside: stub drift, venv install, servers ------------------------------------------------

def tree_files(root):
    found = set()
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        for name in files:
            if not name.endswith(".pyc"):
                found.add(os.path.relpath(os.path.join(folder, name), root))
    return found


def check_stubs(args, work, check):
    fresh = os.path.join(work, "fresh-stubs")
    command = [sys.executable, "-B", os.path.join(args.client_dir, "generate-stubs"),
               "--out", fresh, "--protoc", args.protoc, "--plugin", args.grpc_python_plugin,
               "--proto-root", args.proto_root]
    for include in args.proto_include:
        command += ["--include", include]
    run = subprocess.run(command, capture_output=True, text=True)
    if not check(run.returncode == 0, "generate-stubs runs (%s)" % args.grpc_python_plugin):
        print(run.stdout + run.stderr)
        return
    committed = os.path.join(args.client_dir, "swarmplan_client", "_proto")
    fresh_files, committed_files = tree_files(fresh), tree_files(committed)
    differing = sorted(fresh_files ^ committed_files)
    differing += sorted(f for f in fresh_files & committed_files
                        if not filecmp.cmp(os.path.join(fresh, f), os.path.join(committed, f),
                                           shallow=False))
    check(not differing and len(fresh_files) >= 8,
          "the committed stubs equal freshly generated ones (%d files)%s"
          % (len(fresh_files), "" if not differing else "; differing: %s; run "
             "client/python/generate-stubs" % ", ".join(differing)))


def install(args, work, check):
    """Installs a copy of client/python into a new venv; returns the venv's python or None."""
    source = os.path.join(work, "client-python")
    shutil.copytree(args.client_dir, source, ignore=shutil.ignore_patterns(
        "build", "*.egg-info", "__pycache__", "*.pyc"))
    venv = os.path.join(work, "venv")
    started = time.monotonic()
    run = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv],
                         capture_output=True, text=True)
    if not check(run.returncode == 0, "python3 -m venv --system-site-packages"):
        print(run.stdout + run.stderr + "\n(Debian packages python3-venv; scripts/install-deps)")
        return None
    # No index, no configuration, no cache: the install must succeed from what Debian installed.
    env = {k: v for k, v in os.environ.items() if not k.startswith("PIP_")}
    env.update(PIP_CONFIG_FILE=os.devnull, PIP_DISABLE_PIP_VERSION_CHECK="1")
    python = os.path.join(venv, "bin", "python")
    run = subprocess.run([os.path.join(venv, "bin", "pip"), "install", "--no-index",
                          "--no-build-isolation", "--no-cache-dir", source],
                         capture_output=True, text=True, env=env, cwd=work)
    if not check(run.returncode == 0, "pip install --no-index --no-build-isolation "
                 "client/python into the venv (%.1fs)" % (time.monotonic() - started)):
        print(run.stdout + run.stderr + "\n(needs Debian's python3-wheel; scripts/install-deps)")
        return None
    probe = subprocess.run(
        [python, "-B", "-c", "import grpc, google.protobuf, swarmplan_client, sys; "
         "print(grpc.__file__); print(google.protobuf.__file__); "
         "print(swarmplan_client.__file__); print(sys.prefix)"],
        capture_output=True, text=True, env=env, cwd=work)
    lines = probe.stdout.split()
    check(probe.returncode == 0 and len(lines) == 4 and lines[2].startswith(venv) and
          not lines[0].startswith(venv) and not lines[1].startswith(venv),
          "the venv imports swarmplan_client from its site-packages and grpcio/protobuf from "
          "the system (nothing downloaded)")
    if probe.returncode != 0:
        print(probe.stdout + probe.stderr)
    return python


def outside(args):
    try:
        import grpc  # noqa: F401
        import google.protobuf  # noqa: F401
    except ImportError as error:
        print("SKIP: Python gRPC modules missing (%s); install python3-grpcio and "
              "python3-protobuf (scripts/install-deps does)" % error)
        return SKIP
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from server_fixture import ServerFixture

    check = Checks()
    work = tempfile.mkdtemp(prefix="swarmplan-pyclient-", dir="/tmp")
    try:
        check_stubs(args, work, check)
        python = install(args, work, check)
        if python is not None:
            token_file = os.path.join(work, "token")
            with open(token_file, "w") as f:
                f.write(TOKEN + "\n")
            os.chmod(token_file, 0o600)
            with ServerFixture(args.server_binary) as server, \
                    ServerFixture(args.server_binary, ["--token-file", token_file]) as secured:
                run = subprocess.run(
                    [python, "-B", os.path.abspath(__file__), "--inside",
                     "--address", server.address, "--token-address", secured.address,
                     "--samples", os.path.abspath(args.samples),
                     "--work", os.path.join(work, "inside")],
                    cwd=work, timeout=600)
                check(run.returncode == 0, "the client checks inside the venv pass")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if check.failures:
        print("\n%d check(s) failed" % len(check.failures))
        return 1
    print("\nPython client checks passed")
    return 0


# ---- inside the venv: the client against the servers ------------------------------------------

def write_maps(folder):
    """Writes a small map in each file format the client detects; returns name -> kind."""
    os.makedirs(os.path.join(folder, "ros"))
    width, height = 20, 12
    rows = ["." * width for _ in range(height)]
    rows[5] = "." * 5 + "@" * 10 + "." * 5
    with open(os.path.join(folder, "room.map"), "w") as f:
        f.write("type octile\nheight %d\nwidth %d\nmap\n%s\n" % (height, width, "\n".join(rows)))
    pixels = bytes(0 if c == "@" else 255 for row in rows for c in row)
    pgm = b"P5\n%d %d\n255\n" % (width, height) + pixels
    for path in ("room.pgm", os.path.join("ros", "room-image.pgm")):
        with open(os.path.join(folder, path), "wb") as f:
            f.write(pgm)
    with open(os.path.join(folder, "ros", "room.yaml"), "w") as f:
        f.write("image: room-image.pgm  # next to this file\nresolution: 0.5\n"
                "origin: [1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
                "free_thresh: 0.196\n")

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data)))

    scanlines = b"".join(b"\x00" + pixels[y * width:(y + 1) * width] for y in range(height))
    with open(os.path.join(folder, "room.png"), "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" +
                chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(scanlines)) + chunk(b"IEND", b""))
    with open(os.path.join(folder, "block.geojson"), "w") as f:
        json.dump({"type": "FeatureCollection", "bounds": [0, 0, 50, 40], "features": [
            {"type": "Feature", "properties": {}, "geometry": {
                "type": "Polygon",
                "coordinates": [[[20, 10], [30, 10], [30, 30], [20, 30], [20, 10]]]}}]}, f)
    n = 16
    with open(os.path.join(folder, "hills.asc"), "w") as f:
        f.write("ncols %d\nnrows %d\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
                "NODATA_value -9999\n" % (n, n))
        for y in range(n):
            f.write(" ".join("25" if (x - 8) ** 2 + (y - 8) ** 2 < 10 else "5"
                             for x in range(n)) + "\n")
    return {"room.map": ("occupancy_grid", "movingai", (20, 12)),
            "room.pgm": ("occupancy_grid", "pgm", (20, 12)),
            "room.png": ("occupancy_grid", "png", (20, 12)),
            os.path.join("ros", "room.yaml"): ("occupancy_grid", "ros-yaml-pgm", (20, 12)),
            "block.geojson": ("shape_world", "geojson", (0, 0)),
            "hills.asc": ("terrain", "terrain-asc", (16, 16))}


def inside(args):
    import swarmplan_client
    from swarmplan_client import Client, SwarmplanError

    check = Checks()
    check(swarmplan_client.__file__.startswith(sys.prefix),
          "swarmplan_client imported from the venv (%s)" % swarmplan_client.__file__)
    os.makedirs(args.work)
    formats = write_maps(args.work)

    with Client(args.address) as client:
        warehouse = client.upload_map(os.path.join(args.samples, "warehouse.ascii"))
        check(warehouse.created and warehouse.kind == "occupancy_grid" and
              (warehouse.width, warehouse.height) == (48, 30) and warehouse.format == "ascii" and
              warehouse.name == "warehouse",
              "upload_map warehouse.ascii: a 48x30 grid named warehouse, id %s" % warehouse.id)
        again = client.upload_map(os.path.join(args.samples, "warehouse.ascii"))
        check(not again.created and again.id == warehouse.id,
              "upload_map of the same file again returns the stored map (created False)")
        circles = client.upload_map(os.path.join(args.samples, "circles.json"), name="circles-1")
        check(circles.kind == "shape_world" and circles.format == "shapes-json" and
              circles.name == "circles-1" and circles.obstacle_count == 6,
              "upload_map circles.json: a shape world with 6 obstacles")
        for path, (kind, fmt, size) in formats.items():
            record = client.upload_map(os.path.join(args.work, path))
            check(record.kind == kind and record.format == fmt and
                  (record.width, record.height) == size,
                  "upload_map %s: %s as %s, %dx%d" % (path, kind, fmt, size[0], size[1]))
        try:
            client.upload_map(os.path.join(args.work, "room.bin"))
            check(False, "upload_map of an unknown extension fails")
        except ValueError as error:
            check("format" in str(error), "upload_map of an unknown extension: ValueError (%s)"
                  % str(error)[:60])

        algorithms = {a.id: a for a in client.list_algorithms()}
        check("astar" in algorithms and "pso" in algorithms and
              "occupancy_grid" in algorithms["pso"].map_kinds and
              any(p.name == "iterations" and p.type == "INT"
                  for p in algorithms["pso"].parameters),
              "list_algorithms: %d planners with their parameters" % len(algorithms))

        def plan_pso(seed, **params):
            progress = []
            result = client.plan(
                warehouse.id, START, GOAL, algorithm="pso", seed=seed,
                params=dict(iterations=40, **params),
                on_progress=lambda iteration, fitness: progress.append((iteration, fitness)),
                progress_every=1, labels={"client": "swarmplan-client"}, timeout=120)
            return result, progress

        result, progress = plan_pso(7)
        check(result.succeeded and result.found and result.collision_free and
              result.job_id and result.seed == 7,
              "plan pso seed 7: succeeded, job %s, %d iterations, stop %s"
              % (result.job_id, result.iterations, result.stop_reason))
        check(len(progress) >= 2 and
              all(a[0] < b[0] for a, b in zip(progress, progress[1:])) and
              all(b[1] <= a[1] for a, b in zip(progress, progress[1:])),
              "on_progress: %d calls, iterations growing, best fitness never rising"
              % len(progress))
        check(len(result.path) >= 2 and result.path[0] == START and result.path[-1] == GOAL and
              all(isinstance(p, tuple) and len(p) == 2 for p in result.path),
              "the path is (x, y) tuples from exactly the start to exactly the goal (%d points)"
              % len(result.path))
        check(result.length > 0 and result.fitness > 0,
              "length %.3f, fitness %.3f" % (result.length, result.fitness))

        first, _ = plan_pso(11, init="paper")
        second, _ = plan_pso(11, init="paper")
        check(first.job_id != second.job_id and first.path == second.path and
              first.fitness == second.fitness,
              "two plans with seed 11 (init paper) give the same path (%d points, %s)"
              % (len(first.path), first.state))

        timed = client.plan(warehouse.id, START, GOAL, algorithm="theta-star",
                            smoothing="bounded-curvature",
                            vehicle={"max_speed": 1.5, "max_acceleration": 0.5})
        check(timed.duration is not None and len(timed.timed_path) == len(timed.path) and
              [p for p, _, _ in timed.timed_path] == timed.path and
              timed.timed_path[-1][1] == timed.duration and
              timed.duration > timed.length / 1.5 and result.duration is None,
              "a plan with a vehicle returns its path timed (%.2f s for %.2f units)"
              % (timed.duration or 0.0, timed.length))

        terrain = client.upload_map(os.path.join(args.work, "hills.asc"))
        lattice = client.plan(terrain.id, (5.0, 5.0, 20.0), (155.0, 155.0, 20.0),
                              algorithm="terrain-lattice")
        check(lattice.succeeded and lattice.path[0] == (5.0, 5.0, 20.0) and
              lattice.path[-1] == (155.0, 155.0, 20.0),
              "plan on terrain with (x, y, z) points returns (x, y, z) tuples (%d points)"
              % len(lattice.path))

        job = client.get_job(result.job_id)
        check(job.state == "SUCCEEDED" and job.seed == 7 and job.result is not None and
              job.result.path == result.path and
              job.proto.request.labels["client"] == "swarmplan-client",
              "get_job agrees with the plan")
        cancelled = client.cancel_job(result.job_id)
        check(cancelled.id == result.job_id and cancelled.state == "SUCCEEDED",
              "cancel_job of a finished job leaves it SUCCEEDED")

        def expect_error(code, needle, call, what):
            try:
                call()
                check(False, "%s fails with %s" % (what, code))
            except SwarmplanError as error:
                check(error.code_name == code and needle in error.message,
                      "%s: %s naming %s (%s)" % (what, error.code_name, needle, error.message))

        expect_error("INVALID_ARGUMENT", "clearance",
                     lambda: client.plan(warehouse.id, START, GOAL, clearance=-1.0),
                     "plan with clearance -1")
        expect_error("INVALID_ARGUMENT", "iterations",
                     lambda: client.plan(warehouse.id, START, GOAL, algorithm="pso",
                                         params={"iterations": -4}),
                     "plan with the parameter iterations -4")
        expect_error("NOT_FOUND", "no-such-map",
                     lambda: client.plan("no-such-map", START, GOAL), "plan on an unknown map")
        expect_error("NOT_FOUND", "no-such-job", lambda: client.get_job("no-such-job"),
                     "get_job of an unknown id")
        expect_error("NOT_FOUND", "no-such-job", lambda: client.cancel_job("no-such-job"),
                     "cancel_job of an unknown id")
        try:
            client.plan(warehouse.id, START, GOAL, no_such_field=1)
            check(False, "plan with an unknown keyword fails")
        except TypeError:
            check(True, "plan with an unknown keyword: TypeError")

        # A second upload of other content under the name "circles-1" is its version 2.
        circles_v2 = client.upload_map(os.path.join(args.samples, "warehouse.ascii"),
                                       name="circles-1")
        check(circles_v2.created and circles_v2.version == 2 and circles.version == 1,
              "upload_map of other content under the same name: version 2")
        check(client.get_map(name="circles-1").id == circles_v2.id and
              client.get_map(name="circles-1", version=1).id == circles.id,
              "get_map by name: the latest, or the version asked for")
        check([m.version for m in client.list_map_versions("circles-1")] == [1, 2],
              "list_map_versions lists versions 1 and 2")
        client.delete_map(circles_v2.id)

        client.delete_map(circles.id)
        expect_error("NOT_FOUND", circles.id, lambda: client.get_map(circles.id),
                     "get_map after delete_map")
        expect_error("NOT_FOUND", circles.id, lambda: client.delete_map(circles.id),
                     "delete_map of a deleted map")
    try:
        client.list_algorithms()
        check(False, "the channel is closed after the with block")
    except Exception:
        check(True, "the channel is closed after the with block")

    with Client(args.token_address, token=TOKEN) as client:
        check(len(client.list_algorithms()) == len(algorithms),
              "token: calls with 'authorization: Bearer TOKEN' succeed")
    with Client(args.token_address, token="wrong") as client:
        expect_error("UNAUTHENTICATED", "token", client.list_algorithms, "token: a wrong token")
    with Client(args.token_address) as client:
        expect_error("UNAUTHENTICATED", "authorization", client.list_algorithms,
                     "token: no token")

    if check.failures:
        print("\n%d check(s) failed inside the venv" % len(check.failures))
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--inside", action="store_true", help="run the client checks")
    parser.add_argument("--samples", required=True)
    parser.add_argument("--server-binary")
    parser.add_argument("--client-dir", help="client/python of the repository")
    parser.add_argument("--protoc")
    parser.add_argument("--grpc-python-plugin")
    parser.add_argument("--proto-root", help="folder holding swarmplan/v1/*.proto")
    parser.add_argument("--proto-include", action="append", default=[],
                        help="protoc include folder with google/protobuf/*.proto")
    parser.add_argument("--address")
    parser.add_argument("--token-address")
    parser.add_argument("--work")
    args = parser.parse_args()
    if args.inside:
        return inside(args)
    missing = [name for name in ("server_binary", "client_dir", "protoc", "grpc_python_plugin",
                                 "proto_root") if not getattr(args, name)]
    if missing:
        parser.error("missing --%s" % ", --".join(m.replace("_", "-") for m in missing))
    return outside(args)


if __name__ == "__main__":
    sys.exit(main())
