"""velocity.pyrender called exactly as pyrender users' scripts call pyrender (the
quickstart, offscreen rendering, scenes, nodes, cameras, lights, meshes, segmentation,
point clouds, instancing). trimesh objects are stand-ins (trimesh_standin.py)."""
import math
import os

import numpy as np
import pytest

import velocity.pyrender as pyrender
import trimesh_standin as trimesh

DATA = os.path.join(os.path.dirname(__file__), "data", "pyrender")


def camera_pose_looking_down(z=3.0):
    pose = np.eye(4)
    pose[2, 3] = z  # on +Z, looking down -Z at the origin
    return pose


def box_scene(**scene_kwargs):
    scene = pyrender.Scene(**scene_kwargs)
    node = scene.add(pyrender.Mesh.from_trimesh(trimesh.box()))
    scene.add(pyrender.PerspectiveCamera(yfov=np.pi / 3.0), pose=camera_pose_looking_down())
    scene.add(pyrender.DirectionalLight(color=np.ones(3), intensity=2.0), pose=camera_pose_looking_down())
    return scene, node


def test_quickstart_offscreen_matches_pyrender_silhouette_and_depth():
    # pyrender's "Minimal Example for Offscreen Rendering", line for line.
    Image = pytest.importorskip("PIL.Image")
    fuze_trimesh = trimesh.load_obj(os.path.join(DATA, "fuze.obj"), Image.open(os.path.join(DATA, "fuze_uv.jpg")))
    mesh = pyrender.Mesh.from_trimesh(fuze_trimesh)
    scene = pyrender.Scene()
    scene.add(mesh)
    camera = pyrender.PerspectiveCamera(yfov=np.pi / 3.0, aspectRatio=1.0)
    s = np.sqrt(2) / 2
    camera_pose = np.array([[0.0, -s, s, 0.3], [1.0, 0.0, 0.0, 0.0], [0.0, s, s, 0.35], [0.0, 0.0, 0.0, 1.0]])
    scene.add(camera, pose=camera_pose)
    light = pyrender.SpotLight(color=np.ones(3), intensity=3.0, innerConeAngle=np.pi / 16.0,
                               outerConeAngle=np.pi / 6.0)
    scene.add(light, pose=camera_pose)
    r = pyrender.OffscreenRenderer(400, 400)
    color, depth = r.render(scene)
    assert color.shape == (400, 400, 3) and color.dtype == np.uint8
    assert depth.shape == (400, 400) and depth.dtype == np.float32
    # pyrender's published image (its documentation's minexcolor.png): the same bottle, in
    # the same place. The shading differs until the engine's PBR path lands (docs/python.md).
    ref = np.asarray(Image.open(os.path.join(DATA, "minexcolor.png")).convert("RGB"))
    ours, theirs = depth > 0, (ref < 250).any(axis=2)
    iou = (ours & theirs).sum() / (ours | theirs).sum()
    assert iou > 0.95, iou
    assert np.all(color[~ours] == 255)  # pyrender's white background
    # The depth is the distance along the view axis: the bottle spans the camera's 0.3..0.45 m.
    assert 0.25 < depth[ours].min() < depth[ours].max() < 0.5
    r.delete()


def test_flat_render_is_the_texture_as_it_is():
    # FLAT: no lighting; pyrender's flat shader writes the base colour x texture as they are.
    Image = pytest.importorskip("PIL.Image")
    image = np.zeros((2, 2, 3), dtype=np.uint8)
    image[0] = (200, 30, 40)   # the image's top row: v near 1 in pyrender's (OBJ's) uvs
    image[1] = (20, 210, 60)   # its bottom row: v near 0
    quad = trimesh.Trimesh([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], [[0, 1, 2], [0, 2, 3]],
                           visual=trimesh.Visual(kind="texture", uv=[[0, 0], [1, 0], [1, 1], [0, 1]],
                                                 material=trimesh.SimpleMaterial(image=Image.fromarray(image))))
    mesh = pyrender.Mesh.from_trimesh(quad)
    mesh.primitives[0].material.baseColorTexture.sampler = pyrender.Sampler(magFilter=pyrender.GLTF.NEAREST,
                                                                             minFilter=pyrender.GLTF.NEAREST)
    scene = pyrender.Scene()
    scene.add(mesh)
    scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=camera_pose_looking_down())
    color, _ = pyrender.OffscreenRenderer(32, 32).render(scene, pyrender.RenderFlags.FLAT)
    assert tuple(color[4, 16]) == (200, 30, 40)   # top of the image: the texture's top row
    assert tuple(color[28, 16]) == (20, 210, 60)


