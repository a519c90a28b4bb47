"""Shared helpers for the Python tests (run by ctest: python/tests/CMakeLists.txt)."""
import math
import os

import numpy as np
import pytest

import velocity

DATA = os.path.abspath(os.environ.get("VELOCITY_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "tests", "data")))
SANITIZER = os.environ.get("VELOCITY_SANITIZER", "")


def model(name: str) -> str:
    return os.path.join(DATA, "models", name)


def uv_sphere(segments: int, radius: float = 1.0):
    """A UV sphere made here in numpy (not the engine's generator): vertices on the
    sphere, quads split in two, counter-clockwise outwards. Returns (vertices, faces)."""
    rings = segments // 2
    theta = np.linspace(0, math.pi, rings + 1)            # from the north pole
    phi = np.linspace(0, 2 * math.pi, segments + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    v = np.stack([np.sin(t) * np.sin(p), np.cos(t), np.sin(t) * np.cos(p)], -1).reshape(-1, 3) * radius
    idx = np.arange((rings + 1) * (segments + 1)).reshape(rings + 1, segments + 1)
    a, b, c, d = idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    # Drop the degenerate triangles at the poles (two corners at the same point).
    pts = v[faces]
    area = np.linalg.norm(np.cross(pts[:, 1] - pts[:, 0], pts[:, 2] - pts[:, 0]), axis=1)
    return v.astype(np.float32), faces[area > 1e-12].astype(np.uint32)


def inscribed_radius(vertices, faces) -> float:
    """The radius of the largest ball about the origin inside the (convex) polyhedron:
    the smallest distance from the origin to a face's plane."""
    p = vertices.astype(np.float64)[faces]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    return float(np.min(np.abs(np.einsum("ij,ij->i", n, p[:, 0]))))


def simple_scene(mesh=None, camera=None, pose=None, bg=(0, 0, 0, 1)):
    scene = velocity.Scene(bg_color=bg, ambient_light=(0.3, 0.3, 0.3))
    node = scene.add(mesh or velocity.Mesh.sphere(32))
    cam = camera or velocity.PerspectiveCamera(math.radians(45), znear=0.1, zfar=100)
    scene.add(cam, pose=velocity.look_at([0, 0, 3], [0, 0, 0]) if pose is None else pose)
    scene.add(velocity.DirectionalLight(intensity=2.0), pose=velocity.look_at([0, 0, 0], [-0.3, -0.5, -1]))
    return scene, node


@pytest.fixture
def sphere_scene():
    return simple_scene()
