// Coverage: which pixels of a tile a record covers, as a list of 4x4 blocks with a
// 16-bit mask each (bit y * 4 + x). Hierarchical for triangles: 16x16 blocks are
// accepted or rejected whole with one exact 64-bit evaluation per edge, and only the
// 4x4 blocks of partly covered 16x16 blocks test their pixels, 16 at a time.
//
// Exactness: a pixel is covered when all three edge functions are >= 0 at its centre,
// E = a * px + b * py + c in 24.8 fixed point (contract.hpp). One pixel step adds
// 256 * a, so for a block whose first centre has E0, E at pixel (i, j) of the block is
// E0 + 256 * (a * i + b * j), and E >= 0 exactly when q + a * i + b * j >= 0 with
// q = floor(E0 / 256). With |a|, |b| < 2^24 and q taken only where the block is neither
// wholly inside nor wholly outside the edge, every such value fits int32.
#if defined(VELOCITY_RASTER_COVERAGE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_COVERAGE_INL_H_
#undef VELOCITY_RASTER_COVERAGE_INL_H_
#else
#define VELOCITY_RASTER_COVERAGE_INL_H_
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "raster/contract.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// A covered 4x4 block of a tile: its index (row-major, 16 per row) and pixel mask.
struct Block {
  uint16_t index;
  uint16_t mask;
};
inline constexpr int kMaxBlocks = kBlocksPerTileSide * kBlocksPerTileSide;  // 256

// The pixel offsets of block `index` of the tile whose first pixel is (x0, y0) from the
// record's anchor (its box's first pixel).
HWY_INLINE void block_origin(const RecordHeader& r, int x0, int y0, uint16_t index, float& fx, float& fy) {
  fx = float(x0 + (index & 15) * 4 - r.min_x);
  fy = float(y0 + (index >> 4) * 4 - r.min_y);
}

// The pixels of the 4x4 block at (bx, by) (tile pixels) inside the inclusive box.
HWY_INLINE uint32_t box_mask(int bx, int by, int x0, int y0, int x1, int y1) {
  int c0 = std::max(x0 - bx, 0), c1 = std::min(x1 - bx, 3);
  int r0 = std::max(y0 - by, 0), r1 = std::min(y1 - by, 3);
  if (c0 > c1 || r0 > r1) return 0;
  uint32_t cols = ((1u << (c1 + 1)) - 1) & ~((1u << c0) - 1);
  uint32_t rows = ((1u << (4 * (r1 + 1))) - 1) & ~((1u << (4 * r0)) - 1);
  return (cols * 0x1111u) & rows;
}

// The record's box within the tile, in tile pixels; false when they do not meet.
struct TileBox {
  int x0, y0, x1, y1;  // inclusive
};
HWY_INLINE bool tile_box(const RecordHeader& r, int tx, int ty, int tw, int th, TileBox& b) {
  b.x0 = std::max<int>(r.min_x - tx, 0), b.y0 = std::max<int>(r.min_y - ty, 0);
  b.x1 = std::min<int>(r.max_x - tx, tw - 1), b.y1 = std::min<int>(r.max_y - ty, th - 1);
  return b.x0 <= b.x1 && b.y0 <= b.y1;
}

// A rectangle: every pixel of the box.
HWY_INLINE int rect_blocks(const TileBox& b, Block* out) {
  int n = 0;
  for (int by = b.y0 & ~3; by <= b.y1; by += 4)
    for (int bx = b.x0 & ~3; bx <= b.x1; bx += 4)
      out[n++] = {uint16_t((by >> 2) * kBlocksPerTileSide + (bx >> 2)), uint16_t(box_mask(bx, by, b.x0, b.y0, b.x1, b.y1))};
  return n;
}

// The lanes of vector v of a block (bits as mask_bits places them) where x < 0. With x
// the OR of edge values, the pixels (or blocks) outside some edge: all of them are >= 0
// exactly when the sign bit of their OR is clear, one compare with zero for them all.
// (A compare E > -1 per edge costs twice as much: GCC turns it into E >= 0, which AVX2
// does as a min and an equality.)
HWY_INLINE uint32_t negative_lanes(VI x, int v) {
  return mask_bits(hn::RebindMask(DF(), hn::Lt(x, hn::Zero(DI()))), v);
}

