#!/usr/bin/env python3
"""Checks the oracle against the glTF spec, not against itself: each check writes a small
glTF file (fixtures.py), renders it with render.py and compares pixels with what the spec
says. The inputs are asymmetric (four distinct texel colours, a quad off the image centre,
three distinct channels, a light off every axis) so that a flip, a transpose or a channel
swap cannot pass.

    check_conventions.py texcoords|srgb|lambert|lights|shadows OUT_DIR

  texcoords  an unlit quad textured with a 2x2 image: the image's top-left texel shows at
             the quad's top-left (uv (0, 0) = the image's top-left), and so on; the quad
             sits where the camera puts it (+Y up in the image); texels decoded from sRGB
             and encoded back unchanged.
  srgb       unlit baseColorFactor 0.5 grey shows 188 (linear 0.5 encoded to sRGB), not
             128; a second quad with three distinct channels shows each channel encoded.
  lambert    a rough dielectric (roughness 1, metallic 0) under one directional light at
             60 degrees from the normal: each sampled pixel equals glTF's BRDF (Appendix B)
             in closed form, within 2/255.
  lights     the same surface under a point light with a range, then a spot light:
             KHR_lights_punctual's inverse-square falloff and range window, within
             2/255; the spot's cone is 1 inside the inner angle and 0 outside the outer
             one. Between them three.js uses smoothstep in cos(angle), where the
             extension's reference uses the square of a linear ramp: checked against
             three.js's curve, and the difference printed.
  shadows    (render.py --shadows) a small quad half a unit above the rough quad, one
             directional light: the shadow is black where geometry puts it (the
             occluder moved along the light's direction), the ground lit elsewhere,
             including where a light mirrored in x and y would put it; no acne and no
             light leaking under the occluder anywhere away from the edges.

Exit status 0 pass, 1 fail, 77 Chromium missing (ctest's SKIP_RETURN_CODE).
"""
from __future__ import annotations

import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fixtures  # noqa: E402
import png  # noqa: E402
from camera import Camera, normalize, srgb_encode  # noqa: E402

RENDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render.py")
SKIP = 77
# 64x64, looking down -Z from 3 units: the plane z = 0 spans x, y in about +-1.24.
CAMERA = Camera(eye=[0, 0, 3], target=[0, 0, 0], up=[0, 1, 0], yfov=45, width=64, height=64)
BACKGROUND = (0.2, 0.4, 0.6)  # sRGB / 255: 51, 102, 153


class Failed(Exception):
    pass


def render(gltf_path: str, out_png: str, extra: list[str]) -> tuple[int, int, bytes]:
    cmd = [sys.executable, RENDER, gltf_path, "--out", out_png, *CAMERA.args(),
           "--bg", ",".join(map(str, BACKGROUND)), *extra]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if run.returncode == SKIP:
        print(f"SKIP: {run.stderr.strip()}")
        sys.exit(SKIP)
    if run.returncode != 0:
        raise Failed(f"render.py failed: {run.stderr.strip()}")
    print(run.stdout.strip())
    w, h, c, pixels = png.read(out_png)
    assert c == 3
    return w, h, pixels


def pixel(image, x: float, y: float) -> tuple[int, int, int]:
    w, _, pixels = image
    i = 3 * (int(y) * w + int(x))
    return tuple(pixels[i:i + 3])


def expect(what: str, got, want, tolerance: float) -> None:
    worst = max(abs(g - w) for g, w in zip(got, want))
    verdict = "ok" if worst <= tolerance else "FAIL"
    print(f"  {what}: got {tuple(got)}, want {tuple(round(w, 2) for w in want)}, "
          f"off by {worst:.2f} (tolerance {tolerance}) {verdict}")
    if worst > tolerance:
        raise Failed(f"{what}: got {tuple(got)}, want {tuple(round(w, 2) for w in want)}")


