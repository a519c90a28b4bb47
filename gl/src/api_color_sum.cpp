// The C entry points of GL 1.4's secondary colour and fog coordinates (color_sum.cpp),
// and glIndexPointer's state. glSecondaryColor* and glFogCoord* are compiled into
// display lists; the pointers never are.
#include <GL/gl.h>

#include <cstdint>
#include <limits>
#include <type_traits>

#include "api_entry.hpp"
#include "context.hpp"

using velocity::Vec4;
using velocity::gl::Context;

namespace {

// GL's integer-to-float conversion of colour components (GL 1.5 table 2.9): unsigned
// v / max, signed (2v + 1) / (2^bits - 1).
template <class T>
float color_component(T v) {
  if constexpr (std::is_floating_point_v<T>) {
    return float(v);
  } else {
    constexpr double max = double(std::numeric_limits<T>::max());
    if constexpr (std::is_signed_v<T>) return float((2.0 * double(v) + 1.0) / (2.0 * max + 1.0));
    return float(double(v) / max);
  }
}

template <class T>
void secondary(T r, T g, T b) {
  const Vec4 col{color_component(r), color_component(g), color_component(b), 1};
  LIST(c.set_secondary_color(col));
}
template <class T>
void secondary_v(const T* v) {
  if (v) secondary(v[0], v[1], v[2]);
}

// glSecondaryColorPointer's, glFogCoordPointer's and glIndexPointer's types.
bool secondary_type(GLenum t) {
  switch (t) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_INT: case GL_UNSIGNED_INT:
    case GL_FLOAT: case GL_DOUBLE:
      return true;
    default: return false;
  }
}
bool index_type(GLenum t) {
  return t == GL_UNSIGNED_BYTE || t == GL_SHORT || t == GL_INT || t == GL_FLOAT || t == GL_DOUBLE;
}

// With a buffer bound to GL_ARRAY_BUFFER, `p` is an offset into it (GL 1.5).
void set_array(Context& c, velocity::gl::ClientArray& a, GLint size, GLenum type, GLsizei stride, const void* p) {
  a.size = size, a.type = type, a.stride = stride, a.pointer = p;
  a.buffer = c.arrays.array_buffer;
}

}  // namespace

extern "C" {

void glSecondaryColor3b(GLbyte r, GLbyte g, GLbyte b) { secondary(r, g, b); }
void glSecondaryColor3bv(const GLbyte* v) { secondary_v(v); }
void glSecondaryColor3d(GLdouble r, GLdouble g, GLdouble b) { secondary(r, g, b); }
void glSecondaryColor3dv(const GLdouble* v) { secondary_v(v); }
void glSecondaryColor3f(GLfloat r, GLfloat g, GLfloat b) { secondary(r, g, b); }
void glSecondaryColor3fv(const GLfloat* v) { secondary_v(v); }
void glSecondaryColor3i(GLint r, GLint g, GLint b) { secondary(r, g, b); }
void glSecondaryColor3iv(const GLint* v) { secondary_v(v); }
void glSecondaryColor3s(GLshort r, GLshort g, GLshort b) { secondary(r, g, b); }
void glSecondaryColor3sv(const GLshort* v) { secondary_v(v); }
void glSecondaryColor3ub(GLubyte r, GLubyte g, GLubyte b) { secondary(r, g, b); }
void glSecondaryColor3ubv(const GLubyte* v) { secondary_v(v); }
void glSecondaryColor3ui(GLuint r, GLuint g, GLuint b) { secondary(r, g, b); }
void glSecondaryColor3uiv(const GLuint* v) { secondary_v(v); }
void glSecondaryColor3us(GLushort r, GLushort g, GLushort b) { secondary(r, g, b); }
void glSecondaryColor3usv(const GLushort* v) { secondary_v(v); }

void glFogCoordf(GLfloat f) { LIST(c.set_fog_coord(f)); }
void glFogCoordfv(const GLfloat* f) {
  if (f) glFogCoordf(*f);
}
void glFogCoordd(GLdouble f) { glFogCoordf(float(f)); }
void glFogCoorddv(const GLdouble* f) {
  if (f) glFogCoordf(float(*f));
}

// GL 1.4: the secondary colour array has 3 components (else GL_INVALID_VALUE).
void glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (size != 3 || stride < 0) return c.error(GL_INVALID_VALUE); if (!secondary_type(type)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.secondary_color, size, type, stride, p));
}
void glFogCoordPointer(GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (stride < 0) return c.error(GL_INVALID_VALUE);
      if (type != GL_FLOAT && type != GL_DOUBLE) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.fog_coord, 1, type, stride, p));
}
// Colour index mode does not exist: the array's state is kept and reported, never drawn.
void glIndexPointer(GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (stride < 0) return c.error(GL_INVALID_VALUE); if (!index_type(type)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.index, 1, type, stride, p));
}

}  // extern "C"