// The pixels of vector v of a block outside one of the three edges, E = q[k] + step[k][v].
HWY_INLINE uint32_t negative_bits(const VI (&q)[3], const VI (&step)[3][kVectorsPerBlock], int v) {
  const VI any = hn::Or(hn::Or(hn::Add(q[0], step[0][v]), hn::Add(q[1], step[1][v])), hn::Add(q[2], step[2][v]));
  return negative_lanes(any, v);
}

// A triangle less than 128 pixels wide and tall: every |a| and |b| below 128 pixels
// (in 24.8). Anywhere within a few blocks of its box |E| < 2^32, so floor(E / 256) <
// 2^24 and the steps a * i + b * j across the box fit int32 with room to spare.
HWY_INLINE bool covered_by_rows(const TriangleEdges& e) {
  bool rows = true;
  for (int k = 0; k < 3; ++k) rows = rows && std::abs(e.a[k]) < 128 * kSubpixelOne && std::abs(e.b[k]) < 128 * kSubpixelOne;
  return rows;
}

// Its 4x4 blocks test their pixels directly, row by row of the box, three vector adds
// from one block to the next. The 16x16 and 4x4 classification below pays off on
// larger triangles only: on the dozen pixels of a dense mesh's it was most of the
// coverage's time, and up to 128 pixels a side rows are still faster (velocity bench
// sphere:64 gouraud, triangles of about 35 pixels a side, and a 2048² shadow map's depth
// pass: docs/performance.md, stop 29). The same test, the same pixels; `step` is
// triangle_blocks' per-edge a * i + b * j of a block's pixels.
template <bool kRuns, class Emit>
HWY_INLINE void row_cover(const TriangleEdges& e, const VI (&step)[3][kVectorsPerBlock], int tx, int ty,
                          const TileBox& box, Emit& emit) {
  const DI di;
  const int bx0 = box.x0 & ~3, by0 = box.y0 & ~3;
  const int64_t px = int64_t(tx + bx0) * kSubpixelOne + kSubpixelHalf;
  const int64_t py = int64_t(ty + by0) * kSubpixelOne + kSubpixelHalf;
  // Per edge, floor(E / 256) at the first pixel centre of the row's first block, its step
  // to the next block across, and the most it gains within a block (so that q + most < 0:
  // the whole block is outside the edge).
  int32_t row[3], most[3];
  VI across[3];
  for (int k = 0; k < 3; ++k) {
    row[k] = int32_t((int64_t(e.a[k]) * px + int64_t(e.b[k]) * py + e.c[k]) >> kSubpixelBits);
    most[k] = std::max(0, 3 * e.a[k]) + std::max(0, 3 * e.b[k]);
    across[k] = hn::Set(di, 4 * e.a[k]);
  }
  // box_mask's columns: only the first and last block of a row cut the box's sides; its
  // rows, once a row of blocks.
  const int bx_last = box.x1 & ~3;
  const uint32_t first_cols = box_mask(bx0, 0, box.x0, 0, box.x1, 3), last_cols = box_mask(bx_last, 0, box.x0, 0, box.x1, 3);
  for (int by = by0; by <= box.y1; by += 4) {
    const uint32_t rows = box_mask(0, by, 0, box.y0, 3, box.y1);
    int32_t q[3] = {row[0], row[1], row[2]};
    auto outside_an_edge = [&] { return ((q[0] + most[0]) | (q[1] + most[1]) | (q[2] + most[2])) < 0; };
    auto next = [&] {
      for (int k = 0; k < 3; ++k) q[k] += 4 * e.a[k];
    };
    // kRuns: the blocks of a row that no edge excludes whole are one run (each edge
    // excludes those on one side of a column): skip to it, stop after it, so that only
    // its blocks test their pixels (a triangle covers about half of its box).
    int bx = bx0;
    if constexpr (kRuns)
      for (; bx <= box.x1 && outside_an_edge(); bx += 4) next();
    VI qv[3] = {hn::Set(di, q[0]), hn::Set(di, q[1]), hn::Set(di, q[2])};
    for (; bx <= box.x1; bx += 4) {
      if constexpr (kRuns) {
        if (outside_an_edge()) break;
        next();
      }
      uint32_t outside = 0;
      for (int v = 0; v < kVectorsPerBlock; ++v) outside |= negative_bits(qv, step, v);
      const uint32_t cols = (bx == bx0 ? first_cols : 0xffffu) & (bx == bx_last ? last_cols : 0xffffu);
      emit(uint16_t((by >> 2) * kBlocksPerTileSide + (bx >> 2)), ~outside & rows & cols);
      for (int k = 0; k < 3; ++k) qv[k] = hn::Add(qv[k], across[k]);
    }
    for (int k = 0; k < 3; ++k) row[k] += 4 * e.b[k];
  }
}

