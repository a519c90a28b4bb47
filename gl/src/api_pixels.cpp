// The C entry points of the raster position and pixel rectangles (raster_pos.cpp,
// draw_pixels.cpp): glRasterPos, glWindowPos, glBitmap, glDrawPixels, glCopyPixels,
// glPixelZoom, glPixelStore. Client pixels are unpacked when the call is made, with
// the glPixelStore state of that moment, as GL says (a display list keeps the result);
// an error is raised when the command executes, as GL's are for compiled commands.
#include <GL/gl.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "api_entry.hpp"
#include "context.hpp"
#include "pixel_ops.hpp"

using velocity::Vec3;
using velocity::Vec4;
using velocity::gl::Context;
using velocity::gl::entry::compiled;

namespace {

// One glBitmap or glDrawPixels keeps at most this many pixels (GL_OUT_OF_MEMORY past
// it): 4096 x 4096, 256 MB once converted.
constexpr int64_t kMaxPixelRectangle = int64_t(1) << 24;

// Raises `e` when executed (or GL_INVALID_OPERATION between glBegin and glEnd).
void compiled_error(GLenum e) {
  compiled([=](Context& k) {
    if (!k.in_begin_error()) k.error(e);
  });
}

}  // namespace

extern "C" {

void glPolygonStipple(const GLubyte* mask) {
  if (!mask) return;  // (no pattern to read: nothing changes, as in Mesa)
  NOW(if (c.refuses_in_begin()) return;
      const auto rows = velocity::gl::stipple_rows(c.pixels.unpack, mask);
      compiled([=](Context& k) { k.polygon_stipple(rows); }));
}
void glGetPolygonStipple(GLubyte* mask) { NOW(if (c.in_begin_error()) return; c.get_polygon_stipple(mask)); }

void glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { LIST(c.raster_pos({x, y, z, w})); }
void glRasterPos2d(GLdouble x, GLdouble y) { glRasterPos4f(float(x), float(y), 0, 1); }
void glRasterPos2f(GLfloat x, GLfloat y) { glRasterPos4f(x, y, 0, 1); }
void glRasterPos2i(GLint x, GLint y) { glRasterPos4f(float(x), float(y), 0, 1); }
void glRasterPos2s(GLshort x, GLshort y) { glRasterPos4f(x, y, 0, 1); }
void glRasterPos3d(GLdouble x, GLdouble y, GLdouble z) { glRasterPos4f(float(x), float(y), float(z), 1); }
void glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) { glRasterPos4f(x, y, z, 1); }
void glRasterPos3i(GLint x, GLint y, GLint z) { glRasterPos4f(float(x), float(y), float(z), 1); }
void glRasterPos3s(GLshort x, GLshort y, GLshort z) { glRasterPos4f(x, y, z, 1); }
void glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { glRasterPos4f(float(x), float(y), float(z), float(w)); }
void glRasterPos4i(GLint x, GLint y, GLint z, GLint w) { glRasterPos4f(float(x), float(y), float(z), float(w)); }
void glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { glRasterPos4f(x, y, z, w); }
void glRasterPos2dv(const GLdouble* v) { glRasterPos2d(v[0], v[1]); }
void glRasterPos2fv(const GLfloat* v) { glRasterPos2f(v[0], v[1]); }
void glRasterPos2iv(const GLint* v) { glRasterPos2i(v[0], v[1]); }
void glRasterPos2sv(const GLshort* v) { glRasterPos2s(v[0], v[1]); }
void glRasterPos3dv(const GLdouble* v) { glRasterPos3d(v[0], v[1], v[2]); }
void glRasterPos3fv(const GLfloat* v) { glRasterPos3f(v[0], v[1], v[2]); }
void glRasterPos3iv(const GLint* v) { glRasterPos3i(v[0], v[1], v[2]); }
void glRasterPos3sv(const GLshort* v) { glRasterPos3s(v[0], v[1], v[2]); }
void glRasterPos4dv(const GLdouble* v) { glRasterPos4d(v[0], v[1], v[2], v[3]); }
void glRasterPos4fv(const GLfloat* v) { glRasterPos4f(v[0], v[1], v[2], v[3]); }
void glRasterPos4iv(const GLint* v) { glRasterPos4i(v[0], v[1], v[2], v[3]); }
void glRasterPos4sv(const GLshort* v) { glRasterPos4s(v[0], v[1], v[2], v[3]); }

