#!/usr/bin/env bash
# Builds the plain C++ kernels alone (VELOCITY_SIMD=OFF: Highway's scalar target, one
# lane per vector) and runs the tests (CTest) whose result can change with the kernels
# (scripts/lib/kernel_tests.sh) in build-scalar. CI runs it: the SIMD kernels are written
# once, and this is the build that shows the code is right with no vector instructions
# at all (what a processor without SSE4 runs). Everything is built, so that every part
# is shown to compile without SIMD; the tests left out run in ./test.sh.
#
#   scripts/scalar.sh [CTEST ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-scalar"
"$root/scripts/deps.sh"
werror=OFF
[[ "${CI:-}" == "true" ]] && werror=ON  # as test.sh: warnings are errors in CI
start=$SECONDS
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVELOCITY_SIMD=OFF -DVELOCITY_WERROR=$werror >/dev/null
cmake --build "$build"
built=$SECONDS
cd "$build"
set +e
source "$root/scripts/lib/kernel_tests.sh"
ctest --output-on-failure -j"$(nproc)" "${kernel_tests[@]}" "$@"
rc=$?
set -e
echo "scalar.sh: build $((built - start)) s, tests $((SECONDS - built)) s, ctest exit $rc"
exit $rc
