// Transform state: the modelview, projection and texture matrix stacks (glLoadMatrix,
// glMultMatrix, glRotate, glFrustum...), the matrices the vertex stage derives from
// them, the viewport and the depth range.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

M4 M4::operator*(const M4& b) const {
  M4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      r.m[c * 4 + row] = m[0 * 4 + row] * b.m[c * 4 + 0] + m[1 * 4 + row] * b.m[c * 4 + 1] +
                         m[2 * 4 + row] * b.m[c * 4 + 2] + m[3 * 4 + row] * b.m[c * 4 + 3];
  return r;
}

bool M4::is_identity() const {
  static const M4 id;
  return std::memcmp(m, id.m, sizeof m) == 0;
}

bool invert(const M4& a, M4& out) {
  // Gauss-Jordan elimination with partial pivoting, in double.
  double w[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) w[r][c] = a.m[c * 4 + r], w[r][c + 4] = r == c ? 1 : 0;
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(w[r][c]) > std::fabs(w[p][c])) p = r;
    if (!(std::fabs(w[p][c]) > 1e-30)) return false;
    if (p != c)
      for (int k = 0; k < 8; ++k) std::swap(w[p][k], w[c][k]);
    const double inv = 1.0 / w[c][c];
    for (int k = 0; k < 8; ++k) w[c][k] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = w[r][c];
      if (f != 0)
        for (int k = 0; k < 8; ++k) w[r][k] -= f * w[c][k];
    }
  }
  // Round-off residues of zero entries (1e-40 and the like) would become float
  // denormals, which make every multiply with them dozens of times slower.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const double v = w[r][c + 4];
      out.m[c * 4 + r] = std::fabs(v) < 1e-30 ? 0.0f : float(v);
    }
  return true;
}

// --- matrix stacks ------------------------------------------------------------

M4& Context::top() {
  switch (transform_.matrix_mode) {
    case GL_PROJECTION: return transform_.projection.back();
    case GL_TEXTURE: return transform_.texture.back();
    default: return transform_.modelview.back();
  }
}

void Context::matrix_mode(GLenum mode) {
  if (in_begin_error()) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return error(GL_INVALID_ENUM);
  transform_.matrix_mode = mode;
}

void Context::load(const M4& m) {
  if (in_begin_error()) return;
  top() = m;
  transform_.derived_dirty = true;
}

void Context::multiply(const M4& m) {
  if (in_begin_error()) return;
  top() = top() * m;
  transform_.derived_dirty = true;
}

// glRotate's matrix (the axis normalised); a zero axis leaves the matrix alone (as Mesa).
void Context::rotate(float angle, float x, float y, float z) {
  const float len = std::sqrt(x * x + y * y + z * z);
  if (!(len > 1e-4f)) return void(in_begin_error());
  x /= len, y /= len, z /= len;
  const float a = angle * 3.14159265358979323846f / 180.0f;
  const float c = std::cos(a), s = std::sin(a), t = 1 - c;
  M4 r;
  r.m[0] = x * x * t + c, r.m[4] = x * y * t - z * s, r.m[8] = x * z * t + y * s;
  r.m[1] = y * x * t + z * s, r.m[5] = y * y * t + c, r.m[9] = y * z * t - x * s;
  r.m[2] = x * z * t - y * s, r.m[6] = y * z * t + x * s, r.m[10] = z * z * t + c;
  multiply(r);
}

void Context::translate(float x, float y, float z) {
  M4 r;
  r.m[12] = x, r.m[13] = y, r.m[14] = z;
  multiply(r);
}

void Context::scale(float x, float y, float z) {
  M4 r;
  r.m[0] = x, r.m[5] = y, r.m[10] = z;
  multiply(r);
}

void Context::ortho(double l, double r, double b, double t, double n, double f) {
  if (in_begin_error()) return;
  if (l == r || b == t || n == f) return error(GL_INVALID_VALUE);
  M4 m;
  m.m[0] = float(2 / (r - l)), m.m[5] = float(2 / (t - b)), m.m[10] = float(-2 / (f - n));
  m.m[12] = float(-(r + l) / (r - l)), m.m[13] = float(-(t + b) / (t - b)), m.m[14] = float(-(f + n) / (f - n));
  multiply(m);
}

void Context::frustum(double l, double r, double b, double t, double n, double f) {
  if (in_begin_error()) return;
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) return error(GL_INVALID_VALUE);
  M4 m;
  m.m[0] = float(2 * n / (r - l)), m.m[5] = float(2 * n / (t - b));
  m.m[8] = float((r + l) / (r - l)), m.m[9] = float((t + b) / (t - b)), m.m[10] = float(-(f + n) / (f - n));
  m.m[11] = -1, m.m[14] = float(-2 * f * n / (f - n)), m.m[15] = 0;
  multiply(m);
}

void Context::push_matrix() {
  if (in_begin_error()) return;
  std::vector<M4>& s = transform_.matrix_mode == GL_PROJECTION ? transform_.projection : transform_.matrix_mode == GL_TEXTURE ? transform_.texture : transform_.modelview;
  const size_t limit = transform_.matrix_mode == GL_PROJECTION ? kMaxProjectionDepth
                       : transform_.matrix_mode == GL_TEXTURE  ? kMaxTextureDepth
                                                     : kMaxModelviewDepth;
  if (s.size() >= limit) return error(GL_STACK_OVERFLOW);
  s.push_back(s.back());
}

void Context::pop_matrix() {
  if (in_begin_error()) return;
  std::vector<M4>& s = transform_.matrix_mode == GL_PROJECTION ? transform_.projection : transform_.matrix_mode == GL_TEXTURE ? transform_.texture : transform_.modelview;
  if (s.size() <= 1) return error(GL_STACK_UNDERFLOW);
  s.pop_back();
  transform_.derived_dirty = true;
}

const M4& Context::matrix(GLenum which) const {
  return which == GL_PROJECTION ? transform_.projection.back() : which == GL_TEXTURE ? transform_.texture.back() : transform_.modelview.back();
}

int Context::stack_depth(GLenum which) const {
  return int(which == GL_PROJECTION ? transform_.projection.size() : which == GL_TEXTURE ? transform_.texture.size() : transform_.modelview.size());
}

void Context::update_derived() {
  if (!transform_.derived_dirty) return;
  transform_.derived_dirty = false;
  // Clip-space y is negated: the renderer's row 0 (its top) is then GL's bottom row, so
  // the framebuffer is in GL's (and OSMesa's) row order and is read out without a flip.
  transform_.mvp = transform_.projection.back() * transform_.modelview.back();
  for (int c = 0; c < 4; ++c) transform_.mvp.m[c * 4 + 1] = -transform_.mvp.m[c * 4 + 1];
  M4 inv;
  if (!invert(transform_.modelview.back(), inv)) inv = M4{};
  // The transpose of the inverse.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) transform_.normal_matrix.m[c * 4 + r] = inv.m[r * 4 + c];
  transform_.texture_identity = transform_.texture.back().is_identity();
}

// --- viewport and depth range ---------------------------------------------------

void Context::viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  transform_.viewport_x = std::clamp(x, -kMaxViewport, kMaxViewport), transform_.viewport_y = std::clamp(y, -kMaxViewport, kMaxViewport);
  transform_.viewport_width = std::min(w, kMaxViewport), transform_.viewport_height = std::min(h, kMaxViewport);
  changed();
}

void Context::depth_range(double n, double f) {
  if (in_begin_error()) return;
  transform_.depth_near = unit(n), transform_.depth_far = unit(f);
  changed();
}

}  // namespace velocity::gl
