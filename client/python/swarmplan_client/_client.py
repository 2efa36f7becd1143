"""A typed wrapper of the swarmplan gRPC API (MapService, JobService, AlgorithmService)."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator, Mapping, Sequence, Tuple, Union

import grpc

from ._map_files import read_map_files
from ._proto.swarmplan.v1 import algorithms_pb2, algorithms_pb2_grpc, common_pb2
from ._proto.swarmplan.v1 import jobs_pb2, jobs_pb2_grpc, maps_pb2, maps_pb2_grpc

Point = Tuple[float, ...]  # (x, y) on 2D maps, (x, y, z) on terrain
ParamScalar = Union[bool, int, float, str]
ProgressCallback = Callable[[int, float], Any]


class SwarmplanError(Exception):
    """A failed call: the gRPC status code and the server's message."""

    def __init__(self, code: grpc.StatusCode, message: str) -> None:
        super().__init__("%s: %s" % (code.name, message))
        self.code = code
        self.message = message

    @property
    def code_name(self) -> str:
        """The status code's name, e.g. "INVALID_ARGUMENT"."""
        return self.code.name


def _error(error: grpc.RpcError) -> SwarmplanError:
    code = error.code() if hasattr(error, "code") else grpc.StatusCode.UNKNOWN
    details = error.details() if hasattr(error, "details") else str(error)
    return SwarmplanError(code or grpc.StatusCode.UNKNOWN, details or "")


def _kind_name(kind: int) -> str:
    return common_pb2.MapKind.Name(kind).removeprefix("MAP_KIND_").lower()


def _state_name(state: int) -> str:
    return jobs_pb2.JobState.Name(state).removeprefix("JOB_STATE_")


def _point(value: Sequence[float]) -> common_pb2.Point:
    if len(value) not in (2, 3):
        raise ValueError("a point is (x, y) or (x, y, z), not %r" % (value,))
    return common_pb2.Point(x=value[0], y=value[1], z=value[2] if len(value) == 3 else 0.0)


def _tuple(point: common_pb2.Point, dims: int) -> Point:
    return (point.x, point.y, point.z) if dims == 3 else (point.x, point.y)


def _param(name: str, value: ParamScalar) -> common_pb2.ParamValue:
    if isinstance(value, bool):
        return common_pb2.ParamValue(bool_value=value)
    if isinstance(value, int):
        return common_pb2.ParamValue(int_value=value)
    if isinstance(value, float):
        return common_pb2.ParamValue(double_value=value)
    if isinstance(value, str):
        return common_pb2.ParamValue(string_value=value)
    raise TypeError("parameter %s: expected bool, int, float or str, got %s"
                    % (name, type(value).__name__))


def _param_value(value: common_pb2.ParamValue) -> ParamScalar | None:
    kind = value.WhichOneof("kind")
    return getattr(value, kind) if kind else None


@dataclass(frozen=True)
class MapRecord:
    """A stored map (MapInfo); `created` is False for an idempotent re-upload."""

    id: str
    name: str
    kind: str  # "occupancy_grid", "shape_world" or "terrain"
    width: int
    height: int
    resolution: float
    min: tuple[float, float, float]
    max: tuple[float, float, float]
    obstacle_count: int
    format: str
    content_hash: str
    version: int = 0
    created: bool = False

    @classmethod
    def from_proto(cls, info: maps_pb2.MapInfo, created: bool = False) -> MapRecord:
        return cls(id=info.id, name=info.name, kind=_kind_name(info.kind), width=info.width,
                   height=info.height, resolution=info.resolution,
                   min=(info.min.x, info.min.y, info.min.z),
                   max=(info.max.x, info.max.y, info.max.z),
                   obstacle_count=info.obstacle_count, format=info.format,
                   content_hash=info.content_hash, version=info.version, created=created)


@dataclass(frozen=True)
class Parameter:
    """One planner parameter of an algorithm's schema."""

    name: str
    type: str  # "BOOL", "INT", "DOUBLE" or "ENUM"
    default: ParamScalar | None
    min: float | None
    max: float | None
    choices: list[str]
    unit: str
    description: str


@dataclass(frozen=True)
class Algorithm:
    """A planner the server runs."""

    id: str
    description: str
    encoding: str
    map_kinds: list[str]
    parameters: list[Parameter]

    @classmethod
    def from_proto(cls, algorithm: algorithms_pb2.Algorithm) -> Algorithm:
        parameters = [
            Parameter(name=p.name,
                      type=algorithms_pb2.ParameterType.Name(p.type).removeprefix(
                          "PARAMETER_TYPE_"),
                      default=_param_value(p.default_value),
                      min=p.min if p.HasField("min") else None,
                      max=p.max if p.HasField("max") else None,
                      choices=list(p.choices), unit=p.unit, description=p.description)
            for p in algorithm.parameters]
        return cls(id=algorithm.id, description=algorithm.description,
                   encoding=algorithm.encoding,
                   map_kinds=[_kind_name(k) for k in algorithm.map_kinds],
                   parameters=parameters)


