// Polygon stipple (GL 1.5 section 3.5.2): glPolygonStipple's 32x32 bitmap, tiled over
// the window from its origin, keeps the fragments of filled polygons where its bit is
// set. The pattern is unpacked (and glGetPolygonStipple packs it) as a glBitmap image is,
// with the pixel store's row length, skips, alignment and bit order; the renderer's
// fixed-function kernel applies it (PixelState::stipple) to the draws of filled
// polygons only (not to lines, points, polygon-mode outlines or pixel rectangles).
#include <algorithm>

#include "context.hpp"

namespace velocity::gl {

void Context::polygon_stipple(const std::array<uint32_t, 32>& rows) {
  if (in_begin_error()) return;
  raster_.stipple = rows;
  changed();
}

std::array<uint32_t, 32> stipple_rows(const PixelStore& store, const void* data) {
  const std::vector<uint8_t> bits = unpack_bitmap(32, 32, store, data);
  std::array<uint32_t, 32> rows{};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if (bits[size_t(y) * 32 + size_t(x)]) rows[size_t(y)] |= 1u << x;
  return rows;
}

void Context::get_polygon_stipple(GLubyte* out) const {
  if (!out) return;
  const PixelStore& store = pixels.pack;
  // Rows of ceil(length / 8) bytes, padded to the alignment; skip_pixels counts bits.
  const size_t length = size_t(store.row_length > 0 ? store.row_length : 32);
  const size_t align = size_t(std::max(store.alignment, 1));
  const size_t stride = ((length + 7) / 8 + align - 1) / align * align;
  for (int y = 0; y < 32; ++y) {
    GLubyte* row = out + (size_t(store.skip_rows) + size_t(y)) * stride;
    for (int x = 0; x < 32; ++x) {
      const size_t bit = size_t(store.skip_pixels) + size_t(x);
      const int shift = store.lsb_first ? int(bit % 8) : 7 - int(bit % 8);
      const GLubyte b = GLubyte(1u << shift);
      if (raster_.stipple[size_t(y)] >> x & 1) row[bit / 8] |= b;
      else row[bit / 8] &= GLubyte(~b);
    }
  }
}

}  // namespace velocity::gl
