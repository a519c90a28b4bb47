#!/usr/bin/env bash
# piglit's OpenGL 1.0-1.5 tests on Velocity's GLX vendor library (gl/glx), unmodified,
# compared with tests/piglit/expectations.txt (tests/piglit/compare.py): any crash,
# timeout or result other than the expected one fails the script. Then the few EGL tests
# that apply to the EGL vendor library (gl/egl), each against its expected result (end).
#
#   scripts/piglit.sh [BUILD_DIR]          default: build (libGLX_velocity.so.0 in BUILD_DIR/gl/glx)
#
#   PIGLIT_VENDOR=mesa   run on Mesa's vendor instead and only summarise (for comparison;
#                        MESA_GL_VERSION_OVERRIDE=1.5 makes llvmpipe a GL 1.5 driver)
#   PIGLIT_CACHE=DIR     where Debian's piglit is unpacked when it is not installed
#                        (default ~/.cache/velocity/piglit)
#   PIGLIT_RESULTS=DIR   piglit's results (default BUILD_DIR/piglit)
#   PIGLIT_FROM_PACKAGE=1  use the unpacked package even where piglit is installed
#
# piglit: the installed one (Debian's piglit package) if there is one. Otherwise the
# package is downloaded with apt-get download (34 MB) and only what quick_gl's GL 1.x
# tests need is unpacked (53 MB of the package's 2.2 GB: no generated shader tests, no
# shader, CL or GLSL-parser tests), once, into PIGLIT_CACHE. Its libraries (waffle,
# mako) come from scripts/deps.sh.
#
# The run: a private Xvfb (-noreset: piglit opens and closes many connections),
# PIGLIT_PLATFORM=glx, `piglit run -p glx -t 'spec@!opengl 1\.[0-5]@' quick_gl`, two
# tests at a time, VELOCITY_THREADS=1 each, each at most 300 s (streaming-texture-leak,
# 5000 textures, takes about 100 s).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
vendor="${PIGLIT_VENDOR:-velocity}"
results="${PIGLIT_RESULTS:-$build/piglit}"
tests='spec@!opengl 1\.[0-5]@'
# Excluded from the run (tests/piglit/expectations.txt says why): max-texture-size
# uploads 4096x4096 textures of every internal format, minutes on 2 cores.
exclude='spec@!opengl 1\.1@max-texture-size$'

piglit=""
[[ -n "${PIGLIT_FROM_PACKAGE:-}" ]] || piglit="$(command -v piglit || true)"
libdir=""
bindir=/usr/lib/x86_64-linux-gnu/piglit/bin  # the test programs, run alone for EGL (below)
if [[ -z "$piglit" ]]; then
  cache="${PIGLIT_CACHE:-$HOME/.cache/velocity/piglit}"
  pl=usr/lib/x86_64-linux-gnu/piglit
  if [[ ! -x "$cache/usr/bin/piglit" ]]; then
    echo "piglit: unpacking Debian's piglit (GL tests only) into $cache" >&2
    tmp="$(mktemp -d)"
    (cd "$tmp" && apt-get download piglit >&2)
    mkdir -p "$cache"
    dpkg-deb --fsys-tarfile "$tmp"/piglit_*.deb | tar -x -C "$cache" \
      --exclude="./$pl/generated_tests" --exclude="./$pl/tests/spec" --exclude="./$pl/tests/cl" \
      --exclude="./$pl/tests/glslparsertest" --exclude="./$pl/tests/asmparsertest" --exclude="./$pl/tests/shaders" \
      --exclude="./$pl/tests/*shader*.xml.gz" --exclude="./$pl/tests/glslparser*.xml.gz" \
      --exclude="./$pl/tests/no_error.xml.gz" --exclude=./usr/share/doc
    rm -rf "$tmp"
  fi
  piglit="$cache/usr/bin/piglit"
  libdir="$cache/$pl/lib"  # the tests' RUNPATH is the installed location
  bindir="$cache/$pl/bin"
fi
command -v Xvfb >/dev/null || { echo "piglit: Xvfb is needed (Debian's xvfb)" >&2; exit 2; }

