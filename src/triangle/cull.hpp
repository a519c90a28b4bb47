// The triangle stage's first pass, N triangles at a time: drop what can be dropped from
// the vertex stage's output alone — NaN/Inf corners, triangles outside one view plane,
// back faces, degenerate ones, and small ones that cover no pixel centre — and sort the
// rest into those set up directly and those that must be clipped first. In a dense mesh
// most triangles end here (half are back faces; at a million triangles on 1080p, half
// the front faces cover no pixel centre), so this pass is what a triangle usually costs.
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/viewport.hpp"
#include "velocity/mesh.hpp"

namespace velocity::triangle {

struct CullJob {
  const Triangle* triangles = nullptr;
  uint32_t begin = 0, end = 0;
  const geometry::ProjectedVertex* projected = nullptr;
  const uint32_t* codes = nullptr;
  bool cull_back = true;   // drop back faces (else they go on, for the caller to decide)
  bool drop_empty = true;  // drop front faces that cover no pixel centre (not for lines or points)
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the pixels that may be drawn (inclusive)
};

struct CullCounts {
  size_t nonfinite = 0, rejected = 0, culled = 0;
};

// What the first pass learnt of a triangle it let through (`info` below).
inline constexpr uint32_t kKnownSmall = 1u << 16;  // bits 0-15: its pixels in the 4x4 box at its first centre
inline constexpr uint32_t kKnownFront = 1u << 17;  // surely front-facing
inline constexpr uint32_t kKnownBack = 1u << 18;   // surely back-facing

// Writes the indices of the triangles that go on: unclipped ones to `direct` with what
// was learnt of them in `info`, those needing clipping to `clip` (each room for
// end - begin), and returns how many of each. A small triangle (its pixel centres
// within 4x4) comes with the exact set of centres it covers.
void cull_triangles(const CullJob& job, uint32_t* direct, uint32_t* info, size_t& direct_count, uint32_t* clip,
                    size_t& clip_count, CullCounts& counts);

}  // namespace velocity::triangle
