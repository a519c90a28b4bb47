#!/usr/bin/env python3
"""Velocity against the three.js oracle on glTF files (issue 17): the same file, camera,
lights (the file's KHR_lights_punctual), tone mapping and sRGB output in both renderers,
compared by PSNR over the whole image.

  spheres      3x3 spheres, metallic (0, 0.5, 1) x roughness (0.25, 0.5, 0.9), one
               directional and one point light (inverse square, range): >= 30 dB
  normalmap    a tangent-space normal map of bumps and ramps on four quads: tangents from
               the file and generated, u mirrored on the right (NormalTangentMirrorTest's
               idea): >= 30 dB
  vertexcolors spheres and a quad with COLOR_0 (float RGB, normalised-byte RGBA) times a
               base colour factor (BoxVertexColors' idea): >= 30 dB
  spot         a spot light (15/30 degree cones, range) and a point light on a textured
               floor: >= 30 dB
  boxtextured  assimp's BoxTextured (data-URI .gltf, Khronos's sample model), lit, in a
               three-quarter view: >= 30 dB
  mask         alphaMode MASK (cut-off 0.5) of a texture's alpha and of a vertex alpha,
               over an opaque quad: >= 30 dB
  transform    assimp's TextureTransformTest (Khronos's KHR_texture_transform sample:
               offset, rotation, scale, texCoord override), lit: >= 30 dB
  blend        an opaque quad behind two BLEND quads (alpha 0.5, 0.35): >= 25 dB
  shadows      a box and a floating quad on a floor, a directional and a spot light
               casting through 2048^2 maps (three.js's PCFShadowMap; Velocity's bilinear
               PCF; three's bias 0 and normal bias 0.006, about our 2 texels): >= 38 dB
               (44.9 measured; 18.5 with Velocity's shadows off)

Usage: check_velocity.py CASE OUT_DIR (VELOCITY_CLI names the program). Exit 77 (skip)
when Chromium is missing, as the other threejs_* checks; 0 at or over the floor, else 1.
"""
from __future__ import annotations

import json
import math
import os
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fixtures  # noqa: E402
import png  # noqa: E402

RENDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render.py")
ASSIMP_GLTF = "/usr/share/assimp/models/glTF2"
SKIP = 77
SIZE = 160
BACKGROUND = "0.1,0.1,0.15"  # Velocity's default background (Scene::background), sRGB / 255


