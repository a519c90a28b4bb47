#!/usr/bin/env python3
"""The Python binding's cost and Velocity against llvmpipe, on the same frame, in one run.

For each mesh and size: the benchmark scene's frame (../shared/tools/README.md's
convention: UV sphere, camera at (0, 0, 3), 45 degrees, Gouraud, one light) rendered
  * by the C++ library (velocity_python_bench: draw, read_color, view_depth),
  * through Python (OffscreenRenderer.render -> colour and depth numpy arrays), with
    RGBA colour (what the C++ side reads) and with RGB (pyrender's default: one more
    pass over the image, packing RGBA into RGB),
  * by Mesa's llvmpipe through OSMesa (velocity_python_bench --renderer llvmpipe: draw,
    glFinish, glReadPixels of the colour), which is what pyrender renders with when
    there is no GPU; LP_NUM_THREADS = the cores Velocity uses.
Rounds alternate the three; the figure per renderer is the median of the rounds'
median frame times. First checks that Python and C++ render the very same image.

    PYTHONPATH=build/python python3 python/bench/bench_python.py [--rounds 5] [--frames 40]
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import velocity
from velocity.png import decode_png

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def python_scene(segments):
    ref = velocity.Mesh.sphere(segments).primitives[0]
    mesh = velocity.Mesh.from_arrays(np.array(ref.positions), np.array(ref.indices), normals=np.array(ref.normals),
                                     uvs=np.array(ref.texcoord_0),
                                     material=velocity.Material(color=(0.8, 0.7, 0.6), shading="gouraud"))
    scene = velocity.Scene(bg_color=(0.1, 0.1, 0.15, 1.0), ambient_light=(0.2, 0.2, 0.2))
    node = scene.add(mesh)
    cam = np.eye(4)
    cam[2, 3] = 3
    scene.add(velocity.PerspectiveCamera(math.radians(45), znear=0.1, zfar=100), pose=cam)
    # The convention's light: from (0.3, 0.5, 1) in eye space (= world here), diffuse 0.8.
    scene.add(velocity.DirectionalLight(intensity=0.8 * math.pi), pose=velocity.look_at([0, 0, 0], [-0.3, -0.5, -1]))
    return scene, node


def spin(i, frames):
    a = math.radians(360.0 * i / frames)
    m = np.eye(4)
    m[0, 0], m[0, 2], m[2, 0], m[2, 2] = math.cos(a), math.sin(a), -math.sin(a), math.cos(a)
    return m


def time_python(segments, w, h, frames, threads, flags):
    scene, node = python_scene(segments)
    r = velocity.OffscreenRenderer(w, h, threads=threads)
    r.render(scene, flags)  # warm-up
    ms = []
    for i in range(frames):
        t0 = time.perf_counter()
        scene.set_pose(node, spin(i, frames))
        color, depth = r.render(scene, flags)
        ms.append((time.perf_counter() - t0) * 1e3)
    return statistics.median(ms)


def run_bench(build, renderer, mesh, size, frames, threads, out=None):
    cmd = [os.path.join(build, "python", "velocity_python_bench"), "--renderer", renderer, "--mesh", mesh,
           "--size", size, "--frames", str(frames), "--threads", str(threads)]
    if out:
        cmd += ["--out", out]
    env = dict(os.environ, LP_NUM_THREADS=str(threads or os.cpu_count()))
    line = subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout
    return float(re.search(r"median_ms=([0-9.]+)", line).group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--frames", type=int, default=40)
    p.add_argument("--threads", type=int, default=0, help="cores per frame (0: all)")
    p.add_argument("--cases", default="sphere:64@640x480,sphere:64@1920x1080,sphere:512@640x480,sphere:512@1920x1080")
    args = p.parse_args()
    cases = [c.split("@") for c in args.cases.split(",")]

    # Same frame: Python's image of frame 0 against the C++ library's. (The light's
    # direction is normalised in double in Python, in float in C++: a level here and
    # there may differ.)
    with tempfile.TemporaryDirectory() as tmp:
        for mesh, size in cases:
            w, h = map(int, size.split("x"))
            png = os.path.join(tmp, "cpp.png")
            run_bench(args.build, "velocity", mesh, size, 1, args.threads, png)
            cpp = decode_png(open(png, "rb").read())[:, :, :3]
            scene, node = python_scene(int(mesh.split(":")[1]))
            py = velocity.OffscreenRenderer(w, h).render(scene)[0]
            same = np.array_equal(cpp, py)
            print(f"same frame {mesh} {size}: {'identical' if same else 'DIFFERENT'}"
                  f" (max difference {np.abs(cpp.astype(int) - py).max()})")

    print(f"cores: {os.cpu_count()}, threads per frame: {args.threads or 'all'}, rounds: {args.rounds}, "
          f"frames per round: {args.frames}")
    print("| Mesh | Size | C++ ms | Python RGBA ms | RGBA / C++ | Python RGB ms | RGB / C++ | llvmpipe ms "
          "| llvmpipe / Python RGB (>1: Velocity faster) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for mesh, size in cases:
        w, h = map(int, size.split("x"))
        segs = int(mesh.split(":")[1])
        cpp, rgba, rgb, lp = [], [], [], []
        for _ in range(args.rounds):
            cpp.append(run_bench(args.build, "velocity", mesh, size, args.frames, args.threads))
            rgba.append(time_python(segs, w, h, args.frames, args.threads, velocity.RenderFlags.RGBA))
            rgb.append(time_python(segs, w, h, args.frames, args.threads, velocity.RenderFlags.NONE))
            lp.append(run_bench(args.build, "llvmpipe", mesh, size, args.frames, args.threads))
        c, a, q, l = (statistics.median(x) for x in (cpp, rgba, rgb, lp))
        print(f"| {mesh} | {size} | {c:.2f} | {a:.2f} | {a / c:.3f} | {q:.2f} | {q / c:.3f} | {l:.2f} | {l / q:.2f} |",
              flush=True)


if __name__ == "__main__":
    sys.exit(main())
