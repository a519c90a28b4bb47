#!/usr/bin/env bash
# pGL against Mesa's llvmpipe on the same GL program (gl/bench/gl_bench.c), same machine,
# same run: Velocity on 2 threads (VELOCITY_THREADS=2), llvmpipe on 2 (LP_NUM_THREADS=2).
#
#   scripts/bench_gl.sh [WxH] [FRAMES] [ROUNDS]     default 1920x1080, 30 frames, 3 rounds
#
# THREADS=N sets both renderers' threads (default 2). VELOCITY_BUILD names a build folder
# other than build/ (scripts/bundle.sh gl packs the two programs into one, to run this on
# another machine: there it is not rebuilt).
#
# Each round runs both programs one after the other (median frame time: clear, draw,
# glFinish); the table gives each one's best round, so that a burst of other load on a
# shared machine does not decide the ratio, and the ratio llvmpipe / Velocity (> 1:
# Velocity is faster). Then immediate mode / vertex arrays on Velocity.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
size="${1:-1920x1080}"
frames="${2:-30}"
rounds="${3:-3}"
build="${VELOCITY_BUILD:-$root/build}"
threads="${THREADS:-2}"
[[ -f "$build/CMakeCache.txt" ]] && cmake --build "$build" --target gl_bench gl_bench_mesa >/dev/null
ms() { sed -n 's/.*median_ms=\([0-9.]*\).*/\1/p'; }
best() { printf '%s\n' "$@" | sort -g | head -1; }
declare -A vel
printf '| scene | size | llvmpipe ms | Velocity ms | ratio |\n|---|---|---|---|---|\n'
for scene in gears mesh-immediate mesh-arrays; do
  m=() v=()
  for ((r = 0; r < rounds; ++r)); do
    m+=("$(LP_NUM_THREADS=$threads "$build/gl/bench/gl_bench_mesa" "$scene" "$size" "$frames" | ms)")
    v+=("$(VELOCITY_THREADS=$threads "$build/gl/bench/gl_bench" "$scene" "$size" "$frames" | ms)")
  done
  bm=$(best "${m[@]}") bv=$(best "${v[@]}")
  vel[$scene]=$bv
  awk -v s="$scene" -v z="$size" -v m="$bm" -v v="$bv" 'BEGIN { printf "| %s | %s | %s | %s | %.2f |\n", s, z, m, v, m / v }'
done
awk -v i="${vel[mesh-immediate]}" -v a="${vel[mesh-arrays]}" 'BEGIN { printf "\nVelocity immediate mode / vertex arrays: %.2f\n", i / a }'
