#!/usr/bin/env bash
# Where the GPU backend's frame goes, on a machine with a GPU (issue 19, docs/gpu.md
# "Timing the passes"): for bench_gpu.sh's four cases at 3840x2160 (1 M and 10 M
# triangles, tex and phong), the host's stages (upload, submit, gpu_wait, readback)
# and the GPU's own time per pass from GL_TIME_ELAPSED queries (shadow, opaque, blend,
# read), each the median of the frames. About a minute; VELOCITY names the program
# (default build/velocity, or the bundle's: scripts/bundle.sh gpu).
#
#   scripts/gpu_probe.sh [--frames N] [--size WxH]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
frames=5 size=3840x2160
while (($#)); do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    *) echo "usage: scripts/gpu_probe.sh [--frames N] [--size WxH]" >&2; exit 2 ;;
  esac
done
velocity="${VELOCITY:-$root/build/velocity}"
[[ -x "$velocity" ]] || { echo "gpu_probe.sh: no velocity program at $velocity (build it, or set VELOCITY)" >&2; exit 2; }

for mesh in sphere:1024 sphere:3200; do
  for shade in tex phong; do
    echo "== $mesh $shade $size"
    # (backend= names what drew: a software driver's figures are no GPU measurement)
    timeout 60 "$velocity" bench --mesh "$mesh" --shade "$shade" --size "$size" --frames "$frames" \
      --backend gpu --verbose | grep -E '^(renderer=|backend=|median gpu)' || echo "  failed (rc=$?)"
  done
done
