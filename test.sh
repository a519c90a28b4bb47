#!/usr/bin/env bash
# Quick start, part 2: install what is missing, build everything (Release), run every
# test with CTest. In CI (CI=true) warnings are errors.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/deps.sh"
werror=OFF
[[ "${CI:-}" == "true" ]] && werror=ON
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVELOCITY_WERROR=$werror >/dev/null
cmake --build "$root/build"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)" "$@"