@dataclass(frozen=True)
class PlanResult:
    """A finished job's outcome.

    `path` is the final path (the smoothed one, or the raw one when no smoothing was asked for
    or smoothing lost the clearance), start first and goal last, as (x, y) tuples, or (x, y, z)
    when the start was given with a z. `length` is that path's length. With a vehicle in the
    request (vehicle={"max_speed": ..., "max_acceleration": ...}), `timed_path` holds
    (point, seconds from the start, speed) for every point of `path` and `duration` its total;
    otherwise they are empty and None. `proto` holds the full PlanResult message.
    """

    job_id: str
    state: str  # "SUCCEEDED", "NO_PATH_FOUND", "CANCELLED", "DEADLINE_EXCEEDED", "FAILED"
    found: bool
    path: list[Point]
    raw_path: list[Point]
    length: float
    fitness: float
    collision_free: bool
    seed: int
    iterations: int
    stop_reason: str
    failure_reason: str = ""
    timed_path: list[tuple[Point, float, float]] = field(default_factory=list)
    duration: float | None = None
    proto: jobs_pb2.PlanResult = field(default_factory=jobs_pb2.PlanResult, repr=False)

    @property
    def succeeded(self) -> bool:
        return self.state == "SUCCEEDED"

    @classmethod
    def from_proto(cls, job_id: str, state: int, result: jobs_pb2.PlanResult,
                   failure_reason: str = "", dims: int = 2) -> PlanResult:
        use_smoothed = (result.smoothing not in ("", "none") and
                        result.smoothing_collision_free and len(result.smoothed_path) > 0)
        path = result.smoothed_path if use_smoothed else result.raw_path
        metrics = result.smoothed_metrics if use_smoothed else result.raw_metrics
        return cls(job_id=job_id, state=_state_name(state), found=result.found,
                   path=[_tuple(p, dims) for p in path],
                   raw_path=[_tuple(p, dims) for p in result.raw_path],
                   length=metrics.length, fitness=result.fitness,
                   collision_free=metrics.collision_free, seed=result.seed,
                   iterations=result.iterations, stop_reason=result.stop_reason,
                   failure_reason=failure_reason,
                   timed_path=[(_tuple(p.point, dims), p.time, p.speed)
                               for p in result.timed_path.points],
                   duration=(result.timed_path.duration if result.HasField("timed_path")
                             else None),
                   proto=result)


@dataclass(frozen=True)
class Job:
    """A job's record: state, seed, and the result once finished (else None)."""

    id: str
    state: str
    seed: int
    queue_position: int
    result: PlanResult | None
    failure_reason: str
    proto: jobs_pb2.Job = field(default_factory=jobs_pb2.Job, repr=False)

    @classmethod
    def from_proto(cls, job: jobs_pb2.Job) -> Job:
        dims = 3 if job.request.start.z != 0.0 or job.request.goal.z != 0.0 else 2
        result = (PlanResult.from_proto(job.id, job.state, job.result, job.failure_reason, dims)
                  if job.HasField("result") else None)
        return cls(id=job.id, state=_state_name(job.state), seed=job.seed,
                   queue_position=job.queue_position, result=result,
                   failure_reason=job.failure_reason, proto=job)


