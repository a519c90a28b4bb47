// The C entry points of GL 1.3's multitexture (multitexture.cpp), under their core and
// ARB_multitexture names. glActiveTexture and glMultiTexCoord* are compiled into display
// lists; glClientActiveTexture, client state, never is.
#include <GL/gl.h>

#include "api_entry.hpp"
#include "context.hpp"

using velocity::Vec4;

namespace {
void coord(GLenum target, Vec4 t) { LIST(c.multi_tex_coord(target, t)); }
}  // namespace

extern "C" {

void glActiveTexture(GLenum texture) { LIST(c.active_texture(texture)); }
void glClientActiveTexture(GLenum texture) { NOW(c.client_active_texture(texture)); }
void glActiveTextureARB(GLenum texture) { glActiveTexture(texture); }
void glClientActiveTextureARB(GLenum texture) { glClientActiveTexture(texture); }

void glMultiTexCoord1s(GLenum target, GLshort s) { coord(target, {float(s), 0.0f, 0.0f, 1.0f}); }
void glMultiTexCoord1sv(GLenum target, const GLshort* v) {
  if (v) coord(target, {float(v[0]), 0.0f, 0.0f, 1.0f});
}
void glMultiTexCoord1i(GLenum target, GLint s) { coord(target, {float(s), 0.0f, 0.0f, 1.0f}); }
void glMultiTexCoord1iv(GLenum target, const GLint* v) {
  if (v) coord(target, {float(v[0]), 0.0f, 0.0f, 1.0f});
}
void glMultiTexCoord1f(GLenum target, GLfloat s) { coord(target, {s, 0.0f, 0.0f, 1.0f}); }
void glMultiTexCoord1fv(GLenum target, const GLfloat* v) {
  if (v) coord(target, {v[0], 0.0f, 0.0f, 1.0f});
}
void glMultiTexCoord1d(GLenum target, GLdouble s) { coord(target, {float(s), 0.0f, 0.0f, 1.0f}); }
void glMultiTexCoord1dv(GLenum target, const GLdouble* v) {
  if (v) coord(target, {float(v[0]), 0.0f, 0.0f, 1.0f});
}
void glMultiTexCoord2s(GLenum target, GLshort s, GLshort t) { coord(target, {float(s), float(t), 0.0f, 1.0f}); }
void glMultiTexCoord2sv(GLenum target, const GLshort* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), 0.0f, 1.0f});
}
void glMultiTexCoord2i(GLenum target, GLint s, GLint t) { coord(target, {float(s), float(t), 0.0f, 1.0f}); }
void glMultiTexCoord2iv(GLenum target, const GLint* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), 0.0f, 1.0f});
}
void glMultiTexCoord2f(GLenum target, GLfloat s, GLfloat t) { coord(target, {s, t, 0.0f, 1.0f}); }
void glMultiTexCoord2fv(GLenum target, const GLfloat* v) {
  if (v) coord(target, {v[0], v[1], 0.0f, 1.0f});
}
void glMultiTexCoord2d(GLenum target, GLdouble s, GLdouble t) { coord(target, {float(s), float(t), 0.0f, 1.0f}); }
void glMultiTexCoord2dv(GLenum target, const GLdouble* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), 0.0f, 1.0f});
}
void glMultiTexCoord3s(GLenum target, GLshort s, GLshort t, GLshort r) { coord(target, {float(s), float(t), float(r), 1.0f}); }
void glMultiTexCoord3sv(GLenum target, const GLshort* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), 1.0f});
}
void glMultiTexCoord3i(GLenum target, GLint s, GLint t, GLint r) { coord(target, {float(s), float(t), float(r), 1.0f}); }
void glMultiTexCoord3iv(GLenum target, const GLint* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), 1.0f});
}
void glMultiTexCoord3f(GLenum target, GLfloat s, GLfloat t, GLfloat r) { coord(target, {s, t, r, 1.0f}); }
void glMultiTexCoord3fv(GLenum target, const GLfloat* v) {
  if (v) coord(target, {v[0], v[1], v[2], 1.0f});
}
void glMultiTexCoord3d(GLenum target, GLdouble s, GLdouble t, GLdouble r) { coord(target, {float(s), float(t), float(r), 1.0f}); }
void glMultiTexCoord3dv(GLenum target, const GLdouble* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), 1.0f});
}
void glMultiTexCoord4s(GLenum target, GLshort s, GLshort t, GLshort r, GLshort q) { coord(target, {float(s), float(t), float(r), float(q)}); }
void glMultiTexCoord4sv(GLenum target, const GLshort* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), float(v[3])});
}
void glMultiTexCoord4i(GLenum target, GLint s, GLint t, GLint r, GLint q) { coord(target, {float(s), float(t), float(r), float(q)}); }
void glMultiTexCoord4iv(GLenum target, const GLint* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), float(v[3])});
}
void glMultiTexCoord4f(GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { coord(target, {s, t, r, q}); }
void glMultiTexCoord4fv(GLenum target, const GLfloat* v) {
  if (v) coord(target, {v[0], v[1], v[2], v[3]});
}
void glMultiTexCoord4d(GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q) { coord(target, {float(s), float(t), float(r), float(q)}); }
void glMultiTexCoord4dv(GLenum target, const GLdouble* v) {
  if (v) coord(target, {float(v[0]), float(v[1]), float(v[2]), float(v[3])});
}

void glMultiTexCoord1sARB(GLenum target, GLshort s) { glMultiTexCoord1s(target, s); }
void glMultiTexCoord1svARB(GLenum target, const GLshort* v) { glMultiTexCoord1sv(target, v); }
void glMultiTexCoord1iARB(GLenum target, GLint s) { glMultiTexCoord1i(target, s); }
void glMultiTexCoord1ivARB(GLenum target, const GLint* v) { glMultiTexCoord1iv(target, v); }
void glMultiTexCoord1fARB(GLenum target, GLfloat s) { glMultiTexCoord1f(target, s); }
void glMultiTexCoord1fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord1fv(target, v); }
void glMultiTexCoord1dARB(GLenum target, GLdouble s) { glMultiTexCoord1d(target, s); }
void glMultiTexCoord1dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord1dv(target, v); }
void glMultiTexCoord2sARB(GLenum target, GLshort s, GLshort t) { glMultiTexCoord2s(target, s, t); }
void glMultiTexCoord2svARB(GLenum target, const GLshort* v) { glMultiTexCoord2sv(target, v); }
void glMultiTexCoord2iARB(GLenum target, GLint s, GLint t) { glMultiTexCoord2i(target, s, t); }
void glMultiTexCoord2ivARB(GLenum target, const GLint* v) { glMultiTexCoord2iv(target, v); }
void glMultiTexCoord2fARB(GLenum target, GLfloat s, GLfloat t) { glMultiTexCoord2f(target, s, t); }
void glMultiTexCoord2fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord2fv(target, v); }
void glMultiTexCoord2dARB(GLenum target, GLdouble s, GLdouble t) { glMultiTexCoord2d(target, s, t); }
void glMultiTexCoord2dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord2dv(target, v); }
void glMultiTexCoord3sARB(GLenum target, GLshort s, GLshort t, GLshort r) { glMultiTexCoord3s(target, s, t, r); }
void glMultiTexCoord3svARB(GLenum target, const GLshort* v) { glMultiTexCoord3sv(target, v); }
void glMultiTexCoord3iARB(GLenum target, GLint s, GLint t, GLint r) { glMultiTexCoord3i(target, s, t, r); }
void glMultiTexCoord3ivARB(GLenum target, const GLint* v) { glMultiTexCoord3iv(target, v); }
void glMultiTexCoord3fARB(GLenum target, GLfloat s, GLfloat t, GLfloat r) { glMultiTexCoord3f(target, s, t, r); }
void glMultiTexCoord3fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord3fv(target, v); }
void glMultiTexCoord3dARB(GLenum target, GLdouble s, GLdouble t, GLdouble r) { glMultiTexCoord3d(target, s, t, r); }
void glMultiTexCoord3dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord3dv(target, v); }
void glMultiTexCoord4sARB(GLenum target, GLshort s, GLshort t, GLshort r, GLshort q) { glMultiTexCoord4s(target, s, t, r, q); }
void glMultiTexCoord4svARB(GLenum target, const GLshort* v) { glMultiTexCoord4sv(target, v); }
void glMultiTexCoord4iARB(GLenum target, GLint s, GLint t, GLint r, GLint q) { glMultiTexCoord4i(target, s, t, r, q); }
void glMultiTexCoord4ivARB(GLenum target, const GLint* v) { glMultiTexCoord4iv(target, v); }
void glMultiTexCoord4fARB(GLenum target, GLfloat s, GLfloat t, GLfloat r, GLfloat q) { glMultiTexCoord4f(target, s, t, r, q); }
void glMultiTexCoord4fvARB(GLenum target, const GLfloat* v) { glMultiTexCoord4fv(target, v); }
void glMultiTexCoord4dARB(GLenum target, GLdouble s, GLdouble t, GLdouble r, GLdouble q) { glMultiTexCoord4d(target, s, t, r, q); }
void glMultiTexCoord4dvARB(GLenum target, const GLdouble* v) { glMultiTexCoord4dv(target, v); }

}  // extern "C"
