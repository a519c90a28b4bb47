#!/bin/sh
# `pip install .` offline into a fresh virtual environment (Debian's python3 and pip),
# then the installed module renders and the velocity-batch command runs.
# Usage: scripts/test_pip_install.sh [python3]   (default /usr/bin/python3)
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
python=${1:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" -m venv --system-site-packages "$work/venv"
# --no-index: nothing from the network; the build backend needs no package.
# What this checks is the install (the backend, the wheel, the command), not the kernels,
# which ./test.sh's own build compiles for every instruction set: the module is built
# for this processor alone (VELOCITY_NATIVE, through the backend's CMAKE_ARGS), a
# quarter of the kernels to compile (this test took 488 s with every instruction set,
# by far ./test.sh's longest, and 201 s so, on a 2-core Zen 3). VELOCITY_PIP_CMAKE_ARGS
# overrides it (set and empty: the portable build).
CMAKE_ARGS=${VELOCITY_PIP_CMAKE_ARGS--DVELOCITY_NATIVE=ON} PIP_NO_INPUT=1 \
  "$work/venv/bin/pip" install --no-index --disable-pip-version-check "$src"
cd "$work"  # not the source tree: the installed package must be the one imported
"$work/venv/bin/python" - <<'PY'
import os, sys
import numpy as np
import velocity, velocity.pyrender as pyrender
assert velocity.__file__.startswith(sys.prefix), velocity.__file__
scene = pyrender.Scene(bg_color=[0, 0, 0])
scene.add(pyrender.Mesh.from_points(np.zeros((1, 3)), colors=[[1.0, 0.0, 0.0]]))
scene.add(pyrender.OrthographicCamera(xmag=1.0, ymag=1.0), pose=np.array(
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 2.0], [0, 0, 0, 1]]))
color, depth = pyrender.OffscreenRenderer(8, 8).render(scene)
assert depth[4, 4] == 2.0 and tuple(color[4, 4]) == (255, 0, 0) and (depth > 0).sum() == 1, (depth, color)
from velocity.png import encode_png  # libpng, linked into the installed module
assert encode_png(np.zeros((2, 3), np.uint16))[:8] == b"\x89PNG\r\n\x1a\n"
print("installed velocity", velocity.__file__)
PY
"$work/venv/bin/velocity-batch" --help > "$work/help.txt"
grep -q "velocity-batch" "$work/help.txt"
"$work/venv/bin/pip" uninstall -y velocity > /dev/null
echo "pip install: ok"
