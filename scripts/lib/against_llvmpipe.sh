# Sourced by the scripts that time Velocity against Mesa's llvmpipe (compare_glref.sh,
# scaling.sh): the two programs, the median of a list and the machine's description.
#   VELOCITY  the velocity program (default: build/velocity, built if missing)
#   GLREF     ../shared/tools' glref (default: built into /tmp/velocity-glref)
#   VREF      the project's own llvmpipe harness, tests/reference's velocity-ref, for what
#             glref does not draw: PBR and shadow maps (default: build/tests/reference/
#             velocity-ref, built if missing)
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
velocity="${VELOCITY:-$root/build/velocity}"
glref="${GLREF:-/tmp/velocity-glref/glref}"
if [[ ! -x "$glref" ]]; then
  tools="$root/../shared/tools"
  [[ -d "$tools" ]] || { echo "$(basename "$0"): $tools not found (or set GLREF)" >&2; exit 2; }
  mkdir -p "$(dirname "$glref")"
  g++ -O2 -o "$glref" "$tools/glref/glref.cpp" -lOSMesa -ltinyobjloader -lstb
fi
[[ -x "$velocity" ]] || cmake --build "$root/build" --target velocity_cli >/dev/null
vref="${VREF:-$root/build/tests/reference/velocity-ref}"
[[ -x "$vref" ]] || cmake --build "$root/build" --target velocity-ref >/dev/null

# median: of the numbers on stdin, one a line. ms: a benchmark line's median_ms.
median() { sort -g | awk '{a[NR] = $1} END { if (NR % 2) print a[(NR + 1) / 2]; else printf "%.4f\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
ms() { sed -n 's/.* median_ms=\([0-9.]*\).*/\1/p'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", a / b }'; }

# "<commit>, <date>, <cores> cores (<cpu>)" and the SIMD target Velocity chose.
machine() {
  echo "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u +%Y-%m-%d), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"
}
simd() { "$velocity" bench --mesh sphere:8 --size 64x64 --frames 1 --verbose | sed -n 's/^simd=\([^ ]*\).*/\1/p'; }
