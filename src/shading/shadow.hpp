// Shadow maps as the lighting model reads them: a light's depth images (rendered by the
// frame's own pipeline, src/shadows.cpp) and the visibility of a surface point, the
// fraction of a bilinear percentage-closer filter (PCF) that sees the light. This is the
// scalar form; shadow-inl.h is the same function N points at a time. The lighting
// model (lighting.hpp, lighting-inl.h) multiplies each light's contribution by it; a
// point facing away from the light (N.L <= 0) is in its own shadow.
//
// The filter is bilinear PCF, what a GPU's depth-compare sampler with linear filtering
// gives: the four texels around the point are each compared with its depth and the four
// results weighted by the point's position between their centres, so a shadow's edge is
// a one-texel ramp rather than a staircase.
//
// Bias, in world units scaled by the size of one shadow-map texel at the point (so it
// holds for any map size, scene size and distance to a spot or point light): the point
// is moved kNormalOffset texels along its normal and kLightOffset texels towards the
// light before it is projected. The filter reads texels up to 1.4 texels away
// (diagonally) across the receiving surface; a surface tilted by theta from the light
// rises by 1.4 tan(theta) texels over that reach, while the normal offset lifts the point
// by kNormalOffset / cos(theta) along the light: more than enough at every angle, so no
// acne. Both offsets are a texel or two, so a shadow starts within
// a texel or two of its caster's contact (no peter-panning): docs/appearance.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "velocity/math.hpp"

namespace velocity::shading {

inline constexpr float kNormalOffset = 2.0f;  // texels, along the surface normal
inline constexpr float kLightOffset = 1.0f;   // texels, towards the light
inline constexpr int kShadowLights = 4;       // lights with a shadow map, at most (the first that cast)

// One depth image seen from a light, as 16-bit codes (half the bytes a lookup waits on):
// 0 the near plane, kShadowFar the far one (and nothing drawn). Orthographic, the code is
// the window depth the rasterizer wrote (LESS) times kShadowFar; perspective, it is
// linear in the distance along the light's axis (clip w) from near to far, since a
// perspective window depth crowds the far half of the range into a few codes. Each code
// is rounded up (the caster a fraction of a code farther): one code is 1/65535 of the
// depth range, a small fraction of a texel but very near a spot or point light
// (docs/appearance.md, "Limits").
inline constexpr float kShadowFar = 65535.0f;

// The codes are stored row by row (not in the framebuffer's tiles, which the depth pass
// draws in), with a border of one texel on every side that repeats the texel at the edge
// (clamp to edge): the filter's four texels around any point inside the map are then two
// 32-bit loads, each a texel and its right neighbour, at an index that is one multiply
// and add from the point's texel with nothing clamped (shadow-inl.h).
struct ShadowMap {
  const uint16_t* depth = nullptr;  // texel (x, y), -1 <= x, y <= size, at shadow_texel(x, y)
  int size = 0;     // texels a side
  int stride = 0;   // codes a stored row: shadow_stride(size)
  Mat4 eye_to_clip; // the camera's eye space to the light's clip space
  bool perspective = false;
  // The world size of one texel: orthographic, the texel itself; perspective, per unit
  // of distance along the light's axis (clip w).
  float texel = 0;
  float near = 0, far = 1;  // perspective: the light's near and far planes (clip w)
  // A point's code from its clip coordinates: code_scale * (orthographic: z, perspective:
  // w) + code_offset.
  float code_scale = 0.5f * kShadowFar, code_offset = 0.5f * kShadowFar;
};

// A light's shadow: one map (directional: orthographic; spot: perspective), or six for
// a point light, the faces of a cube around it along the eye-space axes, in the order
// +x, -x, +y, -y, +z, -z.
struct LightShadow {
  int faces = 0;
  ShadowMap face[6];
  Vec3 position;  // cube: the light, eye space
};

// How a map of `size` texels a side is laid out in memory: rows of shadow_stride codes,
// the side and its border rounded up to whole 64-byte lines, starting kShadowLead codes
// into an allocation of shadow_codes_for codes aligned to 64 bytes. Texel (0, y) of every
// row then begins a line, so that the depth pass's tiles (64 texels, two lines of each
// row) share no line with the tiles beside them: two threads writing one line take turns
// owning it, which cost the 2048² depth pass a third of its second thread.
inline int shadow_stride(int size) { return (size + 2 + 31) / 32 * 32; }
inline constexpr size_t kShadowLead = 31;
inline size_t shadow_codes_for(int size) { return kShadowLead + size_t(size + 2) * size_t(shadow_stride(size)); }

// Whether every stored index of a map of `size` texels a side is below 2^24, so that
// float arithmetic computes it exactly.
inline bool shadow_texel_exact_in_float(int size) { return shadow_codes_for(size) <= (size_t(1) << 24); }

// Where texel (x, y) of a map is stored (-1 and size: the border).
inline size_t shadow_texel(const ShadowMap& m, int x, int y) { return size_t(y + 1) * size_t(m.stride) + size_t(x + 1); }

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
  const float x = (c.x / c.w * 0.5f + 0.5f) * s, y = (0.5f - 0.5f * c.y / c.w) * s;
  const float z = (m.perspective ? c.w : c.z) * m.code_scale + m.code_offset;  // its code
  if (!(x >= 0 && x < s && y >= 0 && y < s && z <= kShadowFar)) return 1;
  // The four texel centres around (x, y) and the weights of the bilinear filter.
  const float gx = x - 0.5f, gy = y - 0.5f, fx0 = std::floor(gx), fy0 = std::floor(gy);
  const float fx = gx - fx0, fy = gy - fy0;
  const int x0 = std::max(int(fx0), 0), y0 = std::max(int(fy0), 0);
  const int x1 = std::min(int(fx0) + 1, m.size - 1), y1 = std::min(int(fy0) + 1, m.size - 1);
  auto lit = [&](int tx, int ty) { return z <= float(m.depth[shadow_texel(m, tx, ty)]) ? 1.0f : 0.0f; };
  const float top = lit(x0, y0) + (lit(x1, y0) - lit(x0, y0)) * fx;
  const float bottom = lit(x0, y1) + (lit(x1, y1) - lit(x0, y1)) * fx;
  return top + (bottom - top) * fy;
}

// A light's visibility at `p`: its one map, or the cube face the offset point falls in;
// 0 where the point faces away from the light.
inline float visibility(const LightShadow& s, Vec3 p, Vec3 n, Vec3 to_light) {
  if (!(dot(n, to_light) > 0)) return 0;
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
