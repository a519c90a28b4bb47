"""Velocity: CPU rendering to numpy arrays, with pyrender's names and conventions.

    import numpy as np, velocity
    scene = velocity.Scene(bg_color=(0, 0, 0, 0), ambient_light=(0.2, 0.2, 0.2))
    scene.add(velocity.Mesh.from_file("duck.obj"))
    scene.add(velocity.IntrinsicsCamera(fx=500, fy=500, cx=320, cy=240), pose=camera_pose)
    scene.add(velocity.DirectionalLight(intensity=3.0), pose=camera_pose)
    color, depth, mask = velocity.OffscreenRenderer(640, 480).render(
        scene, flags=velocity.RenderFlags.SEG)

Camera poses follow OpenGL's convention (the camera looks down its -Z axis, +Y up), as
pyrender's do; `opencv_to_opengl_pose` converts one that looks down +Z with +Y down.
Everything renders on the CPU: no display, no GL, no EGL. See docs/python.md.
"""
from __future__ import annotations

import enum
import math
from typing import Any, Union

import numpy as np

from ._velocity import (  # noqa: F401  (re-exported)
    Camera,
    DirectionalLight,
    Error,
    Light,
    Material,
    Mesh,
    Node,
    OrthographicCamera,
    PerspectiveCamera,
    PointLight,
    Primitive,
    Scene,
    SpotLight,
)
from ._velocity import IntrinsicsCamera as _IntrinsicsCamera
from ._velocity import OffscreenRenderer as _OffscreenRenderer

__all__ = [
    "Camera", "DirectionalLight", "Error", "IntrinsicsCamera", "Light", "Material", "Mesh", "Node",
    "OffscreenRenderer", "OrthographicCamera", "PerspectiveCamera", "PointLight", "Primitive", "RenderFlags",
    "Scene", "SpotLight", "look_at", "opencv_to_opengl_pose", "opengl_to_opencv_pose",
]


class RenderFlags(enum.IntFlag):
    """What render() draws and returns. The values are pyrender's, so its flags work here.

    NONE: colour (H x W x 3 uint8) and depth (H x W float32).
    DEPTH_ONLY: depth alone.          RGBA: colour with alpha (H x W x 4).
    FLAT: every surface flat-shaded.  ALL_WIREFRAME: triangle edges only.
    SKIP_CULL_FACES: back faces drawn too.
    SEG: a third array, the instance mask: per pixel the id of the node drawn there
         (Node.id, uint32), 0 where nothing was; exact, never blended at borders.
    NORMALS (Velocity's own): a last array, H x W x 3 float32 camera-space unit normals
         (OpenGL axes: +Z towards the camera), 0 where nothing was drawn; from an
         8-bit pass, so each component is within about 0.004 before normalising.
    SHADOWS_DIRECTIONAL, SHADOWS_POINT, SHADOWS_SPOT, SHADOWS_ALL: shadow maps for this
         frame's lights of that kind whose cast_shadows is on (the renderer's shadows
         option turns them on for every kind).
    """

    NONE = 0
    DEPTH_ONLY = 1
    OFFSCREEN = 2
    ALL_WIREFRAME = 8
    SHADOWS_DIRECTIONAL = 32
    SHADOWS_POINT = 64
    SHADOWS_SPOT = 128
    SHADOWS_ALL = 32 | 64 | 128
    SKIP_CULL_FACES = 1024
    RGBA = 2048
    FLAT = 4096
    SEG = 8192
    NORMALS = 1 << 20


_SUPPORTED = (RenderFlags.DEPTH_ONLY | RenderFlags.OFFSCREEN | RenderFlags.ALL_WIREFRAME |
              RenderFlags.SKIP_CULL_FACES | RenderFlags.RGBA | RenderFlags.FLAT | RenderFlags.SEG |
              RenderFlags.NORMALS | RenderFlags.SHADOWS_ALL)


class OffscreenRenderer(_OffscreenRenderer):
    """Renders scenes to numpy arrays on the CPU (pyrender's OffscreenRenderer).

    OffscreenRenderer(viewport_width, viewport_height, point_size=1.0, ssaa=1, threads=0,
    backend="cpu", color="auto", tone_map="none", exposure=1.0, shadows=False,
    shadow_map_size=2048): point_size is a point's side in pixels (1..64); ssaa is 1..4
    samples per side per pixel (colour averaged; depth and mask from the nearest sample,
    never blended); threads is the cores one frame may use (0: all); backend is "cpu",
    "gpu" (OpenGL through EGL) or "auto" (a hardware GPU, else the CPU). The appearance
    options (docs/appearance.md), also properties: color "auto", "linear" or "display";
    tone_map "none", "aces" or "neutral"; exposure >= 0; shadows (every light whose
    cast_shadows is on); shadow_map_size 16..8192. last_frame says what the engine got
    for the last frame and which backend drew it.
    Many renderers may render at once from many threads: the GIL is released while
    one renders. One renderer renders one frame at a time.
    """

    def __init__(self, viewport_width: int, viewport_height: int, point_size: float = 1.0, *,
                 ssaa: int = 1, threads: int = 0, backend: str = "cpu", color: str = "auto",
                 tone_map: str = "none", exposure: float = 1.0, shadows: bool = False,
                 shadow_map_size: int = 2048) -> None:
        super().__init__(viewport_width, viewport_height, ssaa, threads, backend, color=color, tone_map=tone_map,
                         exposure=exposure, shadows=shadows, shadow_map_size=shadow_map_size, point_size=point_size)

    def render(self, scene: Scene, flags: Union[RenderFlags, int] = RenderFlags.NONE) -> Any:
        """Renders `scene` from its main camera.

        Returns (color, depth); with RenderFlags.SEG (color, depth, mask); with
        RenderFlags.NORMALS the normals come last; with DEPTH_ONLY just depth.
        color: H x W x 3 uint8 (x 4 with RGBA), top row first.
        depth: H x W float32 distance along the camera's view axis (metric, for
        perspective, intrinsics and orthographic cameras alike), 0 where nothing was hit.
        mask: H x W uint32 node ids (Node.id), 0 for none.
        Raises velocity.Error with the engine's message (no camera in the scene, a
        camera pose that is not a rotation and translation, ...).
        """
        flags = int(flags)
        unknown = flags & ~int(_SUPPORTED)
        if unknown:
            raise ValueError(f"render: flags {RenderFlags(unknown)!r} are not supported by Velocity")
        return self._render(scene, flags)


