// The PCX decoder: a real texture sheet checked against an independent decode, small
// files built byte by byte for each rule of the format, and damaged input.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "loader_test_util.hpp"
#include "velocity/pcx.hpp"

namespace velocity {
namespace {

using test::loads_or_throws_error;
using test::read_bytes;
using test::shared_data;

using Bytes = std::vector<uint8_t>;

// A 128-byte PCX header: version 5, the window (0, 0) - (w - 1, h - 1).
Bytes header(int w, int h, int bits, int planes, int bytes_per_line, int encoding = 1) {
  Bytes b(128, 0);
  b[0] = 0x0A, b[1] = 5, b[2] = uint8_t(encoding), b[3] = uint8_t(bits);
  auto put16 = [&](size_t at, int v) { b[at] = uint8_t(v & 0xff), b[at + 1] = uint8_t(v >> 8); };
  put16(8, w - 1);
  put16(10, h - 1);
  b[65] = uint8_t(planes);
  put16(66, bytes_per_line);
  return b;
}

// The 769-byte palette block: 0x0C, then entry i = (i, 255 - i, 7i mod 256).
Bytes palette_block() {
  Bytes b{0x0C};
  for (int i = 0; i < 256; ++i) b.insert(b.end(), {uint8_t(i), uint8_t(255 - i), uint8_t(i * 7)});
  return b;
}

Bytes concat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<uint8_t> rgba(const Image& im, int x, int y) { return {im.pixel(x, y), im.pixel(x, y) + 4}; }
std::vector<uint8_t> palette_rgba(int i) { return {uint8_t(i), uint8_t(255 - i), uint8_t(i * 7), 255}; }

std::string error_of(const Bytes& data) {
  try {
    decode_pcx(data, "t.pcx");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Pcx, EightBitRleRunsLiteralsAndOddRowPadding) {
  // 4 x 2 pixels, 5 bytes per line (odd: one byte of padding per row).
  //   row 0: 1 1 1 0xC5 | pad   -> C3 01 (run of three), C1 C5 (0xC5 must be a run of one), 00
  //   row 1: 2 3F C0 2  | pad 7 -> 02 3F (plain literals), C1 C0, 02, 07
  Bytes rle = {0xC3, 0x01, 0xC1, 0xC5, 0x00, 0x02, 0x3F, 0xC1, 0xC0, 0x02, 0x07};
  Image im = decode_pcx(concat(concat(header(4, 2, 8, 1, 5), rle), palette_block()), "t.pcx");
  ASSERT_EQ(im.width, 4);
  ASSERT_EQ(im.height, 2);
  EXPECT_EQ(rgba(im, 0, 0), palette_rgba(1));
  EXPECT_EQ(rgba(im, 2, 0), palette_rgba(1));
  EXPECT_EQ(rgba(im, 3, 0), palette_rgba(0xC5));
  EXPECT_EQ(rgba(im, 0, 1), palette_rgba(2));
  EXPECT_EQ(rgba(im, 1, 1), palette_rgba(0x3F));
  EXPECT_EQ(rgba(im, 2, 1), palette_rgba(0xC0));
  EXPECT_EQ(rgba(im, 3, 1), palette_rgba(2));
}

TEST(Pcx, RunsMayCrossTheEndOfARow) {
  Bytes rle = {0xC4, 0x09};  // one run of four fills both 2-pixel rows
  Image im = decode_pcx(concat(concat(header(2, 2, 8, 1, 2), rle), palette_block()), "t.pcx");
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) EXPECT_EQ(rgba(im, x, y), palette_rgba(9));
}

TEST(Pcx, TwentyFourBitThreePlanes) {
  // 2 x 1 pixels, 3 bytes per line per plane (odd, one byte of padding per plane).
  Bytes rle = {10, 20, 0, 30, 40, 0, 50, 60, 0};
  Image im = decode_pcx(concat(header(2, 1, 8, 3, 3), rle), "t.pcx");
  EXPECT_EQ(rgba(im, 0, 0), (std::vector<uint8_t>{10, 30, 50, 255}));
  EXPECT_EQ(rgba(im, 1, 0), (std::vector<uint8_t>{20, 40, 60, 255}));
}

TEST(Pcx, ThirtyTwoBitFourPlanesAndUncompressed) {
  Bytes raw = {1, 2, 3, 4, 5, 6, 7, 8};  // 2 x 1, planes R G B A, no RLE
  Image im = decode_pcx(concat(header(2, 1, 8, 4, 2, 0), raw), "t.pcx");
  EXPECT_EQ(rgba(im, 0, 0), (std::vector<uint8_t>{1, 3, 5, 7}));
  EXPECT_EQ(rgba(im, 1, 0), (std::vector<uint8_t>{2, 4, 6, 8}));
}

TEST(Pcx, MalformedFilesAreRefusedWithAReason) {
  EXPECT_EQ(error_of(Bytes(10, 0)), "t.pcx: expected a 128-byte PCX header, got 10 bytes");
  Bytes bad = header(2, 2, 8, 1, 2);
  bad[0] = 'P';
  EXPECT_EQ(error_of(bad), "t.pcx: expected the PCX signature 0x0A in byte 0 (is this a PCX file?)");
  EXPECT_EQ(error_of(concat(header(2, 2, 8, 1, 2), {0xC4, 0x09})),
            "t.pcx: expected a 256-colour palette (0x0C and 768 bytes) at the end of the file, got none");
  EXPECT_NE(error_of(concat(concat(header(2, 2, 8, 1, 2), {0xC3, 0x09}), palette_block())).find("truncated"),
            std::string::npos);
  EXPECT_NE(error_of(concat(header(4, 1, 8, 3, 4), {0xC4, 1, 0xC4, 2, 0xC4})).find("truncated: the RLE data ends"),
            std::string::npos);
  EXPECT_EQ(error_of(concat(header(8, 8, 4, 1, 4), Bytes(64, 0))),
            "t.pcx: unsupported PCX depth: 4 bits x 1 planes (supported: 8 bits with 1, 3 or 4 planes)");
  EXPECT_EQ(error_of(concat(header(8, 1, 8, 3, 7), Bytes(64, 0))),
            "t.pcx: PCX bytes per line 7 is less than the width 8");
  Bytes window = header(2, 2, 8, 3, 2);
  window[4] = 5;  // xmin 5 > xmax 1
  EXPECT_NE(error_of(window).find("bad PCX window"), std::string::npos);
  Bytes enc = header(2, 2, 8, 3, 2);
  enc[2] = 7;
  EXPECT_EQ(error_of(enc), "t.pcx: unknown PCX encoding 7 (expected 0 or 1)");
}

TEST(Pcx, HugeHeaderWithLittleDataAllocatesNothing) {
  // 65535 x 65535 x 3 planes claimed by a few bytes: refused before any allocation.
  std::string e = error_of(concat(header(65535, 65535, 8, 3, 65535), {0xFF, 0x00, 0xFF, 0x00}));
  EXPECT_NE(e.find("truncated: the header needs"), std::string::npos) << e;
}

TEST(Pcx, DecodesTheBlackArtTextureSheet) {
  std::string path = shared_data("textures/TEXTURES.PCX");
  VELOCITY_REQUIRE_SHARED(path);
  Image im = read_pcx(path);
  ASSERT_EQ(im.width, 320);
  ASSERT_EQ(im.height, 200);
  // Expected values from a separate 25-line Python decoder (RLE and palette written
  // from the format description, no code shared with decode_pcx), run once on the file:
  // the pixel's palette index, then the palette's RGB.
  auto px = [&](int x, int y) { return rgba(im, x, y); };
  EXPECT_EQ(px(0, 0), (std::vector<uint8_t>{255, 255, 255, 255}));    // index 15
  EXPECT_EQ(px(1, 0), (std::vector<uint8_t>{255, 255, 255, 255}));    // index 15
  EXPECT_EQ(px(10, 10), (std::vector<uint8_t>{115, 115, 115, 255}));  // index 25
  EXPECT_EQ(px(63, 63), (std::vector<uint8_t>{115, 115, 115, 255}));  // index 25
  EXPECT_EQ(px(100, 50), (std::vector<uint8_t>{7, 91, 0, 255}));      // index 109
  EXPECT_EQ(px(200, 150), (std::vector<uint8_t>{191, 0, 0, 255}));    // index 37
  EXPECT_EQ(px(319, 199), (std::vector<uint8_t>{0, 0, 0, 255}));      // index 0
  // The same script's checksum over every pixel: s = s * 31 + (r << 16 | g << 8 | b).
  uint32_t s = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const uint8_t* p = im.pixel(x, y);
      s = s * 31u + (uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
    }
  EXPECT_EQ(s, 2841012270u);
}

TEST(Pcx, TruncatedTextureSheetDecodesOrThrows) {
  std::string path = shared_data("textures/TEXTURES.PCX");
  VELOCITY_REQUIRE_SHARED(path);
  std::string file = read_bytes(path);
  Bytes bytes(file.begin(), file.end());
  for (int i = 0; i <= 200; ++i) {
    size_t cut = bytes.size() * size_t(i) / 200;
    loads_or_throws_error([&] { decode_pcx(std::span<const uint8_t>(bytes.data(), cut), "cut.pcx"); },
                          "TEXTURES.PCX cut at " + std::to_string(cut));
  }
  // Damaged bytes anywhere, header included.
  test::Rng rng;
  for (int i = 0; i < 300; ++i) {
    Bytes damaged = bytes;
    for (int e = 0; e < 4; ++e) damaged[rng.next() % (i % 2 ? 128 : damaged.size())] = uint8_t(rng.next());
    loads_or_throws_error([&] { decode_pcx(damaged, "damaged.pcx"); }, "damage " + std::to_string(i));
  }
}

TEST(Pcx, ReadPcxNamesAMissingFile) {
  try {
    read_pcx("/nonexistent/dir/x.pcx");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/x.pcx: no such file");
  }
}

}  // namespace
}  // namespace velocity
