#!/usr/bin/env bash
# Issue 19's speed table: the CPU backend against the GPU backend (docs/gpu.md), on the
# shared scene convention (`velocity bench`, read-back included), at each size, mesh
# and shading mode. First it checks what the GPU backend needs on this machine and
# prints exactly what is missing: libglvnd's libEGL, an EGL vendor (its JSON file and
# the library that file names), the GPU's device nodes, libvelocity-gpu; then which
# OpenGL the backend gets (a software driver such as llvmpipe is said so: its rows
# are no GPU measurement).
#
#   scripts/bench_gpu.sh [--sizes "1920x1080 3840x2160"] [--meshes "sphere:1024 sphere:3200"]
#                        [--shades "tex phong"] [--frames N] [--check-only]
#
# sphere:1024 has 1 M triangles, sphere:3200 10 M. VELOCITY names the program (default
# build/velocity, or the bundle's: scripts/bundle.sh gpu). Prints a Markdown table.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sizes="1920x1080 3840x2160" meshes="sphere:1024 sphere:3200" shades="tex phong" frames=5 check_only=0
while (($#)); do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --meshes) meshes="$2"; shift 2 ;;
    --shades) shades="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --check-only) check_only=1; shift ;;
    *) echo "usage: scripts/bench_gpu.sh [--sizes \"WxH ...\"] [--meshes \"sphere:N ...\"] [--shades \"tex phong\"] [--frames N] [--check-only]" >&2; exit 2 ;;
  esac
done
velocity="${VELOCITY:-$root/build/velocity}"
[[ -x "$velocity" ]] || { echo "bench_gpu.sh: no velocity program at $velocity (build it, or set VELOCITY)" >&2; exit 2; }

