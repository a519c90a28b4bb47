// Triangle, line and point set-up: from screen-space vertices to the records (edge
// functions, bounding boxes, interpolation planes) that the tile rasterizer consumes.
#pragma once

#include <cmath>

#include "geometry/viewport.hpp"
#include "raster/bins.hpp"
#include "raster/contract.hpp"

namespace velocity::triangle {

// Snaps a screen coordinate to 24.8 fixed point, rounding to nearest.
inline int64_t snap(float v) { return int64_t(std::lrint(v * float(raster::kSubpixelOne))); }

// The triangle stage keeps vertices within the guard band (16384 pixels around the
// framebuffer, or around a viewport that lies within 16384 pixels of it), but a
// degenerate projection can still hand over NaN or huge coordinates. Set-up refuses
// anything outside +-2^20 pixels: snapped values then stay below 2^28 (they fit int32).
inline constexpr float kMaxScreenCoord = 1048576.0f;

// A vertex after the perspective divide and viewport transform, snapped once (per
// vertex, not per triangle that uses it).
struct ScreenVertex {
  float x, y;      // pixels, y down
  float z;         // window depth in [0, 1]
  float inv_w;     // 1 / w_clip
  int32_t fx, fy;  // x, y in 24.8 fixed point; meaningful only when `snapped`
  bool snapped;    // false when |x| or |y| exceeds kMaxScreenCoord, or is NaN

  static ScreenVertex make(float x, float y, float z, float inv_w) {
    bool ok = std::fabs(x) <= kMaxScreenCoord && std::fabs(y) <= kMaxScreenCoord;  // false for NaN
    return {x, y, z, inv_w, ok ? int32_t(snap(x)) : 0, ok ? int32_t(snap(y)) : 0, ok};
  }
  // A vertex as the vertex stage projected and snapped it, with its region code.
  static ScreenVertex projected(const geometry::ProjectedVertex& p, uint32_t code) {
    return {float(p.fx) * (1.0f / 256), float(p.fy) * (1.0f / 256), p.z, p.inv_w, p.fx, p.fy,
            !(code & (geometry::kMustClipPlanes | geometry::kOutNonFinite | geometry::kOutUnsnapped))};
  }
  // A vertex made by clipping, through the vertex stage's projection.
  static ScreenVertex window(const geometry::ViewportMap& vp, const Vec4& clip) {
    const Vec4 w = vp.window(clip);
    return make(w.x, w.y, w.z, w.w);
  }
};

enum class Facing { Front, Back, Degenerate };

// Counter-clockwise in OpenGL's y-up window space is front; in our y-down screen space
// that is a negative signed area. Uses the snapped coordinates, so it agrees exactly
// with what the rasterizer covers.
Facing facing(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c);


// What every record of a primitive shares.
struct RecordInfo {
  uint8_t kernel = 0;
  uint32_t draw = 0;
  uint32_t flat_color = 0;
};

// Sets up a triangle at the end of `bins`' arena. `var[i]` points at vertex i's
// `num_varyings` varyings (not yet divided by w). Returns the record, with its offset
// in `offset`, or nullptr when the triangle covers no pixel centre inside the box
// (degenerate, too small, or outside). Either winding is accepted; culling is the
// caller's decision, made with facing().
raster::RecordHeader* setup_triangle(raster::WorkerBins& bins, const ScreenVertex& v0, const ScreenVertex& v1,
                                     const ScreenVertex& v2, const float* var0, const float* var1, const float* var2,
                                     int num_varyings, const RecordInfo& info, const geometry::SetupParams& params,
                                     uint32_t& offset);

// Sets up a small triangle whose covered pixel centres are already known: `mask`, the
// centres in the 4x4 box at its first centre (bit y * 4 + x), from the triangle
// stage's exact first pass (cull.hpp). No edge functions.
// (setup_triangle itself turns triangles whose centres lie within 8x8 into the same
// kind of record, finding their pixels with the edge functions.)
raster::RecordHeader* setup_small_triangle(raster::WorkerBins& bins, const ScreenVertex& v0, const ScreenVertex& v1,
                                           const ScreenVertex& v2, const float* var0, const float* var1,
                                           const float* var2, int num_varyings, uint32_t mask, const RecordInfo& info,
                                           const geometry::SetupParams& params, uint32_t& offset);

// A line `width` pixels wide from a to b, varyings interpolated along it.
raster::RecordHeader* setup_line(raster::WorkerBins& bins, const ScreenVertex& a, const ScreenVertex& b,
                                 const float* var_a, const float* var_b, int num_varyings, int width,
                                 const RecordInfo& info, const geometry::SetupParams& params,
                                 uint32_t& offset);

// A point: the size x size square of pixels centred on p, with p's varyings.
raster::RecordHeader* setup_point(raster::WorkerBins& bins, const ScreenVertex& p, const float* var, int num_varyings,
                                  int size, const RecordInfo& info, const geometry::SetupParams& params,
                                  uint32_t& offset);

}  // namespace velocity::triangle
