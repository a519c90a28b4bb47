#!/usr/bin/env bash
# How Velocity and Mesa's llvmpipe scale with threads, on the shared scene convention
# (../shared/tools/README.md): for each scene and each thread count, PAIRS alternating
# runs of glref (LP_NUM_THREADS=N) and `velocity bench --threads N`, each the median
# frame time of FRAMES frames. The table gives each renderer's median over the pairs,
# the median of the pairs' ratios (llvmpipe time / Velocity time), and each renderer's
# speed-up over its own time on one thread.
#
#   scripts/scaling.sh [--threads "1 2 4 8 16"] [--pairs N] [--frames N] [--only REGEX]
#
# Thread counts above the machine's cores are skipped. VELOCITY and GLREF name the two
# programs (default: build/velocity, and glref built into /tmp/velocity-glref from
# ../shared/tools); scripts/bundle.sh render packs both to run this on another machine.
# Prints a Markdown table.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
threads="1 2 4 8 16" pairs=3 frames=20 only=.
while (($#)); do
  case "$1" in
    --threads) threads="$2"; shift 2 ;;
    --pairs) pairs="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    *) echo "usage: scripts/scaling.sh [--threads \"1 2 4 8 16\"] [--pairs N] [--frames N] [--only REGEX]" >&2; exit 2 ;;
  esac
done
velocity="${VELOCITY:-$root/build/velocity}"
glref="${GLREF:-/tmp/velocity-glref/glref}"
if [[ ! -x "$glref" ]]; then
  mkdir -p "$(dirname "$glref")"
  g++ -O2 -o "$glref" "$root/../shared/tools/glref/glref.cpp" -lOSMesa -ltinyobjloader -lstb
fi
[[ -x "$velocity" ]] || cmake --build "$root/build" --target velocity_cli >/dev/null
cores=$(nproc)

scenes=(
  "sphere:1024 gouraud (1 M triangles)|--mesh sphere:1024 --shade gouraud --size 1920x1080"
  "sphere:1024 tex|--mesh sphere:1024 --shade tex --size 1920x1080"
  "sphere:16 x 1000 copies gouraud|--mesh sphere:16 --copies 1000 --shade gouraud --size 1920x1080"
  "sphere:64 tex|--mesh sphere:64 --shade tex --size 1920x1080"
  "sphere:64 phong|--mesh sphere:64 --shade phong --size 1920x1080"
)

median() { sort -g | awk '{a[NR] = $1} END { if (NR % 2) print a[(NR + 1) / 2]; else printf "%.4f\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
ms() { sed -n 's/.* median_ms=\([0-9.]*\).*/\1/p'; }

echo "Velocity $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?') and llvmpipe by threads, $(date -u +%Y-%m-%d), $cores cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), $pairs alternating pairs of $frames frames, simd=$("$velocity" bench --mesh sphere:8 --size 64x64 --frames 1 --verbose | sed -n 's/^simd=\([^ ]*\).*/\1/p')"
echo
echo "| scene (1920x1080) | threads | llvmpipe ms | Velocity ms | ratio | llvmpipe speed-up | Velocity speed-up |"
echo "|---|---|---|---|---|---|---|"
for s in "${scenes[@]}"; do
  IFS='|' read -r name args <<<"$s"
  [[ "$name" =~ $only ]] || continue
  ref1="" ours1=""
  for n in $threads; do
    ((n <= cores)) || continue
    ref=() ours=() ratios=()
    for ((p = 0; p < pairs; ++p)); do
      # shellcheck disable=SC2086
      a=$(LP_NUM_THREADS=$n "$glref" $args --frames "$frames" | ms)
      # shellcheck disable=SC2086
      b=$("$velocity" bench $args --frames "$frames" --threads "$n" | ms)
      ref+=("$a") ours+=("$b") ratios+=("$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.4f", a / b }')")
    done
    r=$(printf '%s\n' "${ref[@]}" | median) o=$(printf '%s\n' "${ours[@]}" | median)
    [[ -z "$ref1" ]] && ref1=$r ours1=$o
    printf '| %s | %d | %.2f | %.2f | %.2f | %.2fx | %.2fx |\n' "$name" "$n" "$r" "$o" \
      "$(printf '%s\n' "${ratios[@]}" | median)" "$(awk -v a="$ref1" -v b="$r" 'BEGIN { print a / b }')" \
      "$(awk -v a="$ours1" -v b="$o" 'BEGIN { print a / b }')"
  done
done
