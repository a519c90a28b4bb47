// Clipping in homogeneous clip space, by the region codes of geometry/viewport.hpp.
// Triangles whose three codes share a bit are rejected whole; triangles with no code bit
// set are accepted whole. Only the near and far planes, and the guard-band planes far outside
// the screen, ever cut a triangle: left/right/top/bottom are otherwise handled by the
// rasterizer's scissored bounding box, which is cheaper than making new vertices.
#pragma once

#include <cstdint>

#include "geometry/viewport.hpp"
#include "raster/contract.hpp"
#include "velocity/primitives.hpp"
#include "velocity/math.hpp"

namespace velocity::triangle {

struct ClipVertex {
  Vec4 pos;                            // clip space
  float var[raster::kMaxVaryings];     // varyings, interpolated linearly in clip space
  int src = -1;                        // the input vertex it is a copy of, or -1 for a new one
  float dist[kMaxUserClipPlanes];      // user clip planes' distances (PrimitiveBatch), >= 0 inside
};

// Most vertices a triangle can have after clipping against the six must-clip planes
// and the user clip planes.
inline constexpr int kMaxClippedVertices = 3 + 6 + int(kMaxUserClipPlanes);

// Clips the convex polygon `poly` (n vertices, n <= kMaxClippedVertices - planes cut so
// far) against each plane in `planes` (a set of geometry::kMustClipPlanes bits), interpolating
// `num_varyings` varyings. Sutherland-Hodgman, one plane at a time. Returns the new
// vertex count (0 when nothing is left); the result is in `poly`.
int clip_polygon(ClipVertex* poly, int n, uint32_t planes, geometry::GuardBand guard, int num_varyings);

// Clips the convex polygon `poly`, whose vertices have `nplanes` user clip distances,
// against the planes in the bit set `planes` (bit k: dist[k] >= 0 is kept), as
// clip_polygon does. (clip_polygon itself carries no distances: it runs after this.)
int clip_polygon_user(ClipVertex* poly, int n, uint32_t planes, uint32_t nplanes, int num_varyings);

// The part [t0, t1] of a segment whose ends have user clip distances da and db (n
// planes) that is inside every plane; false when none is.
bool clip_line_user(const float* da, const float* db, uint32_t n, float* t0, float* t1);

// Clips the segment a-b against the must-clip planes in `planes` (parametric, Liang-
// Barsky style). Returns false when nothing is left; else the new ends, which lie at
// t0 and t1 of the old segment (for interpolating varyings).
bool clip_line(Vec4& a, Vec4& b, uint32_t planes, geometry::GuardBand guard, float* t0 = nullptr, float* t1 = nullptr);

}  // namespace velocity::triangle