def test_scene_nodes_poses_and_bounds():
    scene = pyrender.Scene(bg_color=[0.0, 0.0, 0.0], ambient_light=[0.1, 0.1, 0.1])
    assert np.allclose(scene.bg_color, [0, 0, 0, 1]) and np.allclose(scene.ambient_light, [0.1] * 3)
    box = pyrender.Mesh.from_trimesh(trimesh.box(extents=(2, 2, 2)))
    parent = pyrender.Node(name="parent", translation=[1.0, 0.0, 0.0])
    child = pyrender.Node(name="child", mesh=box, translation=[0.0, 2.0, 0.0], scale=[1.0, 0.5, 1.0])
    parent.children.append(child)
    scene.add_node(parent)
    assert scene.has_node(child) and scene.get_nodes(name="child") == {child}
    assert scene.get_nodes(obj=box) == {child} and scene.mesh_nodes == {child}
    assert np.allclose(scene.get_pose(child)[:3, 3], [1, 2, 0])
    assert np.allclose(scene.bounds, [[0, 1.5, -1], [2, 2.5, 1]])
    assert np.allclose(scene.centroid, [1, 2, 0]) and np.allclose(scene.extents, [2, 1, 2])
    assert math.isclose(scene.scale, 3.0)
    scene.set_pose(parent, np.diag([1.0, 1, 1, 1]))
    assert np.allclose(scene.get_pose(child)[:3, 3], [0, 2, 0])
    # A rotation quaternion [x, y, z, w]: a quarter turn about Z takes +X to +Y.
    n = pyrender.Node(rotation=[0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)])
    assert np.allclose(n.matrix[:3, 0], [0, 1, 0])
    n.matrix = np.diag([2.0, 3.0, 4.0, 1.0])
    assert np.allclose(n.scale, [2, 3, 4]) and np.allclose(n.rotation, [0, 0, 0, 1])
    cam = scene.add(pyrender.PerspectiveCamera(yfov=1.0), name="cam", parent_name="parent")
    assert scene.main_camera_node is cam and cam in parent.children
    with pytest.raises(ValueError):
        scene.add_node(child)  # already in the scene
    scene.remove_node(parent)  # and its children with it
    assert scene.nodes == set() and scene.main_camera_node is None
    with pytest.raises(ValueError):
        scene.get_pose(child)
    with pytest.raises(TypeError):
        scene.add("not a mesh")
    scene.add(box)
    scene.clear()
    assert len(scene.nodes) == 0 and np.allclose(scene.bounds, 0)


def test_render_tracks_set_pose_and_remove_node():
    scene, node = box_scene(bg_color=[0, 0, 0, 0])
    r = pyrender.OffscreenRenderer(64, 64)
    _, depth = r.render(scene)
    assert depth[32, 32] == pytest.approx(2.5, abs=1e-3)  # the box's front face at z = 0.5
    pose = np.eye(4)
    pose[2, 3] = -1.0
    scene.set_pose(node, pose)
    _, depth = r.render(scene)
    assert depth[32, 32] == pytest.approx(3.5, abs=1e-3)
    scene.remove_node(node)
    _, depth = r.render(scene)
    assert not depth.any()


def test_cameras_depth_is_metric():
    # A plane at z = 0 seen from z = 2: depth 2 everywhere it covers, for each camera.
    plane = trimesh.Trimesh([[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0]], [[0, 1, 2], [0, 2, 3]])
    for camera in (pyrender.PerspectiveCamera(yfov=np.pi / 3.0, znear=0.1, zfar=10.0),
                   pyrender.OrthographicCamera(xmag=1.0, ymag=1.0),
                   pyrender.IntrinsicsCamera(fx=40, fy=40, cx=32, cy=24)):
        scene = pyrender.Scene()
        scene.add(pyrender.Mesh.from_trimesh(plane))
        scene.add(camera, pose=camera_pose_looking_down(2.0))
        depth = pyrender.OffscreenRenderer(64, 48).render(scene, flags=pyrender.RenderFlags.DEPTH_ONLY)
        assert depth.shape == (48, 64) and depth.dtype == np.float32
        assert np.allclose(depth, 2.0, atol=1e-4), type(camera).__name__
    P = pyrender.PerspectiveCamera(yfov=np.pi / 2, znear=1.0, zfar=3.0, aspectRatio=2.0).get_projection_matrix(200, 100)
    assert np.allclose(P[:2, :2], [[0.5, 0], [0, 1.0]]) and np.allclose(P[2, 2:], [-2.0, -3.0])


