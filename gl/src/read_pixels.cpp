// glReadPixels: the frame is run, then colour or depth are converted and packed.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

void Context::read_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  int comps;
  switch (format) {
    case GL_RGBA: case GL_BGRA: comps = 4; break;
    case GL_RGB: case GL_BGR: comps = 3; break;
    case GL_ALPHA: case GL_LUMINANCE: case GL_RED: case GL_GREEN:
    case GL_BLUE: case GL_DEPTH_COMPONENT:
      comps = 1;
      break;
    default: return error(GL_INVALID_ENUM);
  }
  size_t tsize;
  switch (type) {
    case GL_UNSIGNED_BYTE: tsize = 1; break;
    case GL_FLOAT: case GL_UNSIGNED_INT: tsize = 4; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (in_begin_error()) return;
  if (!renderer_ || !pixels || w == 0 || h == 0) return;
  run_frame();
  const bool depth = format == GL_DEPTH_COMPONENT;
  if (depth && depth_bits_ <= 0) return error(GL_INVALID_OPERATION);
  std::vector<float> zbuf;
  if (depth) zbuf = renderer_->window_depth();
  // glPixelStore's pack state (GL 1.5 section 4.3.2): rows of GL_PACK_ROW_LENGTH pixels
  // (or w), padded to the alignment unless a component is as large; skipped rows and
  // pixels first; bytes swapped for 4-byte components.
  const PixelStore& pk = this->pixels.pack;
  const size_t align = size_t(std::max(pack_alignment, 1));
  const size_t length = size_t(pk.row_length > 0 ? pk.row_length : w);
  size_t row_bytes = length * comps * tsize;
  if (tsize < align) row_bytes = (row_bytes + align - 1) / align * align;
  uint8_t* out = static_cast<uint8_t*>(pixels) + size_t(pk.skip_rows) * row_bytes + size_t(pk.skip_pixels) * comps * tsize;
  const bool swap = pk.swap_bytes && tsize > 1;
  for (GLsizei j = 0; j < h; ++j) {
    const int64_t wy = int64_t(y) + j;
    if (wy < 0 || wy >= height_) continue;
    const size_t row = size_t(wy);  // the framebuffer is bottom row first
    for (GLsizei i = 0; i < w; ++i) {
      const int64_t wx = int64_t(x) + i;
      if (wx < 0 || wx >= width_) continue;
      const size_t at = row * size_t(width_) + size_t(wx);
      float c[4];
      if (depth) {
        c[0] = zbuf[at];
      } else {
        const uint8_t* p = colour_rows() + at * 4;
        const float r = p[0] / 255.0f, g = p[1] / 255.0f, b = p[2] / 255.0f;
        const float a = format_ == GL_RGB || format_ == 0x4 ? 1.0f : p[3] / 255.0f;
        switch (format) {
          case GL_RGBA: c[0] = r, c[1] = g, c[2] = b, c[3] = a; break;
          case GL_BGRA: c[0] = b, c[1] = g, c[2] = r, c[3] = a; break;
          case GL_RGB: c[0] = r, c[1] = g, c[2] = b; break;
          case GL_BGR: c[0] = b, c[1] = g, c[2] = r; break;
          case GL_ALPHA: c[0] = a; break;
          case GL_LUMINANCE: c[0] = std::min(1.0f, r + g + b); break;
          case GL_RED: c[0] = r; break;
          case GL_GREEN: c[0] = g; break;
          default: c[0] = b; break;
        }
      }
      uint8_t* dst = out + size_t(j) * row_bytes + size_t(i) * comps * tsize;
      for (int k = 0; k < comps; ++k) {
        if (type == GL_UNSIGNED_BYTE) {
          dst[k] = uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
        } else {
          const uint32_t u = type == GL_FLOAT ? 0u : uint32_t(std::llround(double(std::clamp(c[k], 0.0f, 1.0f)) * 4294967295.0));
          uint8_t bytes[4];
          std::memcpy(bytes, type == GL_FLOAT ? static_cast<const void*>(&c[k]) : &u, 4);
          for (int b = 0; b < 4; ++b) dst[4 * k + b] = bytes[swap ? 3 - b : b];
        }
      }
    }
  }
}

}  // namespace velocity::gl
