"""Errors are Python exceptions with the engine's message; bad input never crashes."""
import math

import numpy as np
import pytest

import velocity
from conftest import DATA, simple_scene


def tri(v=None, f=None, **kw):
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32) if v is None else v
    f = np.array([[0, 1, 2]], np.uint32) if f is None else f
    return velocity.Mesh.from_arrays(v, f, **kw)


def test_bad_arrays():
    with pytest.raises(velocity.Error, match=r"faces\[0\] = 3: expected 0..2"):
        tri(f=np.array([[0, 1, 3]], np.uint32))
    with pytest.raises(velocity.Error, match=r"faces\[0\] = -1"):
        tri(f=np.array([[0, 1, -1]], np.int32))
    with pytest.raises(velocity.Error, match=r"vertices\[1\] is not finite"):
        tri(v=np.array([[0, 0, 0], [np.nan, 0, 0], [0, 1, 0]], np.float32))
    with pytest.raises(velocity.Error, match="shape Nx3"):
        tri(v=np.zeros((3, 2), np.float32))
    with pytest.raises(ValueError, match="2-D"):
        tri(v=np.zeros(9, np.float32))
    with pytest.raises(velocity.Error, match="one per vertex"):
        tri(normals=np.zeros((2, 3), np.float32))
    with pytest.raises(velocity.Error, match="integer indices"):
        tri(f=np.array([[0, 1, 2]], np.float32))
    with pytest.raises(velocity.Error, match="no triangles"):
        tri(f=np.zeros((0, 3), np.uint32))
    assert issubclass(velocity.Error, RuntimeError)


def test_bad_files_name_file_and_line():
    with pytest.raises(velocity.Error, match="truncated.asc:5: expected"):
        velocity.Mesh.from_file(f"{DATA}/../fuzz/bad/truncated.asc")
    with pytest.raises(velocity.Error, match="/nonexistent/car.obj"):
        velocity.Mesh.from_file("/nonexistent/car.obj")


def test_bad_cameras_poses_and_sizes():
    with pytest.raises(velocity.Error, match="yfov"):
        velocity.PerspectiveCamera(0)
    with pytest.raises(velocity.Error, match="zfar"):
        velocity.OrthographicCamera(1, 1, znear=5, zfar=1)
    with pytest.raises(velocity.Error, match="pinhole"):
        velocity.IntrinsicsCamera(-1, 1, 0, 0)
    with pytest.raises(velocity.Error, match="image size"):
        velocity.OffscreenRenderer(0, 10)
    scene = velocity.Scene()
    scene.add(velocity.Mesh.cube())
    with pytest.raises(velocity.Error, match="no camera"):
        velocity.OffscreenRenderer(8, 8).render(scene)
    scaled = np.diag([2.0, 2.0, 2.0, 1.0])
    scene.add(velocity.PerspectiveCamera(1.0), pose=scaled)
    with pytest.raises(velocity.Error, match="rotation"):
        velocity.OffscreenRenderer(8, 8).render(scene)
    with pytest.raises(ValueError, match="shape \\(4, 4\\)"):
        scene.add(velocity.Mesh.cube(), pose=np.eye(3))
    with pytest.raises(ValueError, match="finite"):
        scene.add(velocity.Mesh.cube(), pose=np.full((4, 4), np.inf))
    with pytest.raises(TypeError, match="expected a Mesh"):
        scene.add("cube")
    with pytest.raises(ValueError, match="range"):
        velocity.PointLight(range=-3.0)
    with pytest.raises(ValueError, match="innerConeAngle"):
        velocity.SpotLight(innerConeAngle=0.5, outerConeAngle=0.2)


def test_node_of_another_scene():
    a, node = simple_scene()
    b, _ = simple_scene()
    with pytest.raises(ValueError, match="another scene"):
        b.set_pose(node, np.eye(4))


def test_random_arrays_never_crash():
    # A small fuzz of the array path: every outcome is a mesh or a clear error.
    rng = np.random.default_rng(12)
    for _ in range(300):
        n = int(rng.integers(0, 6))
        v = rng.normal(size=(n, int(rng.choice([2, 3, 4])))).astype(rng.choice([np.float32, np.float64, np.int16]))
        if rng.random() < 0.1 and v.size:
            v.flat[0] = rng.choice([np.nan, np.inf]) if v.dtype.kind == "f" else 0
        f = rng.integers(-2, n + 2, size=(int(rng.integers(0, 4)), int(rng.choice([2, 3])))).astype(
            rng.choice([np.int32, np.uint32, np.int64, np.uint8]))
        try:
            m = velocity.Mesh.from_arrays(v, f)
            assert m.primitives[0].indices.max() < n
        except (velocity.Error, ValueError):
            pass
