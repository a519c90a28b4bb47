#include "framebuffer/resolve.hpp"

#include "framebuffer/pack_rgb.hpp"
#include "framebuffer/resolve_rows.hpp"

#include <algorithm>
#include <cstring>

namespace velocity {

namespace {

// Reads the k sample rows behind output row y into `rows` (k rows of fb.width).
template <class T, class Read>
void read_sample_rows(const Framebuffer& fb, int k, int y, std::vector<T>& rows, Read read) {
  rows.resize(size_t(fb.width) * k);
  for (int sy = 0; sy < k; ++sy) (fb.*read)(y * k + sy, rows.data() + size_t(sy) * fb.width);
}

// Calls f(x, sample row, sample column) with each output pixel's nearest sample (the
// smallest depth; the first in row order among equals) of output row y.
template <class F>
void for_each_nearest_sample(const Framebuffer& fb, int k, int y, std::vector<float>& depth_rows, F&& f) {
  read_sample_rows(fb, k, y, depth_rows, &Framebuffer::read_depth_row);
  for (int x = 0; x < fb.width / k; ++x) {
    int best_r = 0, best_c = x * k;
    for (int sy = 0; sy < k; ++sy)
      for (int sx = 0; sx < k; ++sx)
        if (depth_rows[size_t(sy) * fb.width + x * k + sx] < depth_rows[size_t(best_r) * fb.width + best_c])
          best_r = sy, best_c = x * k + sx;
    f(x, best_r, best_c);
  }
}

// Where sample column sx lies from the start of its row in the row's first tile (the
// layout of framebuffer.hpp: 4096 a tile, 16 a block, 1 a sample).
inline size_t column_offset(int sx) { return size_t((sx & ~63) << 6 | (sx & 60) << 2 | (sx & 3)); }

// Output pixels [x0, x1) of output row y into out[0, x1 - x0), each the rounded mean of
// its k x k samples per channel (k <= 16), packed RGBA8; k = 2, 3 and 4 a vector of
// pixels at a time (resolve_rows.cpp). The samples are read where the tiles hold them.
// Two channels a 32-bit add, each in a 16-bit lane (channels 0 and 2, then 1 and 3): k *
// k samples of 255 fit a lane up to k = 16, and the sums are the exact ones a channel at
// a time would give, in a quarter of the work.
void resolve_span(const Framebuffer& fb, int k, int y, int x0, int x1, uint32_t* out) {
  if (k >= 2 && k <= 4) return resolve_span_simd(fb, k, y, x0, x1, out);
  const uint32_t n = uint32_t(k * k);
  const uint32_t* rows_at[16];
  for (int sy = 0; sy < k; ++sy) rows_at[sy] = fb.color.data() + fb.index(0, y * k + sy);
  auto mean = [n](uint32_t sum) { return (sum + n / 2) / n; };
  for (int x = x0; x < x1; ++x) {
    uint32_t even = 0, odd = 0;
    for (int sx = x * k; sx < (x + 1) * k; ++sx) {
      const size_t at = column_offset(sx);
      for (int sy = 0; sy < k; ++sy) {
        const uint32_t v = rows_at[sy][at];
        even += v & 0x00ff00ffu, odd += (v >> 8) & 0x00ff00ffu;
      }
    }
    out[x - x0] = mean(even & 0xffffu) | mean(odd & 0xffffu) << 8 | mean(even >> 16) << 16 | mean(odd >> 16) << 24;
  }
}

// Whether output line i (a row or column) has samples in two tiles.
inline bool is_seam(int i, int k) { return (i * k) >> kTileSizeLog2 != (i * k + k - 1) >> kTileSizeLog2; }

// The output lines across `samples` sample lines that straddle a tile edge: with
// which < 0 how many, else the line of the which-th. An edge at sample 64m falls inside
// output line (64m - 1) / k unless k divides 64m.
int seam_lines(int samples, int k, int which) {
  int count = 0;
  for (int edge = kTileSize; edge < samples; edge += kTileSize) {
    if (edge % k == 0) continue;
    if (count++ == which) return (edge - 1) / k;
  }
  return which < 0 ? count : -1;
}

}  // namespace

Image resolve_color(const Framebuffer& fb, int k) {
  Image out(fb.width / k, fb.height / k);
  resolve_color_into(fb, k, out.pixels.data(), size_t(out.width) * 4);
  return out;
}

void resolve_color_into(const Framebuffer& fb, int k, uint8_t* rgba, size_t row_bytes, int channels) {
  resolve_color_rows(fb, k, rgba, row_bytes, channels, 0, fb.height / k);
}

void resolve_color_rows(const Framebuffer& fb, int k, uint8_t* rgba, size_t row_bytes, int channels, int y0, int y1) {
  const int w = fb.width / k, n = k * k;
  if (k == 1 && channels == 4) {
    for (int y = y0; y < y1; ++y) fb.read_color_row(y, reinterpret_cast<uint32_t*>(rgba + size_t(y) * row_bytes));
    return;
  }
  if (k <= 16) {  // a row of packed pixels, then copied or packed to RGB a vector at a time
    std::vector<uint32_t> row(size_t(fb.width));
    for (int y = y0; y < y1; ++y) {
      if (k == 1) fb.read_color_row(y, row.data());
      else resolve_span(fb, k, y, 0, w, row.data());
      uint8_t* out = rgba + size_t(y) * row_bytes;
      if (channels == 4) std::memcpy(out, row.data(), size_t(w) * 4);
      else pack_rgb(reinterpret_cast<const uint8_t*>(row.data()), out, size_t(w));
    }
    return;
  }
  std::vector<uint32_t> rows;
  for (int y = y0; y < y1; ++y) {
    read_sample_rows(fb, k, y, rows, &Framebuffer::read_color_row);
    for (int x = 0; x < w; ++x) {
      uint32_t sum[4] = {0, 0, 0, 0};
      for (int sy = 0; sy < k; ++sy) {
        const uint32_t* row = rows.data() + size_t(sy) * fb.width + size_t(x) * k;
        for (int sx = 0; sx < k; ++sx)
          for (int c = 0; c < 4; ++c) sum[c] += (row[sx] >> (8 * c)) & 0xff;
      }
      uint8_t* p = rgba + size_t(y) * row_bytes + size_t(x) * channels;
      for (int c = 0; c < channels; ++c) p[c] = uint8_t((sum[c] + uint32_t(n / 2)) / uint32_t(n));
    }
  }
}

void resolve_tile_color(const Framebuffer& fb, int k, int tile, uint32_t* out, size_t stride) {
  const int sx = (tile % fb.tiles_x) * kTileSize, sy = (tile / fb.tiles_x) * kTileSize;
  // From the first pixel whose first sample is in the tile to the last whose last is.
  const int x0 = (sx + k - 1) / k, x1 = std::min(fb.width / k, (sx + kTileSize) / k);
  const int y0 = (sy + k - 1) / k, y1 = std::min(fb.height / k, (sy + kTileSize) / k);
  for (int y = y0; y < y1; ++y)
    if (x0 < x1) resolve_span(fb, k, y, x0, x1, out + size_t(y) * stride + size_t(x0));
}

int resolve_seam_count(const Framebuffer& fb, int k) {
  return seam_lines(fb.height, k, -1) + seam_lines(fb.width, k, -1);
}

void resolve_seam(const Framebuffer& fb, int k, int line, uint32_t* out, size_t stride) {
  const int w = fb.width / k, h = fb.height / k, rows = seam_lines(fb.height, k, -1);
  if (line < rows) {
    const int y = seam_lines(fb.height, k, line);
    resolve_span(fb, k, y, 0, w, out + size_t(y) * stride);
    return;
  }
  const int x = seam_lines(fb.width, k, line - rows);
  if (x < 0) return;
  for (int y = 0; y < h; ++y)
    if (!is_seam(y, k)) resolve_span(fb, k, y, x, x + 1, out + size_t(y) * stride + size_t(x));
}

Image resolve_depth(const Framebuffer& fb, int k) {
  if (k == 1) return fb.depth_image();
  // The nearest sample of each pixel, shown as Framebuffer::depth_image shows depth.
  Framebuffer nearest;
  nearest.resize(fb.width / k, fb.height / k);
  std::vector<float> d = resolve_window_depth(fb, k);
  for (int y = 0; y < nearest.height; ++y)
    for (int x = 0; x < nearest.width; ++x) nearest.depth[nearest.index(x, y)] = d[size_t(y) * nearest.width + x];
  return nearest.depth_image();
}

std::vector<float> resolve_window_depth(const Framebuffer& fb, int k) {
  std::vector<float> out(size_t(fb.width / k) * size_t(fb.height / k));
  resolve_window_depth_rows(fb, k, out.data(), 0, fb.height / k);
  return out;
}

void resolve_window_depth_rows(const Framebuffer& fb, int k, float* out, int y0, int y1) {
  const int w = fb.width / k;
  if (k == 1) {
    for (int y = y0; y < y1; ++y) fb.read_depth_row(y, out + size_t(y) * w);
    return;
  }
  std::vector<float> rows;
  for (int y = y0; y < y1; ++y)
    for_each_nearest_sample(fb, k, y, rows, [&](int x, int r, int c) { out[size_t(y) * w + x] = rows[size_t(r) * fb.width + c]; });
}

std::vector<uint32_t> resolve_object_ids(const Framebuffer& fb, int k) {
  if (fb.ids.empty()) return {};
  const int w = fb.width / k, h = fb.height / k;
  std::vector<uint32_t> out(size_t(w) * h);
  std::vector<float> rows;
  for (int y = 0; y < h; ++y)
    for_each_nearest_sample(fb, k, y, rows,
                            [&](int x, int r, int c) { out[size_t(y) * w + x] = fb.ids[fb.index(c, y * k + r)]; });
  return out;
}

}  // namespace velocity
