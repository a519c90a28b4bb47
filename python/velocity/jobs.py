"""Batch jobs: what to render, and how results reach the output folder. The one
implementation of the job format, the manifest and atomic writes, shared by the local
runner (velocity.batch) and the Dask runner (velocity.dask_runner).

A job is a JSON file (docs/python.md#batch-job-format):

    {"models": ["meshes/*.obj", "duck.asc"],       paths or globs, relative to the job file
     "output": "renders",                          (optional; the command line's --out wins)
     "size": [256, 256],
     "camera": {"type": "perspective", "yfov_deg": 45},      or intrinsics / orthographic
     "views": {"type": "orbit", "count": 24, "elevation_deg": [15, 45]},
                                                   or poses / animation
     "outputs": ["color", "depth", "mask"],        any of color, depth, mask, normals
     "chunk": 0}                                   views per task (0: a model's views in one)

Output folder:

    <out>/<model>/<view>.color.png   .depth.npy   .mask.png   .normals.npy
    <out>/manifest.json              what is done: every model's status, error, views, cameras
    <out>/.velocity/tasks/<task>.json  one record per task, written by whoever ran it
    <out>/.velocity/tmp/             files being written (then renamed into place)

Every file is written to .velocity/tmp and renamed into place (atomic on one file
system), so a file that exists is whole. A task's record says "running" (with the hash
of everything its output depends on) while it works, then "done" or "failed"; a task
that runs again with the same hash skips the views whose files all exist, so a killed
task resumes where it stopped. No two processes ever write the same record or file
except a task run twice, which writes the same bytes.
"""
from __future__ import annotations

import dataclasses
import glob
import hashlib
import json
import math
import os
import socket
import threading
import time
import uuid
from typing import Any, Callable, Iterable

import numpy as np

JOB_VERSION = 1
OUTPUTS = ("color", "depth", "mask", "normals")
_SUFFIX = {"color": "color.png", "depth": "depth.npy", "mask": "mask.png", "normals": "normals.npy"}


class JobError(ValueError):
    """A job that cannot run: the message names the key and what was expected."""


# ---------------------------------------------------------------------------- parsing

def _number(spec: dict, key: str, default: Any, where: str, lo: float | None = None, hi: float | None = None,
            integer: bool = False) -> Any:
    v = spec.get(key, default)
    if v is None:
        return None
    if isinstance(v, bool) or not isinstance(v, (int, float)) or (integer and not isinstance(v, int)):
        raise JobError(f"{where}.{key}: expected {'an integer' if integer else 'a number'}, got {v!r}")
    if not math.isfinite(v) or (lo is not None and v < lo) or (hi is not None and v > hi):
        raise JobError(f"{where}.{key}: expected a finite number in [{lo}, {hi}], got {v!r}")
    return v


def _vector(v: Any, n: int, where: str) -> list[float]:
    if not isinstance(v, (list, tuple)) or len(v) != n or not all(
            isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in v):
        raise JobError(f"{where}: expected {n} finite numbers, got {v!r}")
    return [float(x) for x in v]


def _matrix(v: Any, where: str) -> list[list[float]]:
    if not isinstance(v, (list, tuple)) or len(v) != 4:
        raise JobError(f"{where}: expected a 4x4 matrix (4 rows of 4 numbers), got {v!r}"[:300])
    m = [_vector(row, 4, f"{where}[{i}]") for i, row in enumerate(v)]
    if m[3] != [0.0, 0.0, 0.0, 1.0]:
        raise JobError(f"{where}: the last row must be [0, 0, 0, 1]")
    return m


def _check_keys(spec: dict, allowed: Iterable[str], where: str) -> None:
    if not isinstance(spec, dict):
        raise JobError(f"{where}: expected an object, got {spec!r}"[:300])
    unknown = sorted(set(spec) - set(allowed))
    if unknown:
        raise JobError(f"{where}: unknown key {unknown[0]!r} (expected one of: {', '.join(sorted(allowed))})")


