#!/usr/bin/env bash
# Frame rates of the real-time programs (issue 10): `velocity drive` and `velocity fly`
# at 320x200 and 800x600, default quality and drive's 3x3 high-quality mode, headless
# (render + program, no window) and, when Xvfb is installed, through an SDL window on
# Xvfb (vsync off: Xvfb has no display to wait for). Each run drives or flies a fixed
# script for FRAMES frames and prints the program's own statistics line (median and
# 99th-percentile frame time). Drive races the circuit with its opponent and scenery
# (no best lap read or kept). Then, under Xvfb: drive with SDL's disk audio driver
# against --mute (does sound work hold the frame back?), and the viewer's CPU use
# while idle. The load average is printed before and after: on a shared machine the
# figures are only as good as the quiet they were taken in.
#
#   scripts/bench_realtime.sh [--headless-only] [FRAMES]     default 600 (10 s of game time)
#
# --headless-only: no window runs even when Xvfb is installed (a machine without an X
# server, e.g. pinned with `taskset -c 0,1 scripts/bench_realtime.sh --headless-only`).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
velocity="$root/build/velocity"
headless_only=0
if [[ "${1:-}" == --headless-only ]]; then
  headless_only=1
  shift
fi
frames="${1:-600}"
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || { echo "bench_realtime.sh: FRAMES must be a positive number, got '$frames'" >&2; exit 2; }
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
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"

# CPU time a frame with one rasterizer thread (user + system over the whole run, start-up
# included, divided by the frames): steadier than frame times on a busy machine.
cpu_per_frame() {  # label, frames, then the command's arguments
  local label="$1" n="$2" t
  shift 2
  t="$({ TIMEFORMAT='%U %S'; time "$@" --threads 1 >/dev/null 2>&1; } 2>&1 | tail -1)"
  awk -v t="$t" -v n="$n" -v l="$label" 'BEGIN { split(t, a, " "); printf "%-34s %.2f ms CPU a frame (one thread)\n", l, 1000 * (a[1] + a[2]) / n }'
}
cpu_per_frame "drive 800x600 cpu" "$frames" "$velocity" drive --skip-menu --mute --no-best-lap --size 800x600 \
  --frames "$frames" --script "$work/drive.txt" --headless
cpu_per_frame "drive 800x600 --hq cpu" "$((frames / 4))" "$velocity" drive --skip-menu --mute --no-best-lap --hq \
  --size 800x600 --frames "$((frames / 4))" --script "$work/drive.txt" --headless
for mode in headless window; do
  extra=(--headless)
  if [[ $mode == window ]]; then
    [[ $headless_only == 0 ]] || { echo "(--headless-only: window runs skipped)"; break; }
    command -v Xvfb >/dev/null || { echo "(no Xvfb: window runs skipped)"; break; }
    Xvfb :97 -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
    xvfb_pid=$!
    sleep 1
    export DISPLAY=:97 SDL_VIDEODRIVER=x11 SDL_RENDER_DRIVER=software
    extra=(--no-vsync --scale 1)
  fi
  for size in 320x200 800x600; do
    run "drive $size $mode" "$velocity" drive --skip-menu --mute --no-best-lap --size "$size" --frames "$frames" --script "$work/drive.txt" "${extra[@]}"
    run "drive $size --hq $mode" "$velocity" drive --skip-menu --mute --no-best-lap --hq --size "$size" --frames "$((frames / 4))" --script "$work/drive.txt" "${extra[@]}"
    run "fly $size $mode" "$velocity" fly --skip-menu --mute --size "$size" --frames "$frames" --script "$work/fly.txt" "${extra[@]}"
  done
done

if [[ -n "${xvfb_pid:-}" ]]; then
  # Sound through SDL's disk audio driver (it writes the samples to a file at the
  # device's pace) against no sound, same window, same script.
  run "drive 800x600 window, no sound" "$velocity" drive --skip-menu --mute --no-best-lap --size 800x600 \
    --frames "$frames" --script "$work/drive.txt" --no-vsync --scale 1
  SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE="$work/audio.raw" run "drive 800x600 window, disk audio" "$velocity" drive \
    --skip-menu --no-best-lap --size 800x600 --frames "$frames" --script "$work/drive.txt" --no-vsync --scale 1
  # The viewer left alone: CPU time (user + system) over 5 s once it has started.
  "$velocity" view --mute &
  view_pid=$!
  sleep 2
  ticks() { awk '{print $14 + $15}' "/proc/$view_pid/stat"; }
  before=$(ticks)
  sleep 5
  after=$(ticks)
  kill "$view_pid"
  wait "$view_pid" 2>/dev/null || true
  hz=$(getconf CLK_TCK)
  awk -v t="$((after - before))" -v hz="$hz" 'BEGIN { printf "%-34s %.2f s CPU in 5 s = %.1f %% of a core\n", "view idle window", t / hz, 100 * t / hz / 5 }'
fi
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
