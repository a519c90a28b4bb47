"""The job file: what to render. Parses and checks a job (a JSON file or a dict) into a
Job, the one implementation of the format (docs/python.md#batch-job-format), and says
where the job's files go in its output folder. The rest of the batch runner:
velocity.tasks (the job cut into tasks), velocity.views (each view's camera),
velocity.render_task (one task run), velocity.records and velocity.run (what is done,
the manifest), velocity.progress, velocity.atomic (whole-file writes).

A job is a JSON file:

    {"models": ["meshes/*.obj", "duck.asc"],       paths or globs, relative to the job file
     "output": "renders",                          (optional; the command line's --out wins)
     "size": [256, 256],
     "camera": {"type": "perspective", "yfov_deg": 45},      or intrinsics / orthographic
     "views": {"type": "orbit", "count": 24, "elevation_deg": [15, 45]},
                                                   or poses / animation
     "outputs": ["color", "depth", "mask"],        any of color, depth, mask, normals
     "chunk": 0,                                   views per task (0: a model's views in one)
     "backend": "cpu",                             cpu, gpu or auto (each worker's renderer)
     "color": "auto", "tone_map": "none", "exposure": 1.0, "shadows": false,
     "shadow_map_size": 2048, "point_size": 1.0}   the appearance options (docs/appearance.md)

Output folder:

    <out>/<model>/<view>.color.png   .depth.npy   .mask.png   .normals.npy
    <out>/manifest.json              what is done: every model's status, error, views, cameras
    <out>/.velocity/tasks/<task>.json  one record per task, written by whoever ran it
    <out>/.velocity/tmp/             files being written (then renamed into place)
"""
from __future__ import annotations

import dataclasses
import fnmatch
import glob
import hashlib
import json
import math
import os
import stat
from typing import Any, Iterable

JOB_VERSION = 1
MAX_JOB_BYTES = 16 << 20       # a job file larger than this is refused (it is JSON text)
MAX_VIEWS = 10_000_000         # views in one job (models x views per model)
MAX_MODELS = 1_000_000         # files a job's globs may match
OUTPUTS = ("color", "depth", "mask", "normals")
BACKENDS = ("cpu", "gpu", "auto")
# The renderer's appearance options (velocity.OffscreenRenderer's keywords) and their
# defaults; a job that sets none renders (and hashes) as before they existed.
APPEARANCE = {"color": "auto", "tone_map": "none", "exposure": 1.0, "shadows": False, "shadow_map_size": 2048,
              "point_size": 1.0}
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


def _choice(spec: dict, key: str, default: str, choices: Iterable[str]) -> str:
    v = spec.get(key, default)
    if v not in choices:
        raise JobError(f"job.{key}: expected {', '.join(choices)}, got {v!r}"[:300])
    return v


def _parse_appearance(spec: dict) -> dict:
    shadows = spec.get("shadows", False)
    if not isinstance(shadows, bool):
        raise JobError(f"job.shadows: expected true or false, got {shadows!r}"[:300])
    return {"color": _choice(spec, "color", "auto", ("auto", "linear", "display")),
            "tone_map": _choice(spec, "tone_map", "none", ("none", "aces", "neutral")),
            "exposure": float(_number(spec, "exposure", 1.0, "job", 0.0, 1e30)),
            "shadows": shadows,
            "shadow_map_size": _number(spec, "shadow_map_size", 2048, "job", 16, 8192, integer=True),
            "point_size": float(_number(spec, "point_size", 1.0, "job", 1.0, 64.0))}


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


@dataclasses.dataclass
class Job:
    """A parsed, checked job. Picklable: the Dask runner sends it to workers as it is."""
    spec: dict                      # normalised: every default filled in
    output: str                     # absolute path
    models: list[tuple[str, str]]   # (key, absolute path), in the job's order
    source: str = ""                # what makes it this job: the job file's path (or its models)

    def view_count(self) -> int:
        v = self.spec["views"]
        if v["type"] == "orbit":
            return v["count"] * len(v["elevation_deg"])
        if v["type"] == "poses":
            return len(v["poses"])
        return v["frames"]

    # ---- where its files go
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


