#!/usr/bin/env bash
# Frame rates of the real-time programs (issue 10): `velocity drive` and `velocity fly`
# at 320x200 and 800x600, default quality and drive's 3x3 high-quality mode, headless
# (render + program, no window) and, when Xvfb is installed, through an SDL window on
# Xvfb (vsync off: Xvfb has no display to wait for). Each run drives or flies a fixed
# script for FRAMES frames and prints the program's own statistics line (median and
# 99th-percentile frame time).
#
#   scripts/bench_realtime.sh [FRAMES]     default 600 (10 s of game time)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
velocity="$root/build/velocity"
frames="${1:-600}"
work="$(mktemp -d)"
trap 'rm -rf "$work"; [[ -n "${xvfb_pid:-}" ]] && kill "$xvfb_pid" 2>/dev/null || true' EXIT
printf '0 down up\n3 down left\n3.6 up left\n6 down right\n6.4 up right\n' >"$work/drive.txt"
printf '0 down left\n2 up left\n2 down a\n3 up a\n4 down down\n4.3 up down\n' >"$work/fly.txt"

run() {  # label, then the command's arguments
  local label="$1"
  shift
  local line
  line="$("$@" | grep -o 'frames=.*')"
  printf '%-34s %s\n' "$label" "$line"
  echo "    command: velocity ${*:2}" | sed "s#$root/##g"
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for mode in headless window; do
  extra=(--headless)
  if [[ $mode == window ]]; then
    command -v Xvfb >/dev/null || { echo "(no Xvfb: window runs skipped)"; break; }
    Xvfb :97 -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
    xvfb_pid=$!
    sleep 1
    export DISPLAY=:97 SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software
    extra=(--no-vsync --scale 1)
  fi
  for size in 320x200 800x600; do
    run "drive $size $mode" "$velocity" drive --skip-menu --mute --size "$size" --frames "$frames" --script "$work/drive.txt" "${extra[@]}"
    run "drive $size --hq $mode" "$velocity" drive --skip-menu --mute --hq --size "$size" --frames "$((frames / 4))" --script "$work/drive.txt" "${extra[@]}"
    run "fly $size $mode" "$velocity" fly --skip-menu --mute --size "$size" --frames "$frames" --script "$work/fly.txt" "${extra[@]}"
  done
done