def _parse_camera(spec: Any) -> dict:
    where = "camera"
    spec = {"type": "perspective"} if spec is None else spec
    _check_keys(spec, ("type", "yfov_deg", "fx", "fy", "cx", "cy", "xmag", "ymag", "znear", "zfar"), where)
    kind = spec.get("type", "perspective")
    out: dict[str, Any] = {"type": kind, "znear": _number(spec, "znear", None, where, 1e-9),
                           "zfar": _number(spec, "zfar", None, where, 1e-9)}
    if kind == "perspective":
        out["yfov_deg"] = _number(spec, "yfov_deg", 45.0, where, 0.01, 179.0)
    elif kind == "intrinsics":
        for k in ("fx", "fy", "cx", "cy"):
            if k not in spec:
                raise JobError(f"camera.{k}: required for an intrinsics camera")
            out[k] = _number(spec, k, None, where, 1e-9 if k in ("fx", "fy") else None)
    elif kind == "orthographic":
        out["xmag"] = _number(spec, "xmag", None, where, 1e-9)
        out["ymag"] = _number(spec, "ymag", None, where, 1e-9)
    else:
        raise JobError(f"camera.type: expected perspective, intrinsics or orthographic, got {kind!r}")
    return out


def _parse_views(spec: Any) -> dict:
    where = "views"
    if spec is None:
        spec = {"type": "orbit"}
    _check_keys(spec, ("type", "count", "elevation_deg", "distance", "poses", "convention", "frames", "keyframes",
                       "camera_pose"), where)
    kind = spec.get("type", "orbit")
    if kind == "orbit":
        count = _number(spec, "count", 12, where, 1, 1_000_000, integer=True)
        elev = spec.get("elevation_deg", 20.0)
        elev = [elev] if isinstance(elev, (int, float)) and not isinstance(elev, bool) else elev
        if not isinstance(elev, list) or not elev:
            raise JobError(f"views.elevation_deg: expected a number or a list of numbers, got {elev!r}")
        elev = [float(_number({"e": e}, "e", None, "views.elevation_deg", -89.999, 89.999)) for e in elev]
        distance = _number(spec, "distance", None, where, 1e-6)
        return {"type": "orbit", "count": count, "elevation_deg": elev, "distance": distance}
    if kind == "poses":
        poses = spec.get("poses")
        if not isinstance(poses, list) or not poses:
            raise JobError("views.poses: expected a non-empty list of 4x4 camera poses")
        convention = spec.get("convention", "opengl")
        if convention not in ("opengl", "opencv"):
            raise JobError(f"views.convention: expected opengl or opencv, got {convention!r}")
        return {"type": "poses", "convention": convention,
                "poses": [_matrix(p, f"views.poses[{i}]") for i, p in enumerate(poses)]}
    if kind == "animation":
        frames = _number(spec, "frames", None, where, 1, 1_000_000, integer=True)
        if frames is None:
            raise JobError("views.frames: required for an animation")
        keys = spec.get("keyframes")
        if not isinstance(keys, list) or not keys:
            raise JobError("views.keyframes: expected a non-empty list of {frame, rotation_deg, translation, scale}")
        parsed = []
        for i, k in enumerate(keys):
            w = f"views.keyframes[{i}]"
            _check_keys(k, ("frame", "rotation_deg", "translation", "scale"), w)
            f = _number(k, "frame", None, w, 0, frames - 1, integer=True)
            if f is None:
                raise JobError(f"{w}.frame: required")
            parsed.append({"frame": f, "rotation_deg": _vector(k.get("rotation_deg", [0, 0, 0]), 3, f"{w}.rotation_deg"),
                           "translation": _vector(k.get("translation", [0, 0, 0]), 3, f"{w}.translation"),
                           "scale": float(_number(k, "scale", 1.0, w, 1e-9))})
        parsed.sort(key=lambda k: k["frame"])
        if len({k["frame"] for k in parsed}) != len(parsed):
            raise JobError("views.keyframes: two keyframes at the same frame")
        pose = spec.get("camera_pose")
        return {"type": "animation", "frames": frames, "keyframes": parsed,
                "camera_pose": None if pose is None else _matrix(pose, "views.camera_pose"),
                "distance": _number(spec, "distance", None, where, 1e-6)}
    raise JobError(f"views.type: expected orbit, poses or animation, got {kind!r}")


