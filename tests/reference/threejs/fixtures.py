"""Small self-contained glTF 2.0 files for the convention checks, made here rather than
stored: axis-aligned quads parallel to the plane z = 0, facing +Z, each with its own
material, buffers and images embedded as data URIs.

Texture coordinates follow the glTF spec: uv (0, 0) is the image's top-left texel, so a
quad's top-left corner (min x, max y) gets uv (0, 0) and its bottom-right (max x, min y)
gets uv (1, 1).
"""
from __future__ import annotations

import base64
import json
import struct
from dataclasses import dataclass

import png

FLOAT, UINT16 = 5126, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
NEAREST = 9728
UNLIT = "KHR_materials_unlit"


@dataclass
class Quad:
    x0: float
    x1: float
    y0: float
    y1: float
    material: dict  # a glTF material; "baseColorTexture": {"index": 0} names the image
    z: float = 0.0


def _data_uri(mime: str, data: bytes) -> str:
    return f"data:{mime};base64,{base64.b64encode(data).decode()}"


def image_png(width: int, height: int, texels: list[tuple[int, int, int]]) -> bytes:
    """An RGB PNG from texels listed row by row, top row first."""
    return png.encode(width, height, 3, bytes(c for t in texels for c in t))


def gltf(quads: list[Quad], image: bytes | None = None) -> dict:
    """A glTF document with one node per quad and, if given, one PNG image sampled with
    NEAREST (so a texel's colour arrives unblended)."""
    blob, views, accessors, meshes = bytearray(), [], [], []

    def add(data: bytes, target: int, component: int, kind: str, count: int, bounds=None) -> int:
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
        blob.extend(data + b"\0" * (-len(data) % 4))  # accessors start 4-byte aligned
        accessor = {"bufferView": len(views) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            accessor["min"], accessor["max"] = bounds
        accessors.append(accessor)
        return len(accessors) - 1

    for i, q in enumerate(quads):
        # corners: top-left, bottom-left, bottom-right, top-right; counter-clockwise from +Z
        xy = [(q.x0, q.y1), (q.x0, q.y0), (q.x1, q.y0), (q.x1, q.y1)]
        uv = [(0, 0), (0, 1), (1, 1), (1, 0)]
        pos = add(b"".join(struct.pack("<3f", x, y, q.z) for x, y in xy), ARRAY_BUFFER, FLOAT, "VEC3", 4,
                  ([q.x0, q.y0, q.z], [q.x1, q.y1, q.z]))
        nrm = add(struct.pack("<3f", 0, 0, 1) * 4, ARRAY_BUFFER, FLOAT, "VEC3", 4)
        tex = add(b"".join(struct.pack("<2f", u, v) for u, v in uv), ARRAY_BUFFER, FLOAT, "VEC2", 4)
        idx = add(struct.pack("<6H", 0, 1, 2, 0, 2, 3), ELEMENT_ARRAY_BUFFER, UINT16, "SCALAR", 6)
        meshes.append({"primitives": [{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": tex},
                                       "indices": idx, "material": i}]})

    doc = {
        "asset": {"version": "2.0", "generator": "velocity tests/reference/threejs/fixtures.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(quads)))}],
        "nodes": [{"mesh": i} for i in range(len(quads))],
        "meshes": meshes,
        "materials": [q.material for q in quads],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": _data_uri("application/octet-stream", bytes(blob))}],
    }
    if image is not None:
        doc["images"] = [{"uri": _data_uri("image/png", image)}]
        doc["samplers"] = [{"magFilter": NEAREST, "minFilter": NEAREST}]
        doc["textures"] = [{"source": 0, "sampler": 0}]
    used = sorted({e for q in quads for e in q.material.get("extensions", {})})
    if used:
        doc["extensionsUsed"] = used
    return doc


def write(path: str, doc: dict) -> str:
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
    return path
