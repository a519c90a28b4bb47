// Data the geometry stage hands the rasterizer: set-up triangles, lines and points in
// screen space, and the commands that bins hold.
//
// Screen space: x to the right, y down, pixel (x, y) covers [x, x+1) x [y, y+1) and is
// sampled at its centre (x + 0.5, y + 0.5). Vertex positions are snapped to 24.8 fixed
// point (kSubpixelBits = 8, as in Mesa's llvmpipe), so coverage is exact integer
// arithmetic: a shared edge is evaluated bit-identically by both triangles.
#pragma once

#include <cstdint>

namespace velocity::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelOne = 1 << kSubpixelBits;  // 256
inline constexpr int kSubpixelHalf = kSubpixelOne / 2;   // the pixel centre, 0.5

// Guard band: geometry reaching no further than this many pixels outside the
// framebuffer is rasterised as it is (the bounding box is scissored); anything beyond
// is clipped against the guard-band planes first. With framebuffers up to 16384 pixels
// a side, snapped coordinates stay within +-2^23 (24.8 fixed point), edge deltas within
// 2^24 and edge-function products within 2^48: int64 never overflows.
inline constexpr float kGuardBandPixels = 16384.0f;
inline constexpr int kMaxFramebufferSide = 16384;

inline constexpr int kTileSizeLog2 = 6;
inline constexpr int kTileSize = 1 << kTileSizeLog2;  // 64x64 pixel tiles

// Per-vertex values interpolated across a triangle (colour, normal, eye position, ...).
inline constexpr int kMaxVaryings = 12;

// A linear function of the pixel position, value = c + dx * (x - x0) + dy * (y - y0),
// where (x0, y0) is the centre of the triangle's first bounding-box pixel. Anchoring at
// the box keeps the evaluation free of cancellation far from the origin.
struct Plane {
  float c = 0, dx = 0, dy = 0;
};

struct TriangleSetup {
  // Edge functions E_i(px, py) = a_i * px + b_i * py + c_i over 24.8 fixed-point
  // pixel-centre coordinates; a pixel is covered when all three are >= 0. The
  // top-left rule is folded into c_i: non-top-left edges had 1 subtracted, so a centre
  // exactly on such an edge is left to the neighbour that shares it.
  int64_t a[3], b[3], c[3];
  // Inclusive pixel bounding box, already clipped to the framebuffer (the scissor).
  int min_x, min_y, max_x, max_y;
  Plane depth;                 // window z in [0, 1], affine in screen space
  Plane inv_w;                 // 1 / w_clip, for perspective correction
  Plane var[kMaxVaryings];     // varying / w_clip
  uint32_t flat_color = 0;     // RGBA8 for flat, wireframe-free constant kernels
  uint32_t draw = 0;           // index of the draw call (material, lights) it came from
  uint8_t kernel = 0;          // shading kernel, chosen once per draw
  float sort_key = 0;          // painter's mode: mean window depth
};

struct LineSetup {
  float x0, y0, z0, x1, y1, z1;  // screen position and window depth of the ends
  int min_x, min_y, max_x, max_y;
  uint32_t color;
  float sort_key;
};

struct PointSetup {
  int x, y;
  float z;
  uint32_t color;
  float sort_key;
};

// What a bin holds: the primitive's kind in the top two bits, its index below.
enum class CommandKind : uint32_t { Triangle = 0, Line = 1, Point = 2 };
inline constexpr uint32_t make_command(CommandKind kind, uint32_t index) {
  return (uint32_t(kind) << 30) | index;
}
inline constexpr CommandKind command_kind(uint32_t c) { return CommandKind(c >> 30); }
inline constexpr uint32_t command_index(uint32_t c) { return c & 0x3fffffffu; }
inline constexpr uint32_t kMaxPrimitivesPerFrame = 0x3fffffffu;

// Packs a colour in [0, 1] to RGBA8 as OpenGL does: clamp, scale by 255, round.
inline uint32_t pack_rgba(float r, float g, float b) {
  auto q = [](float v) {
    v = v > 0 ? (v < 1 ? v : 1) : 0;  // NaN (a degenerate normal, say) becomes 0, not UB
    return uint32_t(v * 255.0f + 0.5f);
  };
  return q(r) | (q(g) << 8) | (q(b) << 16) | 0xff000000u;
}

}  // namespace velocity::raster
