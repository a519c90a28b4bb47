// Transform state: the modelview, projection and texture matrix stacks (glLoadMatrix,
// glMultMatrix, glRotate, glFrustum...), the matrices the vertex stage derives from
// them, the viewport and the depth range. The matrices are the engine's (velocity::Mat4,
// include/velocity/math.hpp), built by its constructors: glRotate, glFrustum and
// glOrtho are OpenGL's formulas there, computed in float as Mesa does.
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

// --- matrix stacks ------------------------------------------------------------

std::vector<Mat4>& Context::stack() {
  switch (transform_.matrix_mode) {
    case GL_PROJECTION: return transform_.projection;
    case GL_TEXTURE: return transform_.texture;
    default: return transform_.modelview;
  }
}

void Context::matrix_mode(GLenum mode) {
  if (in_begin_error()) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return error(GL_INVALID_ENUM);
  transform_.matrix_mode = mode;
}

void Context::load(const Mat4& m) {
  if (in_begin_error()) return;
  stack().back() = m;
  transform_.derived_dirty = true;
}

void Context::multiply(const Mat4& m) {
  if (in_begin_error()) return;
  Mat4& top = stack().back();
  top = top * m;
  transform_.derived_dirty = true;
}

void Context::rotate(float degrees, float x, float y, float z) {
  // A zero axis leaves the matrix alone (as Mesa).
  if (!(std::sqrt(x * x + y * y + z * z) > 1e-4f)) return void(in_begin_error());
  multiply(velocity::rotate(radians(degrees), {x, y, z}));
}

void Context::translate(float x, float y, float z) { multiply(velocity::translate({x, y, z})); }

void Context::scale(float x, float y, float z) { multiply(velocity::scale({x, y, z})); }

// glOrtho and glFrustum check their arguments in double, then build the matrix from
// floats (as Mesa's _mesa_Ortho, _mesa_Frustum); an invalid one leaves the matrix alone.
void Context::ortho(double l, double r, double b, double t, double n, double f) {
  if (in_begin_error()) return;
  if (l == r || b == t || n == f) return error(GL_INVALID_VALUE);
  multiply(orthographic(float(l), float(r), float(b), float(t), float(n), float(f)));
}

void Context::frustum(double l, double r, double b, double t, double n, double f) {
  if (in_begin_error()) return;
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) return error(GL_INVALID_VALUE);
  multiply(velocity::frustum(float(l), float(r), float(b), float(t), float(n), float(f)));
}

void Context::push_matrix() {
  if (in_begin_error()) return;
  std::vector<Mat4>& s = stack();
  const size_t limit = transform_.matrix_mode == GL_PROJECTION ? kMaxProjectionDepth
                       : transform_.matrix_mode == GL_TEXTURE  ? kMaxTextureDepth
                                                               : kMaxModelviewDepth;
  if (s.size() >= limit) return error(GL_STACK_OVERFLOW);
  s.push_back(s.back());
}

void Context::pop_matrix() {
  if (in_begin_error()) return;
  std::vector<Mat4>& s = stack();
  if (s.size() <= 1) return error(GL_STACK_UNDERFLOW);
  s.pop_back();
  transform_.derived_dirty = true;
}

void Context::update_derived() {
  TransformState& t = transform_;
  if (!t.derived_dirty) return;
  t.derived_dirty = false;
  // Clip-space y is negated: the renderer's row 0 (its top) is then GL's bottom row, so
  // the framebuffer is in GL's (and OSMesa's) row order and is read out without a flip.
  t.mvp = t.projection.back() * t.modelview.back();
  for (float& v : t.mvp.m[1]) v = -v;
  // Normals go through the inverse transpose of the modelview's upper 3x3 (GL 1.5
  // section 2.11.3; the identity for a singular one). Round-off residues of zero
  // entries (1e-40 and the like) would be float denormals, which make every multiply
  // with them dozens of times slower: they are zeroed.
  t.normal_matrix = normal_matrix(t.modelview.back());
  for (auto& row : t.normal_matrix.m)
    for (float& v : row)
      if (std::fabs(v) < 1e-30f) v = 0;
  t.texture_identity = t.texture.back() == Mat4{};
}

// --- viewport and depth range ---------------------------------------------------

void Context::viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  const Box b = within_reach(x, y, w, h), &old = transform_.viewport;
  // A new viewport closes the open batch (which keeps the one it was drawn with); the
  // same one again, as programs set it every frame, does not split it.
  if (b.x != old.x || b.y != old.y || b.width != old.width || b.height != old.height) changed();
  transform_.viewport = b;
}

void Context::depth_range(double n, double f) {
  if (in_begin_error()) return;
  const float dn = unit(n), df = unit(f);
  if (dn != transform_.depth_near || df != transform_.depth_far) changed();  // (as glViewport)
  transform_.depth_near = dn, transform_.depth_far = df;
}

}  // namespace velocity::gl
