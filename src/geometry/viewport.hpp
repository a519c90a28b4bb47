// From clip space to the window: the region codes a vertex gets in clip space, the
// guard band, and the viewport transform with the snap to 24.8 fixed point.
//
// A vertex is inside the view volume when -w <= x, y, z <= w. Region codes (Cohen-
// Sutherland outcodes) have one bit per plane a vertex is outside of.
#pragma once

#include <cmath>
#include <cstdint>

#include "raster/contract.hpp"
#include "velocity/math.hpp"

namespace velocity::geometry {

enum Outcode : uint32_t {
  kOutLeft = 1u << 0,  // x < -w
  kOutRight = 1u << 1,
  kOutBottom = 1u << 2,
  kOutTop = 1u << 3,
  kOutNear = 1u << 4,  // z < -w
  kOutFar = 1u << 5,
  kOutGuardLeft = 1u << 6,  // x < -g_x * w: must be clipped before snapping
  kOutGuardRight = 1u << 7,
  kOutGuardBottom = 1u << 8,
  kOutGuardTop = 1u << 9,
  kOutNonFinite = 1u << 10,  // a NaN or an infinity: the primitive is dropped
  kOutUnsnapped = 1u << 11,  // inside the guard band, yet too far out to snap (set-up drops it)
};
inline constexpr uint32_t kViewPlanes = kOutLeft | kOutRight | kOutBottom | kOutTop | kOutNear | kOutFar;
// Planes that must be cut before rasterizing.
inline constexpr uint32_t kMustClipPlanes =
    kOutNear | kOutFar | kOutGuardLeft | kOutGuardRight | kOutGuardBottom | kOutGuardTop;

// The guard band in clip units: x is inside it when |x| <= guard_x * w.
struct GuardBand {
  float x, y;
  static GuardBand for_viewport(int width, int height) {
    return {1.0f + 2.0f * raster::kGuardBandPixels / float(width), 1.0f + 2.0f * raster::kGuardBandPixels / float(height)};
  }
};

inline uint32_t outcode(const Vec4& p, GuardBand g) {
  if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w))) return kOutNonFinite;
  uint32_t c = 0;
  if (p.x < -p.w) c |= kOutLeft;
  if (p.x > p.w) c |= kOutRight;
  if (p.y < -p.w) c |= kOutBottom;
  if (p.y > p.w) c |= kOutTop;
  if (p.z < -p.w) c |= kOutNear;
  if (p.z > p.w) c |= kOutFar;
  if (p.x < -g.x * p.w) c |= kOutGuardLeft;
  if (p.x > g.x * p.w) c |= kOutGuardRight;
  if (p.y < -g.y * p.w) c |= kOutGuardBottom;
  if (p.y > g.y * p.w) c |= kOutGuardTop;
  return c;
}

// What the triangle stage reads per vertex. fx, fy are meaningful only when the code
// has no kMustClipPlanes, kOutNonFinite or kOutUnsnapped bit.
struct ProjectedVertex {
  int32_t fx, fy;  // screen position, 24.8 fixed point, y down
  float z;         // window depth
  float inv_w;     // 1 / w_clip
};

// clip -> window: x = (x/w + 1) * scale_x + offset_x, y = offset_y - (y/w + 1) * scale_y,
// z = z/w * scale_z + offset_z (OpenGL's viewport transform in its order of operations,
// so that snapped positions agree with Mesa's; y flipped so that row 0 is the top).
// The one clip -> window projection of the engine: the vertex stage runs its SIMD form
// on every vertex (geometry/vertex_stage.cpp), the triangle stage this scalar form on
// the vertices clipping makes.
struct ViewportMap {
  float scale_x, offset_x, scale_y, offset_y, scale_z, offset_z;
  GuardBand guard;

  // Window x, y, z and 1 / w of clip-space position c.
  Vec4 window(const Vec4& c) const {
    const float inv_w = 1.0f / c.w;
    return {(c.x * inv_w + 1.0f) * scale_x + offset_x, offset_y - (c.y * inv_w + 1.0f) * scale_y,
            (c.z * inv_w) * scale_z + offset_z, inv_w};
  }
};

// clip -> window for a viewport (x, y, width, height) in framebuffer pixels, row 0 at
// the top, with depth range [n, f].
inline ViewportMap viewport_map(int x, int y, int w, int h, float n, float f) {
  ViewportMap m;
  m.scale_x = float(w) * 0.5f, m.offset_x = float(x);
  m.scale_y = float(h) * 0.5f, m.offset_y = float(y + h);
  m.scale_z = (f - n) * 0.5f, m.offset_z = (f + n) * 0.5f;
  m.guard = GuardBand::for_viewport(w, h);
  return m;
}

// What a draw's primitives are set up with (triangle/setup.hpp).
struct SetupParams {
  // Pixels a primitive may touch (inclusive): the framebuffer, narrowed by the
  // viewport (triangles only) and the scissor.
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;   // triangles
  int px0 = 0, py0 = 0, px1 = 0, py1 = 0;  // points and lines
  bool affine = false;      // make 1/w constant: varyings interpolate linearly on screen
  bool offset = false;      // glPolygonOffset: depth += factor * max slope + units * 2^-24
  float offset_factor = 0, offset_units = 0;
};

}  // namespace velocity::geometry
