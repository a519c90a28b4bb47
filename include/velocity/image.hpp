// 8-bit RGBA images in memory and on disk.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace velocity {

// An RGBA8 image, top row first, 4 bytes per pixel, no padding between rows.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;

  Image() = default;
  // A width x height image filled with `rgba` (0xAABBGGRR as it sits in memory on
  // little-endian machines: byte 0 is red). Throws velocity::Error for a size <= 0 or
  // above 65536 on a side.
  Image(int width, int height, uint32_t rgba = 0);

  const uint8_t* pixel(int x, int y) const { return &pixels[(size_t(y) * width + x) * 4]; }
  uint8_t* pixel(int x, int y) { return &pixels[(size_t(y) * width + x) * 4]; }
};

// Writes `image` as PNG or binary PPM (P6, alpha dropped), chosen by the file's
// extension (.png, .ppm; case-insensitive). Throws velocity::Error naming the file when
// the extension is unknown or the file cannot be written.
void write_image(const std::string& path, const Image& image);
void write_png(const std::string& path, const Image& image);
void write_ppm(const std::string& path, const Image& image);

// Reads a PNG, JPEG, TGA, BMP, GIF or binary PPM file as RGBA8. Throws velocity::Error
// naming the file and the reason on failure.
Image read_image(const std::string& path);
// The same from bytes in memory (an image embedded in a model file), with the same
// checks and size bounds; `name` says where the bytes came from in error messages.
Image decode_image(std::string_view bytes, const std::string& name);

}  // namespace velocity