def check_texcoords(out: str) -> None:
    # Off-centre (x in [-1, 0.6], y in [-0.6, 1]) so that an image written bottom-up or
    # mirrored moves the quad, not just its texels.
    texels = {"top-left": (200, 30, 30), "top-right": (30, 200, 30),
              "bottom-left": (30, 30, 200), "bottom-right": (200, 200, 30)}
    image = fixtures.image_png(2, 2, [texels["top-left"], texels["top-right"],
                                      texels["bottom-left"], texels["bottom-right"]])
    material = {"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                "extensions": {fixtures.UNLIT: {}}}
    x0, x1, y0, y1 = -1.0, 0.6, -0.6, 1.0
    path = fixtures.write(os.path.join(out, "texcoords.gltf"), fixtures.gltf([fixtures.Quad(x0, x1, y0, y1, material)], image))
    img = render(path, os.path.join(out, "texcoords.png"), [])
    xs, ys = (x0 + (x1 - x0) / 4, x0 + 3 * (x1 - x0) / 4), (y1 - (y1 - y0) / 4, y1 - 3 * (y1 - y0) / 4)
    for (name, colour), (x, y) in zip(texels.items(), [(xs[0], ys[0]), (xs[1], ys[0]), (xs[0], ys[1]), (xs[1], ys[1])]):
        expect(f"{name} quadrant at ({x:g}, {y:g})", pixel(img, *CAMERA.project([x, y, 0])), colour, 2)
    bg = [255 * c for c in BACKGROUND]
    for name, corner in (("right of the quad", [0.9, 0.2, 0]), ("below the quad", [-0.2, -0.9, 0])):
        expect(f"background {name}", pixel(img, *CAMERA.project(corner)), bg, 1)


def check_srgb(out: str) -> None:
    grey = {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}, "extensions": {fixtures.UNLIT: {}}}
    rgb = (0.8, 0.2, 0.05)
    colour = {"pbrMetallicRoughness": {"baseColorFactor": [*rgb, 1]}, "extensions": {fixtures.UNLIT: {}}}
    path = fixtures.write(os.path.join(out, "srgb.gltf"), fixtures.gltf(
        [fixtures.Quad(-1, -0.1, -1, 1, grey), fixtures.Quad(0.1, 1, -1, 1, colour)]))
    img = render(path, os.path.join(out, "srgb.png"), ["--tone", "none"])
    got = pixel(img, *CAMERA.project([-0.55, 0, 0]))
    expect("unlit baseColorFactor 0.5", got, [255 * srgb_encode(0.5)] * 3, 1)
    if got[0] <= 130:
        raise Failed(f"0.5 grey shows {got[0]}: written linear, not sRGB-encoded")
    expect(f"unlit baseColorFactor {rgb}", pixel(img, *CAMERA.project([0.55, 0, 0])),
           [255 * srgb_encode(c) for c in rgb], 1)


def gltf_brdf(base: float, n, l, v, roughness: float) -> float:
    """glTF 2.0's metallic-roughness BRDF (spec Appendix B) for a dielectric, metallic 0:
    fresnel_mix(ior 1.5, diffuse c/pi, GGX specular), times N.L: the outgoing radiance for
    unit irradiance. V is the spec's separable Smith-GGX visibility, D GGX, alpha = r^2."""
    h = normalize([l[k] + v[k] for k in range(3)])
    nl, nv, nh = (sum(a * b for a, b in zip(n, x)) for x in (l, v, h))
    vh = sum(a * b for a, b in zip(v, h))
    alpha2 = roughness ** 4
    fresnel = 0.04 + (1 - 0.04) * (1 - abs(vh)) ** 5
    d = alpha2 / (math.pi * (nh * nh * (alpha2 - 1) + 1) ** 2)
    vis = 1 / ((abs(nl) + math.sqrt(alpha2 + (1 - alpha2) * nl * nl)) *
               (abs(nv) + math.sqrt(alpha2 + (1 - alpha2) * nv * nv)))
    return nl * ((1 - fresnel) * base / math.pi + fresnel * d * vis)


def window(distance: float, range_: float) -> float:
    """KHR_lights_punctual's recommended range falloff (three.js's too): 1 without a range."""
    return 1.0 if range_ <= 0 else min(max(1 - (distance / range_) ** 4, 0), 1) ** 2


def rough_quad(path: str, base) -> str:
    """A 2x2 quad of a rough dielectric (roughness 1, metallic 0) written to path."""
    material = {"pbrMetallicRoughness": {"baseColorFactor": [*base, 1], "metallicFactor": 0, "roughnessFactor": 1}}
    return fixtures.write(path, fixtures.gltf([fixtures.Quad(-1, 1, -1, 1, material)]))


