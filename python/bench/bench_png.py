#!/usr/bin/env python3
"""What one PNG costs to encode, in CPU time (time.process_time: robust to a loaded
machine), and its size: the module's libpng encoder (velocity.png.encode_png) at each
row filter and zlib level, against Pillow (python3-pil) and the engine's other writer,
stb_image_write (Debian's libstb, called through ctypes with its filter forced and
its level set). Images: real renders (a shaded model, a textured one) at 256x256 and
640x480, and a 16-bit mask. Prints per image ms and bytes, then each encoder's
geometric mean of time and of size relative to Pillow's.

    PYTHONPATH=build/python python3 python/bench/bench_png.py [--repeats 40]
"""
import argparse
import ctypes
import ctypes.util
import io
import math
import os
import statistics
import time

import numpy as np
from PIL import Image

import velocity
from velocity.png import encode_png

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODELS = [os.path.join(ROOT, "tests", "data", "models", "wuson_x4.obj"),
          "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf"]


def render(path, w, h):
    mesh = velocity.Mesh.from_file(path)
    c, r = mesh.bounding_sphere
    base = np.eye(4)
    base[:3, :3] /= r
    base[:3, 3] = -np.array(c) / r
    scene = velocity.Scene(bg_color=(0.1, 0.1, 0.15, 1.0), ambient_light=(0.2, 0.2, 0.2))
    node = scene.add(mesh, pose=base)
    scene.add(velocity.PerspectiveCamera(math.radians(45), znear=0.1, zfar=100), pose=velocity.look_at([0, 1, 2.8], [0, 0, 0]))
    scene.add(velocity.DirectionalLight(intensity=3), pose=velocity.look_at([0, 0, 0], [-0.3, -0.5, -1]))
    color, _, mask = velocity.OffscreenRenderer(w, h).render(scene, velocity.RenderFlags.SEG)
    return np.ascontiguousarray(color), (mask == node.id).astype(np.uint16)


def stb_encoder(filt, level):
    name = ctypes.util.find_library("stb")
    if not name:
        return None
    lib = ctypes.CDLL(name)
    libc = ctypes.CDLL(ctypes.util.find_library("c"))
    lib.stbi_write_png_to_mem.restype = ctypes.c_void_p
    lib.stbi_write_png_to_mem.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                                          ctypes.POINTER(ctypes.c_int)]
    libc.free.argtypes = [ctypes.c_void_p]

    def encode(img):
        ctypes.c_int.in_dll(lib, "stbi_write_force_png_filter").value = filt
        ctypes.c_int.in_dll(lib, "stbi_write_png_compression_level").value = level
        n = ctypes.c_int()
        h, w, c = img.shape
        p = lib.stbi_write_png_to_mem(img.ctypes.data, w * c, w, h, c, ctypes.byref(n))
        libc.free(p)
        return n.value
    return encode


def pillow(img, level=3):
    out = io.BytesIO()
    Image.fromarray(img).save(out, "PNG", compress_level=level)
    return len(out.getvalue())


def cpu_ms(encode, img, repeats):
    times, size = [], 0
    for _ in range(repeats):
        t0 = time.process_time()
        size = encode(img)
        times.append(time.process_time() - t0)
    return statistics.median(times) * 1e3, size


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--repeats", type=int, default=40)
    args = p.parse_args()
    encoders = {"pillow level 3 (adaptive)": pillow}
    for f in ("none", "sub", "up", "paeth", "adaptive"):
        for level in (1, 3, 6):
            encoders[f"libpng {f} level {level}"] = lambda i, f=f, level=level: len(encode_png(i, level, f))
    stb = stb_encoder(2, 1)
    if stb:
        encoders["stb up level 1"] = stb
        encoders["stb adaptive level 8"] = stb_encoder(-1, 8)
    ratios = {k: [] for k in encoders}
    for w, h in ((256, 256), (640, 480)):
        for path in MODELS:
            if not os.path.exists(path):
                continue
            color, mask = render(path, w, h)
            print(f"{w}x{h} {os.path.basename(path)}")
            base = cpu_ms(pillow, color, args.repeats)
            for name, enc in encoders.items():
                ms, size = cpu_ms(enc, color, args.repeats)
                ratios[name].append((ms / base[0], size / base[1]))
                print(f"  {name:28s} {ms:6.2f} ms {size:7d} B")
            for name, enc in (("mask: pillow level 3", pillow_mask),
                              ("mask: libpng up level 3", lambda m: len(encode_png(m))),
                              ("mask: libpng none level 3", lambda m: len(encode_png(m, 3, "none")))):
                ms, size = cpu_ms(enc, mask, args.repeats)
                print(f"  {name:28s} {ms:6.2f} ms {size:7d} B")
    print("geometric means against Pillow (time, size, time x size):")
    for name, rs in ratios.items():
        t = math.exp(statistics.mean(math.log(r[0]) for r in rs))
        s = math.exp(statistics.mean(math.log(r[1]) for r in rs))
        print(f"  {name:28s} {t:.2f}x {s:.2f}x {t * s:.2f}x")


def pillow_mask(mask):
    out = io.BytesIO()
    Image.frombuffer("I;16", (mask.shape[1], mask.shape[0]), np.ascontiguousarray(mask, "<u2"), "raw", "I;16", 0,
                     1).save(out, "PNG", compress_level=3)
    return len(out.getvalue())


if __name__ == "__main__":
    main()
