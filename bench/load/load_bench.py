#!/usr/bin/env python3
"""Load and memory benchmark of one swarmplan-server process (issue 14).

Starts the real swarmplan-server binary on 127.0.0.1 (a port it picks, a temporary data
directory), then
  1. opens --streams concurrent Plan streams (astar on samples/maps/warehouse.ascii) at once and
     reads each to its end: errors by status code, p50/p99 latency from the call to the end of
     the stream, the server's RSS before, at its peak (sampled every 20 ms) and after;
  2. submits detached jobs (SubmitPlan, --in-flight at a time) until --checkpoints finished jobs
     and records the server's RSS at each, with --job-cache-entries finished jobs in memory.
Writes a Markdown report (--out) and prints it. Needs Debian's python3-grpcio and the Python
stubs the build generates (build/<dir>/tests/e2e/python).

  /usr/bin/python3 bench/load/load_bench.py --server-binary build/test/server/swarmplan-server \\
      --stubs build/test/tests/e2e/python --out bench/results/load.md
"""

import argparse
import asyncio
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def mib(kib):
    return "%.1f MiB" % (kib / 1024.0)


def percentile(values, p):
    if not values:
        return float("nan")
    ordered = sorted(values)
    k = min(len(ordered) - 1, max(0, int(round(p / 100.0 * (len(ordered) - 1)))))
    return ordered[k]


