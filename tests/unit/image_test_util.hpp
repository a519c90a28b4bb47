// Helpers for the tests that look at rendered images: a pixel as one packed RGBA value,
// and how many pixels differ from a colour.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "velocity/image.hpp"

namespace velocity::test {

// Pixel (x, y) as the renderer packs it: R in the low byte, A in the high one.
inline uint32_t at(const Image& img, int x, int y) {
  uint32_t c;
  std::memcpy(&c, img.pixel(x, y), 4);
  return c;
}

// The pixels that are not `color` (the background, usually): what was drawn.
inline size_t count_not(const Image& img, uint32_t color) {
  size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += at(img, x, y) != color;
  return n;
}

}  // namespace velocity::test