class Doc:
    """A glTF 2.0 document built up in memory: one data-URI buffer, meshes, nodes,
    materials, images (PNG, data URIs) and KHR_lights_punctual lights."""

    def __init__(self) -> None:
        self.blob = bytearray()
        self.views, self.accessors, self.meshes, self.nodes = [], [], [], []
        self.materials, self.images, self.samplers, self.textures, self.lights = [], [], [], [], []
        self.extensions: set[str] = set()

    def accessor(self, data: bytes, component: int, kind: str, count: int, bounds=None,
                 normalized: bool = False) -> int:
        self.views.append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)})
        self.blob.extend(data + b"\0" * (-len(data) % 4))  # accessors start 4-byte aligned
        acc = {"bufferView": len(self.views) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            acc["min"], acc["max"] = bounds
        if normalized:
            acc["normalized"] = True
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def floats(self, rows: list, kind: str, bounds: bool = False) -> int:
        n = len(rows[0])
        box = ([min(r[k] for r in rows) for k in range(n)], [max(r[k] for r in rows) for k in range(n)]) if bounds else None
        return self.accessor(b"".join(struct.pack(f"<{n}f", *r) for r in rows), fixtures.FLOAT, kind, len(rows), box)

    def mesh(self, pos, idx, material: dict, **attributes) -> int:
        """A node drawing one triangle list; attributes NORMAL, TEXCOORD_0, TANGENT, COLOR_0
        as lists of tuples (floats), or as accessor indices already made."""
        attrs = {"POSITION": self.floats(pos, "VEC3", bounds=True)}
        kinds = {"NORMAL": "VEC3", "TANGENT": "VEC4", "TEXCOORD_0": "VEC2", "TEXCOORD_1": "VEC2"}
        for name, rows in attributes.items():
            attrs[name] = rows if isinstance(rows, int) else self.floats(rows, kinds.get(name, f"VEC{len(rows[0])}"))
        i = self.accessor(struct.pack(f"<{len(idx)}H", *idx), fixtures.UINT16, "SCALAR", len(idx))
        self.materials.append(material)
        self.extensions |= set(material.get("extensions", {}))
        self.meshes.append({"primitives": [{"attributes": attrs, "indices": i, "material": len(self.materials) - 1}]})
        self.nodes.append({"mesh": len(self.meshes) - 1})
        return len(self.nodes) - 1

    def texture(self, image_png: bytes, mag: int = 9729, min_: int = 9987, wrap: int = 10497) -> int:
        self.images.append({"uri": fixtures._data_uri("image/png", image_png)})
        self.samplers.append({"magFilter": mag, "minFilter": min_, "wrapS": wrap, "wrapT": wrap})
        self.textures.append({"source": len(self.images) - 1, "sampler": len(self.samplers) - 1})
        return len(self.textures) - 1

    def light(self, light: dict, position=(0.0, 0.0, 0.0), along=None) -> None:
        """A KHR_lights_punctual light at `position`; directional and spot lights shine
        `along` (the node's -Z)."""
        self.lights.append(light)
        node = {"extensions": {"KHR_lights_punctual": {"light": len(self.lights) - 1}}}
        if along is None:
            node["translation"] = list(position)
        else:
            node["matrix"] = light_matrix(along, position)
        self.nodes.append(node)

    def json(self) -> dict:
        doc = {
            "asset": {"version": "2.0", "generator": "velocity tests/reference/threejs/check_velocity.py"},
            "scene": 0, "scenes": [{"nodes": list(range(len(self.nodes)))}], "nodes": self.nodes,
            "meshes": self.meshes, "materials": self.materials, "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [{"byteLength": len(self.blob),
                         "uri": fixtures._data_uri("application/octet-stream", bytes(self.blob))}],
        }
        if self.images:
            doc["images"], doc["samplers"], doc["textures"] = self.images, self.samplers, self.textures
        used = set(self.extensions)
        if self.lights:
            used.add("KHR_lights_punctual")
            doc["extensions"] = {"KHR_lights_punctual": {"lights": self.lights}}
        if used:
            doc["extensionsUsed"] = sorted(used)
        return doc


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def light_matrix(along, position) -> list[float]:
    """A node matrix (column-major) whose -Z is `along`, at `position`."""
    z = normalize([-x for x in along])  # the node's +Z: towards the light
    x = normalize(cross([0.0, 1.0, 0.0], z) if abs(z[1]) < 0.99 else cross(z, [1.0, 0.0, 0.0]))
    y = cross(z, x)
    return x + [0] + y + [0] + z + [0] + list(position) + [1]


def sphere(cx: float, cy: float, r: float, seg: int = 48):
    pos, nrm, uv, idx = [], [], [], []
    rings = seg // 2
    for j in range(rings + 1):
        th = math.pi * j / rings
        for i in range(seg + 1):
            ph = 2 * math.pi * i / seg
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            nrm.append(n)
            pos.append((cx + r * n[0], cy + r * n[1], r * n[2]))
            uv.append((i / seg, j / rings))
    for j in range(rings):
        for i in range(seg):
            a, b = j * (seg + 1) + i, (j + 1) * (seg + 1) + i
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, uv, idx


