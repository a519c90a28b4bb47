// Image files: PNG through libpng (io/png_write.cpp), PPM by hand, reading through stb_image.
#include <stb/stb_image.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string_view>

#include "io/read_file.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/png.hpp"

namespace velocity {

Image::Image(int w, int h, uint32_t rgba) : width(w), height(h) {
  if (w <= 0 || h <= 0 || w > 65536 || h > 65536)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1..65536 a side)");
  try {
    pixels.resize(size_t(w) * size_t(h) * 4);
  } catch (const std::bad_alloc&) {
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + ": cannot allocate " +
                std::to_string(size_t(w) * size_t(h) * 4) + " bytes");
  }
  uint8_t c[4];
  std::memcpy(c, &rgba, 4);
  for (size_t i = 0; i < pixels.size(); i += 4) std::memcpy(&pixels[i], c, 4);
}

namespace {

std::string extension_of(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void check_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
    throw Error(path + ": cannot write an empty or inconsistent image");
}

// Most pixels read_image accepts: 8192x8192 (256 MiB as RGBA8), a bound on what a small
// file can make the decoder allocate.
constexpr int64_t kMaxImagePixels = int64_t(1) << 26;
// Most bytes of one image file (or embedded image) read.
constexpr size_t kMaxImageFileBytes = size_t(256) << 20;

// stb_image reads a TGA (the one format it knows by no magic number) whose pixel data
// ends early by padding it with zeros, after allocating the whole image: a 19-byte file
// claiming 12800x4097 pixels cost 210 MB and 13 s under the fuzzer (found by
// tests/fuzz/fuzz_embedded.cpp). The least a TGA of w x h pixels can hold is its header
// and, uncompressed, every pixel's bytes; run-length coded, one packet (a byte and one
// pixel) for each 128 pixels. Returns that least size, or 0 for a file that is not a TGA.
int64_t tga_least_bytes(const uint8_t* d, size_t n, int w, int h) {
  if (n < 18) return 0;
  static constexpr std::string_view kOtherMagic[] = {
      {"\xff\xd8", 2}, {"\x89PNG", 4}, {"GIF8", 4}, {"BM", 2}, {"8BPS", 4}, {"\x53\x80\xf6\x34", 4}, {"P5", 2},
      {"P6", 2}, {"#?", 2}};
  for (std::string_view magic : kOtherMagic)
    if (std::memcmp(d, magic.data(), magic.size()) == 0) return 0;
  const int type = d[2];
  const bool rle = type == 9 || type == 10 || type == 11;
  if (!rle && type != 1 && type != 2 && type != 3) return 0;
  const int64_t pixels = int64_t(w) * h, pixel_bytes = std::max(1, (d[16] + 7) / 8);
  return 18 + d[0] + (rle ? (pixels + 127) / 128 * (1 + pixel_bytes) : pixels * pixel_bytes);
}

// stb_image 2.27 (Debian 12's libstb) trusts the 16 code-length counts of a JPEG DHT
// table: counts adding up to more than 256 make stbi__build_huffman write past its
// table (found by tests/fuzz/fuzz_image.cpp; upstream 2.28 refuses them). Walk the
// marker segments as stb does and refuse such a file before stb sees it. Bytes past the
// end read as 0, as stb reads them.
bool jpeg_huffman_counts_ok(const uint8_t* d, size_t n) {
  auto at = [&](size_t i) -> size_t { return i < n ? d[i] : 0; };
  size_t i = 0;
  if (at(i) != 0xFF) return true;
  while (i < n && d[i] == 0xFF) ++i;
  if (at(i) != 0xD8) return true;  // not a JPEG (no SOI)
  while (++i < n) {
    if (d[i] != 0xFF) continue;  // entropy-coded data or padding: stb scans for the next marker too
    while (i + 1 < n && d[i + 1] == 0xFF) ++i;
    size_t m = at(i + 1);
    if (m == 0x00 || m == 0x01 || (m >= 0xD0 && m <= 0xD9)) continue;  // no length field
    long len = long(at(i + 2) << 8 | at(i + 3));
    if (m == 0xC4)
      for (long left = len - 2, p = long(i) + 4; left > 0;) {
        size_t count = 0;
        for (int k = 1; k <= 16; ++k) count += at(size_t(p) + size_t(k));
        if (count > 256) return false;
        p += 17 + long(count), left -= 17 + long(count);
      }
    i += 1 + size_t(len);
  }
  return true;
}

// stb_image 2.27 reads a binary PGM/PPM with a maximum value above 255 as 16 bits per
// channel, but converts it to RGBA as if it were 8 bits, then reads that buffer as 16
// bits: a heap over-read of the image's size (found by tests/fuzz/fuzz_image.cpp;
// fixed upstream in 2.28). Parse the header as stb does and refuse such files.
bool pnm_is_16_bit(const uint8_t* d, size_t n) {
  if (n < 2 || d[0] != 'P' || (d[1] != '5' && d[1] != '6')) return false;
  size_t i = 2;
  auto space = [](uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; };
  auto skip = [&] {  // white space and '#' comments, as stbi__pnm_skip_whitespace
    for (;;) {
      while (i < n && space(d[i])) ++i;
      if (i >= n || d[i] != '#') return;
      while (i < n && d[i] != '\n' && d[i] != '\r') ++i;
    }
  };
  uint64_t value = 0;
  for (int field = 0; field < 3; ++field) {  // width, height, maximum value
    skip();
    value = 0;
    while (i < n && d[i] >= '0' && d[i] <= '9') value = std::min<uint64_t>(value * 10 + (d[i++] - '0'), 1u << 20);
  }
  return value > 255;
}

}  // namespace