def _parse_light(spec: Any) -> dict:
    spec = {"type": "headlight"} if spec is None else spec
    _check_keys(spec, ("type", "intensity", "direction", "color"), "light")
    kind = spec.get("type", "headlight")
    if kind not in ("headlight", "directional", "none"):
        raise JobError(f"light.type: expected headlight, directional or none, got {kind!r}")
    out = {"type": kind, "intensity": float(_number(spec, "intensity", 2.5, "light", 0.0)),
           "color": _vector(spec.get("color", [1, 1, 1]), 3, "light.color")}
    if kind == "directional":
        out["direction"] = _vector(spec.get("direction", [0.3, 0.5, 1.0]), 3, "light.direction")
        if not any(out["direction"]):
            raise JobError("light.direction: must not be zero")
    return out


@dataclasses.dataclass(frozen=True)
class Task:
    """One unit of work: views [start, stop) of one model."""
    id: str
    model: str
    model_key: str
    start: int
    stop: int
    hash: str


@dataclasses.dataclass
class Job:
    """A parsed, checked job. Picklable: the Dask runner sends it to workers as it is."""
    spec: dict                      # normalised: every default filled in
    output: str                     # absolute path
    models: list[tuple[str, str]]   # (key, absolute path), in the job's order

    # ---- views
    def view_count(self) -> int:
        v = self.spec["views"]
        if v["type"] == "orbit":
            return v["count"] * len(v["elevation_deg"])
        if v["type"] == "poses":
            return len(v["poses"])
        return v["frames"]

    def tasks(self) -> list[Task]:
        n, chunk = self.view_count(), self.spec["chunk"] or self.view_count()
        settings = json.dumps({k: self.spec[k] for k in sorted(self.spec) if k not in ("models", "output", "chunk")},
                              sort_keys=True)
        out = []
        for key, path in self.models:
            try:
                st = os.stat(path)
                stamp = f"{st.st_size}:{st.st_mtime_ns}"
            except OSError:
                stamp = "missing"
            for start in range(0, n, chunk):
                stop = min(n, start + chunk)
                h = hashlib.sha1(f"{path}\n{stamp}\n{start}:{stop}\n{settings}".encode()).hexdigest()
                tid = key if chunk >= n else f"{key}.{start:06d}-{stop:06d}"
                out.append(Task(tid, path, key, start, stop, h))
        return out

    # ---- paths
    @property
    def state_dir(self) -> str:
        return os.path.join(self.output, ".velocity")

    @property
    def tmp_dir(self) -> str:
        return os.path.join(self.state_dir, "tmp")

    def record_path(self, task_id: str) -> str:
        return os.path.join(self.state_dir, "tasks", task_id + ".json")

    def view_names(self, model_key: str, view: int) -> dict[str, str]:
        """A view's files, relative to the output folder (as the manifest lists them)."""
        return {o: f"{model_key}/{view:06d}.{_SUFFIX[o]}" for o in self.spec["outputs"]}

    def view_files(self, model_key: str, view: int) -> dict[str, str]:
        return {o: os.path.join(self.output, name) for o, name in self.view_names(model_key, view).items()}


