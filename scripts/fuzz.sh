#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang in build-fuzz and runs each for
# SECONDS (default 30), FUZZ_JOBS targets at a time (default: the processor count).
# The build is for this processor (VELOCITY_NATIVE): the kernels for its best
# instruction set alone, the code the engine runs here.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]     targets: asc plg pcx obj image raster assimp embedded pyconvert pngencode gl glx egl script race
#
# Seeds: tests/fuzz/corpus/<target>, tests/fuzz/regressions/<target>, the project's own
# test files for the format, and the real files under ../shared/data read in place when
# present (never copied: see ../shared/data/SOURCES.md). What the fuzzer learns stays in
# build-fuzz/corpus/<target> for the next run. Logs go to $FUZZ_LOG_DIR (default
# build-fuzz/logs), crashing inputs to build-fuzz/artifacts/<target>/.
#
# A finding fails the script with exit status 3 (other failures: 1 or 2). To keep it as
# a regression test: copy the input to tests/fuzz/regressions/<target>/ (ctest's
# fuzz_replay_<target> replays it in the normal build), then fix the bug.
#
# FUZZ_KEEP_GOING=1 is for long runs: libFuzzer's fork mode (-fork=1) goes on after a
# crash, timeout or out-of-memory, keeps every such input in the artifacts folder and
# counts them; the run still fails (3) at the end if there was any. Each result line gives
# the CPU time the target used (user + system, its child processes included).
#
# Installs clang and libFuzzer's runtime (Debian: clang, libclang-rt-14-dev) when
# missing; the normal build does not need them.
# The whole script is one { ... } block, so bash reads all of it before running any:
# editing the file during a long run cannot break that run.
{
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-30}"
[[ $# -gt 0 ]] && shift
all_targets=(asc plg pcx obj image raster assimp embedded pyconvert pngencode gl glx egl script race)
targets=("$@")
((${#targets[@]})) || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz.sh: unknown target '$t' (expected: ${all_targets[*]})" >&2; exit 2; }
done
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "fuzz.sh: SECONDS must be a whole number, got '$seconds'" >&2; exit 2; }

"$root/scripts/deps.sh" clang libclang-rt-14-dev

build="$root/build-fuzz"
source "$root/scripts/lib/jobs.sh"
jobs="${FUZZ_BUILD_JOBS:-$(machine_jobs)}"  # one per processor, memory allowing
# C too (GLUT's font tool is C): the fuzzing flags are clang's.
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVELOCITY_FUZZ=ON -DVELOCITY_NATIVE=ON \
  -DVELOCITY_WERROR=OFF >/dev/null
build_targets=("${targets[@]/#/velocity_fuzz_}")
[[ " ${targets[*]} " == *" assimp "* ]] && build_targets+=(velocity_fuzz_glb_seed)
cmake --build "$build" -j"$jobs" --target "${build_targets[@]}"

shared="$(cd "$root/.." && pwd)/shared/data"
logs="${FUZZ_LOG_DIR:-$build/logs}"
mkdir -p "$logs"

# assimp: the first byte of an input picks the format (fuzz_assimp.cpp); Debian's
# assimp-testmodels files become seeds with that byte in front. A .gltf whose buffers are
# .bin files beside it also becomes a GLB with them inside (velocity_fuzz_glb_seed), as the
# target's input is one file. Seeds stay within the target's max_len.
assimp_seeds() {
  local dir="$build/seeds/assimp" f ext k name
  local limit=$(( $(max_len assimp) - 1 ))
  rm -rf "$dir"
  mkdir -p "$dir"
  [[ -d /usr/share/assimp/models ]] || { echo "$dir"; return; }
  while IFS= read -r f; do
    ext="${f##*.}"
    name="$(basename "$(dirname "$f")")_$(basename "$f")"
    case "${ext,,}" in gltf) k=0 ;; glb) k=1 ;; 3ds) k=2 ;; ply) k=3 ;; stl) k=4 ;; *) continue ;; esac
    if [[ $k == 0 ]] && "$build/tests/fuzz/velocity_fuzz_glb_seed" "$f" "$dir/$name.glb.seed" 2>/dev/null; then
      (( $(stat -c %s "$dir/$name.glb.seed") <= limit )) || rm -f "$dir/$name.glb.seed"
    fi
    (( $(stat -c %s "$f") <= limit )) || continue
    { printf "\\$(printf '%03o' "$k")"; cat "$f"; } >"$dir/$name.seed"
  done < <(find /usr/share/assimp/models -type f)
  echo "$dir"
}

# Seeds that are files, not folders, go through a folder of links (libFuzzer treats a
# file argument as "run this input", not as a seed).
seed_dir() {  # target files...
  local dir="$build/seeds/$1"
  shift
  rm -rf "$dir"
  mkdir -p "$dir"
  local f
  for f in "$@"; do [[ -f "$f" ]] && ln -sf "$f" "$dir/"; done
  echo "$dir"
}

