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
# programs (scripts/lib/against_llvmpipe.sh); scripts/bundle.sh render packs both to run
# this on another machine.
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
# shellcheck source=lib/against_llvmpipe.sh
source "$root/scripts/lib/against_llvmpipe.sh"
cores=$(nproc)

scenes=(
  "sphere:1024 gouraud (1 M triangles)|--mesh sphere:1024 --shade gouraud --size 1920x1080"
  "sphere:1024 tex|--mesh sphere:1024 --shade tex --size 1920x1080"
  "sphere:16 x 1000 copies gouraud|--mesh sphere:16 --copies 1000 --shade gouraud --size 1920x1080"
  "sphere:64 tex|--mesh sphere:64 --shade tex --size 1920x1080"
  "sphere:64 phong|--mesh sphere:64 --shade phong --size 1920x1080"
)

echo "Velocity $(machine) and llvmpipe by threads, $pairs alternating pairs of $frames frames, simd=$(simd)"
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
      ref+=("$a") ours+=("$b") ratios+=("$(ratio "$a" "$b")")
    done
    r=$(printf '%s\n' "${ref[@]}" | median) o=$(printf '%s\n' "${ours[@]}" | median)
    [[ -z "$ref1" ]] && ref1=$r ours1=$o
    printf '| %s | %d | %.2f | %.2f | %.2f | %.2fx | %.2fx |\n' "$name" "$n" "$r" "$o" \
      "$(printf '%s\n' "${ratios[@]}" | median)" "$(ratio "$ref1" "$r")" \
      "$(ratio "$ours1" "$o")"
  done
done
