#!/usr/bin/env python3
"""The three.js oracle's generated glTF scenes (tests/reference/threejs/check_velocity.py)
rendered by `velocity render` on both backends, compared by PSNR over the whole image:

  spheres   3x3 PBR spheres, metallic x roughness, the file's directional and point
            (inverse square, range) lights, sRGB output: >= 40 dB (untextured)
  blend     an opaque quad behind two BLEND quads, unlit: >= 40 dB

Usage: fixtures_on_gpu.py OUT_DIR (VELOCITY_CLI names the program; the GPU backend as
VELOCITY_GPU_LIBRARY finds it). Needs no browser: three.js is not run here.
"""
from __future__ import annotations

import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "reference", "threejs"))
import check_velocity  # noqa: E402
import fixtures  # noqa: E402
import png  # noqa: E402

MIN_PSNR = 40.0


def render(cli: str, model: str, out: str, backend: str) -> bytes:
    run = subprocess.run([cli, "render", model, "--out", out, "--size", "320x320", "--camera", "0,0,6", "--fov", "45",
                          "--backend", backend], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        raise SystemExit(f"FAIL: velocity render --backend {backend}: {run.stderr.strip()}")
    w, h, c, pixels = png.read(out)
    return bytes(v for k, v in enumerate(pixels) if k % c < 3)


def main() -> int:
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    cli = os.environ.get("VELOCITY_CLI", "velocity")
    failed = 0
    for case, doc in (("spheres", check_velocity.spheres_doc()), ("blend", check_velocity.blend_doc())):
        model = fixtures.write(os.path.join(out, f"{case}.gltf"), doc)
        a = render(cli, model, os.path.join(out, f"{case}-cpu.png"), "cpu")
        b = render(cli, model, os.path.join(out, f"{case}-gpu.png"), "gpu")
        db = check_velocity.psnr(a, b)
        drawn = sum(1 for k in range(0, len(a), 3) if a[k:k + 3] != a[0:3])
        print(f"[gpu-parity] threejs fixture {case}: PSNR {db:.2f} dB (floor {MIN_PSNR}), {drawn} pixels drawn")
        if db < MIN_PSNR or drawn < len(a) // 3 // 20:
            failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