def load_job(source: str | dict, output: str | None = None, overrides: dict | None = None) -> Job:
    """Parses and checks a job (a JSON file's path, or the dict itself). Relative model
    paths and globs are taken from the job file's folder (the current one for a dict);
    `output` overrides the job's own, and `overrides` its keys (the command line's
    --backend, --color, ...). Raises JobError naming what is wrong."""
    if isinstance(source, dict):
        spec, base = source, os.getcwd()
        identity = "models:" + json.dumps(spec.get("models"), sort_keys=True)
    else:
        spec = _read_job_file(source)
        base = os.path.dirname(os.path.abspath(source))
        identity = "file:" + os.path.abspath(source)
    if overrides:
        spec = {**spec, **overrides} if isinstance(spec, dict) else spec
    _check_keys(spec, ("version", "models", "output", "size", "camera", "views", "outputs", "alpha", "bg_color",
                       "ambient_light", "light", "ssaa", "chunk", "normalize", "shading", "backend",
                       *APPEARANCE), "job")
    version = spec.get("version", JOB_VERSION)
    if version != JOB_VERSION:
        raise JobError(f"job.version: this Velocity reads version {JOB_VERSION}, got {version!r}")
    models_spec = spec.get("models")
    if isinstance(models_spec, str):
        models_spec = [models_spec]
    if not isinstance(models_spec, list) or not models_spec or not all(isinstance(m, str) and m for m in models_spec):
        raise JobError("job.models: expected a non-empty list of model paths or globs")
    paths = [p for m in models_spec for p in _model_paths(m, base)]
    paths = list(dict.fromkeys(paths))
    # Output folder per model: the file's stem, with a hash of the path when two share it.
    stems: dict[str, int] = {}
    for p in paths:
        stem = _safe(os.path.splitext(os.path.basename(p))[0])
        stems[stem] = stems.get(stem, 0) + 1
    models = []
    for p in paths:
        stem = _safe(os.path.splitext(os.path.basename(p))[0])
        models.append((stem if stems[stem] == 1 else f"{stem}-{hashlib.sha1(os.fsencode(p)).hexdigest()[:8]}", p))

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
        "backend": _choice(spec, "backend", "cpu", BACKENDS),
        **_parse_appearance(spec),
    }
    out = output or spec.get("output")
    if not out or not isinstance(out, (str, os.PathLike)):
        raise JobError("job.output: no output folder (give one in the job or with --out)")
    out = os.fspath(out)
    if not output and not isinstance(source, dict):  # a job file's own: inside its folder (--out may name any)
        full = os.path.realpath(os.path.join(base, out))
        if not _inside(full, os.path.realpath(base)):
            raise JobError(f"job.output: {out!r} is outside the job file's folder {base}; "
                           "name it with --out to write there")
    out = out if os.path.isabs(out) or output else os.path.join(base, out)
    job = Job(normalized, os.path.abspath(out), models, identity)
    total = job.view_count() * len(models)
    if total > MAX_VIEWS:
        raise JobError(f"job: {len(models)} model(s) x {job.view_count()} views = {total} views; "
                       f"a job may have at most {MAX_VIEWS} (split it)")
    return job


