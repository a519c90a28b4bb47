"""Where the camera is for each view of a job: the orbit, the given poses or the
animation's keyframes, and the camera (projection, near and far) that frames a model's
bounding sphere at that distance."""
from __future__ import annotations

import math

import numpy as np

from .jobs import Job


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


def view_poses(job: Job, view: int, center: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray]:
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


def view_camera(job: Job, dist: float, radius: float):
    """The job's camera for a view `dist` from the centre of a model of bounding radius
    `radius`: near and far (unless the job gives them) and an orthographic camera's size
    around the model."""
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