def grid(x0: float, x1: float, y0: float, y1: float, n: int = 1, z: float = 0.0):
    """A quad in the plane z facing +Z as an n x n grid; uv (0, 0) at its top-left."""
    pos, uv, idx = [], [], []
    for j in range(n + 1):
        for i in range(n + 1):
            s, t = i / n, j / n
            pos.append((x0 + (x1 - x0) * s, y1 - (y1 - y0) * t, z))
            uv.append((s, t))
    for j in range(n):
        for i in range(n):
            a, b = j * (n + 1) + i, (j + 1) * (n + 1) + i
            idx += [a, b, b + 1, a, b + 1, a + 1]
    return pos, uv, idx


def spheres_doc() -> dict:
    doc = Doc()
    for a, metallic in enumerate((0.0, 0.5, 1.0)):
        for b, rough in enumerate((0.25, 0.5, 0.9)):
            pos, nrm, _, idx = sphere((a - 1) * 1.1, (b - 1) * 1.1, 0.5)
            doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.3, 1],
                                                         "metallicFactor": metallic, "roughnessFactor": rough}},
                     NORMAL=nrm)
    doc.light({"type": "directional", "color": [1, 0.95, 0.9], "intensity": 3}, along=(-0.4, -0.5, -1.0))
    doc.light({"type": "point", "color": [0.6, 0.8, 1], "intensity": 4, "range": 6}, position=(1.2, -0.6, 2.0))
    return doc.json()


def normal_map_png(size: int = 32) -> bytes:
    """Tangent-space normals, +x along u (right), +y up the image: a dome on the upper
    left, a dimple on the lower right, a ramp leaning right on the upper right and one
    leaning up on the lower left: no two quarters alike, no symmetry in x or y."""
    texels = []
    for j in range(size):
        for i in range(size):
            x, y = (i + 0.5) / size * 2 - 1, 1 - (j + 0.5) / size * 2  # [-1, 1], y up
            qx, qy = (x + 0.5 if x < 0 else x - 0.5) * 2, (y + 0.5 if y < 0 else y - 0.5) * 2  # per quarter
            nx = ny = 0.0
            r2 = qx * qx + qy * qy
            if x < 0 and y > 0 and r2 < 0.8:
                nx, ny = 0.7 * qx, 0.7 * qy  # dome: leans outwards
            elif x > 0 and y < 0 and r2 < 0.8:
                nx, ny = -0.6 * qx, -0.6 * qy  # dimple: leans inwards
            elif x > 0 and y > 0:
                nx = 0.5  # leans right
            elif x < 0 and y < 0:
                ny = 0.45  # leans up
            nz = math.sqrt(max(0.0, 1 - nx * nx - ny * ny))
            n = normalize([nx, ny, nz])
            texels.append(tuple(round(127.5 * (c + 1)) for c in n))
    return fixtures.image_png(size, size, texels)


def normalmap_doc() -> dict:
    doc = Doc()
    tex = doc.texture(normal_map_png())
    for row, with_tangents in ((0, True), (1, False)):
        for col, mirrored in ((0, False), (1, True)):
            x0, y1 = -1.55 + col * 1.6, 1.55 - row * 1.6
            pos, uv, idx = grid(x0, x0 + 1.5, y1 - 1.5, y1)
            if mirrored:
                uv = [(1 - u, v) for u, v in uv]
            attrs = {"NORMAL": [(0.0, 0.0, 1.0)] * len(pos), "TEXCOORD_0": uv}
            if with_tangents:
                attrs["TANGENT"] = [(-1.0 if mirrored else 1.0, 0.0, 0.0, 1.0)] * len(pos)
            doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.7, 0.6, 1], "metallicFactor": 0.2,
                                                         "roughnessFactor": 0.45},
                                "normalTexture": {"index": tex, "scale": 0.9}}, **attrs)
    doc.light({"type": "directional", "color": [1, 1, 1], "intensity": 2.5}, along=(-0.6, -0.3, -1.0))
    doc.light({"type": "point", "color": [1, 0.7, 0.5], "intensity": 3}, position=(1.0, 1.6, 1.5))
    return doc.json()


