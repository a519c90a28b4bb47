// Triangle, line and point set-up: from screen-space vertices to the edge functions,
// bounding boxes and interpolation planes that the tile rasterizer consumes.
#pragma once

#include <cmath>

#include "raster/raster_types.hpp"

namespace velocity::raster {

// Snaps a screen coordinate to 24.8 fixed point, rounding to nearest.
inline int64_t snap(float v) { return int64_t(std::lrint(v * float(kSubpixelOne))); }

// The geometry stage keeps vertices within the guard band (|x|, |y| < 2^15 pixels), but a
// degenerate projection (a camera with near <= 0, say) can still hand over NaN or huge
// coordinates. Set-up refuses anything outside +-2^20 pixels: snapped values then stay
// below 2^28 (they fit int32), so edge functions (products below 2^58) cannot overflow
// int64.
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
};

enum class Facing { Front, Back, Degenerate };

// Counter-clockwise in OpenGL's y-up window space is front; in our y-down screen space
// that is a negative signed area. Uses the snapped coordinates, so it agrees exactly
// with what the rasterizer covers.
Facing facing(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c);

// Sets up a triangle. `var[i]` points at vertex i's `num_varyings` varyings (not yet
// divided by w). Returns false when the triangle covers no pixel centre inside the
// width x height framebuffer (degenerate, or outside the scissor). Either winding is
// accepted; culling is the caller's decision, made with facing(). `affine` makes 1/w
// constant, so that the kernels interpolate varyings linearly in screen space.
bool setup_triangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, const float* var0,
                    const float* var1, const float* var2, int num_varyings, int width, int height, bool affine,
                    TriangleSetup& out);

bool setup_line(const ScreenVertex& a, const ScreenVertex& b, uint32_t color, int width, int height, LineSetup& out);
bool setup_point(const ScreenVertex& p, uint32_t color, int width, int height, PointSetup& out);

}  // namespace velocity::raster
