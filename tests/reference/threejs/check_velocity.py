#!/usr/bin/env python3
"""Velocity against the three.js oracle on generated glTF files (issue 17): the same
file, camera, lights (the file's KHR_lights_punctual), tone mapping and sRGB output in
both renderers, compared by PSNR over the whole image.

  spheres   3x3 spheres, metallic (0, 0.5, 1) x roughness (0.25, 0.5, 0.9), one
            directional and one point light (inverse square, range): >= 30 dB
  blend     an opaque quad behind two BLEND quads (alpha 0.5, 0.35): >= 25 dB

Usage: check_velocity.py spheres|blend OUT_DIR (VELOCITY_CLI names the program).
Exit 77 (skip) when Chromium is missing, as the other threejs_* checks.
"""
from __future__ import annotations

import math
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fixtures  # noqa: E402
import png  # noqa: E402

RENDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render.py")
SKIP = 77
SIZE = 160


def sphere(cx: float, cy: float, r: float, seg: int = 48):
    pos, nrm, idx = [], [], []
    rings = seg // 2
    for j in range(rings + 1):
        th = math.pi * j / rings
        for i in range(seg + 1):
            ph = 2 * math.pi * i / seg
            n = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            nrm.append(n)
            pos.append((cx + r * n[0], cy + r * n[1], r * n[2]))
    for j in range(rings):
        for i in range(seg):
            a, b = j * (seg + 1) + i, (j + 1) * (seg + 1) + i
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def spheres_doc() -> dict:
    blob, views, accessors, meshes, materials = bytearray(), [], [], [], []

    def add(data: bytes, component: int, kind: str, count: int, bounds=None) -> int:
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data)})
        blob.extend(data + b"\0" * (-len(data) % 4))
        acc = {"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            acc["min"], acc["max"] = bounds
        accessors.append(acc)
        return len(accessors) - 1

    for a, metallic in enumerate((0.0, 0.5, 1.0)):
        for b, rough in enumerate((0.25, 0.5, 0.9)):
            cx, cy = (a - 1) * 1.1, (b - 1) * 1.1
            pos, nrm, idx = sphere(cx, cy, 0.5)
            lo = [min(p[k] for p in pos) for k in range(3)]
            hi = [max(p[k] for p in pos) for k in range(3)]
            p = add(b"".join(struct.pack("<3f", *v) for v in pos), fixtures.FLOAT, "VEC3", len(pos), (lo, hi))
            n = add(b"".join(struct.pack("<3f", *v) for v in nrm), fixtures.FLOAT, "VEC3", len(nrm))
            i = add(struct.pack(f"<{len(idx)}H", *idx), fixtures.UINT16, "SCALAR", len(idx))
            materials.append({"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.3, 1],
                                                       "metallicFactor": metallic, "roughnessFactor": rough}})
            meshes.append({"primitives": [{"attributes": {"POSITION": p, "NORMAL": n}, "indices": i,
                                           "material": len(materials) - 1}]})
    nodes = [{"mesh": k} for k in range(len(meshes))]
    # A directional light along (-0.4, -0.5, -1) (a node's -Z), and a point light.
    d = [0.4, 0.5, 1.0]
    ln = math.sqrt(sum(x * x for x in d))
    z = [x / ln for x in d]  # the node's +Z: towards the light
    x_axis = [z[2], 0.0, -z[0]]
    lx = math.sqrt(sum(v * v for v in x_axis))
    x_axis = [v / lx for v in x_axis]
    y_axis = [z[1] * x_axis[2] - z[2] * x_axis[1], z[2] * x_axis[0] - z[0] * x_axis[2], z[0] * x_axis[1] - z[1] * x_axis[0]]
    nodes.append({"matrix": x_axis + [0] + y_axis + [0] + z + [0] + [0, 0, 0, 1],
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"translation": [1.2, -0.6, 2.0], "extensions": {"KHR_lights_punctual": {"light": 1}}})
    return {
        "asset": {"version": "2.0", "generator": "velocity tests/reference/threejs/check_velocity.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "color": [1, 0.95, 0.9], "intensity": 3},
            {"type": "point", "color": [0.6, 0.8, 1], "intensity": 4, "range": 6}]}},
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": meshes,
        "materials": materials, "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": fixtures._data_uri("application/octet-stream", bytes(blob))}],
    }


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


def psnr(a: bytes, b: bytes) -> float:
    mse = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)
    return float("inf") if mse == 0 else 10 * math.log10(255 * 255 / mse)


def main() -> int:
    case, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    doc, floor = {"spheres": (spheres_doc(), 30.0), "blend": (blend_doc(), 25.0)}[case]
    model = fixtures.write(os.path.join(out, f"{case}.gltf"), doc)
    three_png, velocity_png = os.path.join(out, f"{case}-three.png"), os.path.join(out, f"{case}-velocity.png")
    # Velocity's background (Scene::background, sRGB / 255) in both.
    run = subprocess.run([sys.executable, RENDER, model, "--out", three_png, "--size", f"{SIZE}x{SIZE}",
                          "--camera", "0,0,6,0,0,0", "--yfov", "45", "--file-lights", "--bg", "0.1,0.1,0.15"],
                         capture_output=True, text=True, timeout=120)
    if run.returncode == SKIP:
        print(f"SKIP: {run.stderr.strip()}")
        return SKIP
    if run.returncode != 0:
        print(f"FAIL: render.py: {run.stderr.strip()}")
        return 1
    cli = os.environ.get("VELOCITY_CLI", "velocity")
    run = subprocess.run([cli, "render", model, "--out", velocity_png, "--size", f"{SIZE}x{SIZE}",
                          "--camera", "0,0,6", "--fov", "45"], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        print(f"FAIL: velocity render: {run.stderr.strip()}")
        return 1
    _, _, _, a = png.read(three_png)
    w, h, c, b = png.read(velocity_png)
    if c == 4:
        b = bytes(v for k, v in enumerate(b) if k % 4 != 3)
    db = psnr(a, b)
    print(f"{case}: PSNR {db:.2f} dB against three.js (floor {floor})")
    return 0 if db >= floor else 1


if __name__ == "__main__":
    sys.exit(main())
