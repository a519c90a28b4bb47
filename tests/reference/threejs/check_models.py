#!/usr/bin/env python3
"""Renders the real glTF 2.0 models of Debian's assimp-testmodels with the oracle, one
browser for all of them, writes each image to OUT_DIR, and checks them:

  - BoxTextured (Khronos's textured unit cube), seen face-on: the front face covers
    exactly the square the camera puts it in, and the Cesium logo on it is there, the
    right way up (sky above land) and the right way round (its sun at the right, where
    CesiumLogoFlat.png has it: u runs from 4 at the left to 3 at the right, which the
    file's MIRRORED_REPEAT turns into the image's 0 to 1);
  - the same box as .glb and as .gltf with data URIs: the same pixels; and as the .gltf
    with a .bin and a PNG, whose sampler assimp changed to MIRRORED_REPEAT in u (the
    face's u runs over [3, 4]): the same face mirrored left-right;
  - every other model: it loads and covers some of the image.

    check_models.py OUT_DIR

Exit status 0 pass, 1 fail, 77 Chromium missing (ctest's SKIP_RETURN_CODE). The files
that assimp keeps to test its own failures (missing buffers, bad types, Draco, recursive
nodes, ...) are left out; README.md lists them.
"""
from __future__ import annotations

import glob
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import chromium  # noqa: E402
import render  # noqa: E402
import three_install  # noqa: E402
from camera import Camera  # noqa: E402

ROOT = "/usr/share/assimp/models/glTF2"
BOX = "BoxTextured-glTF/BoxTextured.gltf"
BOX_VARIANTS = ["BoxTextured-glTF-Binary/BoxTextured.glb", "BoxTextured-glTF-Embedded/BoxTextured.gltf"]
OTHERS = ["BoxTexcoords-glTF/boxTexcoords.gltf", "2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
          "textureTransform/TextureTransformTest.gltf", "ClearCoat-glTF/ClearCoatTest.gltf",
          "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", "simple_skin/simple_skin.gltf",
          "cameras/Cameras.gltf"] + sorted(os.path.relpath(p, ROOT) for p in glob.glob(
              f"{ROOT}/glTF-Asset-Generator/Mesh_PrimitiveMode/*.gltf"))
