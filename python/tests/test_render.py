"""The pyrender-style API: scenes, meshes from arrays and files, cameras, lights, flags."""
import math
import os

import numpy as np
import pytest

import velocity
from conftest import model, simple_scene


def test_color_and_depth_arrays(sphere_scene):
    scene, _ = sphere_scene
    color, depth = velocity.OffscreenRenderer(160, 120).render(scene)
    assert color.shape == (120, 160, 3) and color.dtype == np.uint8 and color.flags.c_contiguous
    assert depth.shape == (120, 160) and depth.dtype == np.float32
    assert depth[60, 80] == pytest.approx(2.0, abs=2e-3)      # sphere of radius 1 seen from 3
    assert depth[0, 0] == 0 and tuple(color[0, 0]) == (0, 0, 0)  # background: nothing hit
    assert color[60, 80].max() > 100                            # lit


def test_rgba_alpha_follows_background():
    scene, _ = simple_scene(bg=(0.2, 0.4, 0.6, 0.0))
    color, _ = velocity.OffscreenRenderer(64, 48).render(scene, velocity.RenderFlags.RGBA)
    assert color.shape == (48, 64, 4)
    assert tuple(color[0, 0]) == (51, 102, 153, 0)
    assert color[24, 32, 3] == 255


def test_depth_only():
    scene, _ = simple_scene()
    depth = velocity.OffscreenRenderer(32, 32).render(scene, velocity.RenderFlags.DEPTH_ONLY)
    assert isinstance(depth, np.ndarray) and depth.shape == (32, 32)


def test_from_arrays_matches_generated_sphere():
    ref = velocity.Mesh.sphere(24)
    prim = ref.primitives[0]
    # The engine's own arrays are read-only views (no copy)...
    assert not prim.positions.flags.writeable
    with pytest.raises(ValueError):
        prim.positions[0, 0] = 5
    # ...and the same arrays given back give the same picture.
    mine = velocity.Mesh.from_arrays(np.array(prim.positions), np.array(prim.indices), normals=np.array(prim.normals))
    a = velocity.OffscreenRenderer(96, 72).render(simple_scene(ref)[0])[0]
    b = velocity.OffscreenRenderer(96, 72).render(simple_scene(mine)[0])[0]
    assert np.array_equal(a, b)


def test_from_arrays_takes_any_layout_and_type():
    v = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], dtype=np.float64)
    f = np.array([[0, 1, 2]], dtype=np.int64)
    m1 = velocity.Mesh.from_arrays(v, f)
    vf = np.asfortranarray(v.astype(np.float32))      # strided
    m2 = velocity.Mesh.from_arrays(vf, f.astype(np.uint16), colors=np.array([[255, 0, 0]] * 3, np.uint8))
    assert np.array_equal(m1.primitives[0].positions, m2.primitives[0].positions)
    assert np.allclose(m2.primitives[0].color_0, [[1, 0, 0]] * 3)
    assert np.allclose(m1.primitives[0].normals, [[0, 0, 1]] * 3)  # computed, facing +Z
    big_endian = velocity.Mesh.from_arrays(v.astype(">f4"), f.astype(">i4"))
    assert np.array_equal(big_endian.primitives[0].positions, m1.primitives[0].positions)


def test_vertex_colors_show():
    v, f = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32), np.array([[0, 1, 2]], np.uint32)
    mesh = velocity.Mesh.from_arrays(v, f, colors=np.array([[0, 1, 0]] * 3, np.float32),
                                     material=velocity.Material(shading="unlit"))
    scene, _ = simple_scene(mesh)
    color, _ = velocity.OffscreenRenderer(64, 64).render(scene)
    assert tuple(color[40, 32]) == (0, 255, 0)


@pytest.mark.parametrize("name", ["duck.asc", "fork.asc", "wuson_x4.obj"])
def test_from_file_project_models(name):
    mesh = velocity.Mesh.from_file(model(name))
    assert mesh.triangle_count > 0
    centre, radius = mesh.bounding_sphere
    scene = velocity.Scene(ambient_light=(0.3, 0.3, 0.3))
    scene.add(mesh)
    scene.add(velocity.PerspectiveCamera(math.radians(45)), pose=velocity.look_at(np.array(centre) + [0, 0, 3 * radius], centre))
    color, depth = velocity.OffscreenRenderer(64, 48).render(scene)
    assert (depth > 0).sum() > 5


