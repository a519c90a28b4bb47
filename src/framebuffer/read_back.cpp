#include "framebuffer/read_back.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "framebuffer/pack_rgb.hpp"
#include "framebuffer/resolve.hpp"

namespace velocity {

namespace {

// Calls rows(y0, y1) for bands of an image's `height` rows, on `pool` when there is one.
template <class Rows>
void for_row_bands(ThreadPool* pool, int height, Rows&& rows) {
  constexpr int kBand = 64;
  const int bands = (height + kBand - 1) / kBand;
  auto band = [&](int b) { rows(b * kBand, std::min(height, (b + 1) * kBand)); };
  if (pool) {
    pool->run(bands, band);
  } else {
    for (int b = 0; b < bands; ++b) band(b);
  }
}

}  // namespace

void read_color(const Framebuffer& samples, int k, ThreadPool* pool, uint8_t* rgba, size_t row_bytes, int channels) {
  for_row_bands(pool, samples.height / k,
                [&](int y0, int y1) { resolve_color_rows(samples, k, rgba, row_bytes, channels, y0, y1); });
}

void read_color(const uint32_t* pixels, int w, int h, size_t stride, ThreadPool* pool, uint8_t* rgba, size_t row_bytes,
                int channels) {
  for_row_bands(pool, h, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      const uint32_t* row = pixels + size_t(y) * stride;
      if (channels == 4) std::memcpy(rgba + size_t(y) * row_bytes, row, size_t(w) * 4);
      else pack_rgb(reinterpret_cast<const uint8_t*>(row), rgba + size_t(y) * row_bytes, size_t(w));
    }
  });
}

void read_window_depth(const Framebuffer& samples, int k, ThreadPool* pool, float* out) {
  for_row_bands(pool, samples.height / k, [&](int y0, int y1) { resolve_window_depth_rows(samples, k, out, y0, y1); });
}

void read_stencil(const Framebuffer& samples, int k, uint8_t* out) {
  const int w = samples.width / k, h = samples.height / k;
  std::vector<uint8_t> row(size_t(samples.width));
  for (int y = 0; y < h; ++y) {
    samples.read_stencil_row(y * k, row.data());
    for (int x = 0; x < w; ++x) out[size_t(y) * size_t(w) + size_t(x)] = row[size_t(x) * size_t(k)];
  }
}

void read_view_depth(const Framebuffer& samples, int k, ThreadPool* pool, const Mat4& projection, float* out) {
  // Window depth d = 0.5 z_ndc + 0.5 with z_ndc = (P22 z + P23) / (P32 z + P33) for the
  // eye-space z: solved for z, in double (the projection's own inverse, so it is exact
  // for perspective and orthographic cameras alike up to float depth).
  const Mat4& p = projection;
  const double p22 = p.m[2][2], p23 = p.m[2][3], p32 = p.m[3][2], p33 = p.m[3][3];
  const size_t w = size_t(samples.width / k);
  for_row_bands(pool, samples.height / k, [&](int y0, int y1) {
    resolve_window_depth_rows(samples, k, out, y0, y1);
    float* d = out + size_t(y0) * w;
    const size_t n = size_t(y1 - y0) * w;
    for (size_t i = 0; i < n; ++i) {  // no branch: the compiler vectorises it
      const double ndc = 2.0 * double(d[i]) - 1.0;
      const float z = float((ndc * p33 - p23) / (ndc * p32 - p22));
      d[i] = d[i] < 1.0f ? z : 0.0f;
    }
  });
}

}  // namespace velocity
