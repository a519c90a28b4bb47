#!/usr/bin/env bash
# Quick start, part 1: install what is missing, build (Release), run `velocity` with the
# given arguments. With none, it renders the built-in demo scene to velocity.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" --target velocity_cli >/dev/null
exec "$root/build/velocity" "$@"
