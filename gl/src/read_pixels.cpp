// glReadPixels: the frame is run, then colour, depth or stencil are converted and packed.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
// A stencil index in a pixel type, as it is (GL: indices are not scaled).
void write_index(uint8_t v, GLenum type, uint8_t* dst) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: *dst = v; break;  // (GL_BYTE: 127 is the most it holds)
    case GL_UNSIGNED_SHORT: case GL_SHORT: { const uint16_t u = v; std::memcpy(dst, &u, 2); break; }
    case GL_FLOAT: { const float f = v; std::memcpy(dst, &f, 4); break; }
    default: { const uint32_t u = v; std::memcpy(dst, &u, 4); break; }
  }
  if (type == GL_BYTE && v > 127) *dst = 127;
}

// A component in [0, 1] as GL's signed and 16-bit types hold it (the table of GL
// 1.5's section 4.3.2): unsigned 2^n - 1 c, signed (2^n - 1) c - 1) / 2.
void write_normalized(float c, GLenum type, uint8_t* dst) {
  c = std::clamp(c, 0.0f, 1.0f);
  switch (type) {
    case GL_BYTE: *dst = uint8_t(int8_t(std::lround((255.0 * c - 1) / 2))); break;
    case GL_UNSIGNED_SHORT: { const uint16_t u = uint16_t(std::lround(65535.0 * c)); std::memcpy(dst, &u, 2); break; }
    case GL_SHORT: { const int16_t u = int16_t(std::lround((65535.0 * c - 1) / 2)); std::memcpy(dst, &u, 2); break; }
    default: { const int32_t u = int32_t(std::llround((4294967295.0 * c - 1) / 2)); std::memcpy(dst, &u, 4); break; }  // GL_INT
  }
}
}  // namespace

void Context::read_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (const GLenum e = check_depth_stencil(format, type)) return error(e);  // (pixel_unpack.cpp)
  // GL_EXT_packed_depth_stencil: one 32-bit word a pixel, its depth and stencil.
  const bool depth_stencil = format == kDepthStencilFormat;
  int comps;
  switch (format) {
    case kDepthStencilFormat: comps = 1; break;
    case GL_RGBA: case GL_BGRA: comps = 4; break;
    case GL_RGB: case GL_BGR: comps = 3; break;
    case GL_LUMINANCE_ALPHA: comps = 2; break;
    case GL_ALPHA: case GL_LUMINANCE: case GL_RED: case GL_GREEN:
    case GL_BLUE: case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX:
      comps = 1;
      break;
    default: return error(GL_INVALID_ENUM);
  }
  size_t tsize;
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: tsize = 1; break;
    case GL_UNSIGNED_SHORT: case GL_SHORT: tsize = 2; break;
    case GL_FLOAT: case GL_UNSIGNED_INT: case GL_INT: case kUnsignedInt24_8: tsize = 4; break;
    default:
      tsize = size_t(packed_type_bytes(type));  // GL 1.2's packed types, one element a pixel
      if (!tsize) return error(GL_INVALID_ENUM);
      // Their number of components must be the format's (three: GL_RGB or GL_BGR).
      if (check_draw_format(format, type) != GL_NO_ERROR) return error(GL_INVALID_OPERATION);
  }
  const bool packed = packed_type_bytes(type) != 0;
  const size_t group = packed ? tsize : size_t(comps) * tsize;  // bytes a pixel
  if (in_begin_error() || read_framebuffer_incomplete()) return;
  if (fb_.read != fb_.in_use) {  // GL_READ_FRAMEBUFFER is another framebuffer (framebuffer_objects.cpp)
    use_read_framebuffer();
    read_pixels(x, y, w, h, format, type, pixels);
    return use_draw_framebuffer();
  }
  if (!renderer_ || !pixels || w == 0 || h == 0) return;
  run_frame();
  const bool depth = format == GL_DEPTH_COMPONENT || depth_stencil, stencil = format == GL_STENCIL_INDEX || depth_stencil;
  if (depth && depth_bits_ <= 0) return error(GL_INVALID_OPERATION);
  if (stencil && stencil_bits_ <= 0) return error(GL_INVALID_OPERATION);
  if (!depth && !stencil && no_read_buffer()) return;  // glReadBuffer(GL_NONE)
  std::vector<float> zbuf;
  if (depth) zbuf = renderer_->window_depth();
  std::vector<uint8_t> sbuf;
  if (stencil) {
    sbuf.resize(size_t(width_) * size_t(height_));
    renderer_->read_stencil(sbuf.data());
  }
  // glPixelStore's pack state (GL 1.5 section 4.3.2): rows of GL_PACK_ROW_LENGTH pixels
  // (or w), padded to the alignment unless a component is as large; skipped rows and
  // pixels first; bytes swapped for components of 2 and 4 bytes.
  const PixelStore& pk = this->pixels.pack;
  const size_t align = size_t(std::max(pack_alignment, 1));
  const size_t length = size_t(pk.row_length > 0 ? pk.row_length : w);
  size_t row_bytes = length * group;
  if (tsize < align) row_bytes = (row_bytes + align - 1) / align * align;
  uint8_t* out = static_cast<uint8_t*>(pixels) + size_t(pk.skip_rows) * row_bytes + size_t(pk.skip_pixels) * group;
  const bool swap = pk.swap_bytes && tsize > 1;
  for (GLsizei j = 0; j < h; ++j) {
    const int64_t wy = int64_t(y) + j;
    if (wy < 0 || wy >= height_) continue;
    const size_t row = size_t(wy);  // the framebuffer is bottom row first
    for (GLsizei i = 0; i < w; ++i) {
      const int64_t wx = int64_t(x) + i;
      if (wx < 0 || wx >= width_) continue;
      const size_t at = row * size_t(width_) + size_t(wx);
      float c[4] = {0, 0, 0, 0};
      if (depth) {
        c[0] = zbuf[at];
      } else if (!stencil) {
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
          case GL_LUMINANCE_ALPHA: c[0] = std::min(1.0f, r + g + b), c[1] = a; break;
          case GL_RED: c[0] = r; break;
          case GL_GREEN: c[0] = g; break;
          default: c[0] = b; break;
        }
      }
      uint8_t* dst = out + size_t(j) * row_bytes + size_t(i) * group;
      if (depth_stencil) {  // 24 bits of depth above 8 of stencil
        const double d = std::clamp(double(zbuf[at]), 0.0, 1.0);
        const uint32_t word = uint32_t(std::lround(d * 16777215.0)) << 8 | sbuf[at];
        uint8_t bytes[4];
        std::memcpy(bytes, &word, 4);
        for (int b = 0; b < 4; ++b) dst[b] = bytes[swap ? 3 - b : b];
        continue;
      }
      if (stencil) {  // an index: its value in any type, not scaled
        write_index(sbuf[at], type, dst);
        if (swap) std::reverse(dst, dst + tsize);
        continue;
      }
      if (packed) {
        pack_packed(type, c, dst, swap);
        continue;
      }
      for (int k = 0; k < comps; ++k) {
        if (type == GL_UNSIGNED_BYTE) {
          dst[k] = uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
        } else if (type != GL_FLOAT && type != GL_UNSIGNED_INT) {
          uint8_t* d = dst + tsize * k;
          write_normalized(c[k], type, d);
          if (swap) std::reverse(d, d + tsize);
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