def vertexcolors_doc() -> dict:
    doc = Doc()
    for k, (cx, rough) in enumerate(((-1.1, 0.4), (0.0, 0.7), (1.1, 1.0))):
        pos, nrm, _, idx = sphere(cx, 0.55, 0.5, 40)
        colour = [(0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.2 + 0.3 * (k == 1)) for n in nrm]
        doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.9, 0.8, 1], "metallicFactor": 0.1 * k,
                                                     "roughnessFactor": rough}}, NORMAL=nrm, COLOR_0=colour)
    # A quad of normalised unsigned bytes RGBA (alpha ignored: OPAQUE).
    pos, uv, idx = grid(-1.6, 1.6, -1.2, -0.1, 4)
    rgba = [(int(255 * u), int(255 * (1 - v)), 90 + int(120 * u * v), 60) for u, v in uv]
    colours = doc.accessor(b"".join(struct.pack("<4B", *c) for c in rgba), 5121, "VEC4", len(rgba), normalized=True)
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.8}},
             NORMAL=[(0.0, 0.0, 1.0)] * len(pos), COLOR_0=colours)
    doc.light({"type": "directional", "color": [1, 1, 1], "intensity": 2.8}, along=(-0.3, -0.6, -1.0))
    doc.light({"type": "point", "color": [0.9, 0.9, 1], "intensity": 2, "range": 8}, position=(-1.5, -0.5, 1.5))
    return doc.json()


def checker_png(size: int = 16) -> bytes:
    """Four-colour checks with a darker top row, so neither axis is symmetric."""
    texels = []
    for j in range(size):
        for i in range(size):
            a = ((i // 4) + (j // 4)) % 2
            c = (220, 200, 170) if a else (90, 120, 160)
            if j < 2:
                c = (c[0] // 2, c[1] // 2, c[2])
            if i >= size - 2:
                c = (c[0], 60, 60)
            texels.append(c)
    return fixtures.image_png(size, size, texels)


def spot_doc() -> dict:
    doc = Doc()
    tex = doc.texture(checker_png())
    pos, uv, idx = grid(-2, 2, -2, 2)
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorTexture": {"index": tex}, "metallicFactor": 0,
                                                 "roughnessFactor": 0.6}},
             NORMAL=[(0.0, 0.0, 1.0)] * 4, TEXCOORD_0=uv)
    doc.light({"type": "spot", "color": [1, 0.95, 0.8], "intensity": 10, "range": 9,
               "spot": {"innerConeAngle": math.radians(15), "outerConeAngle": math.radians(30)}},
              position=(0.4, 0.5, 2.2), along=(-0.35, -0.15, -1.0))
    doc.light({"type": "point", "color": [0.3, 0.4, 1], "intensity": 1.2}, position=(-1.4, -1.2, 0.8))
    return doc.json()


def mask_doc() -> dict:
    doc = Doc()
    size, texels = 8, []
    for j in range(size):
        for i in range(size):
            alpha = (0.2, 0.45, 0.55, 0.9)[(i + 2 * j) % 4]
            texels.append((40 + 25 * i, 200 - 20 * j, 120, round(255 * alpha)))
    image = png.encode(size, size, 4, bytes(c for t in texels for c in t))
    tex = doc.texture(image, mag=fixtures.NEAREST, min_=fixtures.NEAREST)
    pos, uv, idx = grid(-1.7, 1.7, -1.7, 1.7, z=-0.5)
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.5, 0.35, 1], "metallicFactor": 0}},
             NORMAL=[(0.0, 0.0, 1.0)] * 4)
    pos, uv, idx = grid(-1.4, 0.4, -0.3, 1.4)
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorTexture": {"index": tex}, "metallicFactor": 0,
                                                 "roughnessFactor": 0.7},
                        "alphaMode": "MASK", "alphaCutoff": 0.5}, NORMAL=[(0.0, 0.0, 1.0)] * 4, TEXCOORD_0=uv)
    # A vertex alpha ramp from 0 (left) to 1 (right), the default cut-off 0.5: the right half.
    pos, uv, idx = grid(-0.6, 1.5, -1.5, -0.1, 3, z=0.2)
    colours = [(0.9, 0.6, 0.2, u) for u, _ in uv]
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"metallicFactor": 0.3, "roughnessFactor": 0.5}, "alphaMode": "MASK"},
             NORMAL=[(0.0, 0.0, 1.0)] * len(pos), COLOR_0=colours)
    doc.light({"type": "directional", "color": [1, 1, 1], "intensity": 3}, along=(-0.2, -0.4, -1.0))
    return doc.json()


