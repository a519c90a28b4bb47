// The colour, depth and object-id buffers the tiles are rasterised into.
//
// Memory layout: the buffers are stored tile by tile, 64x64-pixel tiles in row-major
// order, each tile as 16x16 blocks of 4x4 pixels in row-major order, each block's 16
// pixels in row-major order:
//
//   index(x, y) = tile(x >> 6, y >> 6) * 4096 + block((x >> 2) & 15, (y >> 2) & 15) * 16
//                 + (y & 3) * 4 + (x & 3)
//
// A 4x4 block is one 64-byte cache line of colour (RGBA8) and one of depth (float)
// (and 16 bytes of stencil):
// the SIMD kernels load and store whole blocks, and a tile (32 KiB of colour and depth)
// stays in the core's cache while it is drawn. The buffers are padded to whole tiles;
// pixels outside width x height are never drawn and never read back. Readers see
// ordinary images through color_image() and the resolve functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>
#include <algorithm>

#include "velocity/image.hpp"

namespace velocity {

// The largest framebuffer side, in samples (the guard band and the 24.8 fixed-point
// coordinates of raster/contract.hpp are sized for it).
inline constexpr int kMaxFramebufferSide = 16384;

inline constexpr int kTileSizeLog2 = 6;
inline constexpr int kTileSize = 1 << kTileSizeLog2;  // 64x64 pixel tiles
inline constexpr int kBlockSize = 4;                  // 4x4 pixel blocks: one SIMD block
inline constexpr int kBlocksPerTileSide = kTileSize / kBlockSize;  // 16

// A std::vector allocator aligned to the 64-byte blocks the kernels load and store.
template <class T>
struct BlockAllocator {
  using value_type = T;
  BlockAllocator() = default;
  template <class U>
  BlockAllocator(const BlockAllocator<U>&) {}
  T* allocate(size_t n) {
    if (n > SIZE_MAX / sizeof(T) - 64) throw std::bad_alloc();
    void* p = std::aligned_alloc(64, (n * sizeof(T) + 63) / 64 * 64);
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) { std::free(p); }
  template <class U>
  bool operator==(const BlockAllocator<U>&) const { return true; }
};
template <class T>
using BlockVector = std::vector<T, BlockAllocator<T>>;

struct Framebuffer {
  int width = 0, height = 0;      // pixels (samples, with super-sampling)
  int tiles_x = 0, tiles_y = 0;   // 64x64 tiles covering them
  BlockVector<uint32_t> color;    // RGBA8 (byte 0 red), tiled as above
  BlockVector<float> depth;       // window depth in [0, 1]; 1 is the far plane
  BlockVector<uint8_t> stencil;   // 8-bit stencil values, tiled as above
  BlockVector<uint32_t> ids;      // object id per sample, when the renderer keeps them (else empty)
  // Tiles that hold nothing but the clear values below (colour, depth, stencil, and ids
  // zero): a frame that clears them to the same values and draws nothing there skips them.
  std::vector<uint8_t> tile_clean;
  uint32_t clean_color = 0;
  float clean_depth = 1.0f;
  uint8_t clean_stencil = 0;

  // Forgets which tiles are clean unless they were cleaned with these values.
  void expect_clear(uint32_t color, float depth, uint8_t stencil_value) {
    if (color != clean_color || depth != clean_depth || stencil_value != clean_stencil)
      std::fill(tile_clean.begin(), tile_clean.end(), 0);
    clean_color = color, clean_depth = depth, clean_stencil = stencil_value;
  }

  static constexpr int kTilePixels = kTileSize * kTileSize;  // 4096

  // Where pixel (x, y) is stored (0 <= x < tiles_x * 64, 0 <= y < tiles_y * 64).
  size_t index(int x, int y) const {
    return (size_t(y >> 6) * size_t(tiles_x) + size_t(x >> 6)) * kTilePixels + size_t(((y >> 2) & 15) * 16 + ((x >> 2) & 15)) * 16 +
           size_t((y & 3) * 4 + (x & 3));
  }
  // First pixel of tile t (tiles in row-major order).
  size_t tile_offset(int tile) const { return size_t(tile) * kTilePixels; }

  // Throws velocity::Error unless 1 <= width, height <= 16384; keeps the old buffers when
  // memory runs out.
  void resize(int width, int height);
  // Allocates (or frees, with false) the object-id buffer, zeroed.
  void keep_ids(bool keep);

  // Row y of the image, width pixels, into `out` (linear order). Used by every reader.
  void read_color_row(int y, uint32_t* out) const;
  // Tile t's pixels (those inside width x height) into an image of width x height,
  // RGBA8 (channels 4) or RGB8 (3), rows `row_bytes` apart: what the rows of read_color_row
  // hold there.
  void read_color_tile(int t, uint8_t* out, size_t row_bytes, int channels) const;
  void read_depth_row(int y, float* out) const;
  void read_id_row(int y, uint32_t* out) const;
  void read_stencil_row(int y, uint8_t* out) const;

  Image color_image() const;
  // Depth as greyscale: the nearest depth drawn is white, the farthest drawn is dark
  // grey (32), untouched pixels (still at the clear depth, 1) black. Scaled over the
  // range actually drawn so that a small object still shows its shape.
  Image depth_image() const;
};

}  // namespace velocity
