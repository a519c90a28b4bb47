#!/usr/bin/env python3
"""velocity.pyrender against the native `velocity` module on the same frame: a UV sphere
(segments x segments/2) at the origin, a camera at (0, 0, 3) with a 45-degree field of
view, one directional light, colour + depth at W x H. Both render through the same
engine; the difference is pyrender's object model in Python (its scene converted to an
engine scene at each render, meshes cached). Rounds alternate the two; each figure is
the median of the rounds' median frame times. --clock cpu times the process's CPU time
(every thread's) instead of the wall clock: on a shared, loaded machine it counts the
work done, not the waiting.

    PYTHONPATH=build/python python3 python/bench/bench_pyrender.py [--rounds 5] [--frames 40] [--size 640x480]
        [--threads N] [--clock wall|cpu]
"""
import argparse
import math
import statistics
import time

import numpy as np

import velocity
import velocity.pyrender as pyrender


def native_scene(sphere, pose):
    scene = velocity.Scene(bg_color=(0, 0, 0, 1))
    # pyrender's default material, as velocity.pyrender gives it to the engine.
    material = velocity.Material(color=(1, 1, 1), metallic=1.0, roughness=1.0, color_space="linear")
    scene.add(velocity.Mesh.from_arrays(sphere.positions, sphere.indices, normals=sphere.normals, material=material))
    scene.add(velocity.PerspectiveCamera(math.radians(45), znear=0.05, zfar=100.0), pose=pose)
    scene.add(velocity.DirectionalLight(intensity=3.0 * math.pi), pose=pose)
    return scene


def pyrender_scene(sphere, pose):
    scene = pyrender.Scene(bg_color=[0, 0, 0])
    prim = pyrender.Primitive(positions=np.array(sphere.positions), normals=np.array(sphere.normals),
                              indices=np.array(sphere.indices))
    scene.add(pyrender.Mesh([prim]))
    scene.add(pyrender.PerspectiveCamera(yfov=math.radians(45), znear=0.05, zfar=100.0), pose=pose)
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=pose)
    return scene


def frame_ms(render, frames, clock=time.perf_counter):
    times = []
    for _ in range(frames):
        t0 = clock()
        render()
        times.append((clock() - t0) * 1e3)
    return statistics.median(times)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--frames", type=int, default=40)
    p.add_argument("--size", default="640x480")
    p.add_argument("--segments", type=int, default=64)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--clock", choices=("wall", "cpu"), default="wall")
    args = p.parse_args()
    clock = time.process_time if args.clock == "cpu" else time.perf_counter
    w, h = (int(v) for v in args.size.split("x"))
    sphere = velocity.Mesh.sphere(args.segments).primitives[0]
    pose = np.eye(4)
    pose[2, 3] = 3.0
    native, pyr = native_scene(sphere, pose), pyrender_scene(sphere, pose)
    rn = velocity.OffscreenRenderer(w, h, threads=args.threads)
    rp = pyrender.OffscreenRenderer(w, h, threads=args.threads)
    # The very same frame.
    cn, dn = rn.render(native)
    cp, dp = rp.render(pyr)
    assert np.array_equal(dn, dp) and np.array_equal(cn, cp), "the two scenes do not give the same frame"
    a, b = [], []
    for _ in range(args.rounds):
        a.append(frame_ms(lambda: rn.render(native), args.frames, clock))
        b.append(frame_ms(lambda: rp.render(pyr), args.frames, clock))
    na, nb = statistics.median(a), statistics.median(b)
    print(f"sphere {args.segments} at {w}x{h}: native velocity {na:.3f} ms/frame, velocity.pyrender {nb:.3f} "
          f"ms/frame: {100 * (nb / na - 1):+.1f} % ({args.clock} time)")


if __name__ == "__main__":
    main()