def blend_doc() -> dict:
    unlit = {"KHR_materials_unlit": {}}
    quads = [
        fixtures.Quad(-1.5, 1.5, -1.5, 1.5, {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.6, 0.3, 1]},
                                             "extensions": unlit}, z=-1.0),
        fixtures.Quad(-1.0, 0.6, -0.8, 0.9, {"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.1, 0.1, 0.5]},
                                             "alphaMode": "BLEND", "extensions": unlit}, z=0.5),
        fixtures.Quad(-0.3, 1.2, -1.1, 0.3, {"pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.9, 0.35]},
                                             "alphaMode": "BLEND", "extensions": unlit}, z=0.0),
    ]
    return fixtures.gltf(quads)


# The shadow case's lights: (KHR_lights_punctual light, position, along) for Velocity's
# file and the same light as render.py's --light for three.js (whose shadows are cast by
# --light lights only). The spot's inner cone holds the whole floor, so that the two
# cone falloffs (three.js's smoothstep, the extension's ramp) do not enter the figure.
SHADOW_LIGHTS = [
    ({"type": "directional", "color": [1, 0.95, 0.9], "intensity": 2.5}, (0.0, 0.0, 0.0), (0.55, -1.0, -0.35),
     "directional:0.55,-1,-0.35:1,0.95,0.9:2.5"),
    ({"type": "spot", "color": [0.7, 0.8, 1.0], "intensity": 9,
      "spot": {"innerConeAngle": math.radians(50), "outerConeAngle": math.radians(60)}},
     (-0.9, 2.4, 1.1), (0.35, -1.0, -0.45), "spot:-0.9,2.4,1.1:0.35,-1,-0.45:0.7,0.8,1:9:50:60"),
]


def box(x0, x1, y0, y1, z0, z1):
    """A box's 24 vertices (4 a face, flat normals) and 12 triangles, faces outwards."""
    pos, nrm, idx = [], [], []
    faces = [((1, 0, 0), [(x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1)]),
             ((-1, 0, 0), [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)]),
             ((0, 1, 0), [(x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0)]),
             ((0, -1, 0), [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)]),
             ((0, 0, 1), [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]),
             ((0, 0, -1), [(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)])]
    for n, corners in faces:
        k = len(pos)
        pos += corners
        nrm += [n] * 4
        idx += [k, k + 1, k + 2, k, k + 2, k + 3]
    return pos, nrm, idx


def shadows_doc() -> dict:
    """A floor (y = -0.6, 4 x 4), a box standing on it off-centre and a two-sided quad
    floating over it: the scene's box is centred on the origin (Velocity's --camera looks
    at the model's centre), and no mirror of it is the same."""
    doc = Doc()
    y = -0.6
    floor = [(-2.0, y, 2.0), (2.0, y, 2.0), (2.0, y, -2.0), (-2.0, y, -2.0)]
    doc.mesh(floor, [0, 1, 2, 0, 2, 3], {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.75, 0.7, 1],
                                                                  "metallicFactor": 0, "roughnessFactor": 0.85}},
             NORMAL=[(0.0, 1.0, 0.0)] * 4)
    pos, nrm, idx = box(-1.1, -0.4, y, 0.6, -0.2, 0.5)
    doc.mesh(pos, idx, {"pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.5, 0.8, 1], "metallicFactor": 0,
                                                 "roughnessFactor": 0.6}}, NORMAL=nrm)
    quad = [(0.3, 0.1, -0.3), (1.4, 0.1, -0.3), (1.4, 0.1, -1.3), (0.6, 0.1, -1.3)]  # a trapezoid
    doc.mesh(quad, [0, 1, 2, 0, 2, 3], {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1],
                                                                 "metallicFactor": 0, "roughnessFactor": 0.7},
                                        "doubleSided": True}, NORMAL=[(0.0, 1.0, 0.0)] * 4)
    for light, position, along, _ in SHADOW_LIGHTS:
        doc.light(light, position=position, along=along)
    return doc.json()