// A triangle, hierarchically: 16x16 blocks, then 4x4 blocks, then pixels. Each 4x4
// block whose pixels were tested goes to emit(index, mask) as it is found, mask 0 when
// none is covered: whether a small triangle covers a block is a coin toss to the branch
// predictor, and triangle_blocks lists them without a branch (a depth-only draw writes
// their depth at once, tile-inl.h). kRuns: row_cover's, for a triangle below 128 pixels.
template <bool kRuns, class Emit>
HWY_INLINE void triangle_cover(const RecordHeader& r, int tx, int ty, const TileBox& box, Emit& emit) {
  const TriangleEdges& e = shape<TriangleEdges>(r);
  const DI di;
  // Per edge, a * i + b * j for each pixel (i, j) of a 4x4 block, lane by lane.
  VI step[3][kVectorsPerBlock];
  for (int k = 0; k < 3; ++k)
    for (int v = 0; v < kVectorsPerBlock; ++v)
      step[k][v] = hn::Add(hn::Mul(hn::Set(di, e.a[k]), hn::Load(di, kBlockXi + v * kLanes)),
                           hn::Mul(hn::Set(di, e.b[k]), hn::Load(di, kBlockYi + v * kLanes)));
  if (covered_by_rows(e)) return row_cover<kRuns>(e, step, tx, ty, box, emit);

  for (int my = box.y0 >> 4; my <= box.y1 >> 4; ++my)
    for (int mx = box.x0 >> 4; mx <= box.x1 >> 4; ++mx) {
      // Classify the 16x16 block against each edge at its first pixel centre: wholly
      // outside one edge rejects it; edges it lies wholly inside need no pixel tests.
      const int64_t px = int64_t(tx + mx * 16) * kSubpixelOne + kSubpixelHalf;
      const int64_t py = int64_t(ty + my * 16) * kSubpixelOne + kSubpixelHalf;
      int32_t q[3];
      int edge[3], partial = 0;
      bool outside = false;
      for (int k = 0; k < 3; ++k) {
        const int64_t a = e.a[k], b = e.b[k];
        const int64_t Q = (a * px + b * py + e.c[k]) >> kSubpixelBits;  // floor(E / 256)
        const int64_t lo = Q + std::min<int64_t>(0, 15 * a) + std::min<int64_t>(0, 15 * b);
        const int64_t hi = Q + std::max<int64_t>(0, 15 * a) + std::max<int64_t>(0, 15 * b);
        if (hi < 0) {
          outside = true;
          break;
        }
        if (lo < 0) q[partial] = int32_t(Q), edge[partial++] = k;
      }
      if (outside) continue;
      // Its sixteen 4x4 blocks against each partial edge, exactly, before any pixel
      // test, a lane per block (bit v * 4 + u for block column u, row v): wholly outside
      // one edge rejects a block; wholly inside all needs no pixel test.
      uint32_t out_blocks = 0, not_in_blocks = 0;
      if (partial)
        for (int v = 0; v < kVectorsPerBlock; ++v) {
          const VI u4 = hn::ShiftLeft<2>(hn::Load(di, kBlockXi + v * kLanes));
          const VI v4 = hn::ShiftLeft<2>(hn::Load(di, kBlockYi + v * kLanes));
          // The block's largest and smallest value of edge p (floor(E / 256)).
          auto extreme = [&](int p, bool largest) {
            const int32_t a = e.a[edge[p]], b = e.b[edge[p]];
            const VI qb = hn::Add(hn::Set(di, q[p]), hn::Add(hn::Mul(hn::Set(di, a), u4), hn::Mul(hn::Set(di, b), v4)));
            return hn::Add(qb, hn::Set(di, largest ? std::max(0, 3 * a) + std::max(0, 3 * b)
                                                   : std::min(0, 3 * a) + std::min(0, 3 * b)));
          };
          // Some edge's largest value negative: outside; some edge's smallest negative: not
          // wholly inside.
          VI largest = extreme(0, true), smallest = extreme(0, false);
          for (int p = 1; p < partial; ++p) {
            largest = hn::Or(largest, extreme(p, true));
            smallest = hn::Or(smallest, extreme(p, false));
          }
          out_blocks |= negative_lanes(largest, v);
          not_in_blocks |= negative_lanes(smallest, v);
        }
      const uint32_t in_blocks = ~not_in_blocks;
      const int bx0 = std::max(box.x0, mx * 16) & ~3, bx1 = std::min(box.x1, mx * 16 + 15);
      const int by0 = std::max(box.y0, my * 16) & ~3, by1 = std::min(box.y1, my * 16 + 15);
      // A 16x16 block inside the box (most of a large triangle's) needs no box masks.
      const bool in_box = box.x0 <= mx * 16 && mx * 16 + 15 <= box.x1 && box.y0 <= my * 16 && my * 16 + 15 <= box.y1;
      for (int by = by0; by <= by1; by += 4)
        for (int bx = bx0; bx <= bx1; bx += 4) {
          uint32_t mask = in_box ? 0xffffu : box_mask(bx, by, box.x0, box.y0, box.x1, box.y1);
          if (partial && mask) {
            const int i = bx - mx * 16, j = by - my * 16;  // this 4x4 block in the 16x16 one
            const int k = (j >> 2) * 4 + (i >> 2);
            if (out_blocks >> k & 1) continue;
            if (!(in_blocks >> k & 1)) {
              int32_t qb[3] = {};  // (all set: partial > 0; the compiler cannot tell once inlined)
              for (int p = 0; p < partial; ++p) qb[p] = q[p] + e.a[edge[p]] * i + e.b[edge[p]] * j;
              uint32_t missed = 0;  // pixels outside a partial edge
              for (int v = 0; v < kVectorsPerBlock; ++v) {
                VI any = hn::Add(hn::Set(di, qb[0]), step[edge[0]][v]);
                for (int p = 1; p < partial; ++p) any = hn::Or(any, hn::Add(hn::Set(di, qb[p]), step[edge[p]][v]));
                missed |= negative_lanes(any, v);
              }
              mask &= ~missed;
            }
          }
          emit(uint16_t((by >> 2) * kBlocksPerTileSide + (bx >> 2)), mask);
        }
    }
}