def test_engine_warnings_are_python_warnings(tmp_path):
    # A texture the material names but the folder lacks: the engine warns, and Python hears it.
    (tmp_path / "quad.mtl").write_text("newmtl skin\nKd 1 1 1\nmap_Kd missing.png\n")
    (tmp_path / "quad.obj").write_text("mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                       "usemtl skin\nf 1/1 2/2 3/3\n")
    with pytest.warns(RuntimeWarning, match=r"missing\.png"):
        mesh = velocity.Mesh.from_file(str(tmp_path / "quad.obj"))
    assert mesh.triangle_count == 1


def test_from_file_plg():
    import os
    path = os.path.join(os.path.dirname(model("x")), "..", "..", "fuzz", "corpus", "plg", "cube.plg")
    mesh = velocity.Mesh.from_file(path)
    assert mesh.triangle_count == 12  # six quads, fanned


@pytest.mark.parametrize("path", [
    "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf",
    "/usr/share/assimp/models/PLY/cube.ply",
    "/usr/share/assimp/models/STL/Spider_ascii.stl",
    "/usr/share/assimp/models/3DS/test1.3ds",
])
def test_from_file_assimp_formats(path):
    mesh = velocity.Mesh.from_file(path)
    assert mesh.triangle_count > 0 and len(mesh.primitives) >= 1


SIMPLE_SKIN = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf"


@pytest.mark.skipif(not os.path.exists(SIMPLE_SKIN), reason="assimp-testmodels is not installed")
def test_from_file_posed_at_a_time():
    # The glTF tutorial's SimpleSkin: vertex 9 (bind (1, 2, 0)) on the second joint alone,
    # turned about (0.5, 1) by its angle after the skin's shift of -0.5 in x, plus (0, 1):
    # 22.514 degrees at 0.25 s, a key of 90 degrees at 1.0 s (values worked out by hand).
    def tip(**when):
        prim = velocity.Mesh.from_file(SIMPLE_SKIN, **when).primitives[0]
        return (np.asarray(prim.pose) @ np.append(np.asarray(prim.positions)[9], 1.0))[:2]

    assert tip() == pytest.approx([1.0, 2.0])  # no time: the file's mesh as stored (bind pose)
    assert tip(time=0.25) == pytest.approx([0.0789816, 2.1152407], abs=1e-4)
    assert tip(time=1.0) == pytest.approx([-1.0, 1.5], abs=1e-4)
    assert tip(animation=0) == pytest.approx([0.5, 2.0], abs=1e-5)  # time 0: the rest pose
    with pytest.raises(velocity.Error, match=r"simple_skin.gltf: animation 2: the file has 1 animation \(0..0\)"):
        velocity.Mesh.from_file(SIMPLE_SKIN, animation=2)
    with pytest.raises(velocity.Error, match="animation time must be 0 or more seconds"):
        velocity.Mesh.from_file(SIMPLE_SKIN, time=-0.5)


def test_intrinsics_camera_principal_point_moves_image():
    cam_c = velocity.IntrinsicsCamera(fx=80, fy=80, cx=32, cy=24, znear=0.1, zfar=10)
    cam_l = velocity.IntrinsicsCamera(fx=80, fy=80, cx=16, cy=24, znear=0.1, zfar=10)
    scene_c, _ = simple_scene(camera=cam_c)
    scene_l, _ = simple_scene(camera=cam_l)
    _, dc = velocity.OffscreenRenderer(64, 48).render(scene_c)
    _, dl = velocity.OffscreenRenderer(64, 48).render(scene_l)
    assert np.array_equal(dc[:, 16:48 - 0][:, :16], dl[:, 0:16]) or np.allclose(dc[:, 16:32], dl[:, 0:16])
    p = cam_l.get_projection_matrix(64, 48)
    assert p[0, 2] == pytest.approx(1 - 2 * 16 / 64)  # pyrender's matrix


def test_from_K_adds_half_a_pixel():
    cam = velocity.IntrinsicsCamera.from_K([[500, 0, 319.5], [0, 500, 239.5], [0, 0, 1]])
    assert (cam.cx, cam.cy) == (320, 240)


def test_opencv_pose_helper_sees_the_same():
    pose_gl = velocity.look_at([0.5, 1, 3], [0, 0, 0])
    pose_cv = velocity.opengl_to_opencv_pose(pose_gl)
    assert np.allclose(pose_cv[:3, 2], -pose_gl[:3, 2]) and np.allclose(pose_cv[:3, 1], -pose_gl[:3, 1])
    scene_a, _ = simple_scene(pose=pose_gl)
    scene_b, _ = simple_scene(pose=velocity.opencv_to_opengl_pose(pose_cv))
    r = velocity.OffscreenRenderer(48, 48)
    assert np.array_equal(r.render(scene_a)[1], r.render(scene_b)[1])


def test_camera_pose_round_trip_straight_down_and_rolled():
    for pose in (velocity.look_at([0, 5, 0], [0, 0, 0], up=[0, 0, -1]),
                 velocity.look_at([1, 2, 3], [0, 0, 0], up=[0.3, 1, 0.1]),
                 velocity.look_at([0, -4, 0.0], [0, 0, 0], up=[1, 0, 0])):
        pos, yaw, pitch, roll = velocity._velocity._camera_pose_angles(pose)
        r = np.array(velocity._velocity._rotation_from_angles(yaw, pitch, roll)).reshape(3, 3)
        assert np.allclose(r, pose[:3, :3], atol=1e-6) and np.allclose(pos, pose[:3, 3])


def test_scene_nodes_poses_and_hierarchy():
    scene = velocity.Scene()
    parent = scene.add(velocity.Mesh.cube(), name="parent", pose=np.diag([1, 1, 1, 1.0]))
    t = np.eye(4)
    t[:3, 3] = [1, 2, 3]
    child = scene.add(velocity.Mesh.cube(), name="child", pose=t, parent_node=parent)
    t2 = np.eye(4)
    t2[:3, 3] = [10, 0, 0]
    scene.set_pose(parent, t2)
    assert np.allclose(scene.get_pose(child)[:3, 3], [11, 2, 3])
    assert [n.name for n in scene.mesh_nodes] == ["parent", "child"]
    assert child.id == 2 and scene.get_nodes(name="child") == [child]
    cam = scene.add(velocity.PerspectiveCamera(1.0))
    assert scene.main_camera_node == cam
    scene.remove_node(parent)
    assert not scene.has_node(child) and scene.mesh_nodes == []
    with pytest.raises(ValueError):
        scene.set_pose(child, np.eye(4))


def test_flags_flat_wire_and_cull():
    scene, _ = simple_scene()
    r = velocity.OffscreenRenderer(64, 64)
    smooth = r.render(scene)[0]
    flat = r.render(scene, velocity.RenderFlags.FLAT)[0]
    wire = r.render(scene, velocity.RenderFlags.ALL_WIREFRAME)[0]
    assert not np.array_equal(smooth, flat)
    assert (wire.sum(-1) > 0).sum() < (smooth.sum(-1) > 0).sum()
    with pytest.raises(ValueError, match="not supported"):
        r.render(scene, 16)  # pyrender's ALL_SOLID


def test_point_light_falls_off_with_distance():
    v, f = np.array([[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], np.float32), np.array([[0, 1, 2], [0, 2, 3]], np.uint32)
    scene = velocity.Scene(bg_color=(0, 0, 0, 1))
    scene.add(velocity.Mesh.from_arrays(v, f, material=velocity.Material(color=(1, 1, 1), shading="phong")))
    scene.add(velocity.PerspectiveCamera(math.radians(60), znear=0.1, zfar=20), pose=velocity.look_at([0, 0, 5], [0, 0, 0]))
    light = np.eye(4)
    light[:3, 3] = [0, 0, 1]
    scene.add(velocity.PointLight(intensity=math.pi * 0.5), pose=light)
    color = velocity.OffscreenRenderer(65, 65).render(scene)[0]
    # Straight below the light at distance 1: 0.5 * 1 / 1^2 -> 128; further out, darker.
    assert abs(int(color[32, 32, 0]) - 128) <= 2
    assert color[32, 60, 0] < color[32, 40, 0] < color[32, 32, 0]


def test_resize_and_ssaa():
    scene, _ = simple_scene()
    r = velocity.OffscreenRenderer(32, 32, ssaa=2)
    r.viewport_width = 48
    color, depth = r.render(scene)
    assert color.shape == (32, 48, 3) and depth.shape == (32, 48)


def test_docs_quick_start_runs(tmp_path, monkeypatch):
    # The quick start in docs/python.md, as written, from the source tree's root.
    import os
    import re
    root = os.environ.get("VELOCITY_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
    text = open(os.path.join(root, "docs", "python.md")).read()
    code = re.search(r"## Quick start.*?```python\n(.*?)```", text, re.S).group(1)
    code = code.replace('"tests/data/', '"' + os.path.join(os.path.abspath(root), "tests", "data") + "/")
    monkeypatch.chdir(tmp_path)
    env = {}
    exec(compile(code, "docs/python.md", "exec"), env)
    color, depth, mask, duck = env["color"], env["depth"], env["mask"], env["duck"]
    assert color.shape == (480, 640, 4) and (mask == duck.id).sum() > 1000
    assert np.array_equal(mask > 0, depth > 0)
    assert (tmp_path / "duck.png").stat().st_size > 1000 and (tmp_path / "duck_mask.png").exists()


def test_from_trimesh_takes_a_trimesh_like_object():
    from types import SimpleNamespace
    prim = velocity.Mesh.sphere(16).primitives[0]
    tm = SimpleNamespace(vertices=np.array(prim.positions, np.float64), faces=np.array(prim.indices, np.int64),
                         vertex_normals=np.array(prim.normals), name="ball",
                         visual=SimpleNamespace(kind="vertex", vertex_colors=np.full((len(prim.positions), 4), 200, np.uint8)))
    smooth = velocity.Mesh.from_trimesh(tm)
    assert smooth.name == "ball" and np.allclose(smooth.primitives[0].color_0, 200 / 255)
    flat = velocity.Mesh.from_trimesh(tm, smooth=False)
    assert flat.primitives[0].material.shading == "flat"
    a = velocity.OffscreenRenderer(64, 64).render(simple_scene(smooth)[0])[0]
    b = velocity.OffscreenRenderer(64, 64).render(simple_scene(flat)[0])[0]
    assert not np.array_equal(a, b)
