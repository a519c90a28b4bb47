"""The renderer's appearance options (RenderOptions: color, tone_map, exposure, shadows,
shadow_map_size, point_size) from Python: keywords and properties, validated alike;
each changes the image it should; RenderFlags.SHADOWS_* (here and in velocity.pyrender)
reach the engine's options and lights."""
import math

import numpy as np
import pytest

import velocity
import velocity.pyrender as pyrender

OPTIONS = dict(color="linear", tone_map="aces", exposure=0.5, shadows=True, shadow_map_size=512, point_size=4.0)
BAD = [("color", "srgb", "'auto', 'linear' or 'display'"), ("tone_map", "filmic", "'none', 'aces' or 'neutral'"),
       ("exposure", -1.0, ">= 0"), ("exposure", math.nan, ">= 0"), ("exposure", math.inf, ">= 0"),
       ("shadow_map_size", 8, "16..8192"), ("shadow_map_size", 9000, "16..8192"),
       ("point_size", 0.5, "1..64"), ("point_size", 65.0, "1..64"), ("point_size", math.nan, "1..64")]


def sphere_scene(material, light=None, ambient=(0.0, 0.0, 0.0)):
    scene = velocity.Scene(bg_color=(0, 0, 0, 1), ambient_light=ambient)
    ref = velocity.Mesh.sphere(32).primitives[0]
    scene.add(velocity.Mesh.from_arrays(np.array(ref.positions), np.array(ref.indices),
                                        normals=np.array(ref.normals), material=material))
    scene.add(velocity.PerspectiveCamera(math.radians(40)), pose=velocity.look_at([0, 0, 3.2], [0, 0, 0]))
    scene.add(light or velocity.DirectionalLight(intensity=4.0), pose=velocity.look_at([0, 0, 0], [-0.4, -0.5, -1]))
    return scene


def test_options_are_keywords_and_properties():
    r = velocity.OffscreenRenderer(16, 12, **OPTIONS)
    assert {k: getattr(r, k) for k in OPTIONS} == OPTIONS
    d = velocity.OffscreenRenderer(16, 12)
    assert (d.color, d.tone_map, d.exposure, d.shadows, d.shadow_map_size, d.point_size) == \
        ("auto", "none", 1.0, False, 2048, 1.0)
    for k, v in OPTIONS.items():
        setattr(d, k, v)
    assert {k: getattr(d, k) for k in OPTIONS} == OPTIONS
    assert d.last_frame is None  # nothing rendered yet


@pytest.mark.parametrize("key,value,words", BAD)
def test_bad_values_are_refused_by_constructor_and_setter_alike(key, value, words):
    with pytest.raises(ValueError, match=key) as made:
        velocity.OffscreenRenderer(8, 8, **{key: value})
    r = velocity.OffscreenRenderer(8, 8)
    before = getattr(r, key)
    with pytest.raises(ValueError, match=key) as set_:
        setattr(r, key, value)
    assert words in str(made.value) and str(made.value) == str(set_.value)
    assert getattr(r, key) == before  # unchanged


def test_the_frame_gets_the_options():
    r = velocity.OffscreenRenderer(24, 16, **OPTIONS)
    r.render(sphere_scene(velocity.Material(color=(0.8, 0.5, 0.3), metallic=0.0, roughness=0.5)))
    got = r.last_frame
    assert {k: got[k] for k in OPTIONS} == OPTIONS
    assert got["backend"] == "cpu" and got["backend_reason"] == "asked for"


def lit(image):
    return image[image.sum(axis=2) > 0].astype(np.float64)


def test_exposure_scales_linear_light():
    pbr = velocity.Material(color=(0.6, 0.6, 0.6), metallic=0.0, roughness=0.6)
    scene = sphere_scene(pbr)
    full, _ = velocity.OffscreenRenderer(64, 64, exposure=1.0).render(scene)
    half, _ = velocity.OffscreenRenderer(64, 64, exposure=0.5).render(scene)
    dark, _ = velocity.OffscreenRenderer(64, 64, exposure=0.0).render(scene)
    assert lit(half).mean() < lit(full).mean() - 20
    assert dark.max() == 0  # no light at all (the background is black too)
    # Half the light, encoded to sRGB: a linear 0.5 is 188 of 255, so mid-tones fall to
    # about 0.73 of their value, not 0.5.
    both = (full.sum(axis=2) > 60) & (full.max(axis=2) < 200)
    ratio = half[both].astype(float).mean() / full[both].astype(float).mean()
    assert 0.66 < ratio < 0.80