def test_lights_directions_and_spot_validation():
    # A directional light along the node's -Z lights a face turned to it, not one turned away.
    scene, _ = box_scene(bg_color=[0, 0, 0, 1])
    for n in list(scene.light_nodes):
        scene.remove_node(n)
    color, _ = pyrender.OffscreenRenderer(64, 64).render(scene)
    assert color[32, 32].max() == 0  # no light, no ambient: black, as pyrender's
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=camera_pose_looking_down())
    lit, _ = pyrender.OffscreenRenderer(64, 64).render(scene)
    assert lit[32, 32].min() > 30
    away = np.diag([1.0, -1.0, -1.0, 1.0])  # pointing towards +Z: the lit face is turned from it
    scene.set_pose(next(iter(scene.directional_light_nodes)), away)
    dark, _ = pyrender.OffscreenRenderer(64, 64).render(scene)
    assert dark[32, 32].max() == 0
    point = scene.add(pyrender.PointLight(color=[1.0, 0.0, 0.0], intensity=5.0), pose=camera_pose_looking_down(2))
    red, _ = pyrender.OffscreenRenderer(64, 64).render(scene)
    assert red[32, 32, 0] > 30 and red[32, 32, 1] == 0 and scene.point_light_nodes == {point}
    with pytest.raises(ValueError):
        pyrender.SpotLight(innerConeAngle=1.0, outerConeAngle=0.5)
    with pytest.raises(ValueError):
        pyrender.PointLight(intensity=-1.0)
    spot = pyrender.SpotLight(color=[0, 255, 0], intensity=2.0)
    assert np.allclose(spot.color, [0, 1, 0]) and spot.outerConeAngle == pytest.approx(np.pi / 4)


def test_mesh_vertex_and_face_colors():
    flat = pyrender.RenderFlags.FLAT
    quad_v = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    quad_f = [[0, 1, 2], [0, 2, 3]]
    # Face colours (uint8 RGBA, as trimesh keeps them), smooth=False as pyrender requires.
    faces = trimesh.Trimesh(quad_v, quad_f, visual=trimesh.Visual(
        kind="face", face_colors=np.array([[255, 0, 0, 255], [0, 0, 255, 255]], dtype=np.uint8)))
    with pytest.raises(ValueError):
        pyrender.Mesh.from_trimesh(faces)  # pyrender: "Cannot use face colors with a smooth mesh"
    scene = pyrender.Scene()
    scene.add(pyrender.Mesh.from_trimesh(faces, smooth=False))
    scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=camera_pose_looking_down())
    color, _ = pyrender.OffscreenRenderer(32, 32).render(scene, flat)
    assert tuple(color[28, 26]) == (255, 0, 0)  # below the diagonal: face 0
    assert tuple(color[4, 6]) == (0, 0, 255)    # above it: face 1
    # Vertex colours, interpolated.
    verts = trimesh.Trimesh(quad_v, quad_f, visual=trimesh.Visual(
        kind="vertex", vertex_colors=np.array([[255, 0, 0, 255]] * 2 + [[0, 255, 0, 255]] * 2, dtype=np.uint8)))
    scene = pyrender.Scene()
    scene.add(pyrender.Mesh.from_trimesh(verts))
    scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=camera_pose_looking_down())
    color, _ = pyrender.OffscreenRenderer(32, 32).render(scene, flat)
    bottom, top, middle = color[31, 16].astype(int), color[0, 16].astype(int), color[16, 16].astype(int)
    assert bottom[0] > 240 and top[1] > 240 and abs(middle[0] - middle[1]) < 20


