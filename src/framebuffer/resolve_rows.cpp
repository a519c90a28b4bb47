// The super-sampling box filter a vector of pixels at a time (resolve_rows.hpp), compiled
// once per instruction set.
#include "framebuffer/resolve_rows.hpp"

#include <algorithm>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "framebuffer/resolve_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace velocity {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// In two passes over up to 64 pixels. First the k sample rows are summed down each
// sample column, 4 columns (a row of a 4x4 block: 16 contiguous bytes) at a time; then
// the k column sums of each pixel are added across (the sums loaded de-interleaved, a
// vector of pixels at a time) and divided. The sums hold two channels a 32-bit lane,
// each in 16 bits (channels 0 and 2 in `even`, 1 and 3 in `odd`): 16 samples of 255
// fit, and the sums are exactly those a channel at a time would give.
template <int K>
void SpanK(const Framebuffer& fb, int y, int x0, int x1, uint32_t* out) {
  const hn::ScalableTag<uint32_t> du;
  const hn::RebindToSigned<decltype(du)> di;
  const hn::RebindToFloat<decltype(du)> df;
  const hn::CappedTag<uint32_t, 4> d4;  // one block row
  const size_t lanes = hn::Lanes(du);
  constexpr int kPixels = 64, kMaxLanes = HWY_MAX_BYTES / 4, n = K * K;
  // Sample columns of a pass, from a block's first column (up to 3 before the first
  // pixel's), with room for the last vector of pixels to read past the end.
  constexpr int kColumns = 4 + K * (kPixels + kMaxLanes);
  HWY_ALIGN uint32_t even[kColumns], odd[kColumns];
  HWY_ALIGN uint32_t tail[kMaxLanes];
  const uint32_t* rows_at[K];  // each sample row's first sample in the row's first tile
  for (int sy = 0; sy < K; ++sy) rows_at[sy] = fb.color.data() + fb.index(0, y * K + sy);
  const auto low = hn::Set(d4, 0x00ff00ffu);
  for (int p0 = x0; p0 < x1; p0 += kPixels) {
    const int p1 = std::min(x1, p0 + kPixels), pixels = p1 - p0;
    const int s0 = (p0 * K) & ~3, s1 = p1 * K;
    // Pass 1. A block row never crosses a tile; past the image's edge the tiles' padding
    // is read (allocated, never shown).
    for (int s = s0; s < s1; s += 4) {
      // The offset of sample column s from its row's start in the first tile (the tiled
      // layout of framebuffer.hpp: 4096 a tile, 16 a block, 1 a sample).
      const size_t at = size_t((s & ~63) << 6 | (s & 60) << 2);
      for (size_t i = 0; i < 4; i += hn::Lanes(d4)) {
        auto e = hn::Zero(d4), o = hn::Zero(d4);
        for (int sy = 0; sy < K; ++sy) {
          const auto v = hn::LoadU(d4, rows_at[sy] + at + i);
          e = hn::Add(e, hn::And(v, low)), o = hn::Add(o, hn::And(hn::ShiftRight<8>(v), low));
        }
        hn::StoreU(e, d4, even + (s - s0) + i), hn::StoreU(o, d4, odd + (s - s0) + i);
      }
    }
    // What the last vector of pass 2 reads past the columns filled: zeros, not stale stack.
    const int first = p0 * K - s0, filled = (s1 - s0 + 3) & ~3;
    const int needed = first + K * int((size_t(pixels) + lanes - 1) / lanes * lanes);
    if (needed > filled) {
      std::memset(even + filled, 0, size_t(needed - filled) * 4);
      std::memset(odd + filled, 0, size_t(needed - filled) * 4);
    }
    // Pass 2.
    const auto mask16 = hn::Set(du, 0xffffu);
    for (int v = 0; v < pixels; v += int(lanes)) {
      auto across = [&](const uint32_t* sums) {
        if constexpr (K == 2) {
          hn::Vec<decltype(du)> a, b;
          hn::LoadInterleaved2(du, sums + first + K * v, a, b);
          return hn::Add(a, b);
        } else if constexpr (K == 3) {
          hn::Vec<decltype(du)> a, b, c;
          hn::LoadInterleaved3(du, sums + first + K * v, a, b, c);
          return hn::Add(hn::Add(a, b), c);
        } else {
          hn::Vec<decltype(du)> a, b, c, d;
          hn::LoadInterleaved4(du, sums + first + K * v, a, b, c, d);
          return hn::Add(hn::Add(a, b), hn::Add(c, d));
        }
      };
      // The rounded mean (sum + n/2) / n: a shift for n = 4 and 16; for n = 9 in float,
      // floor((sum + 4.5) / 9): the quotient's fraction is 0.5/9 or more from a whole
      // number, the float product within 2^-22 of it, so it truncates to the exact one.
      auto mean = [&](hn::Vec<decltype(du)> sum) {
        if constexpr ((n & (n - 1)) == 0) {
          return hn::ShiftRight<(K == 2 ? 2 : 4)>(hn::Add(sum, hn::Set(du, uint32_t(n / 2))));
        } else {
          const auto f = hn::Add(hn::ConvertTo(df, hn::BitCast(di, sum)), hn::Set(df, float(n / 2) + 0.5f));
          return hn::BitCast(du, hn::ConvertTo(di, hn::Mul(f, hn::Set(df, 1.0f / float(n)))));
        }
      };
      const auto e = across(even), o = across(odd);
      const auto rgba = hn::Or(hn::Or(mean(hn::And(e, mask16)), hn::ShiftLeft<8>(mean(hn::And(o, mask16)))),
                               hn::Or(hn::ShiftLeft<16>(mean(hn::ShiftRight<16>(e))), hn::ShiftLeft<24>(mean(hn::ShiftRight<16>(o)))));
      uint32_t* to = out + (p0 - x0) + v;
      if (v + int(lanes) <= pixels) {
        hn::StoreU(rgba, du, to);
      } else {
        hn::Store(rgba, du, tail);
        std::memcpy(to, tail, size_t(pixels - v) * 4);
      }
    }
  }
}

void ResolveSpan(const Framebuffer& fb, int k, int y, int x0, int x1, uint32_t* out) {
  switch (k) {
    case 2: return SpanK<2>(fb, y, x0, x1, out);
    case 3: return SpanK<3>(fb, y, x0, x1, out);
    default: return SpanK<4>(fb, y, x0, x1, out);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity {

HWY_EXPORT(ResolveSpan);

void resolve_span_simd(const Framebuffer& samples, int k, int y, int x0, int x1, uint32_t* out) {
  HWY_DYNAMIC_DISPATCH(ResolveSpan)(samples, k, y, x0, x1, out);
}

}  // namespace velocity
#endif  // HWY_ONCE