def with_lights(doc: dict, lights: list[tuple[dict, list[float]]]) -> dict:
    """A glTF document from elsewhere with KHR_lights_punctual lights added at the scene's
    root: (light, node matrix) pairs."""
    doc = json.loads(json.dumps(doc))
    defs = doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {}).setdefault("lights", [])
    scene = doc["scenes"][doc.get("scene", 0)]
    for light, matrix in lights:
        defs.append(light)
        doc["nodes"].append({"matrix": matrix, "extensions": {"KHR_lights_punctual": {"light": len(defs) - 1}}})
        scene["nodes"].append(len(doc["nodes"]) - 1)
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_lights_punctual" not in used:
        used.append("KHR_lights_punctual")
    return doc


def assimp_model(folder: str, name: str, out: str, lights) -> str | None:
    """Copies assimp's model with its files into out/, lights added; None when assimp's
    test models are not installed."""
    src = os.path.join(ASSIMP_GLTF, folder)
    if not os.path.isfile(os.path.join(src, name)):
        return None
    dst = os.path.join(out, folder)
    os.makedirs(dst, exist_ok=True)
    for f in os.listdir(src):
        if f != name and os.path.isfile(os.path.join(src, f)):
            shutil.copyfile(os.path.join(src, f), os.path.join(dst, f))
    with open(os.path.join(src, name)) as f:
        doc = with_lights(json.load(f), lights)
    return fixtures.write(os.path.join(dst, name), doc)


def boxtextured(out: str) -> str | None:
    return assimp_model("BoxTextured-glTF-Embedded", "BoxTextured.gltf", out, [
        ({"type": "directional", "color": [1, 1, 1], "intensity": 2.6}, light_matrix((-0.5, -0.8, -0.6), (0, 0, 0))),
        ({"type": "point", "color": [1, 0.85, 0.7], "intensity": 3, "range": 10}, light_matrix((0, 0, -1), (1.6, 0.4, 1.4))),
    ])


def transform(out: str) -> str | None:
    return assimp_model("textureTransform", "TextureTransformTest.gltf", out, [
        ({"type": "directional", "color": [1, 1, 1], "intensity": 3.0}, light_matrix((0.2, -0.3, -1.0), (0, 0, 0))),
    ])


# case: (document builder or file maker, floor in dB, Velocity's --camera, three.js's
# --camera); a file maker gets the output folder and returns the model's path. Velocity's
# x,y,z,0,0,0 looks down -Z from x,y,z (yaw, pitch and roll 0), as three.js's
# x,y,z,x,y,z-1 does.
CASES = {
    "spheres": (spheres_doc, 30.0, "0,0,6,0,0,0", "0,0,6,0,0,0"),
    "normalmap": (normalmap_doc, 30.0, "0,0,5,0,0,0", "0,0,5,0,0,0"),
    "vertexcolors": (vertexcolors_doc, 30.0, "0,0,5,0,0,0", "0,0,5,0,0,0"),
    "spot": (spot_doc, 30.0, "0,0,5.5,0,0,0", "0,0,5.5,0,0,0"),
    "mask": (mask_doc, 30.0, "0,0,5,0,0,0", "0,0,5,0,0,0"),
    "blend": (blend_doc, 25.0, "0,0,6,0,0,0", "0,0,6,0,0,0"),
    # Velocity's x,y,z looks at the model's centre (the box's is the origin).
    "boxtextured": (boxtextured, 30.0, "2.2,1.6,2.6", "2.2,1.6,2.6,0,0,0"),
    "transform": (transform, 30.0, "0,0,4.6,0,0,0", "0,0,4.6,0,0,0"),
    "shadows": (shadows_doc, 38.0, "0.8,3.2,4.6", "0.8,3.2,4.6,0,0,0"),
}

