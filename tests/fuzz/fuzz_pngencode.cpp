// Fuzz target: the engine's PNG encoder (src/io/png_write.cpp, libpng), which write_png
// and the Python module's encode_png use.
// The input: 8 header bytes (width, height, channels, bits, stride padding, level,
// filter), then the pixels, as many rows as the bytes hold.
// Property: encode_png returns a PNG or throws velocity::Error; a PNG decodes (through
// the engine's own reader, stb_image) to the pixels given; never a read outside them.
#include <algorithm>
#include <cstring>

#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/png.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  if (size < 8) return 0;
  static const int kChannels[] = {1, 3, 4, 2, 0};
  PngImage im;
  im.width = data[0] % 70;  // 0 and 65..69 too: bad or odd sizes
  im.height = data[1] % 70;
  im.channels = kChannels[data[2] % 5];
  im.bits = data[3] % 3 == 0 ? 16 : data[3] % 3 == 1 ? 8 : 4;
  const size_t sample = im.bits == 16 ? 2 : 1;
  im.stride = ptrdiff_t(size_t(std::max(im.width, 0)) * size_t(std::max(im.channels, 0)) * sample + data[4] % 4);
  const int level = data[5] % 11;  // 10 is out of range
  const auto filter = PngFilter(data[6] % 6);
  const uint8_t* pixels = data + 8;
  const size_t bytes = size - 8;
  if (im.stride > 0) im.height = int(std::min<size_t>(size_t(im.height), bytes / size_t(im.stride)));
  im.pixels = pixels;
  std::vector<uint8_t> png;
  try {
    png = encode_png(im, level, filter);
  } catch (const Error&) {
    return 0;
  }
  // The engine decodes to RGBA8: grey and RGB expand, 16-bit grey keeps its high byte.
  Image back = decode_image(std::string_view(reinterpret_cast<const char*>(png.data()), png.size()), "fuzz.png");
  if (back.width != im.width || back.height != im.height) __builtin_trap();
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const uint8_t* s = pixels + size_t(y) * size_t(im.stride) + size_t(x) * size_t(im.channels) * sample;
      const uint8_t* d = back.pixel(x, y);
      uint8_t want[4];
      if (im.bits == 16) {
        uint16_t v;
        std::memcpy(&v, s, 2);
        want[0] = want[1] = want[2] = uint8_t(v >> 8), want[3] = 255;
      } else if (im.channels == 1) {
        want[0] = want[1] = want[2] = s[0], want[3] = 255;
      } else {
        std::memcpy(want, s, size_t(im.channels));
        if (im.channels == 3) want[3] = 255;
      }
      if (std::memcmp(want, d, 4) != 0) __builtin_trap();
    }
  return 0;
}