BACKGROUND = (0.2, 0.4, 0.6)
BG_BYTES = bytes(round(255 * c) for c in BACKGROUND)
# The box's front face (z = +0.5, x and y in +-0.5) seen from 2.5 units away, lit head-on
# (a directional light of intensity pi shows a white Lambertian surface as 1.0).
BOX_CAMERA = Camera(eye=[0, 0, 3], target=[0, 0, 0], up=[0, 1, 0], yfov=45, width=128, height=128)
HEAD_ON = [{"type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1], "intensity": 3.14159265}]
SIDE = [{"type": "directional", "direction": [-1, -2, -3], "color": [1, 1, 1], "intensity": 3.0}]


def spec(model: str, camera: Camera | None, lights: list, ambient=None, size=(256, 192)) -> dict:
    cam = None
    if camera:
        cam = {"eye": camera.eye, "target": camera.target, "up": camera.up, "yfov": camera.yfov,
               "znear": 0.1, "zfar": 100}
        size = (camera.width, camera.height)
    return render.make_spec(os.path.join(ROOT, model), *size, camera=cam, lights=lights,
                            ambient=ambient, background=BACKGROUND)


def check_box(image: render.Image) -> list[str]:
    """The front face's square, and the logo on it the right way up."""
    problems = []
    (x0, y0), (x1, y1) = BOX_CAMERA.project([-0.5, 0.5, 0.5]), BOX_CAMERA.project([0.5, -0.5, 0.5])
    margin = 1.5  # pixels: edges are not anti-aliased, but a pixel on an edge may go either way
    covered = stray = 0
    sky, land = [], []  # rows of the logo's blue sky and green land
    sun = []  # white inside the logo's disc, above its wave: (x, y) as fractions of the face
    for y in range(image.height):
        for x in range(image.width):
            cx, cy = x + 0.5, y + 0.5
            p = image.pixel(x, y)
            inside = x0 + margin < cx < x1 - margin and y0 + margin < cy < y1 - margin
            outside = not (x0 - margin < cx < x1 + margin and y0 - margin < cy < y1 + margin)
            if inside and bytes(p) != BG_BYTES:
                covered += 1
            if outside and bytes(p) != BG_BYTES:
                stray += 1
            if inside and p[2] > p[0] + 40 and p[2] > p[1]:
                sky.append(y)
            if inside and p[1] > p[2] + 30 and p[1] > p[0]:
                land.append(y)
            fx, fy = (cx - x0) / (x1 - x0), (cy - y0) / (y1 - y0)
            if (fx - 0.5) ** 2 + (fy - 0.5) ** 2 < 0.42 ** 2 and fy < 0.32 and min(p) > 200:
                sun.append((fx, fy))
    inside_count = sum(1 for y in range(image.height) for x in range(image.width)
                       if x0 + margin < x + 0.5 < x1 - margin and y0 + margin < y + 0.5 < y1 - margin)
    print(f"  BoxTextured: face x {x0:.1f}..{x1:.1f}, y {y0:.1f}..{y1:.1f}: {covered}/{inside_count} covered, "
          f"{stray} pixels outside; logo: {len(sky)} sky pixels (mean row {sum(sky) / max(len(sky), 1):.1f}), "
          f"{len(land)} land pixels (mean row {sum(land) / max(len(land), 1):.1f}), {len(sun)} sun pixels "
          f"(mean x {sum(x for x, _ in sun) / max(len(sun), 1):.2f} of the face; 0.65 in the image)")
    if covered != inside_count:
        problems.append(f"BoxTextured: {inside_count - covered} pixels of the front face show the background")
    if stray:
        problems.append(f"BoxTextured: {stray} pixels outside the front face are not background")
    if len(sky) < inside_count // 10 or len(land) < inside_count // 10:
        problems.append(f"BoxTextured: the logo is missing ({len(sky)} sky and {len(land)} land pixels of {inside_count})")
    elif sum(sky) / len(sky) >= sum(land) / len(land):
        problems.append("BoxTextured: the logo is upside down (its sky is below its land)")
    if len(sun) < 10:
        problems.append(f"BoxTextured: the logo's sun is missing ({len(sun)} pixels)")
    elif sum(x for x, _ in sun) / len(sun) < 0.5:
        problems.append("BoxTextured: the logo is mirrored left-right (its sun is on the left)")
    return problems


def check_mirrored(image: render.Image, other: render.Image) -> list[str]:
    """image is other mirrored left-right, but for a few pixels on the face's edges, where
    REPEAT and MIRRORED_REPEAT sample different sides of the texture."""
    off = sum(1 for y in range(image.height) for x in range(image.width)
              if max(abs(a - b) for a, b in zip(image.pixel(x, y), other.pixel(image.width - 1 - x, y))) > 2)
    print(f"  BoxTextured.gltf vs .glb mirrored: {off} of {image.width * image.height} pixels off by more than 2")
    if off > image.width * image.height // 100:
        return [f"{BOX}: not {BOX_VARIANTS[0]} mirrored left-right ({off} pixels differ)"]
    return []


def main(out: str) -> int:
    os.makedirs(out, exist_ok=True)
    problems = []
    try:
        with render.Oracle(timeout=60) as oracle:
            def draw(model, camera, lights, name, ambient=None):
                started = time.monotonic()
                image = oracle.render(spec(model, camera, lights, ambient))
                image.save(os.path.join(out, name + ".png"))
                print(f"{model}: {image.width}x{image.height} in {time.monotonic() - started:.2f} s -> {name}.png")
                return image

            box = draw(BOX, BOX_CAMERA, HEAD_ON, "BoxTextured_front")
            problems += check_box(box)
            glb, embedded = (draw(v, BOX_CAMERA, HEAD_ON, v.split("/")[0] + "_front") for v in BOX_VARIANTS)
            if glb.rgb != embedded.rgb:
                problems.append(f"{BOX_VARIANTS[1]}: differs from {BOX_VARIANTS[0]}")
            problems += check_mirrored(box, glb)
            for model in [BOX] + OTHERS:
                try:
                    image = draw(model, None, SIDE, os.path.splitext(os.path.basename(model))[0], [0.3] * 3)
                except chromium.PageError as e:
                    problems.append(f"{model}: {e}")
                    continue
                drawn = sum(1 for i in range(0, len(image.rgb), 3) if image.rgb[i:i + 3] != BG_BYTES)
                if drawn < image.width * image.height // 200:
                    problems.append(f"{model}: only {drawn} pixels differ from the background")
    except chromium.ChromiumMissing as e:
        print(f"SKIP: {e}")
        return render.EXIT_NO_CHROMIUM
    except (chromium.PageError, three_install.InstallError, OSError) as e:
        problems.append(str(e))
    for p in problems:
        print(f"FAIL: {p}")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} OUT_DIR")
    sys.exit(main(sys.argv[1]))