def test_tone_maps_compress_highlights():
    pbr = velocity.Material(color=(0.9, 0.9, 0.9), metallic=0.0, roughness=0.4)
    scene = sphere_scene(pbr, velocity.DirectionalLight(intensity=30.0))
    images = {t: velocity.OffscreenRenderer(64, 64, tone_map=t).render(scene)[0] for t in ("none", "aces", "neutral")}
    clipped = {t: int((im == 255).all(axis=2).sum()) for t, im in images.items()}
    assert clipped["none"] > 200  # over-exposed: a white disc
    assert clipped["aces"] < clipped["none"] // 4 and clipped["neutral"] < clipped["none"]
    assert not np.array_equal(images["aces"], images["neutral"])


def test_color_pipeline_linear_and_display_differ_for_the_seed_shading():
    gouraud = velocity.Material(color=(0.5, 0.5, 0.5), shading="gouraud")
    scene = sphere_scene(gouraud, velocity.DirectionalLight(intensity=math.pi * 0.5))
    display, _ = velocity.OffscreenRenderer(48, 48, color="display").render(scene)
    linear, _ = velocity.OffscreenRenderer(48, 48, color="linear").render(scene)
    auto, _ = velocity.OffscreenRenderer(48, 48).render(scene)
    np.testing.assert_array_equal(auto, display)  # auto: display for a frame without PBR
    assert lit(linear).mean() > lit(display).mean() + 20  # encoded to sRGB: brighter mid-tones


def test_point_size_grows_each_point():
    pts = np.array([[-0.5, -0.5, 0], [0.5, 0.2, 0], [0.1, 0.6, 0]], np.float32)
    faces = np.array([[0, 1, 2]])
    scene = velocity.Scene(bg_color=(0, 0, 0, 1))
    scene.add(velocity.Mesh.from_arrays(pts, faces, material=velocity.Material(color=(1, 1, 1), shading="points")))
    scene.add(velocity.OrthographicCamera(1, 1), pose=velocity.look_at([0, 0, 2], [0, 0, 0]))
    covered = {}
    for size in (1.0, 3.0, 5.0):
        r = velocity.OffscreenRenderer(40, 40, point_size=size)
        _, depth = r.render(scene)
        covered[size] = int((depth > 0).sum())
    assert covered == {1.0: 3, 3.0: 27, 5.0: 75}


def light_scene():
    scene = sphere_scene(velocity.Material(color=(0.7, 0.7, 0.7), metallic=0.0, roughness=0.5))
    point, spot = velocity.PointLight(intensity=5.0), velocity.SpotLight(intensity=5.0)
    scene.add(point, pose=velocity.look_at([0, 2, 2], [0, 0, 0]))
    scene.add(spot, pose=velocity.look_at([2, 0, 2], [0, 0, 0]))
    return scene, point, spot


def test_shadow_flags_reach_the_options_and_the_lights():
    scene, point, spot = light_scene()  # lights in order: directional, point, spot (+ the ambient term)
    r = velocity.OffscreenRenderer(32, 32)
    r.render(scene)
    assert not r.last_frame["shadows"] and r.last_frame["cast_shadows"] == [False] * 4
    r.render(scene, velocity.RenderFlags.SHADOWS_DIRECTIONAL)
    assert r.last_frame["shadows"] and r.last_frame["cast_shadows"] == [True, False, False, False]
    r.render(scene, velocity.RenderFlags.SHADOWS_SPOT | velocity.RenderFlags.SHADOWS_POINT)
    assert r.last_frame["cast_shadows"] == [False, True, True, False]
    spot.cast_shadows = False  # a light may refuse
    r.render(scene, velocity.RenderFlags.SHADOWS_ALL)
    assert r.last_frame["cast_shadows"] == [True, True, False, False]
    r.shadows = True  # every kind, every frame
    r.render(scene)
    assert r.last_frame["shadows"] and r.last_frame["cast_shadows"] == [True, True, False, False]
    r.shadows = False
    r.render(scene)
    assert not r.last_frame["shadows"]  # a flag lasts one frame


