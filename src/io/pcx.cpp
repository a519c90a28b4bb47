// ZSoft PCX decoding.
//
// Layout (ZSoft "PCX Technical Reference Manual", all 16-bit fields little-endian):
//   0   manufacturer, 0x0A          65  planes
//   1   version (0, 2, 3, 4, 5)     66  bytes per line, per plane (may exceed the width)
//   2   encoding: 1 RLE, 0 raw      68  palette info, 70 screen size: unused here
//   3   bits per pixel per plane    128 the image data
//   4   xmin, ymin, xmax, ymax: the image is (xmax - xmin + 1) x (ymax - ymin + 1)
//   16  the 16-colour EGA palette (not needed for the depths read here)
// Each row holds the planes one after another, `bytes per line` bytes each. RLE: a byte
// with its two top bits set (0xC0-0xFF) is a run of (byte & 0x3F) copies of the next
// byte; any other byte is itself. So a literal 0xC0-0xFF must be written as a run of one.
// Writers differ on whether a run may cross the end of a row; decoding the rows as one
// stream accepts both.
// A 256-colour image (8 bits, 1 plane) is followed by 0x0C and 768 bytes of RGB palette.
#include "velocity/pcx.hpp"

#include <algorithm>
#include <vector>

#include "io/read_file.hpp"
#include "velocity/error.hpp"

namespace velocity {

namespace {

constexpr size_t kHeaderBytes = 128;
constexpr size_t kPaletteBytes = 769;  // 0x0C and 256 RGB triples

uint16_t u16(std::span<const uint8_t> d, size_t at) { return uint16_t(d[at] | (d[at + 1] << 8)); }

[[noreturn]] void fail(const std::string& name, const std::string& message) {
  throw Error(name + ": " + message);
}

// Expands the RLE stream `in` into exactly out.size() bytes; false if it runs out first.
bool decode_rle(std::span<const uint8_t> in, std::vector<uint8_t>& out) {
  size_t i = 0, o = 0, n = out.size();
  while (o < n) {
    if (i >= in.size()) return false;
    uint8_t b = in[i++];
    if ((b & 0xC0) == 0xC0) {
      if (i >= in.size()) return false;
      size_t run = std::min<size_t>(b & 0x3F, n - o);  // a last run may overshoot: clip it
      std::fill_n(out.begin() + ptrdiff_t(o), run, in[i++]);
      o += run;
    } else {
      out[o++] = b;
    }
  }
  return true;
}

}  // namespace

Image decode_pcx(std::span<const uint8_t> data, const std::string& name) {
  // ---- parse the header ----
  if (data.size() < kHeaderBytes)
    fail(name, "expected a 128-byte PCX header, got " + std::to_string(data.size()) + " bytes");
  if (data[0] != 0x0A) fail(name, "expected the PCX signature 0x0A in byte 0 (is this a PCX file?)");
  int encoding = data[2], bits = data[3], planes = data[65];
  int xmin = u16(data, 4), ymin = u16(data, 6), xmax = u16(data, 8), ymax = u16(data, 10);
  size_t bytes_per_line = u16(data, 66);

  // ---- validate it against the data ----
  if (encoding != 0 && encoding != 1) fail(name, "unknown PCX encoding " + std::to_string(encoding) + " (expected 0 or 1)");
  if (xmax < xmin || ymax < ymin)
    fail(name, "bad PCX window: xmin " + std::to_string(xmin) + ", xmax " + std::to_string(xmax) + ", ymin " +
                   std::to_string(ymin) + ", ymax " + std::to_string(ymax));
  int width = xmax - xmin + 1, height = ymax - ymin + 1;
  if (bits != 8 || (planes != 1 && planes != 3 && planes != 4))
    fail(name, "unsupported PCX depth: " + std::to_string(bits) + " bits x " + std::to_string(planes) +
                   " planes (supported: 8 bits with 1, 3 or 4 planes)");
  if (bytes_per_line < size_t(width))
    fail(name, "PCX bytes per line " + std::to_string(bytes_per_line) + " is less than the width " +
                   std::to_string(width));

  std::span<const uint8_t> body = data.subspan(kHeaderBytes);
  const uint8_t* palette = nullptr;
  if (planes == 1) {
    if (body.size() < kPaletteBytes || body[body.size() - kPaletteBytes] != 0x0C)
      fail(name, "expected a 256-colour palette (0x0C and 768 bytes) at the end of the file, got none");
    palette = &body[body.size() - kPaletteBytes + 1];
    body = body.first(body.size() - kPaletteBytes);
  }

  // One RLE pair yields at most 63 bytes, so the data bounds the decoded size: a header
  // that claims more is refused before anything is allocated.
  size_t row_bytes = bytes_per_line * size_t(planes);
  size_t total = row_bytes * size_t(height);
  size_t most = encoding == 1 ? body.size() / 2 * 63 + (body.size() & 1) : body.size();
  if (total > most)
    fail(name, "truncated: the header needs " + std::to_string(total) + " bytes of pixels (" + std::to_string(width) +
                   "x" + std::to_string(height) + "), the data holds at most " + std::to_string(most));

  // ---- decode ----
  std::vector<uint8_t> raw(total);
  if (encoding == 1) {
    if (!decode_rle(body, raw)) fail(name, "truncated: the RLE data ends before the last row");
  } else {
    std::copy_n(body.begin(), total, raw.begin());
  }

  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = &raw[size_t(y) * row_bytes];
    for (int x = 0; x < width; ++x) {
      uint8_t* px = image.pixel(x, y);
      if (planes == 1) {
        const uint8_t* c = palette + row[x] * 3;
        px[0] = c[0], px[1] = c[1], px[2] = c[2], px[3] = 255;
      } else {
        for (int p = 0; p < 3; ++p) px[p] = row[size_t(p) * bytes_per_line + size_t(x)];
        px[3] = planes == 4 ? row[3 * bytes_per_line + size_t(x)] : 255;
      }
    }
  }
  return image;
}

Image read_pcx(const std::string& path) {
  std::string bytes = detail::read_file(path, size_t(256) << 20);
  return decode_pcx(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), path);
}

}  // namespace velocity