// A triangle's covered 4x4 blocks, listed in `out`; their number. kRuns: walked as a
// depth-only draw walks it (triangle_cover's; the kernels list blocks without).
template <bool kRuns = false>
HWY_NOINLINE int triangle_blocks(const RecordHeader& r, int tx, int ty, const TileBox& box, Block* out) {
  int n = 0;
  auto list = [&](uint16_t index, uint32_t mask) { out[n] = {index, uint16_t(mask)}; n += mask != 0; };
  triangle_cover<kRuns>(r, tx, ty, box, list);
  return n;
}

// A small triangle: its 8x8 mask at (min_x, min_y), cut into the aligned blocks it
// straddles.
HWY_INLINE int small_blocks(const RecordHeader& r, int tx, int ty, const TileBox& box, Block* out) {
  const uint64_t mask = shape<SmallShape>(r).mask;
  const int ox = r.min_x - tx, oy = r.min_y - ty;  // the mask's origin in tile pixels
  int n = 0;
  for (int by = box.y0 & ~3; by <= box.y1; by += 4)
    for (int bx = box.x0 & ~3; bx <= box.x1; bx += 4) {
      uint32_t m = 0;
      for (int row = 0; row < 4; ++row) {
        const int src = by + row - oy;  // the mask's row landing on this block row
        if (src < 0 || src >= kSmallSide) continue;
        const int shift = ox - bx;  // mask column c lands on block column c + shift
        const uint32_t line = uint32_t(mask >> (kSmallSide * src)) & 0xff;
        const uint32_t bits = (shift >= 0 ? line << shift : line >> -shift) & 0xf;
        m |= bits << (4 * row);
      }
      m &= box_mask(bx, by, box.x0, box.y0, box.x1, box.y1);
      if (m) out[n++] = {uint16_t((by >> 2) * kBlocksPerTileSide + (bx >> 2)), uint16_t(m)};
    }
  return n;
}