# Cases drawn with shadows: render.py's --light lights for three.js (its shadows are cast
# by those only) in place of the file's, and --shadows on both sides, 2048^2 maps.
SHADOW_CASES = {"shadows": [arg for *_, spec in SHADOW_LIGHTS for arg in ("--light", spec)]}


def psnr(a: bytes, b: bytes) -> float:
    mse = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)
    return float("inf") if mse == 0 else 10 * math.log10(255 * 255 / mse)


def main() -> int:
    if len(sys.argv) != 3 or sys.argv[1] not in CASES:
        print(f"usage: check_velocity.py {'|'.join(CASES)} OUT_DIR", file=sys.stderr)
        return 2
    case, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    make, floor, velocity_camera, three_camera = CASES[case]
    if make.__name__.endswith("_doc"):
        model = fixtures.write(os.path.join(out, f"{case}.gltf"), make())
    else:
        model = make(out)
        if model is None:
            print(f"SKIP: assimp's test models are not installed ({ASSIMP_GLTF})")
            return SKIP
    three_png, velocity_png = os.path.join(out, f"{case}-three.png"), os.path.join(out, f"{case}-velocity.png")
    lights = ["--file-lights"]
    if case in SHADOW_CASES:
        # three.js's depth bias is in the map's depth, which a spot light's perspective
        # map stretches (0.0005 lifts its shadows ~0.75 units off this floor): a normal
        # offset in world units instead, 0.006, about Velocity's 2 texels (0.0057 for the
        # directional map, 0.005 for the spot's at 3 units).
        lights = SHADOW_CASES[case] + ["--shadows", "--shadow-map", "2048", "--shadow-bias", "0",
                                       "--shadow-normal-bias", "0.006"]
    run = subprocess.run([sys.executable, RENDER, model, "--out", three_png, "--size", f"{SIZE}x{SIZE}",
                          "--camera", three_camera, "--yfov", "45", "--znear", "0.1", "--zfar", "100",
                          "--bg", BACKGROUND] + lights, capture_output=True, text=True, timeout=120)
    if run.returncode == SKIP:
        print(f"SKIP: {run.stderr.strip()}")
        return SKIP
    if run.returncode != 0:
        print(f"FAIL: render.py: {run.stderr.strip()}")
        return 1
    cli = os.environ.get("VELOCITY_CLI", "velocity")
    shadows = ["--shadows", "--shadow-map-size", "2048"] if case in SHADOW_CASES else []
    run = subprocess.run([cli, "render", model, "--out", velocity_png, "--size", f"{SIZE}x{SIZE}",
                          "--camera", velocity_camera, "--fov", "45"] + shadows, capture_output=True, text=True,
                         timeout=120)
    if run.returncode != 0:
        print(f"FAIL: velocity render: {run.stderr.strip()}")
        return 1
    _, _, _, a = png.read(three_png)
    _, _, c, b = png.read(velocity_png)
    if c == 4:
        b = bytes(v for k, v in enumerate(b) if k % 4 != 3)
    db = psnr(a, b)
    print(f"{case}: PSNR {db:.2f} dB against three.js (floor {floor}); images {three_png}, {velocity_png}")
    return 0 if db >= floor else 1


if __name__ == "__main__":
    sys.exit(main())
