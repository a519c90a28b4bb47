#!/usr/bin/env bash
# Runs the tests (CTest) whose result can change with the kernels once on each SIMD
# target the build compiled and this processor has, other than the best one (what
# ./test.sh already ran): the kernels are written once against Highway and compiled for
# AVX-512 (AVX3), AVX2, SSE4 and plain C++ (SCALAR, one lane), and Highway would
# otherwise only ever run the best. scripts/lib/kernel_tests.sh says which tests, and
# which are left out (those that do not depend on the target: Python, the GPU backend,
# the real-time programs' windows and input, packaging). VELOCITY_SIMD_TARGET picks the
# target (src/simd/targets.hpp); each run first checks that the engine reports that
# target. SCALAR is the plain C++ code that a VELOCITY_SIMD=OFF build has alone
# (scripts/scalar.sh). CI runs this after ./test.sh, on its build.
#
#   scripts/simd_targets.sh [CTEST ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
velocity="$build/velocity"
[[ -x "$velocity" ]] || { echo "simd_targets.sh: $velocity not built; run ./test.sh first" >&2; exit 2; }

# The target the engine picks by itself, and what `bench --verbose` reports for a request.
reported() {
  VELOCITY_SIMD_TARGET="$1" "$velocity" bench --mesh sphere:8 --size 16x16 --frames 1 --verbose 2>&1 |
    sed -n 's/^simd=\([A-Za-z0-9_]*\) .*/\1/p'
}
best=$(reported "")
echo "simd_targets.sh: the processor's best target is $best (tested by ./test.sh)"
source "$root/scripts/lib/kernel_tests.sh"
ran=() skipped=() failed=()
for target in AVX3_DL AVX3 AVX2 SSE4 SSSE3 EMU128 SCALAR; do
  [[ "$target" == "$best" ]] && continue
  got=$(reported "$target" || true)  # a target it cannot run: an error, no simd= line
  if [[ -z "$got" ]]; then
    skipped+=("$target")  # not compiled, or not on this processor
    continue
  fi
  if [[ "$got" != "$target" ]]; then
    echo "simd_targets.sh: asked for $target, the engine ran $got" >&2
    exit 1
  fi
  echo "=== simd_targets.sh: the kernels' tests on $target"
  start=$SECONDS
  if (cd "$build" && VELOCITY_SIMD_TARGET=$target ctest --output-on-failure -j"$(nproc)" "${kernel_tests[@]}" "$@"); then
    ran+=("$target: $((SECONDS - start)) s")
  else
    failed+=("$target")
  fi
done
printf 'simd_targets.sh: tested %s\n' "${ran[@]:-none}"
((${#skipped[@]})) && echo "simd_targets.sh: not compiled or not on this processor: ${skipped[*]}"
if ((${#failed[@]})); then
  echo "simd_targets.sh: FAILED on ${failed[*]}" >&2
  exit 1
fi
