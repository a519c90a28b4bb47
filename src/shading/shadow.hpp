// Shadow maps as the lighting model reads them: a light's depth images (rendered by the
// frame's own pipeline, src/shadows.cpp) and the visibility of a surface point, the
// fraction of a 3x3 percentage-closer filter (PCF) that sees the light. This is the
// scalar form; shadow-inl.h is the same function N points at a time. The lighting
// model (lighting.hpp, lighting-inl.h) multiplies each light's contribution by it.
//
// Bias, in world units scaled by the size of one shadow-map texel at the point (so it
// holds for any map size, scene size and distance to a spot or point light): the point
// is moved kNormalOffset texels along its normal and kLightOffset texels towards the
// light before it is projected. The 3x3 filter reaches up to 2.1 texels (diagonally,
// from the texel nearest the point) across the receiving surface; a surface tilted by
// theta from the light rises by 2.1 tan(theta) texels over that reach, while the normal
// offset lifts the point by kNormalOffset / cos(theta) along the light: more than enough
// at every angle, so no acne. Both offsets are a texel or two, so a shadow starts within
// a texel or two of its caster's contact (no peter-panning): docs/appearance.md.
#pragma once

#include <algorithm>
#include <cmath>

#include "velocity/math.hpp"

namespace velocity::shading {

inline constexpr float kNormalOffset = 2.0f;  // texels, along the surface normal
inline constexpr float kLightOffset = 1.0f;   // texels, towards the light
inline constexpr int kShadowLights = 4;       // lights with a shadow map, at most (the first that cast)

// One depth image seen from a light: window depth in [0, 1] as the rasterizer wrote it
// (LESS), stored tile by tile as framebuffer.hpp lays a framebuffer out.
struct ShadowMap {
  const float* depth = nullptr;
  int size = 0;     // texels a side
  int tiles_x = 0;  // 64x64 tiles a row
  Mat4 eye_to_clip; // the camera's eye space to the light's clip space
  bool perspective = false;
  // The world size of one texel: orthographic, the texel itself; perspective, per unit
  // of distance along the light's axis (clip w).
  float texel = 0;
};

// A light's shadow: one map (directional: orthographic; spot: perspective), or six for
// a point light, the faces of a cube around it along the eye-space axes, in the order
// +x, -x, +y, -y, +z, -z.
struct LightShadow {
  int faces = 0;
  ShadowMap face[6];
  Vec3 position;  // cube: the light, eye space
};

// Where texel (x, y) of a map is stored (framebuffer.hpp's index).
inline size_t shadow_texel(const ShadowMap& m, int x, int y) {
  return (size_t(y >> 6) * size_t(m.tiles_x) + size_t(x >> 6)) * 4096 + size_t(((y >> 2) & 15) * 16 + ((x >> 2) & 15)) * 16 +
         size_t((y & 3) * 4 + (x & 3));
}

// The cube face a direction from the light falls in (its major axis).
inline int cube_face(Vec3 v) {
  const float ax = std::fabs(v.x), ay = std::fabs(v.y), az = std::fabs(v.z);
  if (ax >= ay && ax >= az) return v.x >= 0 ? 0 : 1;
  if (ay >= az) return v.y >= 0 ? 2 : 3;
  return v.z >= 0 ? 4 : 5;
}

// The visibility of eye-space point `p` (unit normal `n`, unit `to_light`) in one map:
// 1 lit, 0 in shadow, the PCF fraction between. Outside the map: lit.
inline float map_visibility(const ShadowMap& m, Vec3 p, Vec3 n, Vec3 to_light) {
  const Mat4& M = m.eye_to_clip;
  const float w0 = M.m[3][0] * p.x + M.m[3][1] * p.y + M.m[3][2] * p.z + M.m[3][3];
  const float texel = m.perspective ? m.texel * w0 : m.texel;
  const Vec3 q = p + n * (kNormalOffset * texel) + to_light * (kLightOffset * texel);
  const Vec4 c = M * Vec4{q.x, q.y, q.z, 1.0f};
  if (!(c.w > 0)) return 1;
  const float s = float(m.size);
  const float x = (c.x / c.w * 0.5f + 0.5f) * s, y = (0.5f - 0.5f * c.y / c.w) * s, z = c.z / c.w * 0.5f + 0.5f;
  if (!(x >= 0 && x < s && y >= 0 && y < s && z <= 1)) return 1;
  const int cx = int(x), cy = int(y);
  int lit = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int tx = std::clamp(cx + dx, 0, m.size - 1), ty = std::clamp(cy + dy, 0, m.size - 1);
      lit += z <= m.depth[shadow_texel(m, tx, ty)];
    }
  return float(lit) * (1.0f / 9.0f);
}

// A light's visibility at `p`: its one map, or the cube face the offset point falls in.
inline float visibility(const LightShadow& s, Vec3 p, Vec3 n, Vec3 to_light) {
  if (s.faces == 1) return map_visibility(s.face[0], p, n, to_light);
  // The face is chosen for the point the bias moves the lookup to, so that a point
  // near a seam reads the face it is projected into.
  const ShadowMap& near = s.face[cube_face(p - s.position)];
  const float w0 = near.eye_to_clip.m[3][0] * p.x + near.eye_to_clip.m[3][1] * p.y + near.eye_to_clip.m[3][2] * p.z +
                   near.eye_to_clip.m[3][3];
  const float texel = near.texel * w0;
  const Vec3 q = p + n * (kNormalOffset * texel) + to_light * (kLightOffset * texel);
  return map_visibility(s.face[cube_face(q - s.position)], p, n, to_light);
}

}  // namespace velocity::shading
