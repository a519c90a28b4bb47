// A texture as the SIMD sampler reads it, resolved once per draw.
#include <algorithm>

#include "raster/rasterize.hpp"

namespace velocity::raster {

namespace {
// Where level l's image starts in its texels: past the border ring, if it has one.
size_t image_origin(const Texture::Level& l, bool volume) {
  const size_t b = size_t(l.border), stride = size_t(l.width) + 2 * b, rows = size_t(l.height) + 2 * b;
  return (volume ? b * rows * stride : 0) + b * stride + b;
}

void set_levels(SamplerView& s, const Texture& t) {
  s.texture = &t;
  const auto& levels = t.levels();
  s.level_count = int(std::min<size_t>(levels.size(), SamplerView::kMaxLevels));
  for (int i = 0; i < s.level_count; ++i) {
    const Texture::Level& l = levels[size_t(i)];
    SamplerLevel& v = s.levels[i];
    v.texels = l.texels.data() + image_origin(l, t.volume());
    v.width = l.width, v.height = l.height, v.depth = l.depth;
    v.stride = l.width + 2 * l.border, v.rows = l.height + 2 * l.border;
    v.bordered = l.border > 0;
  }
  s.volume = t.volume();
}
}  // namespace

SamplerView::SamplerView(const Texture& t, Filter f, Wrap w) {
  set_levels(*this, t);
  wrap_s = wrap_t = w;
  using T = SamplerState::Texel;
  using M = SamplerState::Mip;
  switch (f) {
    case Filter::Nearest: mag = min = T::Nearest, mip = M::None; break;
    case Filter::Bilinear: mag = min = T::Linear, mip = M::None; break;
    case Filter::Trilinear: mag = min = T::Linear, mip = M::Linear; break;
  }
}

SamplerView::SamplerView(const Texture& t, const SamplerState& s) {
  set_levels(*this, t);
  wrap_s = s.wrap_s, wrap_t = s.wrap_t, wrap_r = s.wrap_r;
  mag = s.mag, min = s.min, mip = s.mip;
  lod_bias = s.lod_bias, min_lod = s.min_lod, max_lod = s.max_lod;
  border[0] = s.border_color.x, border[1] = s.border_color.y, border[2] = s.border_color.z, border[3] = s.border_color.w;
}

void SamplerView::read_as_srgb(bool on) {
  srgb = on && texture;
  if (!srgb) return;
  const auto& linear = texture->linear_levels();
  for (int i = 0; i < level_count; ++i)
    levels[i].linear = linear[size_t(i)].data() + image_origin(texture->levels()[size_t(i)], texture->volume());
}

}  // namespace velocity::raster