def load_job(source: str | dict, output: str | None = None) -> Job:
    """Parses and checks a job (a JSON file's path, or the dict itself). Relative model
    paths and globs are taken from the job file's folder (the current one for a dict);
    `output` overrides the job's own. Raises JobError naming what is wrong."""
    if isinstance(source, dict):
        spec, base = source, os.getcwd()
    else:
        try:
            with open(source, encoding="utf-8") as f:
                spec = json.load(f)
        except OSError as e:
            raise JobError(f"{source}: cannot read the job file: {e.strerror}") from None
        except json.JSONDecodeError as e:
            raise JobError(f"{source}:{e.lineno}:{e.colno}: not valid JSON: {e.msg}") from None
        base = os.path.dirname(os.path.abspath(source))
    _check_keys(spec, ("version", "models", "output", "size", "camera", "views", "outputs", "alpha", "bg_color",
                       "ambient_light", "light", "ssaa", "chunk", "normalize", "shading"), "job")
    version = spec.get("version", JOB_VERSION)
    if version != JOB_VERSION:
        raise JobError(f"job.version: this Velocity reads version {JOB_VERSION}, got {version!r}")
    models_spec = spec.get("models")
    if isinstance(models_spec, str):
        models_spec = [models_spec]
    if not isinstance(models_spec, list) or not models_spec or not all(isinstance(m, str) and m for m in models_spec):
        raise JobError("job.models: expected a non-empty list of model paths or globs")
    paths: list[str] = []
    for m in models_spec:
        p = m if os.path.isabs(m) else os.path.join(base, m)
        if glob.has_magic(m):
            found = sorted(glob.glob(p, recursive=True))
            if not found:
                raise JobError(f"job.models: {m!r} matches no file")
            paths += [os.path.abspath(f) for f in found]
        else:
            paths.append(os.path.abspath(p))  # a missing file is the task's failure, not the job's
    paths = list(dict.fromkeys(paths))
    # Output folder per model: the file's stem, with a hash of the path when two share it.
    stems: dict[str, int] = {}
    for p in paths:
        stem = _safe(os.path.splitext(os.path.basename(p))[0])
        stems[stem] = stems.get(stem, 0) + 1
    models = []
    for p in paths:
        stem = _safe(os.path.splitext(os.path.basename(p))[0])
        models.append((stem if stems[stem] == 1 else f"{stem}-{hashlib.sha1(p.encode()).hexdigest()[:8]}", p))

    size = spec.get("size", [256, 256])
    if not (isinstance(size, list) and len(size) == 2 and all(isinstance(s, int) and not isinstance(s, bool)
                                                            and 1 <= s <= 16384 for s in size)):
        raise JobError(f"job.size: expected [width, height], each 1..16384, got {size!r}")
    outputs = spec.get("outputs", ["color", "depth", "mask"])
    if not isinstance(outputs, list) or not outputs or any(o not in OUTPUTS for o in outputs) or \
            len(set(outputs)) != len(outputs):
        raise JobError(f"job.outputs: expected a list of distinct names among {', '.join(OUTPUTS)}, got {outputs!r}")
    shading = spec.get("shading")
    if shading not in (None, "flat", "gouraud", "phong"):
        raise JobError(f"job.shading: expected flat, gouraud or phong, got {shading!r}")
    normalized = {
        "version": JOB_VERSION,
        "models": [p for _, p in models],
        "size": size,
        "camera": _parse_camera(spec.get("camera")),
        "views": _parse_views(spec.get("views")),
        "outputs": outputs,
        "alpha": bool(spec.get("alpha", False)),
        "bg_color": _vector(spec.get("bg_color", [1, 1, 1, 1]), 4, "job.bg_color"),
        "ambient_light": _vector(spec.get("ambient_light", [0.2, 0.2, 0.2]), 3, "job.ambient_light"),
        "light": _parse_light(spec.get("light")),
        "ssaa": _number(spec, "ssaa", 1, "job", 1, 4, integer=True),
        "chunk": _number(spec, "chunk", 0, "job", 0, 1_000_000, integer=True),
        "normalize": bool(spec.get("normalize", False)),
        "shading": shading,
    }
    out = output or spec.get("output")
    if not out or not isinstance(out, str):
        raise JobError("job.output: no output folder (give one in the job or with --out)")
    out = out if os.path.isabs(out) or output else os.path.join(base, out)
    return Job(normalized, os.path.abspath(out), models)


def _safe(name: str) -> str:
    s = "".join(c if c.isalnum() or c in "-_." else "_" for c in name).strip(".")
    return s or "model"