def test_primitive_and_material_directly():
    positions = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], dtype=np.float32)
    material = pyrender.MetallicRoughnessMaterial(baseColorFactor=[0.0, 0.5, 1.0, 1.0], metallicFactor=0.0,
                                                  roughnessFactor=0.5, doubleSided=True)
    prim = pyrender.Primitive(positions=positions, indices=[[0, 1, 2]], material=material)
    mesh = pyrender.Mesh(primitives=[prim])
    assert np.allclose(mesh.bounds, [[-1, -1, 0], [1, 1, 0]])
    scene = pyrender.Scene()
    scene.add(mesh, pose=np.diag([1.0, 1.0, -1.0, 1.0]) @ np.diag([-1.0, 1.0, 1.0, 1.0]))  # seen from behind
    scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=camera_pose_looking_down())
    color, _ = pyrender.OffscreenRenderer(32, 32).render(scene, pyrender.RenderFlags.FLAT)
    assert tuple(color[20, 16]) == (0, 128, 255)  # double-sided: drawn from behind too
    with pytest.raises(ValueError):
        pyrender.Primitive(positions=positions, normals=np.zeros((2, 3)))
    with pytest.raises(ValueError):
        pyrender.Primitive(positions=positions, mode=pyrender.GLTF.LINES)
    strip = pyrender.Primitive(positions=np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], np.float32),
                               mode=pyrender.GLTF.TRIANGLE_STRIP)
    assert strip._faces().tolist() == [[0, 1, 2], [1, 3, 2]]  # both counter-clockwise


def test_segmentation_colour_image_is_the_segmentation():
    scene = pyrender.Scene()
    left = scene.add(pyrender.Mesh.from_trimesh(trimesh.box()), pose=np.array(
        [[1, 0, 0, -0.8], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]))
    right = scene.add(pyrender.Mesh.from_trimesh(trimesh.box()), pose=np.array(
        [[1, 0, 0, 0.8], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]]))
    hidden = scene.add(pyrender.Mesh.from_trimesh(trimesh.box(extents=(4, 4, 0.1))), pose=np.array(
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1.0], [0, 0, 0, 1.0]]))  # in front of both, not in the map
    scene.add(pyrender.OrthographicCamera(xmag=2.0, ymag=1.0), pose=camera_pose_looking_down(3.0))
    r = pyrender.OffscreenRenderer(80, 40)  # 20 pixels a unit: the boxes at columns 14..34 and 46..66
    seg_node_map = {left: [255, 0, 0], right: 7}  # a colour, or one number for grey
    color, depth = r.render(scene, pyrender.RenderFlags.SEG, seg_node_map)
    assert color.shape == (40, 80, 3) and color.dtype == np.uint8
    assert tuple(color[20, 24]) == (255, 0, 0) and tuple(color[20, 56]) == (7, 7, 7)
    assert tuple(color[20, 40]) == (0, 0, 0) and tuple(color[2, 2]) == (0, 0, 0)
    assert depth[20, 24] == pytest.approx(2.5, abs=1e-3)  # the hidden node is not drawn at all
    assert {tuple(c) for c in np.unique(color.reshape(-1, 3), axis=0)} == {(0, 0, 0), (255, 0, 0), (7, 7, 7)}
    assert (color == [255, 0, 0]).all(axis=2).sum() == 20 * 20  # exact edges, no blending
    rgba, _ = r.render(scene, pyrender.RenderFlags.SEG | pyrender.RenderFlags.RGBA, seg_node_map)
    assert rgba.shape == (40, 80, 4) and tuple(rgba[20, 24]) == (255, 0, 0, 255)
    assert hidden in scene.mesh_nodes


def test_point_cloud_with_colours_and_depth():
    points = np.array([[0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.5, 0.5, -1.0], [-0.5, -0.5, 0.5]])
    colors = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 0.0]])
    cloud = pyrender.Mesh.from_points(points, colors=colors)
    scene = pyrender.Scene(bg_color=[0, 0, 0])
    node = scene.add(cloud)
    scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=camera_pose_looking_down(2.0))
    r = pyrender.OffscreenRenderer(40, 40, point_size=1.0)
    color, depth = r.render(scene, pyrender.RenderFlags.FLAT)
    # x = 0 lands on pixel column 20 (the pixel whose left edge is the image's centre line).
    assert tuple(color[20, 20]) == (255, 0, 0) and depth[20, 20] == pytest.approx(2.0)
    assert tuple(color[10, 30]) == (0, 255, 0) and depth[10, 30] == pytest.approx(2.0)  # the nearer of two
    assert tuple(color[30, 10]) == (255, 255, 0) and depth[30, 10] == pytest.approx(1.5)
    assert (depth > 0).sum() == 3
    big = pyrender.OffscreenRenderer(40, 40, point_size=3.0)
    _, depth3 = big.render(scene, pyrender.RenderFlags.FLAT)
    assert (depth3 > 0).sum() == 27
    seg, _ = r.render(scene, pyrender.RenderFlags.SEG, {node: [9, 8, 7]})
    assert tuple(seg[20, 20]) == (9, 8, 7) and (seg.sum(axis=2) > 0).sum() == 3


