#!/usr/bin/env bash
# Runs `velocity bench` and the shared glref (Mesa llvmpipe, 2 threads) on the same scenes in
# one run and prints both lines plus the fps ratio (velocity / llvmpipe). Needs ../shared/tools.
#   scripts/compare_glref.sh [size] [frames] [meshes...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tools="$root/../shared/tools"
[[ -d "$tools" ]] || { echo "compare_glref: $tools not found" >&2; exit 2; }
size="${1:-1920x1080}"; frames="${2:-30}"; shift $(( $# > 2 ? 2 : $# ))
meshes=("$@"); ((${#meshes[@]})) || meshes=(sphere:64 sphere:512)
bin=/tmp/velocity-glref
mkdir -p "$bin"
[[ -x "$bin/glref" ]] || g++ -O2 -o "$bin/glref" "$tools/glref/glref.cpp" -lOSMesa -ltinyobjloader -lstb
[[ -x "$root/build/velocity" ]] || cmake --build "$root/build" --target velocity_cli >/dev/null
fps() { sed -n 's/.* fps=\([0-9.]*\).*/\1/p'; }
for mesh in "${meshes[@]}"; do
  for shade in flat gouraud phong wire; do
    ref=$(LP_NUM_THREADS=2 "$bin/glref" --mesh "$mesh" --size "$size" --frames "$frames" --shade "$shade")
    ours=$("$root/build/velocity" bench --mesh "$mesh" --size "$size" --frames "$frames" --shade "$shade")
    echo "$ref"; echo "$ours"
    awk -v a="$(echo "$ours" | fps)" -v b="$(echo "$ref" | fps)" -v m="$mesh" -v s="$shade" \
      'BEGIN { printf "ratio mesh=%s shade=%s velocity/llvmpipe=%.2f\n", m, s, a / b }'
  done
done
