"""Depth is right: a finely tessellated sphere against the analytic ray-sphere answer.

The mesh's vertices lie on a sphere of radius R, and the mesh (convex) holds the ball
of radius R_in (its smallest face-plane distance): every ray's first hit on the mesh
lies between its hits on those two spheres. That interval, widened only by the
rasterizer's 1/256-pixel vertex snapping (rays moved that far) and by float depth
precision, is what each pixel's depth must fall in; pixels whose rays miss the outer
sphere must read 0. For perspective, intrinsics and orthographic cameras, posed off
axis with a roll, the sphere off centre.
"""
import math
import warnings

import numpy as np
import pytest

import velocity
from conftest import inscribed_radius, uv_sphere

W, H = 160, 120
NEAR, FAR = 1.0, 10.0
CENTER = np.array([0.3, -0.2, 0.1])
R = 1.0
SNAP = 1.0 / 256  # pixels: the rasterizer's 24.8 fixed point


def rays(kind, cam, u, v):
    """Camera-space ray origins and directions (direction z = -1, so t is view depth)
    through image points (u, v), in pixels from the top-left corner."""
    n = u.shape
    o, d = np.zeros(n + (3,)), np.zeros(n + (3,))
    d[..., 2] = -1
    x_ndc, y_ndc = u / W * 2 - 1, 1 - v / H * 2
    if kind == "perspective":
        t = math.tan(cam.yfov / 2)
        d[..., 0], d[..., 1] = x_ndc * t * W / H, y_ndc * t
    elif kind == "intrinsics":
        d[..., 0], d[..., 1] = (u - cam.cx) / cam.fx, -(v - cam.cy) / cam.fy
    else:
        o[..., 0], o[..., 1] = x_ndc * cam.xmag, y_ndc * cam.ymag
    return o, d


def hits(o, d, c, r):
    """(t_enter, t_exit) of the rays on the sphere (c, r); NaN where they miss."""
    oc = o - c
    a = np.einsum("...i,...i", d, d)
    b = 2 * np.einsum("...i,...i", d, oc)
    k = np.einsum("...i,...i", oc, oc) - r * r
    disc = b * b - 4 * a * k
    s = np.sqrt(np.where(disc >= 0, disc, np.nan))
    return (-b - s) / (2 * a), (-b + s) / (2 * a)


@pytest.mark.parametrize("kind", ["perspective", "intrinsics", "orthographic"])
def test_depth_matches_the_analytic_sphere(kind):
    vertices, faces = uv_sphere(256, R)
    r_in = inscribed_radius(vertices, faces)
    assert R - r_in < 2e-4  # finely tessellated: the bound is tight
    mesh = velocity.Mesh.from_arrays(vertices, faces)
    if kind == "perspective":
        cam = velocity.PerspectiveCamera(math.radians(50), znear=NEAR, zfar=FAR)
    elif kind == "intrinsics":
        cam = velocity.IntrinsicsCamera(fx=150, fy=140, cx=70.25, cy=65.5, znear=NEAR, zfar=FAR)
    else:
        cam = velocity.OrthographicCamera(xmag=1.6, ymag=1.2, znear=NEAR, zfar=FAR)
    pose = velocity.look_at([1.2, 1.5, 3.4], [0.1, -0.1, 0.0], up=[0.2, 1.0, 0.1])
    model = np.eye(4)
    model[:3, 3] = CENTER
    scene = velocity.Scene()
    scene.add(mesh, pose=model)
    scene.add(cam, pose=pose)
    depth = velocity.OffscreenRenderer(W, H).render(scene, velocity.RenderFlags.DEPTH_ONLY).astype(np.float64)

    c = (np.linalg.inv(pose) @ np.append(CENTER, 1.0))[:3]
    v, u = np.mgrid[0:H, 0:W].astype(np.float64) + 0.5
    offsets = [(0, 0), (SNAP, 0), (-SNAP, 0), (0, SNAP), (0, -SNAP)]
    outer_in, outer_out, inner_in = [], [], []
    for du, dv in offsets:
        o, d = rays(kind, cam, u + du, v + dv)
        a, b = hits(o, d, c, R)
        outer_in.append(a), outer_out.append(b), inner_in.append(hits(o, d, c, r_in)[0])
    outer_in, outer_out, inner_in = np.array(outer_in), np.array(outer_out), np.array(inner_in)
    misses = np.all(np.isnan(outer_in), axis=0)
    inside = np.all(~np.isnan(inner_in), axis=0)
    rim = ~misses & ~inside
    with warnings.catch_warnings():  # all-NaN columns are the empty pixels
        warnings.simplefilter("ignore", RuntimeWarning)
        lo = np.nanmin(outer_in, axis=0)
        hi_rim = np.nanmax(outer_out, axis=0)
    hi_inside = np.max(inner_in, axis=0)
    # Float depth: window depth in float (4 ulps of 1.0) through the projection's
    # inverse, plus float arithmetic along the way.
    if kind == "orthographic":
        quant = 4 * 2.0 ** -24 * (FAR - NEAR) / 2 * 2
    else:
        quant = 4 * 2.0 ** -24 * (FAR - NEAR) * np.nan_to_num(hi_rim, nan=FAR) ** 2 / (FAR * NEAR)
    tol = 2e-6 * np.nan_to_num(hi_rim, nan=FAR) + quant

    assert inside.sum() > 2000, "the sphere should fill much of the view"
    assert np.all(depth[misses] == 0), "depth where the rays miss the sphere must be 0"
    d_in = depth[inside]
    assert np.all(d_in > 0), "every ray through the inner ball must hit the mesh"
    err_low = lo[inside] - tol[inside] - d_in
    err_high = d_in - hi_inside[inside] - tol[inside]
    worst = max(err_low.max(), err_high.max())
    d_rim = depth[rim]
    hit = d_rim > 0
    worst_rim = max(np.max((lo[rim] - tol[rim] - d_rim)[hit], initial=-1),
                    np.max((d_rim - hi_rim[rim] - tol[rim])[hit], initial=-1))
    band = float(np.max(hi_inside[inside] - lo[inside]))
    print(f"[depth] {kind}: {inside.sum()} pixels inside, {rim.sum()} on the rim, {misses.sum()} empty; "
          f"bound width up to {band:.2e}; worst excess {worst:.2e} (<= 0 passes), rim {worst_rim:.2e}")
    assert worst <= 0, f"{kind}: a depth is outside the tessellation's bound by {worst:.3e}"
    assert worst_rim <= 0, f"{kind}: a rim depth is outside the sphere by {worst_rim:.3e}"


def test_orthographic_depth_is_exact_on_a_plane():
    # A plane facing the camera at a known distance: every pixel reads it exactly
    # (float), whatever the near and far planes.
    v = np.array([[-3, -3, 0], [3, -3, 0], [3, 3, 0], [-3, 3, 0]], np.float32)
    f = np.array([[0, 1, 2], [0, 2, 3]], np.uint32)
    for near, far in ((0.5, 20.0), (3.0, 1000.0)):
        scene = velocity.Scene()
        scene.add(velocity.Mesh.from_arrays(v, f))
        scene.add(velocity.OrthographicCamera(1, 1, znear=near, zfar=far), pose=velocity.look_at([0, 0, 7.25], [0, 0, 0]))
        depth = velocity.OffscreenRenderer(32, 32).render(scene, velocity.RenderFlags.DEPTH_ONLY)
        assert np.allclose(depth, 7.25, rtol=0, atol=4 * 2.0 ** -24 * (far - near))