class Sampler(threading.Thread):
    """Samples the server's RSS every 20 ms and keeps the maximum."""

    def __init__(self, pid):
        super().__init__(daemon=True)
        self.pid = pid
        self.peak = 0
        self.running = True

    def run(self):
        while self.running:
            self.peak = max(self.peak, rss_kib(self.pid))
            time.sleep(0.02)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--stubs", required=True)
    parser.add_argument("--map", default=os.path.join(os.path.dirname(__file__), "..", "..",
                                                       "samples", "maps", "warehouse.ascii"))
    parser.add_argument("--streams", type=int, default=1000)
    parser.add_argument("--channels", type=int, default=8)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--job-cache-entries", type=int, default=1000)
    parser.add_argument("--checkpoints", default="1000,2000,10000,50000")
    parser.add_argument("--in-flight", type=int, default=64)
    parser.add_argument("--out", default="")
    args = parser.parse_args()

    sys.path.insert(0, args.stubs)
    import grpc
    from swarmplan.v1 import common_pb2, jobs_pb2, jobs_pb2_grpc, maps_pb2, maps_pb2_grpc

    workdir = tempfile.mkdtemp(prefix="swarmplan-load-")
    log_path = os.path.join(workdir, "server.log")
    log = open(log_path, "wb")
    command = [args.server_binary, "--listen", "127.0.0.1:0", "--data-dir",
               os.path.join(workdir, "data"), "--metrics-port", "0", "--workers",
               str(args.workers), "--queue-capacity", str(args.streams + 100),
               "--job-cache-entries", str(args.job_cache_entries)]
    server = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT,
                              stdin=subprocess.DEVNULL)
    log.close()
    try:
        port = None
        deadline = time.monotonic() + 60
        while port is None and time.monotonic() < deadline:
            with open(log_path, errors="replace") as f:
                match = re.search(r"listening on port (\d+)", f.read())
            if match:
                port = int(match.group(1))
            elif server.poll() is not None:
                raise RuntimeError("swarmplan-server exited early")
            else:
                time.sleep(0.05)
        if port is None:
            raise RuntimeError("swarmplan-server did not report its port")
        address = "127.0.0.1:%d" % port

        with open(args.map, "rb") as f:
            content = f.read()
        channel = grpc.insecure_channel(address)
        grpc.channel_ready_future(channel).result(timeout=30)
        upload = maps_pb2_grpc.MapServiceStub(channel).UploadMap(maps_pb2.UploadMapRequest(
            name="warehouse", source=maps_pb2.MapSource(files=maps_pb2.MapFiles(
                format="ascii", files=[maps_pb2.MapFile(name="warehouse.ascii",
                                                        content=content)]))), timeout=30)
        map_id = upload.map.id

        def request(seed, **extra):
            return jobs_pb2.PlanRequest(
                map_id=map_id, start=common_pb2.Point(x=2.5, y=2.5),
                goal=common_pb2.Point(x=45.5, y=27.5), algorithm="astar", seed=seed, **extra)

        lines = []
        lines.append("# Load and memory: one swarmplan-server process")
        lines.append("")
        lines.append("Produced by `bench/load/load_bench.py` (Python grpcio %s client, the real "
                     "server binary on 127.0.0.1). Machine: %s, %d cores (shared); server "
                     "flags: `--workers %d --queue-capacity %d --job-cache-entries %d`, the "
                     "rest default (`--max-retained-jobs 100000`). Planner: astar on "
                     "`samples/maps/warehouse.ascii` (48x30), (2.5, 2.5) to (45.5, 27.5)."
                     % (grpc.__version__, platform.machine(), os.cpu_count(), args.workers,
                        args.streams + 100, args.job_cache_entries))
        lines.append("")

        # 1. Concurrent Plan streams.
        rss_before = rss_kib(server.pid)
        sampler = Sampler(server.pid)
        sampler.start()

        async def streams():
            channels = [grpc.aio.insecure_channel(address) for _ in range(args.channels)]
            stubs = [jobs_pb2_grpc.JobServiceStub(c) for c in channels]

            async def one(i):
                start = time.monotonic()
                code = "OK"
                try:
                    finished = None
                    async for event in stubs[i % len(stubs)].Plan(request(i + 1), timeout=600):
                        if event.WhichOneof("event") == "finished":
                            finished = event
                    if finished is None:
                        code = "NO_FINISHED_EVENT"
                except grpc.aio.AioRpcError as e:
                    code = e.code().name
                return code, time.monotonic() - start

            results = await asyncio.gather(*[one(i) for i in range(args.streams)])
            for c in channels:
                await c.close()
            return results

        wall = time.monotonic()
        results = asyncio.run(streams())
        wall = time.monotonic() - wall
        sampler.running = False
        sampler.join()
        time.sleep(1.0)
        rss_after = rss_kib(server.pid)
        codes = {}
        for code, _ in results:
            codes[code] = codes.get(code, 0) + 1
        latencies = [s for code, s in results if code == "OK"]
        lines.append("## %d concurrent Plan streams" % args.streams)
        lines.append("")
        lines.append("All %d streams opened at once over %d channels; each read to its end."
                     % (args.streams, args.channels))
        lines.append("")
        lines.append("| measure | value |")
        lines.append("|---|---|")
        lines.append("| streams by final status | %s |"
                     % ", ".join("%s: %d" % kv for kv in sorted(codes.items())))
        lines.append("| wall time | %.2f s |" % wall)
        lines.append("| latency p50 (call to end of stream) | %.3f s |" % percentile(latencies, 50))
        lines.append("| latency p99 | %.3f s |" % percentile(latencies, 99))
        lines.append("| latency max | %.3f s |" % (max(latencies) if latencies else float("nan")))
        lines.append("| server RSS before | %s |" % mib(rss_before))
        lines.append("| server RSS at peak (20 ms samples) | %s |" % mib(sampler.peak))
        lines.append("| server RSS after (1 s later) | %s |" % mib(rss_after))
        lines.append("")

        # 2. Finished jobs.
        checkpoints = [int(c) for c in args.checkpoints.split(",")]
        finished_so_far = args.streams

        async def submit_until(total, first_seed):
            async with grpc.aio.insecure_channel(address) as ch:
                stub = jobs_pb2_grpc.JobServiceStub(ch)
                semaphore = asyncio.Semaphore(args.in_flight)
                ids = []
                errors = {}

                async def one(seed):
                    async with semaphore:
                        while True:
                            try:
                                response = await stub.SubmitPlan(request(seed), timeout=60)
                                ids.append(response.job.id)
                                return
                            except grpc.aio.AioRpcError as e:
                                if e.code() != grpc.StatusCode.RESOURCE_EXHAUSTED:
                                    errors[e.code().name] = errors.get(e.code().name, 0) + 1
                                    return
                                await asyncio.sleep(0.01)

                await asyncio.gather(*[one(first_seed + k) for k in range(total)])
                # FIFO queue: once the last submitted ones are final, every job is.
                for job_id in ids[-4:]:
                    while True:
                        job = await stub.GetJob(jobs_pb2.GetJobRequest(id=job_id), timeout=30)
                        if job.state not in (jobs_pb2.JOB_STATE_QUEUED,
                                             jobs_pb2.JOB_STATE_RUNNING):
                            break
                        await asyncio.sleep(0.05)
                return errors

        lines.append("## RSS after finished jobs")
        lines.append("")
        lines.append("Detached `SubmitPlan` jobs, %d in flight (RESOURCE_EXHAUSTED is retried), "
                     "counted with the %d jobs of the stream phase. With %d finished jobs the "
                     "cache of finished jobs is full; beyond it RSS should stay flat."
                     % (args.in_flight, args.streams, args.job_cache_entries))
        lines.append("")
        lines.append("| finished jobs | server RSS | vs. the first row | submit errors | time |")
        lines.append("|---|---|---|---|---|")
        first_rss = None
        seed = 1000000
        for checkpoint in checkpoints:
            started = time.monotonic()
            errors = {}
            if checkpoint > finished_so_far:
                errors = asyncio.run(submit_until(checkpoint - finished_so_far, seed))
                seed += checkpoint - finished_so_far
                finished_so_far = checkpoint
            time.sleep(1.0)
            rss = rss_kib(server.pid)
            if first_rss is None:
                first_rss = rss
            lines.append("| %d | %s | %+.1f %% | %s | %.1f s |" % (
                checkpoint, mib(rss), 100.0 * (rss - first_rss) / first_rss,
                ", ".join("%s: %d" % kv for kv in sorted(errors.items())) or "none",
                time.monotonic() - started))
        lines.append("")
        report = "\n".join(lines) + "\n"
        print(report)
        if args.out:
            with open(args.out, "w") as f:
                f.write(report)
    finally:
        if server.poll() is None:
            server.send_signal(signal.SIGTERM)
            try:
                server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                server.kill()
                server.wait()
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    main()
