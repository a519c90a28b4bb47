#include "framebuffer/framebuffer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "framebuffer/pack_rgb.hpp"
#include "velocity/error.hpp"

namespace velocity {

void Framebuffer::resize(int w, int h) {
  if (w < 1 || h < 1 || w > kMaxFramebufferSide || h > kMaxFramebufferSide)
    throw Error("framebuffer size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                std::to_string(kMaxFramebufferSide) + " a side)");
  const int tx = (w + kTileSize - 1) / kTileSize, ty = (h + kTileSize - 1) / kTileSize;
  const size_t n = size_t(tx) * size_t(ty) * kTilePixels;
  if (n <= color.capacity() && (ids.empty() || n <= ids.capacity())) {
    // Within the buffers' capacity (a program that switches between sizes, or
    // super-sampling factors): no new allocation, so the heap does not fragment.
    color.resize(n), depth.resize(n), stencil.resize(n);
    if (!ids.empty()) ids.resize(n);
  } else {
    // New buffers first, so that running out of memory (a velocity::Error, not
    // std::bad_alloc) leaves this framebuffer as it was.
    try {
      BlockVector<uint32_t> c(n, 0);
      BlockVector<float> d(n, 1.0f);
      BlockVector<uint8_t> s(n, 0);
      BlockVector<uint32_t> i(ids.empty() ? 0 : n, 0);
      color.swap(c);
      depth.swap(d);
      stencil.swap(s);
      ids.swap(i);
    } catch (const std::bad_alloc&) {
      throw Error("framebuffer size " + std::to_string(w) + "x" + std::to_string(h) + ": cannot allocate " +
                  std::to_string(n * (sizeof(uint32_t) + sizeof(float) + 1)) + " bytes");
    }
  }
  width = w, height = h, tiles_x = tx, tiles_y = ty;
  tile_clean.assign(size_t(tx) * ty, 0);
}

void Framebuffer::keep_ids(bool keep) {
  if (keep != !ids.empty()) std::fill(tile_clean.begin(), tile_clean.end(), 0);
  if (!keep) {
    BlockVector<uint32_t>().swap(ids);
  } else if (ids.size() != color.size()) {
    try {
      ids.assign(color.size(), 0);
    } catch (const std::bad_alloc&) {
      throw Error("framebuffer: cannot allocate the object-id buffer");
    }
  }
}

namespace {
// Copies row y of a tiled buffer: 4 pixels at a time from each block the row crosses
// (a fixed-size copy: one 16-byte move), then what is left of a last, partial block.
template <class T>
void read_row(const Framebuffer& fb, const T* data, int y, T* out) {
  const T* row = data + fb.index(0, y);  // the row's pixels in the first block of its tiles
  auto block = [&](int x) { return row + size_t(x >> 6) * Framebuffer::kTilePixels + size_t((x >> 2) & 15) * 16; };
  const int whole = fb.width & ~3;
  for (int x = 0; x < whole; x += 4) std::memcpy(out + x, block(x), 4 * sizeof(T));
  if (whole < fb.width) std::memcpy(out + whole, block(whole), size_t(fb.width - whole) * sizeof(T));
}
}  // namespace

void Framebuffer::read_color_row(int y, uint32_t* out) const { read_row(*this, color.data(), y, out); }
void Framebuffer::read_depth_row(int y, float* out) const { read_row(*this, depth.data(), y, out); }
void Framebuffer::read_id_row(int y, uint32_t* out) const { read_row(*this, ids.data(), y, out); }
void Framebuffer::read_stencil_row(int y, uint8_t* out) const { read_row(*this, stencil.data(), y, out); }

void Framebuffer::read_color_tile(int t, uint8_t* out, size_t row_bytes, int channels) const {
  const int x0 = (t % tiles_x) * kTileSize, y0 = (t / tiles_x) * kTileSize;
  const int n = std::min(x0 + kTileSize, width) - x0, y1 = std::min(y0 + kTileSize, height);
  uint32_t row[kTileSize];
  bool streamed = false;
  // A clean tile holds the clear colour alone: written from a register, the tile's
  // 16 KiB not read (most of a frame's tiles when little is drawn: gears).
  const bool clean = tile_clean[size_t(t)] != 0;
  // An image up to 16 MiB (1080p's is 8) stays in the last-level cache from frame to
  // frame beside the tiles drawn: ordinary stores find its lines there. A larger one
  // would only push the tiles out: non-temporal stores, which also spare reading its
  // lines first. (Gears at 1080p, with the clean tiles not read: 1.7-1.8 ms of CPU a
  // frame with ordinary stores, 2.1-2.3 with non-temporal ones.)
  const bool stream = row_bytes * size_t(height) > (size_t(16) << 20);
  for (int y = y0; y < y1; ++y) {
    const uint32_t* blocks = color.data() + index(x0, y);  // the row's 4 pixels in the tile's first block
    uint8_t* to = out + size_t(y) * row_bytes + size_t(x0) * size_t(channels);
#if defined(__SSE2__)
    // A whole tile row of RGBA to 16-byte aligned memory, 16 bytes at a time.
    if (channels == 4 && n == kTileSize && (reinterpret_cast<uintptr_t>(to) & 15) == 0) {
      const __m128i c = _mm_set1_epi32(int(clean_color));
      __m128i* at = reinterpret_cast<__m128i*>(to);
      // A clean row the image already holds (the last frame wrote it, and the program
      // left it) is only read: a line read is cheaper than a line written back (gears,
      // 200 frames at 1080p: 9 % fewer samples here, 900/851/941 against 829/819/800).
      if (clean && !stream) {
        __m128i same = _mm_set1_epi32(-1);
        for (int x = 0; x < kTileSize / 4; ++x) same = _mm_and_si128(same, _mm_cmpeq_epi32(_mm_load_si128(at + x), c));
        if (_mm_movemask_epi8(same) == 0xffff) continue;
      }
      for (int x = 0; x < n; x += 4) {
        const __m128i v = clean ? c : _mm_load_si128(reinterpret_cast<const __m128i*>(blocks + 4 * x));
        if (stream) _mm_stream_si128(at + x / 4, v);
        else _mm_store_si128(at + x / 4, v);
      }
      streamed = stream;
      continue;
    }
#endif
    uint8_t* rgba = channels == 4 ? to : reinterpret_cast<uint8_t*>(row);
    for (int x = 0; x < n; x += 4) std::memcpy(rgba + 4 * x, blocks + 4 * x, size_t(std::min(4, n - x)) * 4);
    if (channels == 3) pack_rgb(rgba, to, size_t(n));
  }
#if defined(__SSE2__)
  if (streamed) _mm_sfence();  // ordered before the pool reports the tile done
#else
  (void)streamed;
#endif
}

Image Framebuffer::color_image() const {
  Image image(width, height);
  for (int y = 0; y < height; ++y) read_color_row(y, reinterpret_cast<uint32_t*>(image.pixel(0, y)));
  return image;
}

Image Framebuffer::depth_image() const {
  std::vector<float> row(static_cast<size_t>(width));
  float lo = 1, hi = 0;
  for (int y = 0; y < height; ++y) {
    read_depth_row(y, row.data());
    for (float d : row)
      if (d < 1) lo = std::min(lo, d), hi = std::max(hi, d);
  }
  Image image(width, height, 0xff000000u);
  float range = hi > lo ? hi - lo : 1.0f;
  for (int y = 0; y < height; ++y) {
    read_depth_row(y, row.data());
    for (int x = 0; x < width; ++x) {
      float d = row[size_t(x)];
      if (!(d < 1)) continue;
      float t = (d - lo) / range;  // 0 nearest, 1 farthest
      auto g = uint8_t(255.0f - t * (255.0f - 32.0f) + 0.5f);
      uint8_t* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = g;
    }
  }
  return image;
}

}  // namespace velocity
