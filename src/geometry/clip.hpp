// Region codes and clipping in homogeneous clip space.
//
// A vertex is inside the view volume when -w <= x, y, z <= w. Region codes (Cohen-
// Sutherland outcodes) have one bit per plane a vertex is outside of. Triangles whose
// three codes share a bit are rejected whole; triangles with no code bit set are
// accepted whole. Only the near and far planes, and the guard-band planes far outside
// the screen, ever cut a triangle: left/right/top/bottom are otherwise handled by the
// rasterizer's scissored bounding box, which is cheaper than making new vertices.
#pragma once

#include <cstdint>

#include "raster/contract.hpp"
#include "velocity/math.hpp"

namespace velocity::geometry {

struct ClipVertex {
  Vec4 pos;                            // clip space
  float var[raster::kMaxVaryings];     // varyings, interpolated linearly in clip space
  int src = -1;                        // the input vertex it is a copy of, or -1 for a new one
};

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

// Most vertices a triangle can have after clipping against the six must-clip planes.
inline constexpr int kMaxClippedVertices = 3 + 6;

// Clips the convex polygon `poly` (n vertices, n <= kMaxClippedVertices - planes cut so
// far) against each plane in `planes` (a set of kMustClipPlanes bits), interpolating
// `num_varyings` varyings. Sutherland-Hodgman, one plane at a time. Returns the new
// vertex count (0 when nothing is left); the result is in `poly`.
int clip_polygon(ClipVertex* poly, int n, uint32_t planes, GuardBand guard, int num_varyings);

// Clips the segment a-b against the must-clip planes in `planes` (parametric, Liang-
// Barsky style). Returns false when nothing is left; else the new ends, which lie at
// t0 and t1 of the old segment (for interpolating varyings).
bool clip_line(Vec4& a, Vec4& b, uint32_t planes, GuardBand guard, float* t0 = nullptr, float* t1 = nullptr);

}  // namespace velocity::geometry
