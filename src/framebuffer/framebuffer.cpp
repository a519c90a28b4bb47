#include "framebuffer/framebuffer.hpp"

#include <algorithm>
#include <cstring>
#include <new>

#include "raster/raster_types.hpp"
#include "velocity/error.hpp"

namespace velocity {

void Framebuffer::resize(int w, int h) {
  if (w < 1 || h < 1 || w > raster::kMaxFramebufferSide || h > raster::kMaxFramebufferSide)
    throw Error("framebuffer size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                std::to_string(raster::kMaxFramebufferSide) + " a side)");
  // New buffers first, so that running out of memory (a velocity::Error, not
  // std::bad_alloc) leaves this framebuffer as it was.
  const size_t n = size_t(w) * size_t(h);
  try {
    std::vector<uint32_t> c(n, 0);
    std::vector<float> d(n, 1.0f);
    color.swap(c);
    depth.swap(d);
  } catch (const std::bad_alloc&) {
    throw Error("framebuffer size " + std::to_string(w) + "x" + std::to_string(h) + ": cannot allocate " +
                std::to_string(n * (sizeof(uint32_t) + sizeof(float))) + " bytes");
  }
  width = w, height = h;
}

Image Framebuffer::color_image() const {
  Image image(width, height);
  std::memcpy(image.pixels.data(), color.data(), color.size() * 4);
  return image;
}

Image Framebuffer::depth_image() const {
  float lo = 1, hi = 0;
  for (float d : depth)
    if (d < 1) lo = std::min(lo, d), hi = std::max(hi, d);
  Image image(width, height, 0xff000000u);
  float range = hi > lo ? hi - lo : 1.0f;
  for (size_t i = 0; i < depth.size(); ++i) {
    if (!(depth[i] < 1)) continue;
    float t = (depth[i] - lo) / range;  // 0 nearest, 1 farthest
    auto g = uint8_t(255.0f - t * (255.0f - 32.0f) + 0.5f);
    uint8_t* p = &image.pixels[i * 4];
    p[0] = p[1] = p[2] = g;
  }
  return image;
}

}  // namespace velocity
