#!/usr/bin/env bash
# Packs what a benchmark needs into one tarball, to measure on another x86-64 Linux
# machine that has none of it installed (no network, another distribution, more cores),
# with every shared library it loads except glibc's own (that machine's glibc must be
# 2.36 or newer). Three parts, each small enough to travel alone:
#   render  the built `velocity` and Mesa's llvmpipe with ../shared's glref
#   python  the built `velocity`, Debian's Python 3.11 with numpy and Dask, the Velocity
#           package, and the batch benchmark's models from Debian's assimp-testmodels
#   gl      the built `velocity`, pGL's benchmark on Velocity and on Mesa's llvmpipe
#           (gl/bench: gl_bench, gl_bench_mesa) for scripts/bench_gl.sh
#   gpu     the built `velocity`, libvelocity-gpu with libepoxy and libglvnd's EGL and
#           OpenGL dispatch, and scripts/bench_gpu.sh; the GPU's own EGL vendor (NVIDIA's
#           libEGL_nvidia, Mesa's) must be that machine's: bench_gpu.sh says if it is not
#
#   scripts/bundle.sh render|python|gpu [OUT.tar.xz]   (default .bundle/velocity-PART.tar.xz)
#
# On the other machine, from a copy of the repository:
#   mkdir -p /tmp/vb && tar -xJf velocity-render.tar.xz -C /tmp/vb && source /tmp/vb/env.sh
#   scripts/scaling.sh --threads "1 2 4 8 16"       (VELOCITY and GLREF point into the bundle)
#   python3.11 python/bench/bench_batch.py --build "$VELOCITY_BUILD" --workers 1,2,4,8   (python)
#   bench_gpu.sh                                     (gpu: the CPU and GPU backends' table)
#   THREADS=16 scripts/bench_gl.sh                   (gl: VELOCITY_BUILD points into the bundle)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
part="${1:-}"
[[ "$part" == render || "$part" == python || "$part" == gpu || "$part" == gl ]] || { echo "usage: scripts/bundle.sh render|python|gpu|gl [OUT.tar.xz]" >&2; exit 2; }
out="${2:-$root/.bundle/velocity-$part.tar.xz}"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT

# Binaries and the Python package, from the build tree.
if [[ $part == gpu ]]; then
  cmake --build "$root/build" --target velocity_cli velocity-gpu >/dev/null
elif [[ $part == gl ]]; then
  cmake --build "$root/build" --target velocity_cli gl_bench gl_bench_mesa >/dev/null
else
  cmake --build "$root/build" --target velocity_cli velocity_python >/dev/null
fi
mkdir -p "$stage/bin" "$stage/build" "$stage/lib"
cp "$root/build/velocity" "$stage/bin/"
ln -s ../bin/velocity "$stage/build/velocity"
if [[ $part == render ]]; then
  # shellcheck source=lib/against_llvmpipe.sh
  source "$root/scripts/lib/against_llvmpipe.sh"  # builds glref if it is not there
  cp "$glref" "$stage/bin/"
elif [[ $part == gl ]]; then
  mkdir -p "$stage/build/gl/bench"
  cp "$root/build/gl/bench/gl_bench" "$root/build/gl/bench/gl_bench_mesa" "$stage/build/gl/bench/"
elif [[ $part == gpu ]]; then
  cp "$root/build/gpu/libvelocity-gpu.so" "$stage/lib/"
  cp "$root/scripts/bench_gpu.sh" "$stage/bin/"
  # libepoxy opens these at run time (ldd below does not see them): libglvnd's EGL and
  # OpenGL front ends, which load whichever vendor that machine's driver installs.
  for l in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0; do cp -L "/usr/lib/x86_64-linux-gnu/$l" "$stage/lib/"; done
else
  mkdir -p "$stage/build/python" "$stage/py/usr/bin" "$stage/py/usr/lib"
  cp -r "$root/build/python/velocity" "$stage/build/python/"
  # Debian's Python: the interpreter, the standard library (without its tests and GUI),
  # and the packages the batch runners import.
  cp /usr/bin/python3.11 "$stage/py/usr/bin/"
  copy() {  # copy FROM_DIR NAME TO_DIR: NAME (a file or folder) without tests and byte code
    tar -C "$1" --exclude test --exclude tests --exclude __pycache__ --exclude idlelib --exclude tkinter \
      --exclude turtledemo --exclude ensurepip --exclude lib2to3 --exclude 'config-3.11-*' -cf - "$2" | tar -C "$3" -xf -
  }
  copy /usr/lib python3.11 "$stage/py/usr/lib"
  mkdir -p "$stage/py/dist"
  for p in numpy dask distributed tornado yaml _yaml msgpack psutil toolz tlz cloudpickle zict tblib partd locket \
    fsspec sortedcontainers click jinja2 markupsafe packaging heapdict.py colorama urllib3; do
    [[ -e "/usr/lib/python3/dist-packages/$p" ]] && copy /usr/lib/python3/dist-packages "$p" "$stage/py/dist"
  done

  # Models the batch benchmark reads from Debian's assimp-testmodels, at the same paths.
  for d in glTF2/BoxTextured-glTF PLY STL 3DS; do
    mkdir -p "$stage/assimp/models/$d"
  done
  cp -r /usr/share/assimp/models/glTF2/BoxTextured-glTF/. "$stage/assimp/models/glTF2/BoxTextured-glTF/"
  cp /usr/share/assimp/models/PLY/cube.ply "$stage/assimp/models/PLY/"
  cp /usr/share/assimp/models/STL/Spider_ascii.stl "$stage/assimp/models/STL/"
  cp /usr/share/assimp/models/3DS/test1.3ds "$stage/assimp/models/3DS/"
fi

# Every shared library any of these ELF files loads, glibc's own excepted.
find "$stage" -type f \( -perm -u+x -o -name '*.so*' \) -print0 |
  xargs -0 file | grep -E 'ELF 64-bit' | cut -d: -f1 |
  xargs -n1 ldd 2>/dev/null | awk '$3 ~ /^\// {print $3}' | sort -u |
  grep -v -E '/(libc|libm|libpthread|libdl|librt|libresolv|libutil|ld-linux-x86-64)\.so' |
  while read -r lib; do cp -L "$lib" "$stage/lib/"; done

cat >"$stage/env.sh" <<'EOF'
# Source this: puts the bundle's programs, libraries and Python first.
b="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export LD_LIBRARY_PATH="$b/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$b/bin:$b/py/usr/bin:$PATH"
[[ -d "$b/py" ]] && export PYTHONHOME="$b/py/usr" PYTHONPATH="$b/build/python:$b/py/dist" PYTHONNOUSERSITE=1
export VELOCITY="$b/bin/velocity" GLREF="$b/bin/glref" VELOCITY_BUILD="$b/build"
[[ -f "$b/lib/libvelocity-gpu.so" ]] && export VELOCITY_GPU_LIBRARY="$b/lib/libvelocity-gpu.so"
[[ -d "$b/assimp" ]] && mkdir -p /usr/share/assimp && cp -rn "$b/assimp/models" /usr/share/assimp/ 2>/dev/null
true
EOF
mkdir -p "$(dirname "$out")"
tar -C "$stage" -cf - . | xz -T0 -9e >"$out"
echo "$out: $(du -h "$out" | cut -f1)"