void write_png(const std::string& path, const Image& image) {
  check_image(path, image);
  PngImage png;
  png.pixels = image.pixels.data();
  png.width = image.width, png.height = image.height;
  png.channels = 4;
  png.stride = ptrdiff_t(image.width) * 4;
  write_png(path, png);
}

void write_ppm(const std::string& path, const Image& image) {
  check_image(path, image);
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for writing (" + std::strerror(errno) + ")");
  std::fprintf(f.get(), "P6\n%d %d\n255\n", image.width, image.height);
  std::vector<uint8_t> row(size_t(image.width) * 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) std::memcpy(&row[size_t(x) * 3], image.pixel(x, y), 3);
    if (std::fwrite(row.data(), 1, row.size(), f.get()) != row.size())
      throw Error(path + ": write failed (" + std::strerror(errno) + ")");
  }
  if (std::fflush(f.get()) != 0) throw Error(path + ": write failed (" + std::strerror(errno) + ")");
}

void write_image(const std::string& path, const Image& image) {
  std::string ext = extension_of(path);
  if (ext == "png") return write_png(path, image);
  if (ext == "ppm") return write_ppm(path, image);
  throw Error(path + ": unknown image extension '" + ext + "' (expected .png or .ppm)");
}

Image read_image(const std::string& path) {
  // Through read_file: a missing file, a directory, a device or a FIFO gets a clear
  // error, and the size is bounded (as read_pcx's).
  return decode_image(detail::read_file(path, kMaxImageFileBytes), path);
}

Image decode_image(std::string_view bytes, const std::string& path) {
  if (bytes.size() > kMaxImageFileBytes)
    throw Error(path + ": image data of " + std::to_string(bytes.size()) + " bytes is more than the limit of " +
                std::to_string(kMaxImageFileBytes >> 20) + " MiB");
  const auto* p = reinterpret_cast<const stbi_uc*>(bytes.data());
  if (!jpeg_huffman_counts_ok(p, bytes.size()))
    throw Error(path + ": cannot read image (corrupt JPEG: a Huffman table has more than 256 codes)");
  if (pnm_is_16_bit(p, bytes.size()))
    throw Error(path + ": cannot read image (16-bit PGM/PPM files are not supported)");
  // The header's size, before stb allocates for it: a 14-byte GIF can claim 65535x65535
  // (stb would allocate and clear three buffers of that size). Images are refused above
  // kMaxImagePixels.
  int w = 0, h = 0, n = 0;  // bytes.size() < 2^31: the casts are exact
  if (stbi_info_from_memory(p, int(bytes.size()), &w, &h, &n) &&
      (w > 65536 || h > 65536 || int64_t(w) * h > kMaxImagePixels))
    throw Error(path + ": image is " + std::to_string(w) + "x" + std::to_string(h) + ", more than the limit of " +
                std::to_string(kMaxImagePixels >> 20) + " megapixels");
  if (const int64_t least = tga_least_bytes(p, bytes.size(), w, h); int64_t(bytes.size()) < least)
    throw Error(path + ": cannot read image (truncated TGA: " + std::to_string(w) + "x" + std::to_string(h) +
                " pixels need at least " + std::to_string(least) + " bytes, the data has " +
                std::to_string(bytes.size()) + ")");
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_memory(p, int(bytes.size()), &w, &h, &n, 4),
                                                 &stbi_image_free);
  if (!data) throw Error(path + ": cannot read image (" + stbi_failure_reason() + ")");
  if (w > 65536 || h > 65536)
    throw Error(path + ": image is " + std::to_string(w) + "x" + std::to_string(h) + ", more than 65536 a side");
  Image image(w, h);
  std::memcpy(image.pixels.data(), data.get(), image.pixels.size());
  return image;
}

}  // namespace velocity
