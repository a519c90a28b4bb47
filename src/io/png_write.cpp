// PNG through libpng. libpng reports errors by longjmp: the function that calls setjmp
// (write_png_rows) and the callbacks hold nothing with a destructor, so that no C++
// object is skipped when libpng jumps back.
#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>

#include "velocity/error.hpp"
#include "velocity/png.hpp"

namespace velocity {
namespace {

constexpr int kMaxSide = 65536;  // as velocity::Image

struct Sink {
  std::vector<uint8_t>* bytes;
  char message[160];
};

void on_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<Sink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // none matter for what we write

void on_write(png_structp png, png_bytep data, png_size_t n) {
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  bool ok = true;
  try {
    sink->bytes->insert(sink->bytes->end(), data, data + n);
  } catch (const std::bad_alloc&) {
    ok = false;
  }
  if (!ok) png_error(png, "out of memory");  // outside the handler: the jump skips nothing
}

int filter_mask(PngFilter f) {
  switch (f) {
    case PngFilter::None: return PNG_FILTER_NONE;
    case PngFilter::Sub: return PNG_FILTER_SUB;
    case PngFilter::Up: return PNG_FILTER_UP;
    case PngFilter::Average: return PNG_FILTER_AVG;
    case PngFilter::Paeth: return PNG_FILTER_PAETH;
    case PngFilter::Adaptive: break;
  }
  return PNG_ALL_FILTERS;
}

bool write_png_rows(png_structp png, png_infop info, const PngImage& im, int level, PngFilter filter, Sink* sink) {
  if (setjmp(png_jmpbuf(png))) return false;
  static const int kColorType[5] = {0, PNG_COLOR_TYPE_GRAY, 0, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGBA};
  png_set_write_fn(png, sink, on_write, nullptr);
  png_set_IHDR(png, info, png_uint_32(im.width), png_uint_32(im.height), im.bits, kColorType[im.channels],
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, level);
  png_set_compression_buffer_size(png, 1 << 16);  // fewer, larger IDAT chunks
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filter_mask(filter));
  png_write_info(png, info);
  const uint16_t one = 1;
  uint8_t first;
  std::memcpy(&first, &one, 1);
  if (im.bits == 16 && first == 1) png_set_swap(png);  // PNG's samples are big-endian
  const auto* row = static_cast<const uint8_t*>(im.pixels);
  for (int y = 0; y < im.height; ++y, row += im.stride) png_write_row(png, row);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::vector<uint8_t> encode_png(const PngImage& im, int level, PngFilter filter) {
  if (im.width < 1 || im.height < 1 || im.width > kMaxSide || im.height > kMaxSide)
    throw Error("PNG: image size " + std::to_string(im.width) + "x" + std::to_string(im.height) +
                " is out of range (1..65536 a side)");
  if (im.channels != 1 && im.channels != 3 && im.channels != 4)
    throw Error("PNG: expected 1, 3 or 4 channels, got " + std::to_string(im.channels));
  if (im.bits != 8 && !(im.bits == 16 && im.channels == 1))
    throw Error("PNG: expected 8 bits a sample, or 16 for grey, got " + std::to_string(im.bits));
  if (level < 0 || level > 9) throw Error("PNG: compression level must be 0..9, got " + std::to_string(level));
  if (!im.pixels || im.stride < ptrdiff_t(im.width) * im.channels * (im.bits / 8))
    throw Error("PNG: rows are shorter than the image is wide");
  std::vector<uint8_t> bytes;
  Sink sink{&bytes, ""};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  if (!png) throw std::bad_alloc();
  png_infop info = png_create_info_struct(png);
  const bool ok = info && write_png_rows(png, info, im, level, filter, &sink);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw Error(std::string("PNG: ") + (sink.message[0] ? sink.message : "libpng cannot write the image"));
  return bytes;
}

void write_png(const std::string& path, const PngImage& image, int level, PngFilter filter) {
  std::vector<uint8_t> bytes;
  try {
    bytes = encode_png(image, level, filter);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for writing (" + std::strerror(errno) + ")");
  if (std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size() || std::fflush(f.get()) != 0)
    throw Error(path + ": write failed (" + std::strerror(errno) + ")");
  // fclose reports what a full disk leaves until the buffer is handed over.
  if (std::fclose(f.release()) != 0) throw Error(path + ": write failed (" + std::strerror(errno) + ")");
}

}  // namespace velocity
