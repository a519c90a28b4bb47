"""The instance mask (exact node ids, never blended) and camera-space normals."""
import math

import numpy as np

import velocity
from conftest import simple_scene


def two_spheres(ssaa=1):
    scene = velocity.Scene(bg_color=(0, 0, 0, 1), ambient_light=(0.5, 0.5, 0.5))
    near = np.eye(4)
    near[:3, 3] = [-0.4, 0, 0.5]
    far = np.eye(4)
    far[:3, 3] = [0.5, 0.1, -0.5]
    a = scene.add(velocity.Mesh.sphere(64), pose=near, name="near")
    b = scene.add(velocity.Mesh.sphere(64), pose=far, name="far")
    scene.add(velocity.PerspectiveCamera(math.radians(50), znear=0.5, zfar=10), pose=velocity.look_at([0, 0, 4], [0, 0, 0]))
    return scene, a, b


def test_mask_holds_node_ids_exactly_even_with_supersampling():
    for ssaa in (1, 3):
        scene, a, b = two_spheres()
        color, depth, mask = velocity.OffscreenRenderer(200, 150, ssaa=ssaa).render(scene, velocity.RenderFlags.SEG)
        assert mask.dtype == np.uint32 and mask.shape == (150, 200)
        assert set(np.unique(mask)) == {0, a.id, b.id}  # never a blend of the two ids
        assert np.array_equal(mask > 0, depth > 0)      # the same pixels, exactly


def test_mask_picks_the_nearer_object():
    scene, a, b = two_spheres()
    _, depth, mask = velocity.OffscreenRenderer(200, 150).render(scene, velocity.RenderFlags.SEG)
    # Per pixel, render each sphere alone: the mask must name the one with the smaller depth.
    only = {}
    for keep, drop in ((a, b), (b, a)):
        s, x, y = two_spheres()
        s.remove_node(y if keep is a else x)
        only[keep.id] = velocity.OffscreenRenderer(200, 150).render(s, velocity.RenderFlags.DEPTH_ONLY)
    da, db = only[a.id], only[b.id]
    both = (da > 0) & (db > 0)
    assert both.sum() > 100
    expect = np.where(da[both] < db[both], a.id, b.id)
    assert np.array_equal(mask[both], expect)
    assert np.allclose(depth[both], np.minimum(da[both], db[both]))


def test_normals_of_a_sphere_point_away_from_its_centre():
    scene, _ = simple_scene(velocity.Mesh.sphere(128))
    color, depth, normals = velocity.OffscreenRenderer(120, 120).render(scene, velocity.RenderFlags.NORMALS)
    assert normals.shape == (120, 120, 3) and normals.dtype == np.float32
    hit = depth > 0
    assert np.all(normals[~hit] == 0)
    # Camera at (0, 0, 3) looking at the unit sphere: the surface point of pixel (u, v)
    # is where its ray meets the sphere; its normal is that point minus the centre.
    v, u = np.mgrid[0:120, 0:120] + 0.5
    t = math.tan(math.radians(45) / 2)
    d = np.stack([(u / 120 * 2 - 1) * t, (1 - v / 120 * 2) * t, -np.ones_like(u)], -1)
    p = d * depth[..., None]
    p[..., 2] += 3  # camera space -> world (identity rotation), centre at the origin
    expect = p / np.linalg.norm(p, axis=-1, keepdims=True)
    err = np.degrees(np.arccos(np.clip(np.einsum("...i,...i", normals[hit], expect[hit]), -1, 1)))
    print(f"[normals] angle error: median {np.median(err):.2f} deg, 99th percentile {np.percentile(err, 99):.2f} deg")
    assert np.median(err) < 1.0 and np.percentile(err, 99) < 3.0