def check_lights(out: str) -> None:
    base = (0.8, 0.5, 0.2)
    path = rough_quad(os.path.join(out, "lights.gltf"), base)
    n = [0, 0, 1]

    def radiance(i, j, light_pos, intensity, range_, cone=lambda to_point: 1.0):
        p = CAMERA.on_plane_z0(i, j)
        d = [light_pos[k] - p[k] for k in range(3)]
        dist = math.sqrt(sum(c * c for c in d))
        to_light = [c / dist for c in d]
        v = normalize([CAMERA.eye[k] - p[k] for k in range(3)])
        e = intensity / dist ** 2 * window(dist, range_) * cone([-c for c in to_light])
        return [255 * srgb_encode(e * gltf_brdf(c, n, to_light, v, 1.0)) for c in base]

    # Point light off the axis, its range reaching some of the quad but not its far corner.
    pos, intensity, range_ = [0.3, -0.2, 1.0], 2.0, 2.0
    img = render(path, os.path.join(out, "point.png"), ["--light", f"point:{','.join(map(str, pos))}:1,1,1:{intensity}:{range_}"])
    for i, j in ((32, 32), (40, 38), (20, 22), (8, 8)):
        expect(f"point light, pixel ({i}, {j})", pixel(img, i, j), radiance(i, j, pos, intensity, range_), 2)

    # Spot light 2 units above (0.2, 0.1), pointing straight down; cones 15 and 30 degrees.
    pos, axis, intensity, inner, outer = [0.2, 0.1, 2.0], [0, 0, -1], 8.0, 15.0, 30.0
    cos_in, cos_out = math.cos(math.radians(inner)), math.cos(math.radians(outer))

    def ramp(to_point):
        return min(max((sum(a * b for a, b in zip(to_point, axis)) - cos_out) / (cos_in - cos_out), 0), 1)

    def smoothstep(to_point):
        t = ramp(to_point)
        return t * t * (3 - 2 * t)

    img = render(path, os.path.join(out, "spot.png"),
                 ["--light", f"spot:{','.join(map(str, pos))}:{','.join(map(str, axis))}:1,1,1:{intensity}:{inner}:{outer}"])

    def off_axis(i, j):  # degrees
        p = CAMERA.on_plane_z0(i, j)
        return math.degrees(math.atan2(math.hypot(p[0] - pos[0], p[1] - pos[1]), pos[2]))

    for i, j in ((36, 30), (30, 34)):
        assert off_axis(i, j) < inner
        expect(f"spot, {off_axis(i, j):.1f} deg off its axis, pixel ({i}, {j})", pixel(img, i, j),
               radiance(i, j, pos, intensity, 0), 2)
    i, j = 8, 56
    assert off_axis(i, j) > outer
    expect(f"spot, {off_axis(i, j):.1f} deg off its axis, pixel ({i}, {j})", pixel(img, i, j), (0, 0, 0), 0)
    i, j = 16, 29
    assert inner < off_axis(i, j) < outer
    expect(f"spot, {off_axis(i, j):.1f} deg off its axis, pixel ({i}, {j}), three.js's smoothstep", pixel(img, i, j),
           radiance(i, j, pos, intensity, 0, smoothstep), 2)
    khr = radiance(i, j, pos, intensity, 0, lambda t: ramp(t) ** 2)
    print(f"  (the extension's reference falloff, ramp squared, would give {tuple(round(c, 1) for c in khr)})")


def check_lambert(out: str) -> None:
    base, intensity = (0.8, 0.5, 0.2), 3.0
    # Towards the light: 60 degrees from the normal (+Z), in neither the x-z nor the y-z plane.
    theta, phi = math.radians(60), math.radians(30)
    to_light = [math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)]
    path = rough_quad(os.path.join(out, "lambert.gltf"), base)
    light = f"directional:{','.join(f'{-c:.9f}' for c in to_light)}:1,1,1:{intensity:g}"
    img = render(path, os.path.join(out, "lambert.png"), ["--light", light, "--tone", "none"])
    for i, j in ((32, 32), (16, 20), (47, 12), (20, 50)):
        p = CAMERA.on_plane_z0(i, j)
        v = normalize([CAMERA.eye[k] - p[k] for k in range(3)])
        want = [255 * srgb_encode(intensity * gltf_brdf(c, [0, 0, 1], to_light, v, 1.0)) for c in base]
        expect(f"pixel ({i}, {j}), N.L = {to_light[2]:.3f}", pixel(img, i, j), want, 2)


