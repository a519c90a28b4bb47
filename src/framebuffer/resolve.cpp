#include "framebuffer/resolve.hpp"

#include <algorithm>

namespace velocity {

Image resolve_color(const Framebuffer& fb, int k) {
  if (k == 1) return fb.color_image();
  const int w = fb.width / k, h = fb.height / k, n = k * k;
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint32_t sum[4] = {0, 0, 0, 0};
      for (int sy = 0; sy < k; ++sy) {
        const uint32_t* row = &fb.color[size_t(y * k + sy) * fb.width + size_t(x) * k];
        for (int sx = 0; sx < k; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += (row[sx] >> (8 * c)) & 0xff;
      }
      uint8_t* p = out.pixel(x, y);
      for (int c = 0; c < 4; ++c) p[c] = uint8_t((sum[c] + uint32_t(n / 2)) / uint32_t(n));
    }
  return out;
}

Image resolve_depth(const Framebuffer& fb, int k) {
  if (k == 1) return fb.depth_image();
  Framebuffer nearest;
  nearest.width = fb.width / k, nearest.height = fb.height / k;
  nearest.depth.assign(size_t(nearest.width) * nearest.height, 1.0f);
  for (int y = 0; y < fb.height; ++y)
    for (int x = 0; x < fb.width; ++x) {
      float& d = nearest.depth[size_t(y / k) * nearest.width + x / k];
      d = std::min(d, fb.depth[size_t(y) * fb.width + x]);
    }
  return nearest.depth_image();
}

}  // namespace velocity