void glWindowPos3f(GLfloat x, GLfloat y, GLfloat z) { LIST(c.window_pos({x, y, z})); }
void glWindowPos2d(GLdouble x, GLdouble y) { glWindowPos3f(float(x), float(y), 0); }
void glWindowPos2f(GLfloat x, GLfloat y) { glWindowPos3f(x, y, 0); }
void glWindowPos2i(GLint x, GLint y) { glWindowPos3f(float(x), float(y), 0); }
void glWindowPos2s(GLshort x, GLshort y) { glWindowPos3f(x, y, 0); }
void glWindowPos3d(GLdouble x, GLdouble y, GLdouble z) { glWindowPos3f(float(x), float(y), float(z)); }
void glWindowPos3i(GLint x, GLint y, GLint z) { glWindowPos3f(float(x), float(y), float(z)); }
void glWindowPos3s(GLshort x, GLshort y, GLshort z) { glWindowPos3f(x, y, z); }
void glWindowPos2dv(const GLdouble* v) { glWindowPos2d(v[0], v[1]); }
void glWindowPos2fv(const GLfloat* v) { glWindowPos2f(v[0], v[1]); }
void glWindowPos2iv(const GLint* v) { glWindowPos2i(v[0], v[1]); }
void glWindowPos2sv(const GLshort* v) { glWindowPos2s(v[0], v[1]); }
void glWindowPos3dv(const GLdouble* v) { glWindowPos3d(v[0], v[1], v[2]); }
void glWindowPos3fv(const GLfloat* v) { glWindowPos3f(v[0], v[1], v[2]); }
void glWindowPos3iv(const GLint* v) { glWindowPos3i(v[0], v[1], v[2]); }
void glWindowPos3sv(const GLshort* v) { glWindowPos3s(v[0], v[1], v[2]); }

// GL_ARB_window_pos: the same calls under their ARB names.
void glWindowPos2dARB(GLdouble x, GLdouble y) { glWindowPos2d(x, y); }
void glWindowPos2fARB(GLfloat x, GLfloat y) { glWindowPos2f(x, y); }
void glWindowPos2iARB(GLint x, GLint y) { glWindowPos2i(x, y); }
void glWindowPos2sARB(GLshort x, GLshort y) { glWindowPos2s(x, y); }
void glWindowPos3dARB(GLdouble x, GLdouble y, GLdouble z) { glWindowPos3d(x, y, z); }
void glWindowPos3fARB(GLfloat x, GLfloat y, GLfloat z) { glWindowPos3f(x, y, z); }
void glWindowPos3iARB(GLint x, GLint y, GLint z) { glWindowPos3i(x, y, z); }
void glWindowPos3sARB(GLshort x, GLshort y, GLshort z) { glWindowPos3s(x, y, z); }
void glWindowPos2dvARB(const GLdouble* v) { glWindowPos2dv(v); }
void glWindowPos2fvARB(const GLfloat* v) { glWindowPos2fv(v); }
void glWindowPos2ivARB(const GLint* v) { glWindowPos2iv(v); }
void glWindowPos2svARB(const GLshort* v) { glWindowPos2sv(v); }
void glWindowPos3dvARB(const GLdouble* v) { glWindowPos3dv(v); }
void glWindowPos3fvARB(const GLfloat* v) { glWindowPos3fv(v); }
void glWindowPos3ivARB(const GLint* v) { glWindowPos3iv(v); }
void glWindowPos3svARB(const GLshort* v) { glWindowPos3sv(v); }

void glBitmap(GLsizei w, GLsizei h, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove, const GLubyte* bitmap) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (w < 0 || h < 0) return compiled_error(GL_INVALID_VALUE);
      if (int64_t(w) * h > kMaxPixelRectangle) return compiled_error(GL_OUT_OF_MEMORY);
      std::shared_ptr<const std::vector<uint8_t>> bits;
      if (bitmap) bits = std::make_shared<const std::vector<uint8_t>>(velocity::gl::unpack_bitmap(w, h, c.pixels.unpack, bitmap));
      compiled([=](Context& k) { k.bitmap(w, h, xorig, yorig, xmove, ymove, bits.get()); }));
}

void glDrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (w < 0 || h < 0) return compiled_error(GL_INVALID_VALUE);
      // (Colour index mode is not implemented: docs/gl.md.)
      const bool stencil = format == GL_STENCIL_INDEX;
      // GL_EXT_packed_depth_stencil: depth and stencil in one word (draw_pixels.cpp).
      if (const GLenum e = velocity::gl::check_depth_stencil(format, type)) return compiled_error(e);
      if (format == velocity::gl::kDepthStencilFormat) {
        if (int64_t(w) * h > kMaxPixelRectangle) return compiled_error(GL_OUT_OF_MEMORY);
        auto depth = std::make_shared<std::vector<Vec4>>();
        auto indices = std::make_shared<std::vector<uint8_t>>();
        velocity::gl::unpack_depth_stencil(w, h, c.pixels.unpack, pixels, c.pixels.transfer, *depth, *indices);
        return compiled([=](Context& k) { k.draw_depth_stencil_pixels(w, h, *depth, *indices); });
      }
      if (const GLenum e = stencil ? velocity::gl::check_stencil_type(type) : velocity::gl::check_draw_format(format, type))
        return compiled_error(e);
      if (int64_t(w) * h > kMaxPixelRectangle) return compiled_error(GL_OUT_OF_MEMORY);
      if (!pixels) return compiled([](Context& k) { k.in_begin_error(); });
      if (stencil) {
        auto indices = std::make_shared<const std::vector<uint8_t>>(
            velocity::gl::unpack_stencil(type, w, h, c.pixels.unpack, pixels, c.pixels.transfer));
        return compiled([=](Context& k) { k.draw_stencil_pixels(w, h, *indices); });
      }
      auto image = std::make_shared<const std::vector<Vec4>>(
          velocity::gl::unpack_pixels(format, type, w, h, c.pixels.unpack, pixels, c.pixels.transfer));
      compiled([=](Context& k) { k.draw_pixels(w, h, format, *image); }));
}

void glCopyPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type) { LIST(c.copy_pixels(x, y, w, h, type)); }
void glPixelZoom(GLfloat x, GLfloat y) { LIST(c.pixel_zoom(x, y)); }
void glPixelTransferf(GLenum pname, GLfloat v) { LIST(c.pixel_transfer(pname, double(v))); }
void glPixelTransferi(GLenum pname, GLint v) { LIST(c.pixel_transfer(pname, double(v))); }

// glPixelMap: the values converted when called (unsigned ints and shorts of a colour
// table as fractions of their maximum, of an index table as they are), so a display
// list keeps them; a size beyond the largest table is refused before anything is read.
}  // extern "C"
namespace {
bool colour_map(GLenum map) { return map >= GL_PIXEL_MAP_I_TO_R && map <= GL_PIXEL_MAP_A_TO_A; }

template <class T>
void pixel_map(GLenum map, GLsizei size, const T* values, double max) {
  NOW(if (size < 1 || size > velocity::gl::kMaxPixelMap) {
        if (!c.in_begin_error()) c.error(GL_INVALID_VALUE);
        return;
      } if (!values) return;
      std::vector<float> v(static_cast<size_t>(size));
      const double unit = colour_map(map) ? max : 1.0;
      for (size_t i = 0; i < v.size(); ++i) v[i] = float(double(values[i]) / unit);
      velocity::gl::entry::compiled([=](Context& x) { x.pixel_map(map, v); }));
}

template <class T, class Convert>
void get_pixel_map(GLenum map, T* values, Convert convert) {
  NOW(std::vector<float> out; bool colour = false; if (!c.get_pixel_map(map, out, &colour) || !values) return;
      for (size_t i = 0; i < out.size(); ++i) values[i] = convert(out[i], colour));
}
}  // namespace
extern "C" {

void glPixelMapfv(GLenum map, GLsizei size, const GLfloat* values) { pixel_map(map, size, values, 1.0); }
void glPixelMapuiv(GLenum map, GLsizei size, const GLuint* values) { pixel_map(map, size, values, 4294967295.0); }
void glPixelMapusv(GLenum map, GLsizei size, const GLushort* values) { pixel_map(map, size, values, 65535.0); }
void glGetPixelMapfv(GLenum map, GLfloat* values) {
  get_pixel_map(map, values, [](float v, bool) { return v; });
}
void glGetPixelMapuiv(GLenum map, GLuint* values) {
  get_pixel_map(map, values, [](float v, bool colour) {
    return colour ? GLuint(std::lround(double(v) * 4294967295.0)) : GLuint(GLint(std::lround(v)));
  });
}
void glGetPixelMapusv(GLenum map, GLushort* values) {
  get_pixel_map(map, values, [](float v, bool colour) {
    return colour ? GLushort(std::lround(v * 65535.0f)) : GLushort(GLint(std::lround(v)));
  });
}
void glPixelStoref(GLenum pname, GLfloat v) {
  // A float count is rounded to the nearest integer, halves away from zero as Mesa
  // does (-0.5 is -1: GL_INVALID_VALUE); a boolean is true when non-zero.
  NOW(c.pixel_store(pname, pname == GL_UNPACK_SWAP_BYTES || pname == GL_UNPACK_LSB_FIRST || pname == GL_PACK_SWAP_BYTES ||
                                   pname == GL_PACK_LSB_FIRST
                               ? double(v != 0)
                               : std::round(double(v))));
}

}  // extern "C"
