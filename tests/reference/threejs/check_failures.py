#!/usr/bin/env python3
"""render.py fails clearly: for each bad input, exit status 1 and one line on stderr that
says what went wrong, within its timeout, and no image written.

    check_failures.py OUT_DIR

Exit status 0 pass, 1 fail, 77 Chromium missing (ctest's SKIP_RETURN_CODE).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import chromium  # noqa: E402

BOX = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf"


def cases(out: str) -> list[tuple[str, list[str], dict, str]]:
    """(name, arguments, extra environment, text the one line must contain)"""
    garbage = os.path.join(out, "garbage.glb")
    with open(garbage, "w") as f:
        f.write("not a glTF file\n")
    no_bin = os.path.join(out, "no_bin.gltf")  # BoxTextured without its .bin beside it
    with open(BOX) as f, open(no_bin, "w") as g:
        json.dump(json.load(f), g)
    return [
        ("missing file", [os.path.join(out, "nonexistent.gltf")], {}, "no such file"),
        ("not glTF", [garbage], {}, "GLTFLoader could not load it"),
        ("missing buffer", [no_bin], {}, 'Failed to load buffer "BoxTextured0.bin"'),
        ("no WebGL", [BOX], {"VELOCITY_CHROMIUM_FLAGS": "--disable-webgl"}, "WebGL is not available"),
        ("timeout", [BOX, "--timeout", "0.01"], {}, "timed out after 0.01 s"),
        ("no Chromium", [BOX], {"VELOCITY_CHROMIUM": "/nonexistent/chromium"}, "is not an executable"),
    ]


def main(out: str) -> int:
    try:
        chromium.find_chromium()
    except chromium.ChromiumMissing as e:
        print(f"SKIP: {e}")
        return 77
    os.makedirs(out, exist_ok=True)
    failed = 0
    for name, args, env, want in cases(out):
        png_out = os.path.join(out, "failure.png")
        if os.path.exists(png_out):
            os.remove(png_out)
        run = subprocess.run([sys.executable, os.path.join(HERE, "render.py"), *args, "--out", png_out],
                             capture_output=True, text=True, timeout=90, env={**os.environ, **env})
        lines = run.stderr.splitlines()
        want_status = 77 if name == "no Chromium" else 1
        ok = run.returncode == want_status and len(lines) == 1 and want in lines[0] and not os.path.exists(png_out)
        print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {run.returncode}, stderr {run.stderr.strip()!r}")
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} OUT_DIR")
    sys.exit(main(sys.argv[1]))
