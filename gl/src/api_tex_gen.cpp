// The C entry points of texture coordinate generation (tex_gen.cpp): glTexGen (compiled
// into display lists) and glGetTexGen. glEnable(GL_TEXTURE_GEN_S..Q) goes through
// glEnable.
#include <GL/gl.h>

#include <array>

#include "api_entry.hpp"
#include "context.hpp"

namespace {

// glTexGen's parameters as doubles: four for the planes, one for the mode (a null
// pointer is GL_INVALID_VALUE, raised by the caller).
template <class T>
std::array<double, 4> tex_gen_params(GLenum pname, const T* v) {
  std::array<double, 4> p{};
  const int n = pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE ? 4 : 1;
  for (int i = 0; i < n; ++i) p[size_t(i)] = double(v[i]);
  return p;
}

template <class T>
void tex_gen_v(GLenum coord, GLenum pname, const T* v) {
  if (!v) return NOW(c.error(GL_INVALID_VALUE));
  const auto p = tex_gen_params(pname, v);
  LIST(c.tex_gen(coord, pname, p.data()));
}

template <class T>
void tex_gen_1(GLenum coord, GLenum pname, T v) {
  // The one-value forms: GL names only the mode for them; a plane given so is
  // (v 0 0 0), as Mesa takes it.
  const std::array<double, 4> p = {double(v), 0, 0, 0};
  LIST(c.tex_gen(coord, pname, p.data()));
}

template <class T>
void get_tex_gen(GLenum coord, GLenum pname, T* out) {
  NOW(if (c.in_begin_error()) return; double v[4]; int n = 0;
      if (!c.get_tex_gen(coord, pname, v, &n)) return c.error(GL_INVALID_ENUM);
      // (glGetTexGeniv truncates a plane's values, as Mesa's does.)
      if (out) for (int i = 0; i < n; ++i) out[i] = T(v[i]));
}

}  // namespace

extern "C" {

void glTexGend(GLenum coord, GLenum pname, GLdouble param) { tex_gen_1(coord, pname, param); }
void glTexGenf(GLenum coord, GLenum pname, GLfloat param) { tex_gen_1(coord, pname, param); }
void glTexGeni(GLenum coord, GLenum pname, GLint param) { tex_gen_1(coord, pname, param); }
void glTexGendv(GLenum coord, GLenum pname, const GLdouble* params) { tex_gen_v(coord, pname, params); }
void glTexGenfv(GLenum coord, GLenum pname, const GLfloat* params) { tex_gen_v(coord, pname, params); }
void glTexGeniv(GLenum coord, GLenum pname, const GLint* params) { tex_gen_v(coord, pname, params); }
void glGetTexGendv(GLenum coord, GLenum pname, GLdouble* params) { get_tex_gen(coord, pname, params); }
void glGetTexGenfv(GLenum coord, GLenum pname, GLfloat* params) { get_tex_gen(coord, pname, params); }
void glGetTexGeniv(GLenum coord, GLenum pname, GLint* params) { get_tex_gen(coord, pname, params); }

}  // extern "C"
