// The pixel centres a small triangle covers, a vector of centres at a time (set-up's
// small-triangle path). Compiled once per instruction set.
#include "triangle/small_coverage.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "triangle/small_coverage.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::triangle {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// Lane i of a vector starting at centre p is centre p + i of the 8-wide box: column
// (p + i) & 7, row (p + i) >> 3. A row of 8 is half an AVX-512 vector, one AVX2 vector,
// two SSE4 vectors.
uint64_t SmallCoverage(const SmallEdges& e, int columns, int rows) {
  const DI di;
  constexpr int N = int(kLanes);
  const VI zero = hn::Zero(di), seven = hn::Set(di, raster::kSmallSide - 1);
  const VI cols = hn::Set(di, columns), last_rows = hn::Set(di, rows);
  const VI lanes = hn::Iota(di, 0);  // once: Highway 1.0 builds it through memory
  uint64_t mask = 0;
  for (int p = 0; p < rows * raster::kSmallSide; p += N) {
    const VI index = hn::Add(lanes, hn::Set(di, p));
    const VI x = hn::And(index, seven), y = hn::ShiftRight<3>(index);
    // The three edge functions at these centres; any negative one has its sign bit set,
    // and so has the OR of the three.
    VI any = zero;
    for (int i = 0; i < 3; ++i) {
      const VI ei = hn::Add(hn::Set(di, e.row_start[i]),
                            hn::Add(hn::Mul(x, hn::Set(di, e.step_x[i])), hn::Mul(y, hn::Set(di, e.step_y[i]))));
      any = hn::Or(any, ei);
    }
    const MI in_box = hn::And(hn::Lt(x, cols), hn::Lt(y, last_rows));  // a vector may run past the last row
    const MI inside = hn::And(hn::Not(hn::Lt(any, zero)), in_box);
    mask |= uint64_t(lane_bits(di, inside)) << p;
  }
  return mask;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::triangle
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::triangle {

HWY_EXPORT(SmallCoverage);

uint64_t small_coverage(const SmallEdges& edges, int columns, int rows) {
  return HWY_DYNAMIC_DISPATCH(SmallCoverage)(edges, columns, rows);
}

}  // namespace velocity::triangle
#endif  // HWY_ONCE
