#!/usr/bin/env bash
# Builds the plain C++ kernels alone (VELOCITY_SIMD=OFF: Highway's scalar target, one
# lane per vector) and runs the tests (CTest) whose result can change with the kernels
# (scripts/lib/kernel_tests.sh) in build-scalar: the build for a processor Highway has
# no SIMD target for, with no vector instructions at all. Everything is built, so that
# every part is shown to compile without SIMD; the tests left out run in ./test.sh.
# CI does not run it: the normal build carries the same plain C++ kernels as its SCALAR
# target (with GCC 12, Highway's fallback is HWY_SCALAR, the one-lane code built here),
# and scripts/simd_targets.sh runs these tests on it; this script costs a whole build.
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
