// What the geometry stage hands the rasterizer: primitive records in screen space.
//
// Screen space: x to the right, y down, pixel (x, y) covers [x, x+1) x [y, y+1) and is
// sampled at its centre (x + 0.5, y + 0.5). Triangle vertices are snapped to 24.8 fixed
// point (kSubpixelBits = 8, as in Mesa's llvmpipe), so coverage is exact integer
// arithmetic: a shared edge is evaluated bit-identically by both triangles.
//
// A record is a RecordHeader, then its shape (TriangleEdges, LineShape or ClearShape by
// kind), then `num_varyings` interpolation planes. Records live in per-worker arenas
// (raster/bins.hpp) and are read, never written, by the tiles.
#pragma once

#include <cstddef>
#include <cstdint>

namespace velocity::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelOne = 1 << kSubpixelBits;  // 256
inline constexpr int kSubpixelHalf = kSubpixelOne / 2;   // the pixel centre, 0.5

// Guard band: geometry reaching no further than this many pixels outside the
// framebuffer is rasterised as it is (the bounding box is scissored); anything beyond
// is clipped against the guard-band planes first. With framebuffers up to 16384 pixels
// a side, snapped coordinates stay within +-2^23 (24.8 fixed point), so edge
// coefficients (coordinate differences) stay below 2^24 and fit int32, and edge
// functions (products below 2^48) fit int64.
inline constexpr float kGuardBandPixels = 16384.0f;
inline constexpr int kMaxFramebufferSide = 16384;

inline constexpr int kTileSizeLog2 = 6;
inline constexpr int kTileSize = 1 << kTileSizeLog2;  // 64x64 pixel tiles
inline constexpr int kBlockSize = 4;                  // 4x4 pixel blocks: one SIMD block
inline constexpr int kBlocksPerTileSide = kTileSize / kBlockSize;  // 16

// Per-vertex values interpolated across a primitive (colour, normal, eye position, ...).
inline constexpr int kMaxVaryings = 12;

// A linear function of the pixel position, value = c + dx * (x - x0) + dy * (y - y0),
// where (x0, y0) is the centre of the record's first bounding-box pixel (min_x, min_y).
// Anchoring at the box keeps the evaluation free of cancellation far from the origin.
struct Plane {
  float c = 0, dx = 0, dy = 0;
};

enum class RecordKind : uint8_t { Triangle, Small, Line, Rect, Clear };

struct RecordHeader {
  RecordKind kind;
  uint8_t kernel;        // shading kernel (raster/kernels.hpp), chosen once per draw
  uint8_t num_varyings;  // planes after the shape
  uint8_t pad = 0;
  uint32_t draw;         // index of the DrawState it came from
  // Inclusive pixel bounding box, clipped to the framebuffer and the draw's scissor.
  int16_t min_x, min_y, max_x, max_y;
  uint32_t flat_color;  // RGBA8 of the flat kernels (a lit face, a line's colour)
  Plane depth;          // window z in [0, 1], affine in screen space
  Plane inv_w;          // 1 / w_clip, for perspective correction (constant 1 when affine)
  float sort_key = 0;   // painter's mode: mean window depth, drawn far to near
};
static_assert(sizeof(RecordHeader) == 48);

// Edge functions E_i(px, py) = a_i * px + b_i * py + c_i over 24.8 fixed-point
// pixel-centre coordinates; a pixel is covered when all three are >= 0. The top-left
// rule is folded into c_i: non-top-left edges had 1 subtracted, so a centre exactly on
// such an edge is left to the neighbour that shares it.
struct TriangleEdges {
  int32_t a[3], b[3];
  int64_t c[3];
};

// A line `width` pixels wide: for each pixel column (x-major) or row (y-major) whose
// centre lies in [start, end) along the major axis, the `width` pixels across it
// centred where the segment crosses that centre line (OpenGL's aliased wide lines; the
// half-open range is the diamond-exit rule in effect, so lines that meet at a vertex
// do not both draw it).
struct LineShape {
  float x0, y0, x1, y1;
  int32_t width;
  int32_t x_major;
};

// A small triangle (its pixel centres within 8x8): the pixels it covers, found exactly
// at set-up (or by the triangle stage's first pass), as an 8x8 mask at (min_x, min_y),
// bit y * 8 + x. No edges.
struct SmallShape {
  uint64_t mask;
};
inline constexpr int kSmallSide = 8;

// A 4x4 mask (bit y * 4 + x) as an 8x8 one (bit y * 8 + x).
inline constexpr uint64_t small_mask_from_4x4(uint32_t m) {
  uint64_t out = 0;
  for (int row = 0; row < 4; ++row) out |= uint64_t((m >> (4 * row)) & 0xf) << (8 * row);
  return out;
}

// A clear of the bounding box (the record's min/max): the colour value under
// `color_mask` and/or the depth value.
struct ClearShape {
  uint32_t color;
  float depth;
  uint32_t color_mask;  // RGBA8 bits that are written (0 when colour is not cleared)
  uint32_t clear_depth;
};

// Rect records (points, and a fully covered box) have no shape: the bounding box is the
// coverage.

inline constexpr size_t shape_bytes(RecordKind k) {
  switch (k) {
    case RecordKind::Triangle: return sizeof(TriangleEdges);
    case RecordKind::Small: return sizeof(SmallShape);
    case RecordKind::Line: return sizeof(LineShape);
    case RecordKind::Clear: return sizeof(ClearShape);
    default: return 0;
  }
}
inline constexpr size_t record_bytes(RecordKind k, int num_varyings) {
  return (sizeof(RecordHeader) + shape_bytes(k) + sizeof(Plane) * size_t(num_varyings) + 7) / 8 * 8;
}
template <class Shape>
inline const Shape& shape(const RecordHeader& r) {
  return *reinterpret_cast<const Shape*>(reinterpret_cast<const std::byte*>(&r) + sizeof(RecordHeader));
}
template <class Shape>
inline Shape& shape(RecordHeader& r) {
  return *reinterpret_cast<Shape*>(reinterpret_cast<std::byte*>(&r) + sizeof(RecordHeader));
}
inline const Plane* varyings(const RecordHeader& r) {
  return reinterpret_cast<const Plane*>(reinterpret_cast<const std::byte*>(&r) + sizeof(RecordHeader) +
                                        shape_bytes(r.kind));
}
inline Plane* varyings(RecordHeader& r) {
  return reinterpret_cast<Plane*>(reinterpret_cast<std::byte*>(&r) + sizeof(RecordHeader) + shape_bytes(r.kind));
}

// Packs a colour in [0, 1] to RGBA8 as OpenGL does: clamp, scale by 255, round.
inline uint32_t pack_rgba(float r, float g, float b, float a = 1.0f) {
  auto q = [](float v) {
    v = v > 0 ? (v < 1 ? v : 1) : 0;  // NaN (a degenerate normal, say) becomes 0, not UB
    return uint32_t(v * 255.0f + 0.5f);
  };
  return q(r) | (q(g) << 8) | (q(b) << 16) | (q(a) << 24);
}

}  // namespace velocity::raster