@pytest.mark.parametrize("flag,casts", [
    ("SHADOWS_DIRECTIONAL", [True, False, False]), ("SHADOWS_POINT", [False, True, False]),
    ("SHADOWS_SPOT", [False, False, True]), ("SHADOWS_ALL", [True, True, True])])
def test_pyrender_shadow_flags_reach_the_engine(flag, casts):
    # As a pyrender script asks for shadows.
    scene = pyrender.Scene()
    box = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1]], float) * 0.5
    scene.add(pyrender.Mesh([pyrender.Primitive(positions=box, indices=np.array([[0, 1, 2], [0, 2, 3]]))]))
    scene.add(pyrender.PerspectiveCamera(yfov=np.pi / 3.0), pose=velocity.look_at([0, 0, 3], [0, 0, 0]))
    scene.add(pyrender.DirectionalLight(intensity=2.0), pose=velocity.look_at([0, 0, 2], [0, 0, 0]))
    scene.add(pyrender.PointLight(intensity=2.0), pose=velocity.look_at([0, 1, 2], [0, 0, 0]))
    scene.add(pyrender.SpotLight(intensity=2.0), pose=velocity.look_at([1, 0, 2], [0, 0, 0]))
    r = pyrender.OffscreenRenderer(32, 32)
    r.render(scene, getattr(pyrender.RenderFlags, flag))
    got = r._renderer.last_frame
    assert got["shadows"] and got["cast_shadows"] == casts + [False]
    r.render(scene)
    assert not r._renderer.last_frame["shadows"]


def test_pyrender_shadow_flag_darkens_the_floor_under_a_box():
    # pyrender's SHADOWS_DIRECTIONAL, as a script asks for it: a floor with a block above
    # it under a light from straight above. The floor under the block is in shadow (only
    # the ambient light left), the floor beyond it as lit as without the flag.
    scene = pyrender.Scene(ambient_light=(0.1, 0.1, 0.1), bg_color=(0, 0, 0))
    floor = np.array([[-3, 0, -3], [3, 0, -3], [3, 0, 3], [-3, 0, 3]], float)
    scene.add(pyrender.Mesh([pyrender.Primitive(positions=floor, normals=np.tile([0.0, 1.0, 0.0], (4, 1)),
                                                indices=np.array([[0, 2, 1], [0, 3, 2]]))]))
    top = np.array([[-0.5, 1, -0.5], [0.5, 1, -0.5], [0.5, 1, 0.5], [-0.5, 1, 0.5]], float)
    scene.add(pyrender.Mesh([pyrender.Primitive(positions=top, normals=np.tile([0.0, 1.0, 0.0], (4, 1)),
                                                indices=np.array([[0, 2, 1], [0, 3, 2]]))]))
    # Seen from above and in front; the light comes from above and to the right, so the
    # shadow falls to the left of the block, most of it where the camera sees the floor.
    scene.add(pyrender.PerspectiveCamera(yfov=np.pi / 3.0), pose=velocity.look_at([0, 3, 3], [0, 0, 0]))
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=velocity.look_at([4, 5, 0], [0, 0, 0]))
    r = pyrender.OffscreenRenderer(96, 96)
    lit, _ = r.render(scene)
    shadowed, _ = r.render(scene, pyrender.RenderFlags.SHADOWS_DIRECTIONAL)
    darker = np.abs(lit.astype(int) - shadowed.astype(int)).max(axis=2) > 40
    assert darker.sum() > 100, "no shadow under the block"
    # Where the floor is not under the block nothing changes: at most the shadow's edge.
    changed = np.abs(lit.astype(int) - shadowed.astype(int)).max(axis=2) > 2
    assert changed.sum() < darker.sum() * 1.3
    # Left of the block, as the light falls.
    cols = np.nonzero(darker.any(axis=0))[0]
    assert cols.mean() < 48
    r.delete()