def _read_job_file(source: Any) -> dict:
    """The job file's JSON: a regular file of at most MAX_JOB_BYTES (never a device,
    pipe or folder, which could be read for ever)."""
    name = os.fsdecode(source)
    try:
        fd = os.open(source, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as e:
        raise JobError(f"{name}: cannot read the job file: {e.strerror}") from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise JobError(f"{name}: the job file is not a regular file")
        if st.st_size > MAX_JOB_BYTES:
            raise JobError(f"{name}: the job file is {st.st_size} bytes; at most {MAX_JOB_BYTES} are read")
        with os.fdopen(fd, "rb", closefd=False) as f:
            data = f.read(MAX_JOB_BYTES + 1)
    except OSError as e:
        raise JobError(f"{name}: cannot read the job file: {e.strerror}") from None
    finally:
        os.close(fd)
    if len(data) > MAX_JOB_BYTES:
        raise JobError(f"{name}: the job file is larger than {MAX_JOB_BYTES} bytes")
    try:
        spec = json.loads(data.decode("utf-8"))
    except UnicodeDecodeError as e:
        raise JobError(f"{name}: not UTF-8 text (byte {e.start})") from None
    except json.JSONDecodeError as e:
        raise JobError(f"{name}:{e.lineno}:{e.colno}: not valid JSON: {e.msg}") from None
    except RecursionError:
        raise JobError(f"{name}: the JSON is nested too deeply") from None
    return spec


def _walk_glob(pattern: str, base: str) -> Iterable[str]:
    """glob's matches of `pattern` (relative, '/'-separated, '**' for any folders) below
    `base`, found by walking the tree without following links to folders: a link loop
    (/proc/self/root, say) cannot make it walk for ever. Names starting with '.' match
    only a pattern part that does too, as glob's."""
    parts = pattern.split(os.sep)
    fixed = 0
    while fixed < len(parts) - 1 and not glob.has_magic(parts[fixed]):
        fixed += 1
    start, rest = os.path.join(base, *parts[:fixed]), parts[fixed:]

    def match(names: list[str], pats: list[str]) -> bool:
        if not pats:
            return not names
        if pats[0] == "**":
            return any(match(names[k:], pats[1:]) for k in range(len(names) + 1)
                       if all(not n.startswith(".") for n in names[:k]))
        return bool(names) and (not names[0].startswith(".") or pats[0].startswith(".")) and \
            fnmatch.fnmatchcase(names[0], pats[0]) and match(names[1:], pats[1:])

    for folder, dirs, files in os.walk(start, followlinks=False):
        rel = os.path.relpath(folder, start)
        above = [] if rel == os.curdir else rel.split(os.sep)
        for name in sorted(files + [d for d in dirs if os.path.islink(os.path.join(folder, d))]):
            if match(above + [name], rest):
                yield os.path.join(folder, name)


def _inside(path: str, folder: str) -> bool:
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


def _model_paths(m: str, base: str) -> list[str]:
    """A job's model entry as absolute paths. A plain path is taken as it is (a missing
    or unreadable file is that model's failure). A glob stays in the job file's folder
    tree (a pattern that leaves it is refused; a match reached through a link out of it
    is skipped) and matches regular files only."""
    p = m if os.path.isabs(m) else os.path.join(base, m)
    if not glob.has_magic(m):
        return [os.path.abspath(p)]
    root = os.path.realpath(base)
    if os.pardir in m.replace("\\", "/").split("/") or not _inside(os.path.abspath(p), os.path.abspath(base)):
        raise JobError(f"job.models: the glob {m!r} leaves the job file's folder {base}; "
                       "a glob may match only files below it (name files elsewhere one by one)")
    found = []
    for f in _walk_glob(os.path.relpath(os.path.abspath(p), os.path.abspath(base)), os.path.abspath(base)):
        try:
            if not stat.S_ISREG(os.stat(f).st_mode) or not _inside(os.path.realpath(f), root):
                continue
        except OSError:
            continue
        found.append(f)
        if len(found) > MAX_MODELS:
            raise JobError(f"job.models: {m!r} matches more than {MAX_MODELS} files")
    if not found:
        raise JobError(f"job.models: {m!r} matches no file")
    return sorted(found)


def _safe(name: str) -> str:
    s = "".join(c if c.isalnum() or c in "-_." else "_" for c in name).strip(".")
    return s or "model"