def test_instancing_with_poses():
    poses = np.tile(np.eye(4), (3, 1, 1))
    poses[:, 0, 3] = [-2.0, 0.0, 2.0]  # three boxes in a row
    mesh = pyrender.Mesh.from_trimesh(trimesh.box(extents=(0.5, 0.5, 0.5)), poses=poses)
    scene = pyrender.Scene()
    node = scene.add(mesh)
    assert np.allclose(scene.bounds, [[-2.25, -0.25, -0.25], [2.25, 0.25, 0.25]])
    scene.add(pyrender.OrthographicCamera(xmag=3.0, ymag=1.0), pose=camera_pose_looking_down())
    r = pyrender.OffscreenRenderer(60, 20)
    seg, depth = r.render(scene, pyrender.RenderFlags.SEG, {node: [1, 2, 3]})
    covered = depth > 0
    columns = np.flatnonzero(covered.any(axis=0))
    assert len(columns) == 15  # three boxes, each 0.5 wide = 5 pixels
    assert np.all(seg[covered] == [1, 2, 3])


def test_render_flags_every_member_and_refusals():
    names = ["NONE", "DEPTH_ONLY", "OFFSCREEN", "FLIP_WIREFRAME", "ALL_WIREFRAME", "ALL_SOLID",
             "SHADOWS_DIRECTIONAL", "SHADOWS_POINT", "SHADOWS_SPOT", "SHADOWS_ALL", "VERTEX_NORMALS",
             "FACE_NORMALS", "SKIP_CULL_FACES", "RGBA", "FLAT", "SEG"]
    values = [0, 1, 2, 4, 8, 16, 32, 64, 128, 224, 256, 512, 1024, 2048, 4096, 8192]
    assert [int(getattr(pyrender.RenderFlags, n)) for n in names] == values
    scene, _ = box_scene()
    r = pyrender.OffscreenRenderer(16, 16)
    for flag in (pyrender.RenderFlags.VERTEX_NORMALS, pyrender.RenderFlags.FACE_NORMALS):
        with pytest.raises(ValueError, match=flag.name):
            r.render(scene, flag)
    color, depth = r.render(scene, pyrender.RenderFlags.OFFSCREEN | pyrender.RenderFlags.SHADOWS_ALL |
                            pyrender.RenderFlags.SKIP_CULL_FACES)
    assert color.shape == (16, 16, 3) and depth[8, 8] > 0
    rgba, _ = r.render(scene, pyrender.RenderFlags.RGBA)
    assert rgba.shape == (16, 16, 4) and rgba[8, 8, 3] == 255
    wire, _ = r.render(scene, pyrender.RenderFlags.ALL_WIREFRAME)
    solid, _ = r.render(scene, pyrender.RenderFlags.FLIP_WIREFRAME | pyrender.RenderFlags.ALL_SOLID)
    assert (wire != 255).any(axis=2).sum() < (solid != 255).any(axis=2).sum()
    r.delete()
    with pytest.raises(RuntimeError):
        r.render(scene)


def test_camera_setters_validate_like_the_constructors():
    cam = pyrender.PerspectiveCamera(yfov=np.pi / 3.0, znear=0.1, zfar=10.0)
    with pytest.raises(ValueError, match="yfov"):
        cam.yfov = 0.0
    with pytest.raises(ValueError, match="smallest znear"):
        cam.znear = 1e-9
    assert cam.yfov == pytest.approx(np.pi / 3.0) and cam.znear == 0.1
    with pytest.raises(ValueError):
        pyrender.IntrinsicsCamera(fx=0, fy=1, cx=0, cy=0)
    ortho = pyrender.OrthographicCamera(xmag=1.0, ymag=1.0)
    with pytest.raises(ValueError, match="xmag"):
        ortho.xmag = -1.0
    light = pyrender.PointLight()
    with pytest.raises(ValueError):
        light.intensity = float("inf")


