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
    with pytest.raises(ValueError, match="shape Nx3") as shape:
        tri(v=np.zeros((3, 2), np.float32))
    assert isinstance(shape.value, velocity.Error)  # both, so that either except clause catches it
    with pytest.raises(ValueError, match="2-D"):
        tri(v=np.zeros(9, np.float32))
    with pytest.raises(ValueError, match="one per vertex"):
        tri(normals=np.zeros((2, 3), np.float32))
    with pytest.raises(TypeError, match="integer indices") as dtype:
        tri(f=np.array([[0, 1, 2]], np.float32))
    assert isinstance(dtype.value, velocity.Error)
    with pytest.raises(TypeError, match="float32 or float64"):
        tri(v=np.zeros((3, 3), np.int32))
    with pytest.raises(velocity.Error, match="no triangles"):
        tri(f=np.zeros((0, 3), np.uint32))
    assert issubclass(velocity.Error, RuntimeError)


def test_bad_files_name_file_and_line():
    with pytest.raises(velocity.Error, match="truncated.asc:5: expected"):
        velocity.Mesh.from_file(f"{DATA}/../fuzz/bad/truncated.asc")
    with pytest.raises(velocity.Error, match="/nonexistent/car.obj"):
        velocity.Mesh.from_file("/nonexistent/car.obj")


def test_bad_cameras_poses_and_sizes():
    with pytest.raises(ValueError, match="yfov"):
        velocity.PerspectiveCamera(0)
    with pytest.raises(ValueError, match="zfar"):
        velocity.OrthographicCamera(1, 1, znear=5, zfar=1)
    with pytest.raises(ValueError, match="pinhole"):
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


def test_setters_validate_like_the_constructors():
    cam = velocity.PerspectiveCamera(1.0, znear=0.1, zfar=10.0)
    for name, bad in (("yfov", 0.0), ("yfov", 4.0), ("znear", -1.0), ("zfar", 0.05), ("aspectRatio", -2.0)):
        with pytest.raises(ValueError):
            setattr(cam, name, bad)
    assert (cam.yfov, cam.znear, cam.zfar, cam.aspectRatio) == (1.0, 0.1, 10.0, None)  # unchanged
    ortho = velocity.OrthographicCamera(1, 1)
    with pytest.raises(ValueError, match="xmag"):
        ortho.xmag = float("nan")
    intr = velocity.IntrinsicsCamera(100, 100, 50, 50)
    with pytest.raises(ValueError):
        intr.fx = 0.0
    light = velocity.PointLight()
    with pytest.raises(ValueError, match="intensity"):
        light.intensity = -1.0
    with pytest.raises(ValueError, match="range"):
        light.range = 0.0
    with pytest.raises(TypeError):
        light.intensity = "bright"


def test_znear_too_small_for_the_depth_buffer_names_the_smallest_that_works():
    with pytest.raises(ValueError, match=r"the smallest znear that works is 3e-06"):
        velocity.PerspectiveCamera(1.0, znear=1e-7, zfar=3.0)
    cam = velocity.PerspectiveCamera(1.0, znear=0.1, zfar=3.0)
    with pytest.raises(ValueError, match="smallest znear"):
        cam.znear = 1e-7
    velocity.OrthographicCamera(1, 1, znear=1e-7, zfar=3.0)  # linear depth: no such limit
    # zfar None: the far plane is fitted to the scene, and checked when it is rendered.
    scene = velocity.Scene()
    scene.add(velocity.Mesh.cube())
    scene.add(velocity.PerspectiveCamera(1.0, znear=1e-7), pose=velocity.look_at((0, 0, 3), (0, 0, 0)))
    with pytest.raises(velocity.Error, match="smallest znear that works is"):
        velocity.OffscreenRenderer(8, 8).render(scene)
    # The smallest that works renders depth within the bound (6e-8 * z / znear: 4 % at 2).
    scene = velocity.Scene()
    scene.add(velocity.Mesh.cube())
    scene.add(velocity.PerspectiveCamera(1.0, znear=3e-6, zfar=3.0), pose=velocity.look_at((0, 0, 2.5), (0, 0, 0)))
    _, depth = velocity.OffscreenRenderer(16, 16).render(scene)
    assert depth[8, 8] == pytest.approx(2.0, rel=0.04)


def test_look_at_errors_are_value_errors():
    with pytest.raises(ValueError, match="eye and target must differ"):
        velocity.look_at((1, 2, 3), (1, 2, 3))
    with pytest.raises(ValueError):
        velocity.look_at((0, 0, 0), (0, 0, 1), up=(0, 0, 0))
    with pytest.raises(ValueError):
        velocity.look_at((0, 0, float("nan")), (0, 0, 1))
    with pytest.raises(ValueError):
        velocity.look_at((0, 0), (0, 0, 1))
    pose = velocity.look_at((0, 0, 5), (0, 0, 0), up=(0, 0, 1))  # looking along up: any perpendicular
    assert np.allclose(pose[:3, 2], [0, 0, 1]) and np.allclose(pose[:3, :3].T @ pose[:3, :3], np.eye(3))


def test_paths_may_be_pathlike_bytes_or_not_utf8(tmp_path):
    import os
    import pathlib
    import shutil
    src = os.path.join(os.environ.get("VELOCITY_TEST_DATA", "tests/data"), "models", "duck.asc")
    by_str = velocity.Mesh.from_file(src)
    assert velocity.Mesh.from_file(pathlib.Path(src)).triangle_count == by_str.triangle_count
    assert velocity.Mesh.from_file(os.fsencode(src)).triangle_count == by_str.triangle_count
    # A file whose name is not UTF-8 (Latin-1 "ente": a byte 0xe9), as bytes and as the
    # str os.listdir gives (surrogate escapes).
    odd = os.path.join(os.fsencode(str(tmp_path)), b"\xe9nte.asc")
    shutil.copyfile(src, odd)
    (listed,) = os.listdir(str(tmp_path))
    for path in (odd, os.path.join(str(tmp_path), listed)):
        mesh = velocity.Mesh.from_file(path)
        assert mesh.triangle_count == by_str.triangle_count and "nte.asc" in repr(mesh)
    with pytest.raises(velocity.Error, match=r"\\xe9missing.asc"):  # named, escaped, in the message
        velocity.Mesh.from_file(os.path.join(os.fsencode(str(tmp_path)), b"\xe9missing.asc"))
    with pytest.raises(TypeError):
        velocity.Mesh.from_file(3)