class IntrinsicsCamera(_IntrinsicsCamera):
    __doc__ = _IntrinsicsCamera.__doc__

    @classmethod
    def from_K(cls, K: Any, znear: float = 0.05, zfar: float = 100.0, name: str | None = None) -> "IntrinsicsCamera":
        """From an OpenCV 3x3 camera matrix K (pixel centres on whole numbers): cx and cy
        move by half a pixel to Velocity's (and pyrender's) convention."""
        K = np.asarray(K, dtype=np.float64)
        if K.shape != (3, 3):
            raise ValueError(f"K: expected a 3x3 matrix, got shape {K.shape}")
        if K[0, 1] != 0:
            raise ValueError("K: skew (K[0, 1]) is not supported")
        return cls(K[0, 0], K[1, 1], K[0, 2] + 0.5, K[1, 2] + 0.5, znear, zfar, name)


def _from_trimesh(mesh: Any, material: "Material | None" = None, smooth: bool = True,
                  name: str | None = None) -> Mesh:
    """pyrender's Mesh.from_trimesh: a mesh from a trimesh.Trimesh (anything with
    `vertices` and `faces`; `vertex_normals` and `visual.vertex_colors` are used when
    there). smooth=False shades each triangle flat (the material's shading otherwise)."""
    if isinstance(mesh, (list, tuple)):
        raise ValueError("from_trimesh: one mesh at a time (add each to the scene)")
    colors = None
    visual = getattr(mesh, "visual", None)
    if visual is not None and getattr(visual, "kind", None) == "vertex":
        colors = np.asarray(visual.vertex_colors)
    normals = getattr(mesh, "vertex_normals", None) if smooth else None
    if not smooth:
        material = Material(color=material.color if material else None, shading="flat",
                            specular=material.specular if material else 0.0,
                            shininess=material.shininess if material else 32.0,
                            two_sided=material.two_sided if material else False)
    return Mesh.from_arrays(mesh.vertices, mesh.faces, normals=normals, colors=colors, material=material,
                            name=name or getattr(mesh, "name", None) or "mesh")


Mesh.from_trimesh = staticmethod(_from_trimesh)

# OpenCV's camera axes (+X right, +Y down, +Z forward) -> OpenGL's (+X right, +Y up, -Z forward).
_FLIP_YZ = np.diag([1.0, -1.0, -1.0, 1.0])


def opencv_to_opengl_pose(pose: Any) -> np.ndarray:
    """A camera-to-world pose whose camera looks down +Z with +Y down (OpenCV, COLMAP,
    ROS optical frames) as one that looks down -Z with +Y up (OpenGL, pyrender, Velocity):
    the same camera, its Y and Z axes turned half a turn about X. Also takes N x 4 x 4."""
    pose = np.asarray(pose, dtype=np.float64)
    if pose.shape[-2:] != (4, 4):
        raise ValueError(f"pose: expected 4x4 (or N x 4 x 4), got shape {pose.shape}")
    return pose @ _FLIP_YZ


def opengl_to_opencv_pose(pose: Any) -> np.ndarray:
    """The inverse of opencv_to_opengl_pose (the same flip)."""
    return opencv_to_opengl_pose(pose)


def look_at(eye: Any, target: Any, up: Any = (0.0, 1.0, 0.0)) -> np.ndarray:
    """The OpenGL-convention camera pose (4x4) of a camera at `eye` looking at `target`."""
    # Plain floats: numpy's per-call overhead would dominate for three-vectors.
    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def unit(a):
        n = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
        return (a[0] / n, a[1] / n, a[2] / n), n

    def three(v, what):
        a = np.asarray(v, dtype=np.float64)
        if a.shape != (3,):
            raise ValueError(f"look_at: {what} must be 3 numbers, got shape {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"look_at: {what} must be finite")
        return [float(x) for x in a]

    e, t, u = three(eye, "eye"), three(target, "target"), three(up, "up")
    d = (e[0] - t[0], e[1] - t[1], e[2] - t[2])
    if d == (0.0, 0.0, 0.0):
        raise ValueError("look_at: eye and target must differ")
    if u == [0.0, 0.0, 0.0]:
        raise ValueError("look_at: up must not be zero")
    z, n = unit(d)  # the camera looks down -z
    if not math.isfinite(n) or n == 0:
        raise ValueError("look_at: eye and target must differ (and be finite)")
    x = cross(u, z)
    if math.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2) < 1e-9:  # looking along `up`: any perpendicular will do
        x = cross((1.0, 0.0, 0.0) if abs(z[0]) < 0.9 else (0.0, 0.0, 1.0), z)
    x, _ = unit(x)
    y = cross(z, x)
    return np.array([[x[0], y[0], z[0], e[0]], [x[1], y[1], z[1], e[1]], [x[2], y[2], z[2], e[2]], [0, 0, 0, 1.0]])
