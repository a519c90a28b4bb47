// PNG bytes of an image in memory, through libpng (Debian's libpng-dev), for the Python
// module's batch runner (velocity.png.encode_png). Fast settings for rendered frames:
// one filter for every row, and a low zlib level (the figures are in docs/python.md).
// Needs no Python, so that the C++ tests and the pyconvert fuzz target drive it too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace velocity::python {

struct PngImage {
  const void* pixels = nullptr;  // rows top first, `stride` bytes apart
  int width = 0, height = 0;
  int channels = 1;              // 1 grey, 3 RGB, 4 RGBA
  int bits = 8;                  // 8, or 16 (grey only; samples in the host's byte order)
  ptrdiff_t stride = 0;          // bytes from one row to the next, >= width * channels * bits / 8
};

// Row filters (PNG's filter types); Up is the default: rendered frames' rows repeat.
enum class PngFilter { None = 0, Sub = 1, Up = 2, Average = 3, Paeth = 4, Adaptive = 5 };

// The PNG file's bytes. `level` is zlib's, 0..9. Throws velocity::Error for a bad size,
// channel count or bit depth, or a level out of range.
std::vector<uint8_t> encode_png(const PngImage& image, int level = 3, PngFilter filter = PngFilter::Up);

}  // namespace velocity::python
