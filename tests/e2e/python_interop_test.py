"""Interoperability test: a client no one here wrote (Python's grpcio from Debian's packages,
with stubs generated from the project's .proto at build time) uploads a map and streams a plan
from the real swarmplan-server.

Checks: the map is parsed as uploaded; the Plan stream delivers accepted, started, progress...,
finished in that order with growing sequence numbers and one job id; the final path starts at
the start and ends at the goal; GetJob agrees with the stream.

Exits 77 (ctest SKIP_RETURN_CODE) when the grpc/protobuf modules or the stubs are missing.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_fixture import ServerFixture  # noqa: E402

SKIP = 77
START = (2.5, 2.5)
GOAL = (45.5, 27.5)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--stubs", required=True, help="folder with the generated *_pb2*.py")
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--samples", required=True)
    args = parser.parse_args()

    try:
        import grpc  # noqa: F401
        import google.protobuf  # noqa: F401
    except ImportError as error:
        print("SKIP: Python gRPC modules missing (%s); install python3-grpcio and "
              "python3-protobuf (scripts/install-deps does)" % error)
        return SKIP
    if not os.path.exists(os.path.join(args.stubs, "swarmplan", "v1", "jobs_pb2_grpc.py")):
        print("SKIP: no Python stubs in %s; build the target swarmplan_python_stubs (needs "
              "grpc_python_plugin from protobuf-compiler-grpc)" % args.stubs)
        return SKIP
    sys.path.insert(0, args.stubs)
    from swarmplan.v1 import jobs_pb2, jobs_pb2_grpc, maps_pb2, maps_pb2_grpc  # noqa: E402
    from swarmplan.v1 import algorithms_pb2, algorithms_pb2_grpc, common_pb2  # noqa: E402

    failures = []

    def check(condition, message):
        print(("ok   " if condition else "FAIL ") + message)
        if not condition:
            failures.append(message)

    with ServerFixture(args.server_binary) as server:
        channel = grpc.insecure_channel(server.address)
        grpc.channel_ready_future(channel).result(timeout=30)
        maps = maps_pb2_grpc.MapServiceStub(channel)
        jobs = jobs_pb2_grpc.JobServiceStub(channel)
        algorithms = algorithms_pb2_grpc.AlgorithmServiceStub(channel)

        with open(os.path.join(args.samples, "warehouse.ascii"), "rb") as f:
            content = f.read()
        upload = maps.UploadMap(maps_pb2.UploadMapRequest(
            name="warehouse-from-python",
            source=maps_pb2.MapSource(files=maps_pb2.MapFiles(
                format="ascii", files=[maps_pb2.MapFile(name="warehouse.ascii",
                                                        content=content)]))), timeout=30)
        check(upload.created and upload.map.kind == common_pb2.MAP_KIND_OCCUPANCY_GRID and
              (upload.map.width, upload.map.height) == (48, 30),
              "UploadMap: a 48x30 occupancy grid, id %s" % upload.map.id)

        listed = algorithms.ListAlgorithms(algorithms_pb2.ListAlgorithmsRequest(), timeout=30)
        ids = [a.id for a in listed.algorithms]
        check("astar" in ids, "ListAlgorithms: %s" % ", ".join(ids))

        def stream_plan(algorithm, **limits):
            request = jobs_pb2.PlanRequest(
                map_id=upload.map.id, start=common_pb2.Point(x=START[0], y=START[1]),
                goal=common_pb2.Point(x=GOAL[0], y=GOAL[1]), algorithm=algorithm, seed=11,
                labels={"client": "python-grpcio"}, limits=jobs_pb2.JobLimits(**limits),
                progress=jobs_pb2.ProgressOptions(every_iterations=1))
            events = list(jobs.Plan(request, timeout=120))
            kinds = [e.WhichOneof("event") for e in events]
            shown = kinds if len(kinds) <= 8 else kinds[:5] + ["..."] + kinds[-2:]
            print("     %s events: %s" % (algorithm, " ".join(shown)))
            check(len(events) >= 3 and kinds[0] == "accepted" and kinds[-1] == "finished",
                  "Plan %s: the stream starts with accepted and ends with finished" % algorithm)
            check("started" in kinds and kinds.count("started") == 1 and
                  kinds.count("finished") == 1 and
                  all(k == "progress" for k in kinds[kinds.index("started") + 1:-1]),
                  "Plan %s: started comes once, before every progress event" % algorithm)
            sequences = [e.sequence for e in events]
            check(all(a < b for a, b in zip(sequences, sequences[1:])),
                  "Plan %s: sequence numbers grow" % algorithm)
            check(len({e.job_id for e in events}) == 1 and events[0].job_id,
                  "Plan %s: every event names the same job" % algorithm)
            progress = [e.progress for e in events if e.HasField("progress")]
            check(all(a.iteration < b.iteration for a, b in zip(progress, progress[1:])),
                  "Plan %s: progress iterations grow (%d progress events)" % (algorithm, len(progress)))
            check(all(b.best_fitness <= a.best_fitness for a, b in zip(progress, progress[1:])),
                  "Plan %s: best fitness never rises" % algorithm)
            return events

        events = stream_plan("astar")
        finished = events[-1].finished
        check(finished.state == jobs_pb2.JOB_STATE_SUCCEEDED, "Plan astar: the job succeeded")
        path = finished.result.raw_path
        check(len(path) >= 2 and (path[0].x, path[0].y) == START and
              (path[-1].x, path[-1].y) == GOAL,
              "Plan astar: the path runs from start to goal (%d points)" % len(path))
        check(finished.result.raw_metrics.collision_free, "Plan astar: the path is collision-free")

        # A swarm planner streams one progress event per iteration.
        swarm = [a.id for a in listed.algorithms
                 if a.encoding != "exact" and common_pb2.MAP_KIND_OCCUPANCY_GRID in a.map_kinds]
        if swarm:
            swarm_events = stream_plan(swarm[0], max_iterations=25)
            swarm_finished = swarm_events[-1].finished
            check(sum(1 for e in swarm_events if e.HasField("progress")) >= 2,
                  "Plan %s: several progress events" % swarm[0])
            swarm_path = swarm_finished.result.raw_path
            if swarm_finished.state == jobs_pb2.JOB_STATE_SUCCEEDED:
                check((swarm_path[0].x, swarm_path[0].y) == START and
                      (swarm_path[-1].x, swarm_path[-1].y) == GOAL,
                      "Plan %s: the path runs from start to goal" % swarm[0])
            else:
                print("note %s finished %s in 25 iterations" %
                      (swarm[0], jobs_pb2.JobState.Name(swarm_finished.state)))

        job = jobs.GetJob(jobs_pb2.GetJobRequest(id=events[0].job_id), timeout=30)
        check(job.state == jobs_pb2.JOB_STATE_SUCCEEDED and
              list(job.result.raw_path) == list(path) and
              job.request.labels["client"] == "python-grpcio",
              "GetJob agrees with the stream")

        try:
            maps.GetMap(maps_pb2.GetMapRequest(id="no-such-map"), timeout=30)
            check(False, "GetMap of an unknown id fails")
        except grpc.RpcError as error:
            check(error.code() == grpc.StatusCode.NOT_FOUND, "GetMap of an unknown id: NOT_FOUND")
        channel.close()

    if failures:
        print("\n%d check(s) failed" % len(failures))
        return 1
    print("\nPython grpcio interoperability checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
