// PNG files through libpng (Debian's libpng-dev): the one PNG encoder, used by
// write_png (velocity/image.hpp), the command-line program and the Python module
// (velocity.png.encode_png). Fast settings for rendered frames: one filter for every
// row, and a low zlib level (the figures are in docs/python.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace velocity {

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

// Writes encode_png's bytes to `path`. Throws velocity::Error naming the file when it
// cannot be written (the reason from errno: "No space left on device" on a full disk).
void write_png(const std::string& path, const PngImage& image, int level = 3, PngFilter filter = PngFilter::Up);

}  // namespace velocity