class Client:
    """A connection to a swarmplan server; use it as a context manager to close the channel.

    `target` is "host:port". `token` is sent as "authorization: Bearer TOKEN" on every call.
    `credentials` makes a TLS channel; without them the channel is plaintext. `timeout` is the
    deadline of the unary calls in seconds.
    """

    def __init__(self, target: str, token: str | None = None, *,
                 credentials: grpc.ChannelCredentials | None = None,
                 timeout: float = 30.0) -> None:
        self._channel = (grpc.secure_channel(target, credentials) if credentials is not None
                         else grpc.insecure_channel(target))
        token = token.strip() if token else ""
        self._metadata = (("authorization", "Bearer " + token),) if token else ()
        self.timeout = timeout
        self.maps = maps_pb2_grpc.MapServiceStub(self._channel)
        self.jobs = jobs_pb2_grpc.JobServiceStub(self._channel)
        self.algorithms = algorithms_pb2_grpc.AlgorithmServiceStub(self._channel)

    def close(self) -> None:
        self._channel.close()

    def __enter__(self) -> Client:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _call(self, method: Callable[..., Any], request: Any) -> Any:
        try:
            return method(request, timeout=self.timeout, metadata=self._metadata)
        except grpc.RpcError as error:
            raise _error(error) from None

    def upload_map(self, path: str | os.PathLike[str], name: str | None = None, *,
                   format: str | None = None, terrain_height_scale: float | None = None,
                   terrain_ceiling: float | None = None) -> MapRecord:
        """Uploads a map file; the format comes from the extension unless given.

        A ROS .yaml is sent with the image it names. `name` defaults to the file's stem.
        """
        path = os.fspath(path)
        files = read_map_files(path, format)
        if terrain_height_scale is not None:
            files.terrain_height_scale = terrain_height_scale
        if terrain_ceiling is not None:
            files.terrain_ceiling = terrain_ceiling
        if name is None:
            name = os.path.splitext(os.path.basename(path))[0]
        request = maps_pb2.UploadMapRequest(name=name, source=maps_pb2.MapSource(files=files))
        response = self._call(self.maps.UploadMap, request)
        return MapRecord.from_proto(response.map, response.created)

    def get_map(self, map_id: str = "", *, name: str = "", version: int = 0) -> MapRecord:
        """A map version by its id, or by its name and version (0: the latest)."""
        request = maps_pb2.GetMapRequest(id=map_id, name=name, version=version)
        return MapRecord.from_proto(self._call(self.maps.GetMap, request).map)

    def list_map_versions(self, name: str) -> list[MapRecord]:
        """Every stored version of the map `name`, oldest first."""
        versions: list[MapRecord] = []
        request = maps_pb2.ListMapsRequest(name=name)
        while True:
            page = self._call(self.maps.ListMaps, request)
            versions.extend(MapRecord.from_proto(m) for m in page.maps)
            if not page.next_page_token:
                return versions
            request.page_token = page.next_page_token

    def delete_map(self, map_id: str) -> None:
        self._call(self.maps.DeleteMap, maps_pb2.DeleteMapRequest(id=map_id))

    def list_algorithms(self) -> list[Algorithm]:
        response = self._call(self.algorithms.ListAlgorithms,
                              algorithms_pb2.ListAlgorithmsRequest())
        return [Algorithm.from_proto(a) for a in response.algorithms]

    def get_job(self, job_id: str) -> Job:
        return Job.from_proto(self._call(self.jobs.GetJob, jobs_pb2.GetJobRequest(id=job_id)))

    def cancel_job(self, job_id: str) -> Job:
        return Job.from_proto(
            self._call(self.jobs.CancelJob, jobs_pb2.CancelJobRequest(id=job_id)))

    def plan_request(self, map_id: str, start: Sequence[float], goal: Sequence[float],
                     algorithm: str = "astar", params: Mapping[str, ParamScalar] | None = None,
                     seed: int | None = None, **fields: Any) -> jobs_pb2.PlanRequest:
        """Builds a PlanRequest (see plan() for the arguments)."""
        limits = jobs_pb2.JobLimits()
        if "max_iterations" in fields:
            limits.max_iterations = fields.pop("max_iterations")
        if "time_budget" in fields:
            limits.time_budget.FromNanoseconds(round(fields.pop("time_budget") * 1e9))
        progress = jobs_pb2.ProgressOptions()
        if "progress_every" in fields:
            progress.every_iterations = fields.pop("progress_every")
        try:
            request = jobs_pb2.PlanRequest(**fields)
        except ValueError as error:
            raise TypeError("plan(): %s" % error) from None
        request.map_id = map_id
        request.start.CopyFrom(_point(start))
        request.goal.CopyFrom(_point(goal))
        request.algorithm = algorithm
        if seed is not None:
            request.seed = seed
        for name, value in (params or {}).items():
            request.parameters[name].CopyFrom(_param(name, value))
        request.limits.MergeFrom(limits)
        request.progress.MergeFrom(progress)
        return request

    def plan(self, map_id: str, start: Sequence[float], goal: Sequence[float],
             algorithm: str = "astar", params: Mapping[str, ParamScalar] | None = None,
             seed: int | None = None, on_progress: ProgressCallback | None = None,
             timeout: float | None = None, **fields: Any) -> PlanResult:
        """Streams Plan until the job finishes and returns its result.

        `params` are planner parameters by name. `on_progress(iteration, best_fitness)` is
        called per progress event. Other PlanRequest fields go as keywords (clearance=,
        smoothing=, labels=, preferences=, vehicle=, alternatives=, detached=,
        client_request_id=, limits=, progress=), plus max_iterations=, time_budget= (seconds) and
        progress_every= (iterations). `timeout` bounds the whole stream in seconds.
        Raises SwarmplanError on a failed call.
        """
        request = self.plan_request(map_id, start, goal, algorithm, params, seed, **fields)
        dims = 3 if len(start) == 3 else 2
        stream = self.jobs.Plan(request, timeout=timeout, metadata=self._metadata)
        finished = None
        job_id = ""
        try:
            for event in _events(stream):
                job_id = event.job_id or job_id
                kind = event.WhichOneof("event")
                if kind == "progress" and on_progress is not None:
                    on_progress(event.progress.iteration, event.progress.best_fitness)
                elif kind == "finished":
                    finished = event.finished
        finally:
            if finished is None:
                stream.cancel()
        if finished is None:
            raise SwarmplanError(grpc.StatusCode.UNKNOWN,
                                 "the Plan stream of job %s ended without a result" % job_id)
        return PlanResult.from_proto(job_id, finished.state, finished.result,
                                     finished.failure_reason, dims)


def _events(stream: Iterator[jobs_pb2.JobEvent]) -> Iterator[jobs_pb2.JobEvent]:
    try:
        yield from stream
    except grpc.RpcError as error:
        raise _error(error) from None