max_len() {
  case "$1" in
    raster) echo 4096 ;;
    gl) echo 8192 ;;
    pyconvert) echo 4096 ;;
    pngencode) echo 8192 ;;
    assimp) echo 262144 ;;  # assimp-testmodels' Draco engine is a 245 KB GLB
    *) echo 131072 ;;
  esac
}

# One target's run; its result line goes to $logs/<target>.result. Targets run
# FUZZ_JOBS at a time (default: one per processor), as libFuzzer uses one each.
run_target() {
  local t="$1"
  work="$build/corpus/$t"
  artifacts="$build/artifacts/$t"
  mkdir -p "$work" "$artifacts"
  dirs=("$work" "$root/tests/fuzz/corpus/$t")
  [[ -d "$root/tests/fuzz/regressions/$t" ]] && dirs+=("$root/tests/fuzz/regressions/$t")
  case "$t" in
    asc) dirs+=("$(seed_dir asc "$root"/tests/data/models/*.[aA][sS][cC])")
         [[ -d "$shared/models/asc" ]] && dirs+=("$shared/models/asc") ;;
    plg) [[ -d "$shared/models/plg" ]] && dirs+=("$shared/models/plg" "$shared/models/plg/invalid") ;;
    pcx) [[ -d "$shared/textures" ]] && dirs+=("$(seed_dir pcx "$shared"/textures/*.[pP][cC][xX])") ;;
    assimp) dirs+=("$(assimp_seeds)") ;;
  esac
  dict=()
  [[ -f "$root/tests/fuzz/$t.dict" ]] && dict=("-dict=$root/tests/fuzz/$t.dict")
  keep_going=()
  [[ "${FUZZ_KEEP_GOING:-0}" == 1 ]] && keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  log="$logs/$t.log"
  echo "fuzz.sh: $t for ${seconds}s (log: $log)"
  known=$(ls "$artifacts" | wc -l)
  set +e
  TIMEFORMAT='%U %S'
  { time ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0" \
    "$build/tests/fuzz/velocity_fuzz_$t" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2560 \
    -malloc_limit_mb=2048 -max_len="$(max_len "$t")" -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "${keep_going[@]}" "${dict[@]}" "${dirs[@]}" >"$log" 2>&1 ; } 2>"$logs/$t.cpu"
  rc=$?
  set -e
  cpu=$(awk 'END { printf "%d", $1 + $2 }' "$logs/$t.cpu")  # the last line: bash may report a crash above it
  findings=$(( $(ls "$artifacts" | wc -l) - known ))
  ((findings == 0)) || rc=${rc/#0/1}
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  # Fork mode prints no final stats; its status lines start "#EXECUTIONS: cov: ...".
  [[ -n "$execs" ]] || execs=$(grep -oE '^#[0-9]+: cov:' "$log" | tail -1 | grep -oE '[0-9]+' || true)
  cov=$(grep -oE '((INITED|DONE|REDUCE|NEW|pulse) +|^#[0-9]+: )cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+' || true)
  if ((rc != 0)); then
    found=$(ls -t "$artifacts" 2>/dev/null | head -1)
    echo "$t: FINDING (exit $rc) execs=${execs:-?} ${cov} cpu=${cpu}s artifacts=$findings newest=$artifacts/$found" >"$logs/$t.result"
    grep -m3 -E 'ERROR: |runtime error|fuzz_check failed|deadly signal|out-of-memory|timeout' "$log" | sed 's/^/    /' >&2 || true
  else
    echo "$t: ok execs=${execs:-?} ${cov} cpu=${cpu}s" >"$logs/$t.result"
  fi
}
fuzz_jobs="${FUZZ_JOBS:-$(nproc)}"
for t in "${targets[@]}"; do
  rm -f "$logs/$t.result"
  while (( $(jobs -rp | wc -l) >= fuzz_jobs )); do wait -n || true; done
  run_target "$t" &
done
wait
status=0
summary=()
for t in "${targets[@]}"; do
  if [[ ! -f "$logs/$t.result" ]]; then
    summary+=("$t: no result (the script broke off; see the output above)")
    status=1
    continue
  fi
  summary+=("$(cat "$logs/$t.result")")
  [[ "${summary[-1]}" == "$t: ok "* ]] || ((status)) || status=3
done
echo "fuzz.sh: results (${seconds}s per target)"
printf '  %s\n' "${summary[@]}"
if ((status)); then
  echo "fuzz.sh: findings above. Keep each input as tests/fuzz/regressions/<target>/<name> and fix the bug." >&2
fi
exit $status
}