env_vendor=(__GLX_VENDOR_LIBRARY_NAME="$vendor")
if [[ "$vendor" == velocity ]]; then
  [[ -f "$build/gl/glx/libGLX_velocity.so.0" ]] || { echo "piglit: no $build/gl/glx/libGLX_velocity.so.0: build target GLX_velocity" >&2; exit 2; }
  libdir="$build/gl/glx${libdir:+:$libdir}"
fi

# A private X server: its display number comes back through -displayfd.
fifo="$(mktemp -u)"
mkfifo "$fifo"
Xvfb -displayfd 3 -screen 0 1024x768x24 -noreset -nolisten tcp 3>"$fifo" &
xvfb=$!
runner=""
# Stopped (SIGTERM, Ctrl-C) or done: the run and the X server go too. Xvfb is killed
# outright if it has not gone after 2 s (one was seen spinning after SIGTERM, its
# clients gone). The run is waited for in the background so that a signal is handled
# at once, not after piglit ends.
# Every kill may find its process gone (bash reaps an exited child at once): under set -e
# a failed kill in this trap would end the script with status 1 after a passing run, so
# each is allowed to fail.
cleanup() {
  # (piglit starts each test in a session of its own: they go as the runner's children.)
  if [[ -n "$runner" ]]; then
    pkill -TERM -P "$runner" 2>/dev/null || true
    kill "$runner" 2>/dev/null || true
  fi
  kill "$xvfb" 2>/dev/null || true
  for _ in $(seq 20); do kill -0 "$xvfb" 2>/dev/null || break; sleep 0.1; done
  kill -9 "$xvfb" 2>/dev/null || true
  rm -f "$fifo"
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT
read -r display <"$fifo"

rm -rf "$results"
start=$SECONDS
env DISPLAY=":$display" PIGLIT_PLATFORM=glx "${env_vendor[@]}" VELOCITY_THREADS=1 LP_NUM_THREADS=1 \
  ${libdir:+LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"} \
  "$piglit" run -p glx -j 2 --timeout 300 -t "$tests" -x "$exclude" quick_gl "$results" >"$results.log" 2>&1 &
runner=$!
wait "$runner" || { tail -20 "$results.log"; echo "piglit: the run failed" >&2; exit 1; }
runner=""
echo "piglit: $((SECONDS - start)) s on $vendor's GLX vendor"
if [[ "$vendor" == velocity ]]; then
  python3 "$root/tests/piglit/compare.py" "$results/results.json.bz2" "$root/tests/piglit/expectations.txt"
else
  python3 "$root/tests/piglit/compare.py" --summary "$results/results.json.bz2"
fi

# piglit's EGL tests that a headless vendor answers (the others open an X display:
# EGL's X11 platform, which the EGL vendor does not serve), run alone on its JSON file
# (gl/egl), each with the result expected; any other fails the script.
#   egl-surfaceless-context-viewport: fail. It asks eglChooseConfig for EGL's defaults,
#   a window and OpenGL ES, which no configuration of a headless desktop-GL vendor has
#   (nor any of Mesa's on its surfaceless platform); the display it then needs is X11's.
json="$build/gl/egl/60_velocity.json"
if [[ "$vendor" == velocity && -f "$json" ]]; then
  egl_failed=0
  while read -r expected name args; do
    out="$(env __EGL_VENDOR_LIBRARY_FILENAMES="$json" VELOCITY_THREADS=1 \
      ${libdir:+LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"} \
      timeout 60 "$bindir/$name" $args -auto 2>&1 || true)"
    result="$(sed -n 's/.*"result": "\([a-z]*\)".*/\1/p' <<<"$out" | tail -1)"
    if [[ "$result" == "$expected" ]]; then
      echo "piglit EGL: $name $args: $result, as expected"
    else
      echo "piglit EGL: $name $args: ${result:-no result} (expected $expected)"$'\n'"$out"
      egl_failed=1
    fi
  done <<'TESTS'
pass egl_mesa_platform_surfaceless
pass egl_khr_get_all_proc_addresses
pass egl_ext_client_extensions 1
pass egl_ext_client_extensions 2
pass egl_ext_client_extensions 3
fail egl-surfaceless-context-viewport
TESTS
  ((egl_failed == 0)) || { echo "piglit: an EGL test gave another result" >&2; exit 1; }
fi
