#!/usr/bin/env bash
# Builds everything with sanitizers and runs the tests (CTest).
#
#   scripts/sanitize.sh asan [CTEST ARGS...]   AddressSanitizer + UndefinedBehaviorSanitizer
#                                              + LeakSanitizer, in build-asan
#   scripts/sanitize.sh tsan [CTEST ARGS...]   ThreadSanitizer, in build-tsan
#
# Each runs every test with Velocity's code in it (scripts/lib/kernel_tests.sh's
# no_engine_tests are left out; TSan also leaves out the GPU backend's and the
# downstream build).
#
# Any report fails the test that caused it: UB is fatal (-fno-sanitize-recover=all), leaks
# are checked at every process exit (detect_leaks=1), and a report in the output of a
# test that expects a failure still fails it (FAIL_REGULAR_EXPRESSION, see CMakeLists.txt).
# Mesa's llvmpipe (the golden tests' reference) is not instrumented; what it does is
# suppressed precisely in tests/sanitizers/*.supp, never our code.
# The Python tests (ctest label "python") run too: the module is instrumented, the
# interpreter is not, so python/tests/CMakeLists.txt starts each with the sanitizer's
# runtime in LD_PRELOAD (and libstdc++, for ASan); under ASan with leak checking off in
# those processes (CPython leaves its objects to the OS at exit by design; the C++ they
# run is leak-checked by the C++ tests), and without fork-started pools under TSan (TSan
# does not support a fork after threads have started; the spawn-started ones run).
# Built for this processor alone (VELOCITY_NATIVE: -march=native, the kernels for its best
# instruction set only, the one the tests run; CMakeLists.txt says why) and optimised as
# the sanitizers' own documentation suggests (-O1), with debug lines (-g1): on a 2-core
# Zen 3 the whole ASan build took 23 minutes at -O2 and 16.5 at -O1 (both for AVX2
# alone; AVX2 and plain C++ made each kernel file 2.6 to 3 times as long), and its tests
# 5 to 6 minutes either way.
# Assertions are on (no NDEBUG); libstdc++'s own
# assertions too (_GLIBCXX_ASSERTIONS, as Fedora's and Arch's package builds have them).
# One check is off, in two files: GCC's ASan use-after-scope in the PBR and the
# fixed-function kernels (src/raster/kernels_pbr.cpp, kernels_fixed.cpp; see
# src/CMakeLists.txt). Its marks keep every inlined Highway vector addressable there, and
# each file alone took most of the stage to compile (the PBR one about 950 s in a full
# ASan build, where each other kernel file took 60-120 s; 108 s of CPU without the marks;
# the fixed one over 33 minutes of CPU once its masked stores became load, blend and
# store). The coverage, tile, sampler and output code they share with the other files
# keeps the check there; their own (src/raster/shade_pbr-inl.h, shade_fixed-inl.h) have
# one local array (four pointers used in the block that declares them), and their
# lambdas are called only inside the blocks that declare them.
# Heap, stack and global bounds, use after free, leaks and every UBSan check stay on.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mode="${1:-}"
[[ $# -gt 0 ]] && shift
supp="$root/tests/sanitizers"
# Neither stage runs the tests with none of Velocity's code in them (Chromium's three.js
# renders, the docs' checks): $no_engine_tests.
source "$root/scripts/lib/kernel_tests.sh"
source "$root/scripts/lib/jobs.sh"  # machine_jobs: SANITIZE_BUILD_JOBS, SANITIZE_TEST_JOBS by default
case "$mode" in
  asan)
    build="$root/build-asan"
    sanitize="address,undefined"
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_init_order=1:check_initialization_order=1:suppressions=$supp/asan.supp"
    export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp"
    ctest_args=(-E "^($no_engine_tests)\$")
    ;;
  tsan)
    build="$root/build-tsan"
    sanitize="thread"
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp"
    # What runs on several threads, and what feeds it: the unit tests (the renderer on
    # 1..8 threads among them), the golden tests, the fuzz corpora, the CLI and the soak
    # on 4 threads. The install-and-build-downstream test has no threads of ours, nor
    # has the GPU backend (label gpu: Mesa's threads, not instrumented, and CPU renders
    # the golden tests make too; ASan runs them): 200 of TSan's 580 s of tests here.
    ctest_args=(-LE '^gpu$' -E "^(downstream_find_package|$no_engine_tests)\$")
    ;;
  *)
    echo "usage: scripts/sanitize.sh asan|tsan [ctest arguments...]" >&2
    exit 2
    ;;
esac

"$root/scripts/deps.sh"
werror=OFF
[[ "${CI:-}" == "true" ]] && werror=ON  # as test.sh: warnings are errors in CI
start=$SECONDS
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DVELOCITY_SANITIZE="$sanitize" -DVELOCITY_NATIVE=ON -DVELOCITY_ASSERTIONS=ON -DVELOCITY_WERROR=$werror >/dev/null
cmake --build "$build" -j"${SANITIZE_BUILD_JOBS:-$(machine_jobs)}"
built=$SECONDS
cd "$build"
set +e
ctest --output-on-failure -j"${SANITIZE_TEST_JOBS:-$(machine_jobs)}" --timeout 1200 "${ctest_args[@]}" "$@"
rc=$?
set -e
echo "sanitize.sh $mode: build $((built - start)) s, tests $((SECONDS - built)) s, ctest exit $rc"
exit $rc
