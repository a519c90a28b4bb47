// Matrix constructors and inversion. The formulas are OpenGL's (glRotate, glFrustum,
// glOrtho), so a scene set up here and through OpenGL gives the same clip coordinates.
#include "velocity/math.hpp"

namespace velocity {

Mat4 translate(Vec3 t) {
  Mat4 r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Mat4 scale(Vec3 s) {
  Mat4 r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

Mat4 rotate_x(float a) {
  Mat4 r;
  float c = std::cos(a), s = std::sin(a);
  r.m[1][1] = c, r.m[1][2] = -s;
  r.m[2][1] = s, r.m[2][2] = c;
  return r;
}

Mat4 rotate_y(float a) {
  Mat4 r;
  float c = std::cos(a), s = std::sin(a);
  r.m[0][0] = c, r.m[0][2] = s;
  r.m[2][0] = -s, r.m[2][2] = c;
  return r;
}

Mat4 rotate_z(float a) {
  Mat4 r;
  float c = std::cos(a), s = std::sin(a);
  r.m[0][0] = c, r.m[0][1] = -s;
  r.m[1][0] = s, r.m[1][1] = c;
  return r;
}

Mat4 rotate(float a, Vec3 axis) {
  Vec3 n = normalize(axis);
  float c = std::cos(a), s = std::sin(a), k = 1 - c;
  Mat4 r;
  r.m[0][0] = n.x * n.x * k + c, r.m[0][1] = n.x * n.y * k - n.z * s, r.m[0][2] = n.x * n.z * k + n.y * s;
  r.m[1][0] = n.y * n.x * k + n.z * s, r.m[1][1] = n.y * n.y * k + c, r.m[1][2] = n.y * n.z * k - n.x * s;
  r.m[2][0] = n.z * n.x * k - n.y * s, r.m[2][1] = n.z * n.y * k + n.x * s, r.m[2][2] = n.z * n.z * k + c;
  return r;
}

Mat4 transpose(const Mat4& a) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

// Cofactor expansion in double precision: matrices here are small and well scaled, and
// doubles keep a camera far from the origin from losing its last bits.
bool invert(const Mat4& a, Mat4& out) {
  double m[16], inv[16];
  for (int i = 0; i < 16; ++i) m[i] = a.m[i / 4][i % 4];
  inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] + m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
  inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] - m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
  inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] + m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
  inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] - m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
  inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] - m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
  inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] + m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
  inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] - m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
  inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] + m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
  inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] + m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
  inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] - m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
  inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] + m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
  inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] - m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
  inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] - m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
  inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] + m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
  inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] - m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
  inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] + m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
  double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
  if (det == 0 || !std::isfinite(det)) return false;
  for (int i = 0; i < 16; ++i) out.m[i / 4][i % 4] = float(inv[i] / det);
  return true;
}

Mat4 normal_matrix(const Mat4& mv) {
  Mat4 upper = mv;
  for (int i = 0; i < 3; ++i) upper.m[i][3] = upper.m[3][i] = 0;
  upper.m[3][3] = 1;
  Mat4 inv;
  if (!invert(upper, inv)) return Mat4::identity();
  return transpose(inv);
}

Mat4 frustum(float l, float r, float b, float t, float n, float f) {
  Mat4 m;
  m.m[0][0] = 2 * n / (r - l), m.m[0][2] = (r + l) / (r - l);
  m.m[1][1] = 2 * n / (t - b), m.m[1][2] = (t + b) / (t - b);
  m.m[2][2] = -(f + n) / (f - n), m.m[2][3] = -2 * f * n / (f - n);
  m.m[3][2] = -1, m.m[3][3] = 0;
  return m;
}

Mat4 perspective(float fov_y, float aspect, float n, float f) {
  // Computed as the reference does (glFrustum with the half-height at the near plane)
  // so that both sides round the same way.
  double h = double(n) * std::tan(double(fov_y) / 2);
  return frustum(float(-h * aspect), float(h * aspect), float(-h), float(h), n, f);
}

Mat4 orthographic(float l, float r, float b, float t, float n, float f) {
  Mat4 m;
  m.m[0][0] = 2 / (r - l), m.m[0][3] = -(r + l) / (r - l);
  m.m[1][1] = 2 / (t - b), m.m[1][3] = -(t + b) / (t - b);
  m.m[2][2] = -2 / (f - n), m.m[2][3] = -(f + n) / (f - n);
  return m;
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  Vec3 f = normalize(target - eye);
  Vec3 s = normalize(cross(f, up));
  Vec3 u = cross(s, f);
  Mat4 m;
  m.m[0][0] = s.x, m.m[0][1] = s.y, m.m[0][2] = s.z, m.m[0][3] = -dot(s, eye);
  m.m[1][0] = u.x, m.m[1][1] = u.y, m.m[1][2] = u.z, m.m[1][3] = -dot(u, eye);
  m.m[2][0] = -f.x, m.m[2][1] = -f.y, m.m[2][2] = -f.z, m.m[2][3] = dot(f, eye);
  return m;
}

}  // namespace velocity
