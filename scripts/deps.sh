#!/usr/bin/env bash
# Installs the Debian 12 packages Velocity builds and tests with, when any is missing.
#
#   scripts/deps.sh [PACKAGE...]   the packages below, and these too (fuzz.sh: clang)
#
# Every dependency is a Debian package (no vendored copies, nothing downloaded else):
#   cmake, ninja-build, g++          the build
#   libstb-dev                       PNG/JPEG/... reading (stb_image)
#   libtinyobjloader-dev             OBJ files
#   libassimp-dev                    glTF 2.0, 3DS, PLY and STL files (Assimp)
#   nlohmann-json3-dev               JSON, to check a glTF file before Assimp reads it
#   assimp-testmodels                real glTF/3DS/PLY/STL files the format tests read in place
#   libcli11-dev                     the command line
#   libgtest-dev                     unit and golden tests
#   libhwy-dev                       Google Highway: the SIMD kernels, one source for every instruction set
#   libbenchmark-dev                 Google Benchmark: the stages' micro-benchmarks (tests/bench/micro.cpp)
#   libosmesa6-dev                   the golden tests' reference: Mesa's llvmpipe through OSMesa
#   libglu1-mesa-dev                 GLU: the tessellator pGL programs link (gl/CMakeLists.txt), and GLU for
#                                    pGL's conformance programs built against Mesa (gl/tests)
#   pkg-config                       finds OSMesa
#   python3-dev, pybind11-dev        the Python module (python/): headers and the bindings
#   python3-numpy                    its arrays (colour, depth, masks, meshes)
#   python3-pytest                   the Python tests, run by ctest
#   python3-distributed              the batch renderer on a Dask cluster (and its tests)
#   libpng-dev                       the engine's PNG writer (src/io/png_write.cpp), used by the CLI and Python: zlib's speed, 16-bit masks
#   python3-pil                      pyrender's textures as PIL images (velocity.pyrender)
#   python3-tqdm                     the batch runner's progress bar
#   libepoxy-dev                     the GPU backend (gpu/): OpenGL entry points, loaded at run time
#   libegl-dev                       the GPU backend: EGL from libglvnd, a headless OpenGL context
#   libegl-mesa0, libgl1-mesa-dri    the GPU backend's tests: Mesa's EGL driver and llvmpipe (surfaceless)
#   libsdl2-dev                      the real-time window, input and sound (present/: view, fly, drive)
#   xvfb                             a display for the window's test (present/tests/window_test.py)
#   xdotool, python3-gi,             a real X drag and drop onto the viewer (present/tests/drop_test.py):
#   gir1.2-gtk-3.0                   xdotool moves the mouse, a GTK window is the drag source
#   libx11-dev, libxext-dev          the GLX vendor library (gl/glx/): Xlib, and MIT-SHM to show frames
#   libglvnd-dev                     its interface to libglvnd (glvnd/libglxabi.h) and the system's
#                                    libGL its tests link, as any GLX program does; the EGL vendor
#                                    library's (gl/egl/: glvnd/libeglabi.h), and the libEGL and
#                                    libOpenGL its check program links (libegl-dev, libopengl-dev)
#   mesa-utils                       glxgears and eglinfo, run unmodified on the vendors (gl/glx/tests,
#                                    gl/egl/tests)
#   freeglut3-dev                    freeglut: its font data become GLUT's fonts (gl/glut/font_tables.c);
#                                    GLUT's shapes and fonts are compared with its (gl/glut/tests/shapes_test.py)
#   libwaffle-1-0, python3-mako,     what piglit's GL 1.x tests need to run (scripts/piglit.sh unpacks
#   python3-six                      piglit itself from its package, without its 2 GB of shader tests)
#   chromium                         the glTF oracle: three.js in headless Chromium, WebGL on SwiftShader
#   nodejs, npm                      its pinned three.js from npm (tests/reference/threejs/package-lock.json);
#                                    only when there is no npm command (NodeSource's nodejs carries its own)
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config libstb-dev libtinyobjloader-dev libassimp-dev nlohmann-json3-dev assimp-testmodels libcli11-dev libgtest-dev libhwy-dev libbenchmark-dev libosmesa6-dev libglu1-mesa-dev
  python3-dev pybind11-dev python3-numpy libpng-dev python3-pytest python3-distributed python3-pil python3-tqdm
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libsdl2-dev xvfb xdotool python3-gi gir1.2-gtk-3.0
  libx11-dev libxext-dev libglvnd-dev mesa-utils freeglut3-dev libwaffle-1-0 python3-mako python3-six chromium "$@")
# Debian's npm conflicts with a nodejs from NodeSource, which provides npm itself.
command -v npm >/dev/null || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "velocity: installing missing Debian packages: ${missing[*]}" >&2
  sudo=""
  [[ $(id -u) -eq 0 ]] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
