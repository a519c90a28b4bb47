// The C entry points of one-dimensional evaluators (evaluators.cpp). glMap1 copies the
// control points (each `stride` values apart) when it is called, so a display list
// keeps them; the evaluation calls are compiled as glVertex is.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "api_entry.hpp"
#include "context.hpp"

using velocity::gl::Context;

namespace {
template <class T>
void map1(GLenum target, T u1, T u2, GLint stride, GLint order, const T* points) {
  NOW(const int k = Context::map1_components(target); if (!k) return c.error(GL_INVALID_ENUM);
      if (u1 == u2 || stride < k || order < 1 || order > velocity::gl::kMaxEvalOrder) return c.error(GL_INVALID_VALUE);
      if (!points) return;
      std::vector<float> p(size_t(order) * size_t(k));
      for (GLint i = 0; i < order; ++i)
        for (int j = 0; j < k; ++j) p[size_t(i) * size_t(k) + size_t(j)] = float(points[size_t(i) * size_t(stride) + size_t(j)]);
      const float a = float(u1), b = float(u2);
      velocity::gl::entry::compiled([=](Context& x) { x.map1(target, a, b, stride, order, p); }));
}

template <class T, class Convert>
void get_map(GLenum target, GLenum query, T* v, Convert convert) {
  NOW(if (c.in_begin_error()) return; std::vector<double> out; if (!c.get_map1(target, query, out) || !v) return;
      for (size_t i = 0; i < out.size(); ++i) v[i] = convert(out[i]));
}
}  // namespace

extern "C" {

void glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order, const GLfloat* points) {
  map1(target, u1, u2, stride, order, points);
}
void glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order, const GLdouble* points) {
  map1(target, u1, u2, stride, order, points);
}
void glEvalCoord1f(GLfloat u) { LIST(c.eval_coord1(u)); }
void glEvalCoord1d(GLdouble u) { glEvalCoord1f(GLfloat(u)); }
void glEvalCoord1fv(const GLfloat* u) {
  if (u) glEvalCoord1f(u[0]);
}
void glEvalCoord1dv(const GLdouble* u) {
  if (u) glEvalCoord1f(GLfloat(u[0]));
}
void glMapGrid1f(GLint n, GLfloat u1, GLfloat u2) { LIST(c.map_grid1(n, u1, u2)); }
void glMapGrid1d(GLint n, GLdouble u1, GLdouble u2) { glMapGrid1f(n, GLfloat(u1), GLfloat(u2)); }
void glEvalMesh1(GLenum mode, GLint i1, GLint i2) { LIST(c.eval_mesh1(mode, i1, i2)); }
void glEvalPoint1(GLint i) { LIST(c.eval_coord1(c.grid_u(i))); }
void glGetMapfv(GLenum target, GLenum query, GLfloat* v) {
  get_map(target, query, v, [](double d) { return GLfloat(d); });
}
void glGetMapdv(GLenum target, GLenum query, GLdouble* v) {
  get_map(target, query, v, [](double d) { return d; });
}
void glGetMapiv(GLenum target, GLenum query, GLint* v) {
  get_map(target, query, v, [](double d) { return GLint(std::lround(d)); });
}

}  // extern "C"
