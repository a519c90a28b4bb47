// The engine's PNG writer (src/io/png_write.cpp, libpng): files decoded by another
// library (stb_image, behind read_image) give back the very pixels written, and a
// file that cannot be written is an error naming it and the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/png.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;

std::string temp_png(const char* name) {
  return (fs::temp_directory_path() / (std::string("velocity_png_write_") + std::to_string(getpid()) + name)).string();
}

// Width != height, every channel different, alpha not 255: a swapped axis, channel or
// byte order, or a dropped alpha shows.
Image asymmetric_image() {
  Image img(37, 11);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      uint8_t* p = img.pixel(x, y);
      p[0] = uint8_t(x * 7), p[1] = uint8_t(y * 23), p[2] = uint8_t((x * y) ^ 0x5a), p[3] = uint8_t(255 - x - y);
    }
  return img;
}

TEST(PngWrite, RgbaDecodesToThePixelsWritten) {
  const Image img = asymmetric_image();
  const std::string path = temp_png("rgba.png");
  write_png(path, img);
  const Image back = read_image(path);
  fs::remove(path);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  EXPECT_EQ(back.pixels, img.pixels);
}

TEST(PngWrite, WriteImageChoosesPngByExtension) {
  const Image img = asymmetric_image();
  const std::string path = temp_png("upper.PNG");
  write_image(path, img);
  EXPECT_EQ(read_image(path).pixels, img.pixels);
  fs::remove(path);
}

TEST(PngWrite, EveryFilterAndLevelDecodes) {
  const Image img = asymmetric_image();
  PngImage png;
  png.pixels = img.pixels.data(), png.width = img.width, png.height = img.height, png.channels = 4;
  png.stride = ptrdiff_t(img.width) * 4;
  for (int f = 0; f <= 5; ++f)
    for (int level : {0, 3, 9}) {
      const auto bytes = encode_png(png, level, PngFilter(f));
      const Image back = decode_image({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, "memory");
      EXPECT_EQ(back.pixels, img.pixels) << "filter " << f << " level " << level;
    }
}

TEST(PngWrite, SixteenBitGreyIsWrittenHighByteFirst) {
  // stb_image reads 16-bit PNGs as 8 bits (the high byte): the high bytes must match,
  // and the file must say 16 bits (IHDR's bit depth, byte 24).
  uint16_t grey[3 * 5];
  for (int i = 0; i < 15; ++i) grey[i] = uint16_t(i * 4099 + 3);
  PngImage png;
  png.pixels = grey, png.width = 5, png.height = 3, png.channels = 1, png.bits = 16, png.stride = 10;
  const auto bytes = encode_png(png);
  ASSERT_GT(bytes.size(), 25u);
  EXPECT_EQ(bytes[24], 16);
  const Image back = decode_image({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, "memory");
  for (int i = 0; i < 15; ++i) EXPECT_EQ(back.pixels[size_t(i) * 4], grey[i] >> 8) << i;
}

TEST(PngWrite, BadArgumentsAreErrors) {
  uint8_t px[4] = {};
  PngImage png;
  png.pixels = px, png.width = 1, png.height = 1, png.channels = 2, png.stride = 2;
  EXPECT_THROW(encode_png(png), Error);  // 2 channels
  png.channels = 4, png.stride = 4;
  EXPECT_THROW(encode_png(png, 10), Error);  // level
  png.bits = 16;
  EXPECT_THROW(encode_png(png), Error);  // 16-bit RGBA
  png.bits = 8, png.stride = 3;
  EXPECT_THROW(encode_png(png), Error);  // rows shorter than the image
}

TEST(PngWrite, UnwritableFilesNameThePathAndReason) {
  const Image img = asymmetric_image();
  try {
    write_png("/nonexistent-dir/x.png", img);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png: cannot open for writing (No such file"),
              std::string::npos) << e.what();
  }
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    write_png("/dev/full", img);  // every write: ENOSPC, as a full disk
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: write failed (No space left on device)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace velocity