def test_random_inputs_raise_documented_errors_only():
    # A fuzz of the API surface: random shapes, types and values for what scripts pass.
    # Every call either works or raises ValueError / TypeError / velocity.Error; the
    # process never crashes, and a render that works returns pyrender's shapes.
    import velocity
    rng = np.random.default_rng(20261126)
    allowed = (ValueError, TypeError, velocity.Error)

    def junk():
        kind = rng.integers(7)
        shape = tuple(int(s) for s in rng.integers(0, 5, size=rng.integers(0, 4)))
        if kind == 0:
            return rng.normal(size=shape) * 10 ** rng.integers(-9, 9)
        if kind == 1:
            return rng.integers(-300, 300, size=shape).astype(rng.choice([np.int8, np.int64, np.uint16]))
        if kind == 2:
            return np.full(shape, rng.choice([np.nan, np.inf, -np.inf]))
        if kind == 3:
            return [float(x) for x in rng.normal(size=int(rng.integers(0, 6)))]
        if kind == 4:
            return "text"
        if kind == 5:
            return None
        return rng.random((int(rng.integers(1, 9)), 3)).astype(np.float32)

    r = pyrender.OffscreenRenderer(24, 16, point_size=2)
    for i in range(300):
        scene = pyrender.Scene(bg_color=[0, 0, 0])
        try:
            what = i % 6
            if what == 0:
                prim = pyrender.Primitive(positions=junk(), normals=junk() if rng.random() < 0.3 else None,
                                          color_0=junk() if rng.random() < 0.3 else None,
                                          indices=junk() if rng.random() < 0.5 else None,
                                          mode=int(rng.choice([0, 4, 5, 6])))
                scene.add(pyrender.Mesh([prim]))
            elif what == 1:
                scene.add(pyrender.Mesh.from_points(junk(), colors=junk() if rng.random() < 0.5 else None))
            elif what == 2:
                mat = pyrender.MetallicRoughnessMaterial(baseColorFactor=junk(), metallicFactor=float(rng.normal()),
                                                         roughnessFactor=float(rng.normal()),
                                                         baseColorTexture=junk() if rng.random() < 0.5 else None)
                scene.add(pyrender.Mesh.from_trimesh(trimesh.box(), material=mat))
            elif what == 3:
                scene.add(pyrender.Mesh.from_trimesh(trimesh.box()), pose=junk())
            elif what == 4:
                scene.add(pyrender.SpotLight(color=junk(), intensity=float(rng.normal()),
                                             innerConeAngle=float(rng.normal()), outerConeAngle=float(rng.normal())))
            else:
                velocity.Material(image=junk(), metallic=float(rng.normal()))
            scene.add(pyrender.PerspectiveCamera(yfov=float(rng.uniform(-1, 4)), znear=float(rng.uniform(-1, 1))),
                      pose=camera_pose_looking_down())
            out = r.render(scene, int(rng.integers(0, 1 << 14)) & ~(256 | 512))
        except allowed:
            continue
        if isinstance(out, tuple):
            assert out[0].shape[:2] == (16, 24) and out[1].shape == (16, 24)
        else:
            assert out.shape == (16, 24)


def test_viewer_says_what_to_use_instead():
    scene, _ = box_scene()
    with pytest.raises(NotImplementedError, match="OffscreenRenderer"):
        pyrender.Viewer(scene, use_raymond_lighting=True)  # pyrender's quickstart, first example


def test_spot_light_cone_and_resized_viewport():
    # A spot light straight above a floor lights a disc: inside the inner cone fully,
    # outside the outer cone not at all; then the renderer resized, as users do.
    floor = trimesh.Trimesh([[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], [[0, 1, 2], [0, 2, 3]])
    scene = pyrender.Scene(bg_color=[0, 0, 0], ambient_light=[0, 0, 0])
    scene.add(pyrender.Mesh.from_trimesh(floor))
    scene.add(pyrender.OrthographicCamera(xmag=4.0, ymag=4.0), pose=camera_pose_looking_down(5.0))
    inner, outer = np.pi / 12, np.pi / 6
    scene.add(pyrender.SpotLight(color=np.ones(3), intensity=20.0, innerConeAngle=inner, outerConeAngle=outer),
              pose=camera_pose_looking_down(2.0))
    r = pyrender.OffscreenRenderer(80, 80)
    color, _ = r.render(scene)
    grey = color[:, :, 0].astype(int)
    px = 80 / 8.0  # pixels per unit
    yy, xx = np.mgrid[0:80, 0:80]
    dist = np.hypot(xx + 0.5 - 40, yy + 0.5 - 40) / px  # from the spot's centre, in units
    inside = dist < 2.0 * np.tan(inner) * 0.9
    outside = dist > 2.0 * np.tan(outer) * 1.1
    assert grey[inside].min() > 40 and grey[outside].max() == 0
    r.viewport_width, r.viewport_height = 40, 20
    color, depth = r.render(scene)
    assert color.shape == (20, 40, 3) and depth.shape == (20, 40)