// A line: per column (x-major) or row (y-major) of the tile whose centre lies between
// its start (included) and end (excluded), `width` pixels across, centred on the segment.
inline HWY_NOINLINE int line_blocks(const RecordHeader& r, int tx, int ty, const TileBox& box, Block* out) {
  const LineShape& l = shape<LineShape>(r);
  // Most lines touch a few blocks of the tile: collect their masks in `out` directly,
  // through a map from block to its place there (valid where `seen` has the block's
  // bit), rather than clearing and scanning a mask for every block of the tile.
  uint64_t seen[kMaxBlocks / 64] = {};
  uint8_t place[kMaxBlocks];
  int n = 0;
  const bool xm = l.x_major != 0;
  const float a0 = xm ? l.x0 : l.y0, a1 = xm ? l.x1 : l.y1;  // major axis, start to end
  const float b0 = xm ? l.y0 : l.x0, b1 = xm ? l.y1 : l.x1;  // minor axis
  const float len = a1 - a0;
  const int origin_a = xm ? tx : ty, origin_b = xm ? ty : tx;
  // GL's diamond-exit rule along the major axis: the pixels whose centres lie from the
  // start (included: the line leaves that pixel) to the end (excluded), in the line's
  // direction, so reversing a line moves its first and last pixel, as in Mesa.
  const int first = len >= 0 ? int(std::ceil(a0 - 0.5f)) : int(std::floor(a1 - 0.5f)) + 1;
  const int last = len >= 0 ? int(std::ceil(a1 - 0.5f)) - 1 : int(std::floor(a0 - 0.5f));
  const int lo_a = std::max(first, origin_a + (xm ? box.x0 : box.y0));
  const int hi_a = std::min(last, origin_a + (xm ? box.x1 : box.y1));
  const int lo_b = origin_b + (xm ? box.y0 : box.x0), hi_b = origin_b + (xm ? box.y1 : box.x1);
  const int half = (l.width - 1) / 2;
  // A crossing exactly on a pixel boundary lights the pixel below or left of it (a
  // line on the boundary with gluOrtho2D(0, w, 0, h) and integer coordinates), except
  // for a rising x-major line, which lights the one above: where Mesa puts them.
  const bool tie_up = xm && (b1 - b0) * len > 0;
  const bool skip_tied_start = len < 0 && (xm ? b1 - b0 >= 0 : b1 - b0 < 0);
  for (int a = lo_a; a <= hi_a; ++a) {
    const float s = len != 0 ? (float(a) + 0.5f - a0) / len : 0.0f;
    const float v = b0 + s * (b1 - b0);
    const float up = std::ceil(v);
    const int centre = int(up) - 1 + (tie_up && up == v ? 1 : 0);
    // A line going left (or down) that starts exactly on such a boundary, at a pixel
    // centre, leaves out that first pixel when it goes up (x-major) or left (y-major),
    // as Mesa does.
    if (skip_tied_start && up == v && float(a) + 0.5f == a0) continue;
    for (int b = std::max(centre - half, lo_b); b <= std::min(centre - half + l.width - 1, hi_b); ++b) {
      const int x = (xm ? a : b) - tx, y = (xm ? b : a) - ty;
      const int block = (y >> 2) * kBlocksPerTileSide + (x >> 2);
      const uint16_t bit = uint16_t(1u << ((y & 3) * 4 + (x & 3)));
      uint64_t& word = seen[block >> 6];
      if (word >> (block & 63) & 1) {
        out[place[block]].mask |= bit;
      } else {
        word |= uint64_t(1) << (block & 63);
        place[block] = uint8_t(n);
        out[n++] = {uint16_t(block), bit};
      }
    }
  }
  return n;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_COVERAGE_INL_H_ toggle
