// RGBA8 rows to RGB8, a vector at a time (Highway's interleaved loads and stores),
// compiled once per instruction set.
#include "framebuffer/pack_rgb.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "framebuffer/pack_rgb.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace velocity {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

void PackRgb(const uint8_t* rgba, uint8_t* rgb, size_t pixels) {
  const hn::ScalableTag<uint8_t> d;
  const size_t n = hn::Lanes(d);
  size_t i = 0;
  for (; i + n <= pixels; i += n) {
    hn::Vec<decltype(d)> r, g, b, a;
    hn::LoadInterleaved4(d, rgba + 4 * i, r, g, b, a);
    hn::StoreInterleaved3(r, g, b, d, rgb + 3 * i);
  }
  for (; i < pixels; ++i) rgb[3 * i] = rgba[4 * i], rgb[3 * i + 1] = rgba[4 * i + 1], rgb[3 * i + 2] = rgba[4 * i + 2];
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity {

HWY_EXPORT(PackRgb);

void pack_rgb(const uint8_t* rgba, uint8_t* rgb, size_t pixels) { HWY_DYNAMIC_DISPATCH(PackRgb)(rgba, rgb, pixels); }

}  // namespace velocity
#endif  // HWY_ONCE