# --- What the GPU backend needs ------------------------------------------------------
missing=()
found() { echo "  found:   $*"; }
lacks() { echo "  MISSING: $*"; missing+=("$*"); }
# A shared library the dynamic linker can load (LD_LIBRARY_PATH, then ldconfig's cache);
# a name with a slash is a path.
loadable() {
  local name="$1" dir
  if [[ "$name" == */* ]]; then [[ -f "$name" ]]; return; fi
  IFS=: read -r -a dirs <<<"${LD_LIBRARY_PATH:-}"
  for dir in "${dirs[@]}"; do [[ -n "$dir" && -f "$dir/$name" ]] && return 0; done
  /sbin/ldconfig -p 2>/dev/null | grep -q "[[:space:]]$name " && return 0
  for dir in /usr/lib/x86_64-linux-gnu /usr/lib64 /usr/lib /lib/x86_64-linux-gnu; do [[ -f "$dir/$name" ]] && return 0; done
  return 1
}

echo "GPU backend requirements on $(hostname):"
if loadable libEGL.so.1; then found "libEGL.so.1 (libglvnd's EGL)"; else lacks "libEGL.so.1 (Debian: libegl1)"; fi
if loadable libOpenGL.so.0 || loadable libGL.so.1; then found "an OpenGL library (libOpenGL.so.0 or libGL.so.1)"
else lacks "libOpenGL.so.0 (Debian: libopengl0)"; fi
# EGL vendors: libglvnd reads __EGL_VENDOR_LIBRARY_FILENAMES, else the JSON files in
# __EGL_VENDOR_LIBRARY_DIRS (default /etc/glvnd/egl_vendor.d:/usr/share/glvnd/egl_vendor.d).
vendor_files=()
if [[ -n "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]]; then
  IFS=: read -r -a vendor_files <<<"$__EGL_VENDOR_LIBRARY_FILENAMES"
else
  IFS=: read -r -a vdirs <<<"${__EGL_VENDOR_LIBRARY_DIRS:-/etc/glvnd/egl_vendor.d:/usr/share/glvnd/egl_vendor.d}"
  for d in "${vdirs[@]}"; do
    for f in "$d"/*.json; do [[ -f "$f" ]] && vendor_files+=("$f"); done
  done
fi
hardware_vendor=0
if ((${#vendor_files[@]} == 0)); then
  lacks "an EGL vendor: no JSON file in ${__EGL_VENDOR_LIBRARY_DIRS:-/etc/glvnd/egl_vendor.d:/usr/share/glvnd/egl_vendor.d} (NVIDIA: 10_nvidia.json with libEGL_nvidia.so.0, from the driver's graphics part; Mesa: 50_mesa.json, Debian libegl-mesa0)"
fi
for f in "${vendor_files[@]}"; do
  lib="$(grep -o '"library_path"[^,}]*' "$f" | sed 's/.*: *"\(.*\)"/\1/')"
  if [[ -z "$lib" ]]; then lacks "EGL vendor file $f names no library_path"; continue; fi
  if loadable "$lib"; then
    found "EGL vendor $f -> $lib"
    [[ "$lib" != *mesa* ]] && hardware_vendor=1
  else
    lacks "EGL vendor library $lib (named by $f)"
  fi
done
# Device nodes: DRM render nodes (Mesa's hardware drivers, NVIDIA with nvidia-drm) or
# NVIDIA's own nodes.
render_nodes=(/dev/dri/renderD*)
if [[ -e "${render_nodes[0]}" ]]; then found "DRM render nodes: ${render_nodes[*]}"; else echo "  none:    /dev/dri/renderD* (no DRM render node)"; fi
if [[ -e /dev/nvidiactl ]]; then
  nodes=(/dev/nvidia[0-9]*)
  found "NVIDIA device nodes: /dev/nvidiactl ${nodes[*]}"
  if command -v nvidia-smi >/dev/null; then
    found "NVIDIA driver $(nvidia-smi --query-gpu=driver_version,name --format=csv,noheader 2>/dev/null | head -1)"
  fi
  if ((!hardware_vendor)); then
    lacks "NVIDIA's EGL vendor (libEGL_nvidia.so.0 and its 10_nvidia.json): a compute-only driver image; add the driver's graphics libraries (NVIDIA_DRIVER_CAPABILITIES=graphics,compute,utility in a container)"
  fi
elif [[ ! -e "${render_nodes[0]}" ]]; then
  lacks "a GPU device node (/dev/dri/renderD* or /dev/nvidia*): no GPU is visible to this machine"
fi
if [[ -n "${VELOCITY_GPU_LIBRARY:-}" ]]; then
  if [[ -f "$VELOCITY_GPU_LIBRARY" ]]; then found "VELOCITY_GPU_LIBRARY=$VELOCITY_GPU_LIBRARY"; else lacks "libvelocity-gpu at VELOCITY_GPU_LIBRARY=$VELOCITY_GPU_LIBRARY"; fi
fi
# What the backend itself gets (its one-line error names anything missed above).
probe="$("$velocity" bench --mesh sphere:16 --frames 1 --size 64x48 --backend gpu --verbose 2>&1 | grep -E '^backend=|velocity:' || true)"
echo "  velocity --backend gpu: ${probe:-no answer}"
auto="$("$velocity" bench --mesh sphere:16 --frames 1 --size 64x48 --backend auto --verbose 2>&1 | grep -E '^backend=' || true)"
echo "  velocity --backend auto: ${auto:-no answer}"
software=0
[[ "$probe" == *llvmpipe* || "$probe" == *softpipe* || "$probe" == *SwiftShader* ]] && software=1
((software)) && echo "  NOTE:    the GPU backend runs on a software OpenGL driver here: its rows are not a GPU measurement"
if ((${#missing[@]})); then
  echo "Missing for the GPU backend (${#missing[@]}):"
  for m in "${missing[@]}"; do echo "  - $m"; done
fi
((check_only)) && exit 0
[[ "$probe" == backend=gpu* ]] || { echo "bench_gpu.sh: the GPU backend cannot run here (see above); no table" >&2; exit 1; }

# --- The table --------------------------------------------------------------------
median() {  # median() BACKEND MESH SHADE SIZE: the bench's median_ms
  "$velocity" bench --mesh "$2" --shade "$3" --size "$4" --frames "$frames" --backend "$1" |
    grep -o 'median_ms=[0-9.]*' | cut -d= -f2
}
renderer="$(sed -n 's/.* on \(.*\), EGL.*/\1/p' <<<"$probe")"
echo
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//') ($(nproc) threads); GPU: ${renderer:-?}"
echo "velocity bench --frames $frames, median ms a frame, read-back included"
echo
echo "| Size | Mesh | Triangles | Shade | cpu ms | gpu ms | cpu / gpu |"
echo "|---|---|---|---|---|---|---|"
for size in $sizes; do
  for mesh in $meshes; do
    seg="${mesh#sphere:}"
    tris=$([[ "$mesh" == sphere:* ]] && echo "$((seg * (seg / 2) * 2))" || echo "?")
    for shade in $shades; do
      c="$(median cpu "$mesh" "$shade" "$size")"
      g="$(median gpu "$mesh" "$shade" "$size")"
      ratio="$(awk -v c="$c" -v g="$g" 'BEGIN { if (g > 0) printf "%.2f", c / g; else print "?" }')"
      echo "| $size | $mesh | $tris | $shade | $c | $g | $ratio |"
    done
  done
done
