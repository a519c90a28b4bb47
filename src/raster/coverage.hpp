// Which pixels of a tile a set-up triangle covers, as horizontal spans.
//
// For each row the three edge functions are linear in x, so the covered pixels form one
// span whose ends follow from three integer divisions: no per-pixel edge test. The
// result is exactly the set of pixels with all E_i >= 0 (tests check this against the
// per-pixel definition), so the top-left rule holds and shared edges are watertight.
#pragma once

#include <algorithm>
#include <cstdint>

#include "raster/raster_types.hpp"

namespace velocity::raster {

// A rectangle of pixels [x0, x1) x [y0, y1).
struct PixelRect {
  int x0, y0, x1, y1;
};

namespace detail {
inline int64_t floor_div(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }
inline int64_t ceil_div(int64_t n, int64_t d) { return -floor_div(-n, d); }
}  // namespace detail

// Calls span(y, x_first, x_last) (inclusive) for every row of `rect` the triangle
// covers, top to bottom.
template <class SpanFn>
inline void for_each_span(const TriangleSetup& t, PixelRect rect, SpanFn&& span) {
  const int x0 = std::max(t.min_x, rect.x0), x1 = std::min(t.max_x, rect.x1 - 1);
  const int y0 = std::max(t.min_y, rect.y0), y1 = std::min(t.max_y, rect.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const int64_t px = int64_t(x0) * kSubpixelOne + kSubpixelHalf;
  int64_t e[3];
  for (int i = 0; i < 3; ++i) e[i] = t.a[i] * px + t.b[i] * (int64_t(y0) * kSubpixelOne + kSubpixelHalf) + t.c[i];
  for (int y = y0; y <= y1; ++y) {
    // E_i(x) = e_i + a_i * 256 * (x - x0) >= 0, solved for x.
    int64_t lo = x0, hi = x1;
    for (int i = 0; i < 3; ++i) {
      const int64_t step = t.a[i] * kSubpixelOne;
      if (step > 0) {
        lo = std::max(lo, x0 + detail::ceil_div(-e[i], step));
      } else if (step < 0) {
        hi = std::min(hi, x0 + detail::floor_div(e[i], -step));
      } else if (e[i] < 0) {
        hi = lo - 1;
      }
    }
    if (lo <= hi) span(y, int(lo), int(hi));
    for (int i = 0; i < 3; ++i) e[i] += t.b[i] * kSubpixelOne;
  }
}

// The per-pixel definition of coverage, for tests and assertions.
inline bool covers(const TriangleSetup& t, int x, int y) {
  const int64_t px = int64_t(x) * kSubpixelOne + kSubpixelHalf, py = int64_t(y) * kSubpixelOne + kSubpixelHalf;
  for (int i = 0; i < 3; ++i)
    if (t.a[i] * px + t.b[i] * py + t.c[i] < 0) return false;
  return x >= t.min_x && x <= t.max_x && y >= t.min_y && y <= t.max_y;
}

}  // namespace velocity::raster
