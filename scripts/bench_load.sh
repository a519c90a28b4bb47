#!/usr/bin/env bash
# Load-speed benchmark: writes a 1,002,528-triangle grid as ASC (3D Studio style: CRLF,
# Page lines, a Material and a Smoothing line per face) and as OBJ into a scratch folder,
# then times `velocity info` on each (load + normals + counts), best of 3.
#   scripts/bench_load.sh [scratch-dir]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:-/tmp/velocity-bench-load}"
mkdir -p "$dir"
[[ -x "$root/build/velocity" ]] || cmake --build "$root/build" --target velocity_cli >/dev/null
python3 - "$dir" <<'PY'
import os, sys
d = sys.argv[1]; n = 708  # n x n quads: 2 n^2 = 1,002,528 triangles
if not os.path.exists(f"{d}/grid.obj"):
    with open(f"{d}/grid.obj", "w") as f:
        for j in range(n + 1):
            for i in range(n + 1):
                f.write("v %.5f %.5f %.5f\n" % (i / n, j / n, 0.1 * ((i * j) % 7) / 7))
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; e = c + 1
                f.write("f %d %d %d\nf %d %d %d\n" % (a, b, e, a, e, c))
if not os.path.exists(f"{d}/grid.asc"):
    with open(f"{d}/grid.asc", "w", newline="") as f:
        w = lambda s: f.write(s + "\r\n")
        w("Ambient light color: Red=0.3 Green=0.3 Blue=0.3"); w("")
        w('Named object: "grid"')
        w("Tri-mesh, Vertices: %d     Faces: %d" % ((n + 1) ** 2, 2 * n * n))
        w("Vertex list:")
        k = 0
        for j in range(n + 1):
            for i in range(n + 1):
                w("Vertex %d:  X: %.6f     Y: %.6f     Z: %.6f" % (k, i / n, j / n, 0.1 * ((i * j) % 7) / 7)); k += 1
                if k % 60 == 0: w(""); w(" " * 36 + "Page %d" % (k // 60)); w("")
        w("Face list:")
        k = 0
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i; b = a + 1; c = a + n + 1; e = c + 1
                for (p, q, r) in ((a, b, e), (a, e, c)):
                    w("Face %d:    A:%d B:%d C:%d AB:1 BC:1 CA:1" % (k, p, q, r)); k += 1
                    w('Material:"r200g180b160a0"'); w("Smoothing:  1")
PY
for f in grid.asc grid.obj; do
  best=""
  for i in 1 2 3; do
    t=$( { /usr/bin/time -f "%e" "$root/build/velocity" info "$dir/$f" >/dev/null; } 2>&1 | tail -1)
    best=$(awk -v t="$t" -v b="$best" 'BEGIN { print (b == "" || t < b) ? t : b }')
  done
  echo "load $f: $(ls -la "$dir/$f" | awk '{print $5}') bytes, 1002528 triangles, best of 3: $best s"
done
