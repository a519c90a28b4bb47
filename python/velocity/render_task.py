"""One task run: a model's views [start, stop) rendered and written to the output
folder (velocity.atomic), with the task's record (velocity.records). Run by the local
runner in its process or its workers, and by the Dask runner on the cluster's workers."""
from __future__ import annotations

import errno
import io
import os
import socket
import threading
import time
from typing import Any

import numpy as np

from .atomic import atomic_write, write_json
from .jobs import APPEARANCE, Job
from .records import is_done, read_record, task_record
from .tasks import Task
from .views import view_camera, view_poses

_local = threading.local()


def _renderer(job: Job, threads: int):
    """One renderer per thread and settings, kept between tasks (its thread pool too, and
    on the GPU its context and uploaded meshes)."""
    import velocity
    s = job.spec
    options = {k: s[k] for k in APPEARANCE}
    key = (tuple(s["size"]), s["ssaa"], threads, s["backend"], tuple(sorted(options.items())))
    cache = getattr(_local, "renderers", None)
    if cache is None:
        cache = _local.renderers = {}
    if key not in cache:
        cache[key] = velocity.OffscreenRenderer(*s["size"], ssaa=s["ssaa"], threads=threads, backend=s["backend"],
                                                **options)
    return cache[key]


def _npy(a: np.ndarray) -> bytes:
    # Through memory, then one write: np.save straight to a file reports a full disk
    # without its errno ("N requested and 0 written"); a file's write() says ENOSPC.
    buf = io.BytesIO()
    np.save(buf, a)
    return buf.getvalue()


def disk_full(e: BaseException) -> bool:
    """Whether `e` says the output's file system is full (or the user's quota)."""
    return isinstance(e, OSError) and e.errno in (errno.ENOSPC, errno.EDQUOT)


def _failure(e: BaseException) -> str:
    import velocity
    return str(e) if isinstance(e, velocity.Error) else f"{type(e).__name__}: {e}"


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
    if is_done(job, task, prev):
        return prev
    record = task_record(task, "running", worker=f"{socket.gethostname()}:{os.getpid()}")
    written = 0
    cameras: dict[str, Any] = {}
    try:
        write_json(job, job.record_path(task.id), record)
        if not os.path.isfile(task.model) and os.path.exists(task.model):
            raise ValueError(f"{os.fsdecode(task.model)}: not a regular file")
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
        cam_node = scene.add(view_camera(job, 1.0, radius), pose=np.eye(4))
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
            cam_pose, model_pose = view_poses(job, view, center, radius)
            dist = float(np.linalg.norm(cam_pose[:3, 3] - (model_pose[:3, :3] @ center + model_pose[:3, 3])))
            camera = view_camera(job, dist, radius)
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
                    atomic_write(job, path, lambda f: f.write(_npy(depth)))
                elif kind == "mask":
                    # No row filter: a mask's rows are runs of one id, which zlib takes as they
                    # are; filtered they only cost more (bench_png.py).
                    atomic_write(job, path, lambda f: f.write(encode_png(mask.astype(np.uint16), filter="none")))
                else:
                    atomic_write(job, path, lambda f: f.write(_npy(normals)))
            written += 1
        record.update(status="done", cameras=cameras)
    except Exception as e:  # a bad model: reported, never fatal to the job
        if disk_full(e):  # not the model's fault: the job stops, and resumes when there is room
            record.update(status="interrupted", error=f"no space left on device ({os.strerror(e.errno)})")
        else:
            record.update(status="failed", error=_failure(e))
    record["seconds"] = round(time.time() - started, 3)
    record["written"] = written
    try:
        write_json(job, job.record_path(task.id), record)
    except OSError as e:
        if not disk_full(e):
            raise
        # The record on disk still says "running": the task is done again on resume.
        record.update(status="interrupted", error=f"no space left on device ({os.strerror(e.errno)})")
    return record
