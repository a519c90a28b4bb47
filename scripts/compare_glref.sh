#!/usr/bin/env bash
# Velocity against Mesa's llvmpipe (../shared/tools/glref, through OSMesa) on the shared
# scene convention, in one run on one machine: for each scene, PAIRS alternating runs of
# glref and `velocity bench`, each the median frame time of FRAMES frames; the table
# gives each renderer's median over the pairs and the median of the pairs' ratios
# (llvmpipe time / Velocity time: above 1, Velocity is faster), with the target where
# the speed issue sets one. glref draws the seeds' modes; glTF's PBR and shadow maps
# come from the project's own harness on llvmpipe (velocity-ref: the same BRDF in GLSL,
# and a depth texture read through GL's depth-compare sampler). Then each renderer's
# PBR-textured and shadowed frames as multiples of its own Phong frame, Velocity's own
# scaling from 1 thread to THREADS, and seed 000's headline figures restated as what
# Velocity does here.
#
#   scripts/compare_glref.sh [--threads N] [--pairs N] [--frames N] [--only REGEX]
#
# Both renderers use the same number of threads (LP_NUM_THREADS for llvmpipe, --threads
# for Velocity; default 2, this machine's cores). VELOCITY and GLREF name the programs
# (scripts/lib/against_llvmpipe.sh). Prints a Markdown table.
#
# BASELINE=/path/to/an/older/velocity adds that build to every pair of the first table
# (three runs a pair, in turn), with two more columns: its median and the median of the
# pairs' ratios of this build's time to its time (above 1: this build is slower). That
# is how a change is shown not to slow a scene down: both builds in one run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
threads=2 pairs=5 frames=20 only=.
while (($#)); do
  case "$1" in
    --threads) threads="$2"; shift 2 ;;
    --pairs) pairs="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    *) echo "usage: scripts/compare_glref.sh [--threads N] [--pairs N] [--frames N] [--only REGEX]" >&2; exit 2 ;;
  esac
done
# shellcheck source=lib/against_llvmpipe.sh
source "$root/scripts/lib/against_llvmpipe.sh"

# scene: "name|bench arguments|target ratio (or -)"
scenes=(
  "sphere:1024 gouraud (1 M triangles)|--mesh sphere:1024 --shade gouraud --size 1920x1080|3.0"
  "sphere:1024 tex|--mesh sphere:1024 --shade tex --size 1920x1080|3.0"
  "sphere:16 x 1000 copies gouraud|--mesh sphere:16 --copies 1000 --shade gouraud --size 1920x1080|3.0"
  "sphere:64 phong|--mesh sphere:64 --shade phong --size 1920x1080|1.5"
  "sphere:64 env|--mesh sphere:64 --shade env --size 1920x1080|1.5"
  "sphere:64 tex|--mesh sphere:64 --shade tex --size 1920x1080|1.5"
  "sphere:24 tex 320x200 (seed 000's scene)|--mesh sphere:24 --shade tex --size 320x200|2.0"
  "sphere:64 flat|--mesh sphere:64 --shade flat --size 1920x1080|-"
  "sphere:64 gouraud|--mesh sphere:64 --shade gouraud --size 1920x1080|-"
  "sphere:64 wire|--mesh sphere:64 --shade wire --size 1920x1080|-"
  "sphere:512 flat|--mesh sphere:512 --shade flat --size 1920x1080|-"
  "sphere:512 gouraud|--mesh sphere:512 --shade gouraud --size 1920x1080|-"
  "sphere:512 phong|--mesh sphere:512 --shade phong --size 1920x1080|-"
  "sphere:512 wire|--mesh sphere:512 --shade wire --size 1920x1080|-"
  "sphere:64 pbr|--mesh sphere:64 --shade pbr --size 1920x1080|-"
  "sphere:64 pbrtex|--mesh sphere:64 --shade pbrtex --size 1920x1080|-"
  "sphere:64 phong + 2048² shadow map|--mesh sphere:64 --shade phong --shadows --size 1920x1080|-"
  "sphere:64 pbrtex + 2048² shadow map|--mesh sphere:64 --shade pbrtex --shadows --size 1920x1080|-"
)
# Each scene's medians, by name, for the table of ratios to the Phong frame.
declare -A ref_ms ours_ms

echo "Velocity $(machine) against llvmpipe, both on $threads threads, $pairs alternating pairs of $frames frames, simd=$(simd)"
echo
baseline="${BASELINE:-}"
if [[ -n "$baseline" ]]; then
  echo "| scene (1920x1080 unless said) | llvmpipe ms | Velocity ms | ratio | target | baseline ms | Velocity / baseline |"
  echo "|---|---|---|---|---|---|---|"
else
  echo "| scene (1920x1080 unless said) | llvmpipe ms | Velocity ms | ratio | target |"
  echo "|---|---|---|---|---|"