def check_shadows(out: str) -> None:
    base = (0.8, 0.5, 0.2)
    ground = {"pbrMetallicRoughness": {"baseColorFactor": [*base, 1], "metallicFactor": 0, "roughnessFactor": 1}}
    blocker = {"pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.1, 0.1, 1]}}
    x0, x1, y0, y1, height = -0.3, 0.1, -0.2, 0.3, 0.5
    path = fixtures.write(os.path.join(out, "shadows.gltf"), fixtures.gltf(
        [fixtures.Quad(-1, 1, -1, 1, ground), fixtures.Quad(x0, x1, y0, y1, blocker, z=height)]))
    d = [0.6, 0.3, -1.0]  # the light travels along d: the shadow is the blocker moved by (0.3, 0.15)
    to_light = normalize([-c for c in d])
    img = render(path, os.path.join(out, "shadows.png"),
                 ["--light", f"directional:{','.join(map(str, d))}:1,1,1:3", "--shadows"])
    shift = [d[0] * height / -d[2], d[1] * height / -d[2]]

    def shadowed(x, y):
        return x0 + shift[0] < x < x1 + shift[0] and y0 + shift[1] < y < y1 + shift[1]

    def lit(i, j):  # the spec's colour of the ground seen through pixel (i, j), in the light
        p = CAMERA.on_plane_z0(i, j)
        v = normalize([CAMERA.eye[k] - p[k] for k in range(3)])
        return [255 * srgb_encode(3 * gltf_brdf(c, [0, 0, 1], to_light, v, 1.0)) for c in base]

    # In the shadow and not hidden behind the blocker (seen from the camera it spans
    # x up to 0.1 * 3 / 2.5 = 0.12).
    for x, y in ((0.3, 0.2), (0.35, 0.0)):
        assert shadowed(x, y)
        i, j = (int(c) for c in CAMERA.project([x, y, 0]))
        expect(f"in the shadow at ({x:g}, {y:g}), pixel ({i}, {j})", pixel(img, i, j), (0, 0, 0), 2)
    # Lit: beside the shadow, and where a mirrored light would have put it.
    for x, y in ((0.6, -0.5), (-0.5, -0.25), (0.3, 0.6), (-0.7, 0.6)):
        assert not shadowed(x, y)
        i, j = (int(c) for c in CAMERA.project([x, y, 0]))
        expect(f"lit at ({x:g}, {y:g}), pixel ({i}, {j})", pixel(img, i, j), lit(i, j), 2)
    # Every pixel of ground seen past the blocker, but those within 0.06 (1.5 pixels) of
    # the shadow's or the ground's edge: no acne in the light, no light leaking under
    # the blocker (peter-panning).
    wrong = total = 0
    for j in range(CAMERA.height):
        for i in range(CAMERA.width):
            x, y, _ = CAMERA.on_plane_z0(i, j)
            bx, by = x * (3 - height) / 3, y * (3 - height) / 3  # where the ray crosses the blocker's plane
            near_edge = any(shadowed(x + dx, y + dy) != shadowed(x, y) for dx in (-0.06, 0.06) for dy in (-0.06, 0.06))
            if max(abs(x), abs(y)) > 0.94 or (x0 < bx < x1 and y0 < by < y1) or near_edge:
                continue
            want = (0, 0, 0) if shadowed(x, y) else lit(i, j)
            total += 1
            wrong += max(abs(g - w) for g, w in zip(pixel(img, i, j), want)) > 2
    print(f"  ground pixels away from edges: {wrong} of {total} off by more than 2 (acne or light leaks)")
    if wrong:
        raise Failed(f"{wrong} of {total} ground pixels away from edges are neither lit nor shadowed as they should be")


CHECKS = {"texcoords": check_texcoords, "srgb": check_srgb, "lambert": check_lambert, "lights": check_lights,
          "shadows": check_shadows}

if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in CHECKS:
        sys.exit(f"usage: {sys.argv[0]} {'|'.join(CHECKS)} OUT_DIR")
    os.makedirs(sys.argv[2], exist_ok=True)
    try:
        CHECKS[sys.argv[1]](sys.argv[2])
    except (Failed, subprocess.TimeoutExpired) as e:
        print(f"FAIL: {e}")
        sys.exit(1)
    print(f"PASS: {sys.argv[1]}")
