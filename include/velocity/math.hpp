// Small vector and matrix types for the pipeline.
//
// Conventions (the same as OpenGL, so results compare one to one with Mesa):
//   * right-handed world, the camera looks down -Z with +Y up;
//   * Mat4 multiplies column vectors (p' = M * p), so M = T * R * S applies S first;
//   * clip space keeps x, y, z in [-w, w]; window depth is 0.5 * z/w + 0.5 in [0, 1].
// Everything here is header-only and constexpr-friendly: it sits in the innermost loops.
#pragma once

#include <cmath>
#include <numbers>

namespace velocity {

struct Vec2 {
  float x = 0, y = 0;
  constexpr bool operator==(const Vec2&) const = default;
};

struct Vec3 {
  float x = 0, y = 0, z = 0;

  constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(float s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator*(Vec3 o) const { return {x * o.x, y * o.y, z * o.z}; }
  constexpr Vec3 operator/(float s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(Vec3 o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(float s, Vec3 v) { return v * s; }
constexpr float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3 v) { return std::sqrt(dot(v, v)); }
// Returns v scaled to unit length, or the zero vector when v has no length.
inline Vec3 normalize(Vec3 v) {
  float l = length(v);
  return l > 0 ? v / l : Vec3{};
}

struct Vec4 {
  float x = 0, y = 0, z = 0, w = 0;

  constexpr Vec3 xyz() const { return {x, y, z}; }
  constexpr Vec4 operator+(Vec4 o) const { return {x + o.x, y + o.y, z + o.z, w + o.w}; }
  constexpr Vec4 operator-(Vec4 o) const { return {x - o.x, y - o.y, z - o.z, w - o.w}; }
  constexpr Vec4 operator*(float s) const { return {x * s, y * s, z * s, w * s}; }
};

constexpr float radians(float degrees) { return degrees * std::numbers::pi_v<float> / 180.0f; }

// 4x4 matrix, row-major storage: m[row][col]. Multiplies column vectors.
struct Mat4 {
  float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

  static constexpr Mat4 identity() { return {}; }

  constexpr Mat4 operator*(const Mat4& o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j] + m[i][3] * o.m[3][j];
    return r;
  }
  constexpr Vec4 operator*(Vec4 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z + m[0][3] * v.w,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z + m[1][3] * v.w,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z + m[2][3] * v.w,
            m[3][0] * v.x + m[3][1] * v.y + m[3][2] * v.z + m[3][3] * v.w};
  }
  // Transforms a point (w = 1), ignoring the projective row.
  constexpr Vec3 transform_point(Vec3 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  // Transforms a direction (w = 0).
  constexpr Vec3 transform_vector(Vec3 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  constexpr bool operator==(const Mat4&) const = default;
};

Mat4 translate(Vec3 t);
Mat4 scale(Vec3 s);
Mat4 rotate_x(float radians);
Mat4 rotate_y(float radians);
Mat4 rotate_z(float radians);
// Rotation by `radians` about `axis` (normalised here), right-handed, as glRotate.
Mat4 rotate(float radians, Vec3 axis);
Mat4 transpose(const Mat4& a);
// General inverse; returns false (and leaves `out` untouched) when `a` is singular.
bool invert(const Mat4& a, Mat4& out);
// Inverse transpose of the upper 3x3 (for normals); identity when singular.
Mat4 normal_matrix(const Mat4& model_view);
// As glFrustum / gluPerspective / glOrtho: clip z = -w at `near`, +w at `far`.
Mat4 frustum(float left, float right, float bottom, float top, float near, float far);
Mat4 perspective(float fov_y_radians, float aspect, float near, float far);
Mat4 orthographic(float left, float right, float bottom, float top, float near, float far);
// View matrix of an eye at `eye` looking at `target`.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);

}  // namespace velocity