fi
for s in "${scenes[@]}"; do
  IFS='|' read -r name args target <<<"$s"
  [[ "$name" =~ $only ]] || continue
  ref=() ours=() ratios=() old=() slower=()
  reference="$glref"
  [[ "$args" =~ pbr|--shadows ]] && reference="$vref"
  for ((p = 0; p < pairs; ++p)); do
    # shellcheck disable=SC2086
    a=$(LP_NUM_THREADS=$threads "$reference" $args --frames "$frames" | ms)
    # shellcheck disable=SC2086
    b=$("$velocity" bench $args --frames "$frames" --threads "$threads" | ms)
    ref+=("$a") ours+=("$b") ratios+=("$(ratio "$a" "$b")")
    if [[ -n "$baseline" ]]; then
      # shellcheck disable=SC2086
      c=$("$baseline" bench $args --frames "$frames" --threads "$threads" | ms)
      old+=("$c") slower+=("$(ratio "$b" "$c")")
    fi
  done
  r=$(printf '%s\n' "${ratios[@]}" | median)
  ref_ms[$name]=$(printf '%s\n' "${ref[@]}" | median) ours_ms[$name]=$(printf '%s\n' "${ours[@]}" | median)
  verdict=""
  [[ "$target" != "-" ]] && verdict=$(awk -v r="$r" -v t="$target" 'BEGIN { print (r >= t ? "≥ " t " met" : "≥ " t " missed") }')
  printf '| %s | %.2f | %.2f | %.2f | %s |' "$name" "$(printf '%s\n' "${ref[@]}" | median)" \
    "$(printf '%s\n' "${ours[@]}" | median)" "$r" "${verdict:--}"
  [[ -n "$baseline" ]] && printf ' %.2f | %.3f |' "$(printf '%s\n' "${old[@]}" | median)" "$(printf '%s\n' "${slower[@]}" | median)"
  echo
done

# Issue 17's two ratios, for both renderers: a frame's median over the Phong frame's.
phong="sphere:64 phong"
if [[ -n "${ours_ms[$phong]:-}" ]]; then
  echo
  echo "| frame ÷ the same renderer's sphere:64 phong frame | llvmpipe | Velocity | Velocity's target |"
  echo "|---|---|---|---|"
  for row in "sphere:64 pbrtex|1.6" "sphere:64 phong + 2048² shadow map|1.5"; do
    IFS='|' read -r name target <<<"$row"
    [[ -n "${ours_ms[$name]:-}" ]] || continue
    printf '| %s | %.2f | %.2f | ≤ %s |\n' "$name" "$(ratio "${ref_ms[$name]}" "${ref_ms[$phong]}")" \
      "$(ratio "${ours_ms[$name]}" "${ours_ms[$phong]}")" "$target"
  done
fi

# Velocity's scaling from 1 thread to `threads`, alternating as above.
echo
echo "| Velocity, sphere:512 gouraud 1920x1080 | 1 thread ms | $threads threads ms | speed-up | target |"
echo "|---|---|---|---|---|"
one=() many=() ratios=()
for ((p = 0; p < pairs; ++p)); do
  a=$("$velocity" bench --mesh sphere:512 --shade gouraud --frames "$frames" --threads 1 | ms)
  b=$("$velocity" bench --mesh sphere:512 --shade gouraud --frames "$frames" --threads "$threads" | ms)
  one+=("$a") many+=("$b") ratios+=("$(ratio "$a" "$b")")
done
r=$(printf '%s\n' "${ratios[@]}" | median)
printf '| | %.2f | %.2f | %.2fx | %s |\n' "$(printf '%s\n' "${one[@]}" | median)" "$(printf '%s\n' "${many[@]}" | median)" "$r" \
  "$([[ $threads == 2 ]] && awk -v r="$r" 'BEGIN { print (r >= 1.9 ? "≥ 1.9x met" : "≥ 1.9x missed") }' || echo -)"

# Seed 000's headline, restated: its engine drew 50,000 texture-mapped triangles a second
# (1,600 a frame at 30 frames a second) on a 300 MHz Pentium II, and about 60 frames a
# second for a 2,000-polygon scene at low resolution (under 15 with Phong shading).
# Velocity alone, on the same threads, median of `pairs` runs.
echo
echo "| seed 000's figure | scene | Velocity ms/frame | frames/s | triangles/s |"
echo "|---|---|---|---|---|"
seed_row() {
  local label="$1" scene="$2" tris="$3"; shift 3
  local runs=()
  for ((p = 0; p < pairs; ++p)); do runs+=("$("$velocity" bench "$@" --frames "$frames" --threads "$threads" | ms)"); done
  local m; m=$(printf '%s\n' "${runs[@]}" | median)
  printf '| %s | %s | %.3f | %.0f | %s |\n' "$label" "$scene" "$m" "$(awk -v m="$m" 'BEGIN { print 1000 / m }')" \
    "$(awk -v m="$m" -v t="$tris" 'BEGIN { printf "%.3g", t * 1000 / m }')"
}
seed_row "50,000 textured triangles/s (Pentium II 300)" "sphere:1024 tex 800x600 (1,048,576 tris)" 1048576 \
  --mesh sphere:1024 --shade tex --size 800x600
seed_row "60 frames/s, 2,000 polygons, low resolution" "sphere:32 tex 320x200 (2,048 tris)" 2048 \
  --mesh sphere:32 --shade tex --size 320x200
seed_row "under 15 frames/s with Phong on small objects" "sphere:32 phong 320x200 (2,048 tris)" 2048 \
  --mesh sphere:32 --shade phong --size 320x200