# ---------------------------------------------------------------------------- writes

def atomic_write(job: Job, path: str, write: Callable[[Any], None]) -> None:
    """Writes a file whole or not at all: `write(f)` fills a temporary file in the job's
    tmp folder (same file system), which then replaces `path` in one rename."""
    os.makedirs(job.tmp_dir, exist_ok=True)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = os.path.join(job.tmp_dir, f"{uuid.uuid4().hex}.{os.path.basename(path)}")
    try:
        with open(tmp, "wb") as f:
            write(f)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_json(job: Job, path: str, data: Any) -> None:
    # Compact: the json module's C encoder runs only without indent (10x faster).
    atomic_write(job, path, lambda f: f.write(json.dumps(data, sort_keys=True, separators=(",", ":")).encode()))


def read_record(job: Job, task_id: str) -> dict | None:
    try:
        with open(job.record_path(task_id), encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


# ---------------------------------------------------------------------------- cameras

def _rotation(deg: list[float]) -> np.ndarray:
    """The engine's Transform order: Ry(yaw) Rx(pitch) Rz(roll), angles (x, y, z) in degrees."""
    x, y, z = (math.radians(a) for a in deg)
    rx = np.array([[1, 0, 0], [0, math.cos(x), -math.sin(x)], [0, math.sin(x), math.cos(x)]])
    ry = np.array([[math.cos(y), 0, math.sin(y)], [0, 1, 0], [-math.sin(y), 0, math.cos(y)]])
    rz = np.array([[math.cos(z), -math.sin(z), 0], [math.sin(z), math.cos(z), 0], [0, 0, 1]])
    return ry @ rx @ rz


def _half_fov(job: Job) -> float:
    """The smaller half field of view (radians) of a perspective or intrinsics camera."""
    cam, (w, h) = job.spec["camera"], job.spec["size"]
    if cam["type"] == "perspective":
        t = math.tan(math.radians(cam["yfov_deg"]) / 2)
        return math.atan(t * min(1.0, w / h))
    return min(math.atan(min(cam["cx"], w - cam["cx"]) / cam["fx"]), math.atan(min(cam["cy"], h - cam["cy"]) / cam["fy"]))


def view_setup(job: Job, view: int, center: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """(camera pose, model pose) for `view`, both 4x4 in the OpenGL convention, for a
    model whose bounding sphere (after any normalisation) is (center, radius)."""
    import velocity
    v = job.spec["views"]
    model_pose = np.eye(4)
    radius = radius if radius > 0 else 1.0
    if job.spec["camera"]["type"] == "orthographic":
        fit = 1.1 * radius * 3  # any distance outside the sphere sees the same picture
    else:
        fit = 1.05 * radius / math.sin(max(1e-3, _half_fov(job)))
    if v["type"] == "orbit":
        per_ring = v["count"]
        elev = math.radians(v["elevation_deg"][view // per_ring])
        azim = 2 * math.pi * (view % per_ring) / per_ring
        d = v["distance"] * radius if v["distance"] else fit
        eye = center + d * np.array([math.cos(elev) * math.sin(azim), math.sin(elev), math.cos(elev) * math.cos(azim)])
        return velocity.look_at(eye, center), model_pose
    if v["type"] == "poses":
        pose = np.array(v["poses"][view], dtype=np.float64)
        return (velocity.opencv_to_opengl_pose(pose) if v["convention"] == "opencv" else pose), model_pose
    # Animation: keyframes interpolated linearly (rotation angles too, so spins of more
    # than half a turn come out as written); before the first and after the last, held.
    keys = v["keyframes"]
    a = max([k for k in keys if k["frame"] <= view], key=lambda k: k["frame"], default=keys[0])
    b = min([k for k in keys if k["frame"] >= view], key=lambda k: k["frame"], default=keys[-1])
    t = 0.0 if a["frame"] == b["frame"] else (view - a["frame"]) / (b["frame"] - a["frame"])
    mix = lambda p, q: [(1 - t) * x + t * y for x, y in zip(p, q)]  # noqa: E731
    rot = _rotation(mix(a["rotation_deg"], b["rotation_deg"]))
    scale = (1 - t) * a["scale"] + t * b["scale"]
    model_pose[:3, :3] = rot * scale
    # Turn and scale about the model's centre, then move.
    model_pose[:3, 3] = center - model_pose[:3, :3] @ center + np.array(mix(a["translation"], b["translation"]))
    if v["camera_pose"] is not None:
        return np.array(v["camera_pose"], dtype=np.float64), model_pose
    d = v["distance"] * radius if v["distance"] else fit
    return velocity.look_at(center + np.array([0.0, 0.0, d]), center), model_pose


# ---------------------------------------------------------------------------- one task

_local = threading.local()


def _renderer(job: Job, threads: int):
    """One renderer per thread and settings, kept between tasks (its thread pool too)."""
    import velocity
    key = (tuple(job.spec["size"]), job.spec["ssaa"], threads)
    cache = getattr(_local, "renderers", None)
    if cache is None:
        cache = _local.renderers = {}
    if key not in cache:
        cache[key] = velocity.OffscreenRenderer(*job.spec["size"], ssaa=job.spec["ssaa"], threads=threads)
    return cache[key]


def _camera(job: Job, dist: float, radius: float):
    import velocity
    c = job.spec["camera"]
    near = c["znear"] or max(dist - 1.05 * radius, 1e-3 * max(dist, radius))
    far = c["zfar"] or max(dist + 1.05 * radius, near * 2)
    if c["type"] == "perspective":
        return velocity.PerspectiveCamera(math.radians(c["yfov_deg"]), znear=near, zfar=far)
    if c["type"] == "intrinsics":
        return velocity.IntrinsicsCamera(c["fx"], c["fy"], c["cx"], c["cy"], znear=near, zfar=far)
    w, h = job.spec["size"]
    xmag = c["xmag"] or 1.05 * radius * max(1.0, w / h)
    ymag = c["ymag"] or 1.05 * radius * max(1.0, h / w)
    return velocity.OrthographicCamera(xmag, ymag, znear=near, zfar=far)


def _failure(e: BaseException) -> str:
    import velocity
    return str(e) if isinstance(e, velocity.Error) else f"{type(e).__name__}: {e}"


def task_record(task: Task, status: str, **fields: Any) -> dict[str, Any]:
    """A task's record: which task, model and views, the hash its output depends on,
    its status ("running", "done" or "failed"), and `fields`."""
    return {"task": task.id, "model": task.model, "model_key": task.model_key, "hash": task.hash,
            "views": [task.start, task.stop], "status": status, **fields}


def run_task(job: Job, task: Task, threads: int = 1, hooks: dict | None = None) -> dict:
    """Renders one task's views and returns its record (also written to the task's
    record file). A model that cannot be loaded or rendered gives a "failed" record
    with the engine's message; nothing else stops. Safe to run again: views whose
    files exist from a run with the same hash are skipped."""
    import velocity
    from .png import encode_png
    started = time.time()
    prev = read_record(job, task.id)
    same = prev is not None and prev.get("hash") == task.hash
    if same and prev.get("status") == "done" and all(
            os.path.exists(p) for v in range(task.start, task.stop) for p in job.view_files(task.model_key, v).values()):
        return prev
    record = task_record(task, "running", worker=f"{socket.gethostname()}:{os.getpid()}")
    write_json(job, job.record_path(task.id), record)
    cameras: dict[str, Any] = {}
    try:
        mesh = velocity.Mesh.from_file(task.model)
        center, radius = mesh.bounding_sphere
        center = np.array(center, dtype=np.float64)
        base = np.eye(4)
        if job.spec["normalize"]:
            s = 1.0 / radius if radius > 0 else 1.0
            base[:3, :3] *= s
            base[:3, 3] = -s * center
            center, radius = np.zeros(3), 1.0
        s = job.spec
        scene = velocity.Scene(bg_color=s["bg_color"], ambient_light=s["ambient_light"])
        model_node = scene.add(mesh, name=task.model_key, pose=base)
        cam_node = scene.add(_camera(job, 1.0, radius), pose=np.eye(4))
        light_node = None
        light = s["light"]
        if light["type"] != "none":
            light_node = scene.add(velocity.DirectionalLight(color=light["color"], intensity=light["intensity"]))
        flags = velocity.RenderFlags.NONE
        if s["alpha"]:
            flags |= velocity.RenderFlags.RGBA
        if "mask" in s["outputs"]:
            flags |= velocity.RenderFlags.SEG
        if "normals" in s["outputs"]:
            flags |= velocity.RenderFlags.NORMALS
        if s["shading"] == "flat":
            flags |= velocity.RenderFlags.FLAT
        renderer = _renderer(job, threads)
        for view in range(task.start, task.stop):
            files = job.view_files(task.model_key, view)
            cam_pose, model_pose = view_setup(job, view, center, radius)
            dist = float(np.linalg.norm(cam_pose[:3, 3] - (model_pose[:3, :3] @ center + model_pose[:3, 3])))
            camera = _camera(job, dist, radius)
            cameras[str(view)] = {"camera_pose": cam_pose.tolist(), "model_pose": (model_pose @ base).tolist(),
                                  "projection": camera.get_projection_matrix(*s["size"]).tolist()}
            if same and all(os.path.exists(p) for p in files.values()):
                continue  # done by an earlier run of this task
            scene.remove_node(cam_node)
            cam_node = scene.add(camera, pose=cam_pose)
            scene.set_pose(model_node, model_pose @ base)
            if light_node is not None:
                if light["type"] == "headlight":
                    scene.set_pose(light_node, cam_pose)
                else:
                    scene.set_pose(light_node, velocity.look_at([0, 0, 0], -np.array(light["direction"])))
            out = renderer.render(scene, flags)
            color, depth, rest = out[0], out[1], list(out[2:])
            mask = rest.pop(0) if "mask" in s["outputs"] else None
            normals = rest.pop(0) if "normals" in s["outputs"] else None
            if hooks and "before_view" in hooks:
                hooks["before_view"](job, task, view)
            for kind, path in files.items():
                if kind == "color":
                    atomic_write(job, path, lambda f: f.write(encode_png(color)))
                elif kind == "depth":
                    atomic_write(job, path, lambda f: np.save(f, depth))
                elif kind == "mask":
                    atomic_write(job, path, lambda f: f.write(encode_png(mask.astype(np.uint16))))
                else:
                    atomic_write(job, path, lambda f: np.save(f, normals))
        record.update(status="done", cameras=cameras)
    except Exception as e:  # a bad model: reported, never fatal to the job
        record.update(status="failed", error=_failure(e))
    record["seconds"] = round(time.time() - started, 3)
    write_json(job, job.record_path(task.id), record)
    return record


# ---------------------------------------------------------------------------- the run

class Run:
    """One runner's pass over a job: the lock on the output folder, what is left to do,
    progress, and the manifest. Used by both runners:

        with Run(job) as run:
            for task in run.todo: ...; run.finished(record)
    """

    def __init__(self, job: Job, progress: "Progress | None" = None) -> None:
        self.job, self.progress = job, progress
        self.tasks = job.tasks()
        self.records: dict[str, dict] = {}
        self._lock_file = None
        self._last_manifest = 0.0

    def __enter__(self) -> "Run":
        import fcntl
        os.makedirs(os.path.join(self.job.state_dir, "tasks"), exist_ok=True)
        self._lock_file = open(os.path.join(self.job.state_dir, "lock"), "w")
        try:
            fcntl.flock(self._lock_file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            self._lock_file.close()
            raise JobError(f"{self.job.output}: another velocity batch run is using this folder") from None
        self._sweep()
        self.todo = []
        for t in self.tasks:
            rec = read_record(self.job, t.id)
            if rec and rec.get("hash") == t.hash and rec.get("status") == "done" and all(
                    os.path.exists(p) for v in range(t.start, t.stop) for p in self.job.view_files(t.model_key, v).values()):
                self.records[t.id] = rec
            else:
                self.todo.append(t)
        if self.progress:
            self.progress.start(sum(t.stop - t.start for t in self.tasks),
                                sum(t.stop - t.start for t in self.tasks if t.id in self.records))
        return self

    def finished(self, record: dict) -> None:
        self.records[record["task"]] = record
        if self.progress:
            a, b = record["views"]
            self.progress.advance(b - a, failed=record["status"] != "done")
        if time.time() - self._last_manifest > 2.0:
            self.write_manifest()

    def _sweep(self) -> None:
        """Removes half-written files left by killed processes (this run holds the lock)."""
        try:
            names = os.listdir(self.job.tmp_dir)
        except OSError:
            return
        for n in names:
            try:
                os.unlink(os.path.join(self.job.tmp_dir, n))
            except OSError:
                pass

    def write_manifest(self) -> dict:
        self._last_manifest = time.time()
        models: dict[str, Any] = {}
        total = done = 0
        for t in self.tasks:
            m = models.setdefault(t.model_key, {"model": t.model, "status": "pending", "views": {}, "errors": []})
            rec = self.records.get(t.id)
            total += t.stop - t.start
            if rec is None:
                continue
            if rec["status"] == "done":
                done += t.stop - t.start
                for v, cam in rec.get("cameras", {}).items():
                    m["views"][v] = dict(cam, files=self.job.view_names(t.model_key, int(v)))
            else:
                m["errors"].append(f"views {t.start}..{t.stop - 1}: {rec.get('error', 'unknown error')}")
        failed = []
        for key, m in models.items():
            parts = [r["status"] for t in self.tasks if t.model_key == key for r in [self.records.get(t.id)] if r]
            n_tasks = sum(1 for t in self.tasks if t.model_key == key)
            m["status"] = "failed" if "failed" in parts else "done" if parts.count("done") == n_tasks else "pending"
            if m["status"] == "failed":
                failed.append(key)
        manifest = {"version": JOB_VERSION, "job": self.job.spec, "views_total": total, "views_done": done,
                    "models_failed": failed, "complete": done == total, "models": models}
        write_json(self.job, os.path.join(self.job.output, "manifest.json"), manifest)
        return manifest

    def __exit__(self, *exc: Any) -> None:
        self.manifest = self.write_manifest()
        self._sweep()
        if self.progress:
            self.progress.close()
        if self._lock_file:
            self._lock_file.close()


class Progress:
    """A progress bar with the rate and ETA on a terminal (stderr); silent otherwise."""

    def __init__(self, enabled: bool | None = None, stream: Any = None) -> None:
        import sys
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.total = self.done = self.skipped = self.failed = 0
        self.t0 = time.time()
        self._last = 0.0

    def start(self, total: int, already: int) -> None:
        self.total, self.done, self.skipped, self.t0 = total, already, already, time.time()
        self._draw(force=True)

    def advance(self, views: int, failed: bool = False) -> None:
        self.done += views
        self.failed += views if failed else 0
        self._draw()

    def _draw(self, force: bool = False) -> None:
        if not self.enabled or (not force and time.time() - self._last < 0.1 and self.done < self.total):
            return
        self._last = time.time()
        new, elapsed = self.done - self.skipped, time.time() - self.t0
        rate = new / elapsed if elapsed > 0 else 0.0
        left = self.total - self.done
        eta = f"{int(left / rate) // 60}:{int(left / rate) % 60:02d}" if rate > 0 else "?"
        width = 30
        filled = int(width * self.done / self.total) if self.total else width
        fail = f"  {self.failed} failed" if self.failed else ""
        self.stream.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} views"
                          f"  {rate:.1f}/s  ETA {eta}{fail} ")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled:
            self._draw(force=True)
            self.stream.write("\n")
            self.stream.flush()
