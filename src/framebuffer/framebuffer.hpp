// The colour and depth buffers the tiles are rasterised into.
#pragma once

#include <cstdint>
#include <vector>

#include "velocity/image.hpp"

namespace velocity {

struct Framebuffer {
  int width = 0, height = 0;
  std::vector<uint32_t> color;  // RGBA8 (byte 0 red), top row first
  std::vector<float> depth;     // window depth in [0, 1]; 1 is the far plane

  // Throws velocity::Error unless 1 <= width, height <= 16384.
  void resize(int width, int height);
  Image color_image() const;
  // Depth as greyscale: the nearest depth drawn is white, the farthest drawn is dark
  // grey (32), untouched pixels (still at the clear depth, 1) black. Scaled over the
  // range actually drawn so that a small object still shows its shape.
  Image depth_image() const;
};

}  // namespace velocity
