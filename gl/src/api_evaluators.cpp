// The C entry points of the evaluators (evaluators.cpp). glMap1 and glMap2 copy the
// control points (each `stride` values apart) when they are called, so a display list
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

template <class T>
void map2(GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2, GLint vstride, GLint vorder,
          const T* points) {
  using velocity::gl::kMaxEvalOrder;
  NOW(const int k = Context::map2_components(target); if (!k) return c.error(GL_INVALID_ENUM);
      if (u1 == u2 || v1 == v2 || ustride < k || vstride < k || uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 ||
          vorder > kMaxEvalOrder)
        return c.error(GL_INVALID_VALUE);
      if (!points) return;
      velocity::gl::Map2 m;
      m.u1 = float(u1), m.u2 = float(u2), m.v1 = float(v1), m.v2 = float(v2), m.uorder = uorder, m.vorder = vorder;
      m.points.resize(size_t(uorder) * size_t(vorder) * size_t(k));
      for (GLint i = 0; i < uorder; ++i) for (GLint j = 0; j < vorder; ++j) for (int n = 0; n < k; ++n)
        m.points[(size_t(i) * size_t(vorder) + size_t(j)) * size_t(k) + size_t(n)] =
            float(points[size_t(i) * size_t(ustride) + size_t(j) * size_t(vstride) + size_t(n)]);
      velocity::gl::entry::compiled([=](Context& x) { x.map2(target, m, ustride, vstride); }));
}

template <class T, class Convert>
void get_map(GLenum target, GLenum query, T* v, Convert convert) {
  NOW(if (c.in_begin_error()) return; std::vector<double> out; if (!c.get_map(target, query, out) || !v) return;
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
void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride,
             GLint vorder, const GLfloat* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder, GLdouble v1, GLdouble v2,
             GLint vstride, GLint vorder, const GLdouble* points) {
  map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void glEvalCoord2f(GLfloat u, GLfloat v) { LIST(c.eval_coord2(u, v)); }
void glEvalCoord2d(GLdouble u, GLdouble v) { glEvalCoord2f(GLfloat(u), GLfloat(v)); }
void glEvalCoord2fv(const GLfloat* u) {
  if (u) glEvalCoord2f(u[0], u[1]);
}
void glEvalCoord2dv(const GLdouble* u) {
  if (u) glEvalCoord2f(GLfloat(u[0]), GLfloat(u[1]));
}
void glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  LIST(c.map_grid2(un, u1, u2, vn, v1, v2));
}
void glMapGrid2d(GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
  glMapGrid2f(un, GLfloat(u1), GLfloat(u2), vn, GLfloat(v1), GLfloat(v2));
}
void glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) { LIST(c.eval_mesh2(mode, i1, i2, j1, j2)); }
void glEvalPoint2(GLint i, GLint j) { LIST(c.eval_point2(i, j)); }
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
