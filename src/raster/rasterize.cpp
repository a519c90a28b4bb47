// The tile rasterizer, compiled once per instruction set (Highway's foreach_target) and
// dispatched at run time to the best one the processor has.
#include "raster/rasterize.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>

#include "framebuffer/framebuffer.hpp"
#include "shading/shadow.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/rasterize.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage-inl.h"
#include "raster/fragments-inl.h"
#include "raster/sampler-inl.h"
#include "raster/tile-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// A clear record: the box, colour under its mask, depth, stencil under its mask.
void clear_box(const RecordHeader& r, const TileBox& b, const TileTarget& t) {
  const ClearShape& c = shape<ClearShape>(r);
  Block blocks[kMaxBlocks];
  const int n = rect_blocks(b, blocks);
  for (int i = 0; i < n; ++i) {
    const size_t at = size_t(blocks[i].index) * 16;
    for (int k = 0; k < 16; ++k) {
      if (!(blocks[i].mask >> k & 1)) continue;
      if (c.color_mask) {
        t.color[at + k] = (t.color[at + k] & ~c.color_mask) | (c.color & c.color_mask);
        if (t.ids) t.ids[at + k] = 0;
      }
      if (c.clear_depth) t.depth[at + k] = c.depth;
      if (c.stencil_mask) t.stencil[at + k] = uint8_t((t.stencil[at + k] & ~c.stencil_mask) | (c.stencil & c.stencil_mask));
    }
  }
}

// The kernel of a KernelId, from the table of the translation unit that holds it.
HWY_INLINE KernelFn kernel(uint8_t id) {
  static const KernelFn* const basic = basic_kernels();
  static const KernelFn* const phong = phong_kernels();
  static const KernelFn* const pbr = pbr_kernels();
  static const KernelFn* const fixed = fixed_kernels();
  if (id < uint8_t(KernelId::Phong)) return basic[id];
  if (id < uint8_t(KernelId::Pbr)) return phong[id - uint8_t(KernelId::Phong)];
  if (id < uint8_t(KernelId::Fixed)) return pbr[id - uint8_t(KernelId::Pbr)];
  return fixed[id - uint8_t(KernelId::Fixed)];
}

// A shadow map's tile: window depths to the map's 16-bit codes (shading/shadow.hpp),
// rounded up, stored in the map's rows; the tiles at the map's edges also fill its border
// (the edge texels repeated). Perspective: the clip w of depth z, w = n f / (f - z (f - n))
// (glFrustum's depth), as a fraction of (n, f): kShadowFar n z / (f - z (f - n)).
void store_shadow_codes(const TileInputs& frame, const float* depth, int tx, int ty) {
  const DF d;
  const hn::Rebind<uint16_t, DI> d16;
  const VF far = hn::Set(d, shading::kShadowFar);
  const VF scale = hn::Set(d, frame.shadow_perspective ? shading::kShadowFar * frame.shadow_near : shading::kShadowFar);
  const VF f = hn::Set(d, frame.shadow_far), f_minus_n = hn::Set(d, frame.shadow_far - frame.shadow_near);
  alignas(64) uint16_t codes[Framebuffer::kTilePixels];  // the tile's layout: 4x4 blocks
  for (int i = 0; i < Framebuffer::kTilePixels; i += int(kLanes)) {
    const VF z = hn::Load(d, depth + i);
    VF code = hn::Mul(scale, z);
    if (frame.shadow_perspective) code = hn::Div(code, hn::NegMulAdd(z, f_minus_n, f));
    code = hn::Min(hn::Max(hn::Ceil(code), hn::Zero(d)), far);  // (a NaN's Max gives 0)
    hn::Store(hn::DemoteTo(d16, truncate_in_range(code)), d16, codes + i);
  }
  // Row by row into the map (a block's row of four codes is 8 bytes), as far as the
  // map's edge, which need not be a tile's.
  const int size = frame.shadow_size;
  const size_t stride = size_t(shading::shadow_stride(size));
  const int w = std::min(kTileSize, size - tx), h = std::min(kTileSize, size - ty);
  auto row = [&](int y) { return frame.shadow_codes + size_t(ty + y + 1) * stride + size_t(tx + 1); };
  for (int y = 0; y < h; ++y) {
    const uint16_t* in = codes + (y >> 2) * kBlocksPerTileSide * 16 + (y & 3) * 4;
    uint16_t* out = row(y);
    if (w == kTileSize) {
      for (int b = 0; b < kBlocksPerTileSide; ++b) std::memcpy(out + b * 4, in + b * 16, 8);
    } else {
      for (int x = 0; x < w; ++x) out[x] = in[(x >> 2) * 16 + (x & 3)];
    }
    if (tx == 0) out[-1] = out[0];
    if (tx + w == size) out[w] = out[w - 1];
  }
  const int x0 = tx == 0 ? -1 : 0, x1 = tx + w == size ? w : w - 1;  // this tile's part of a border row
  if (ty == 0) std::memcpy(row(-1) + x0, row(0) + x0, size_t(x1 - x0 + 1) * 2);
  if (ty + h == size) std::memcpy(row(h) + x0, row(h - 1) + x0, size_t(x1 - x0 + 1) * 2);
}

bool RasterizeTile(const TileInputs& frame, int tile, Framebuffer& fb) {
  const Bins& bins = *frame.bins;
  const int tx = (tile % bins.tiles_x()) * kTileSize, ty = (tile / bins.tiles_x()) * kTileSize;
  const size_t base = fb.tile_offset(tile);
  alignas(64) static thread_local uint32_t scratch[Framebuffer::kTilePixels];  // depth only: colour lands here
  alignas(64) static thread_local float scratch_depth[Framebuffer::kTilePixels];  // a shadow map's depth
  const bool codes = frame.shadow_codes != nullptr;
  TileTarget target{frame, frame.depth_only ? scratch : fb.color.data() + base, codes ? scratch_depth : fb.depth.data() + base,
                    fb.stencil.empty() ? nullptr : fb.stencil.data() + base, fb.ids.empty() ? nullptr : fb.ids.data() + base,
                    tx, ty};
  constexpr int kPixels = Framebuffer::kTilePixels;
  // A tile with nothing to draw that already holds exactly the clear values (it was
  // cleared and left empty last frame too: the background of most frames) is done. A
  // stencil buffer the frame does not clear stays as it was: clean if it was.
  const bool full_clear = (frame.clear_color_buffer || frame.depth_only) && frame.clear_depth_buffer;
  const bool nothing = bins.empty(tile);
  uint8_t& clean = fb.tile_clean[size_t(tile)];
  if (full_clear && nothing && clean) return false;
  clean = full_clear && nothing && (frame.clear_stencil_buffer || clean);
  if (frame.clear_color_buffer && !frame.depth_only) {
    std::fill_n(target.color, kPixels, frame.color);
    if (target.ids) std::fill_n(target.ids, kPixels, 0u);
  }
  if (frame.clear_depth_buffer) std::fill_n(target.depth, kPixels, frame.depth);
  if (frame.clear_stencil_buffer && target.stencil) std::fill_n(target.stencil, kPixels, frame.stencil);
  Block blocks[kMaxBlocks];
  Fragments fragments;  // small triangles' pixels, shaded 16 at a time (fragments-inl.h)
  auto flush = [&] { fragments.draw(frame, target.color, target.depth, target.ids); };
  bins.for_each_in_order(tile, [&](const RecordHeader& r, uint32_t) {
    TileBox box;
    if (!tile_box(r, tx, ty, kTileSize, kTileSize, box)) return;
    if (batchable(r)) return fragments.add(r, (*frame.draws)[r.draw], r.min_x - tx, r.min_y - ty, box, flush);
    if (!fragments.empty()) flush();
    if (frame.depth_only && frame.depth_test && r.kind == RecordKind::Triangle && r.kernel == uint8_t(KernelId::Flat))
      return depth_only_triangle(r, box, target);
    int n = 0;
    switch (r.kind) {
      case RecordKind::Triangle: n = triangle_blocks(r, tx, ty, box, blocks); break;
      case RecordKind::Small: n = small_blocks(r, tx, ty, box, blocks); break;
      case RecordKind::Line: n = line_blocks(r, tx, ty, box, blocks); break;
      case RecordKind::Rect: n = rect_blocks(box, blocks); break;
      case RecordKind::Clear: return clear_box(r, box, target);
    }
    if (n) kernel(r.kernel)(r, blocks, n, target);
  });
  flush();
  if (codes) store_shadow_codes(frame, target.depth, tx, ty);
  return true;
}

void CoverageForTest(const RecordHeader& r, int tx, int ty, int tw, int th,
                     void (*callback)(void*, int, int, uint32_t), void* user, bool depth_only) {
  TileBox box;
  if (!tile_box(r, tx, ty, tw, th, box)) return;
  Block blocks[kMaxBlocks];
  int n = r.kind == RecordKind::Triangle
              ? (depth_only ? triangle_blocks<true>(r, tx, ty, box, blocks) : triangle_blocks(r, tx, ty, box, blocks))
          : r.kind == RecordKind::Small  ? small_blocks(r, tx, ty, box, blocks)
          : r.kind == RecordKind::Line   ? line_blocks(r, tx, ty, box, blocks)
                                         : rect_blocks(box, blocks);
  for (int i = 0; i < n; ++i) callback(user, tx + (blocks[i].index & 15) * 4, ty + (blocks[i].index >> 4) * 4, blocks[i].mask);
}

void SampleForTest(const SamplerView& view, float u, float v, float lod, float rgba[4]) {
  const DF d;
  const Rgba c = sample(view, choose_levels(view, lod), hn::Set(d, u), hn::Set(d, v));
  rgba[0] = hn::GetLane(c.r), rgba[1] = hn::GetLane(c.g), rgba[2] = hn::GetLane(c.b), rgba[3] = hn::GetLane(c.a);
}

void SamplePointsForTest(const SamplerView& view, const float* u, const float* v, int n, float lod, float* rgba) {
  const DF d;
  const LevelChoice level = choose_levels(view, lod);
  for (int first = 0; first < n; first += int(kLanes)) {
    alignas(64) float us[kLanes], vs[kLanes], out[4][kLanes];
    for (size_t l = 0; l < kLanes; ++l) {
      const int i = std::min(first + int(l), n - 1);
      us[l] = u[i], vs[l] = v[i];
    }
    const Rgba c = sample(view, level, hn::Load(d, us), hn::Load(d, vs));
    hn::Store(c.r, d, out[0]), hn::Store(c.g, d, out[1]), hn::Store(c.b, d, out[2]), hn::Store(c.a, d, out[3]);
    for (int l = 0; l < int(kLanes) && first + l < n; ++l)
      for (int k = 0; k < 4; ++k) rgba[4 * (first + l) + k] = out[k][l];
  }
}

void Sample3ForTest(const SamplerView& view, float u, float v, float w, float lod, float rgba[4]) {
  const DF d;
  const Rgba c = sample3(view, choose_levels(view, lod), hn::Set(d, u), hn::Set(d, v), hn::Set(d, w));
  rgba[0] = hn::GetLane(c.r), rgba[1] = hn::GetLane(c.g), rgba[2] = hn::GetLane(c.b), rgba[3] = hn::GetLane(c.a);
}

float LevelOfDetailForTest(const SamplerView& view, float dudx, float dvdx, float dudy, float dvdy) {
  return level_of_detail(view, dudx, dvdx, dudy, dvdy);
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::raster {

namespace {
std::atomic<bool> g_pixel_packing{true};
}  // namespace

void set_pixel_packing_for_test(bool on) { g_pixel_packing.store(on, std::memory_order_relaxed); }
bool pixel_packing() { return g_pixel_packing.load(std::memory_order_relaxed); }

HWY_EXPORT(RasterizeTile);
HWY_EXPORT(CoverageForTest);
HWY_EXPORT(TargetName);
HWY_EXPORT(SampleForTest);
HWY_EXPORT(LevelOfDetailForTest);
HWY_EXPORT(Sample3ForTest);
HWY_EXPORT(SamplePointsForTest);

void sample_for_test(const SamplerView& view, float u, float v, float lod, float rgba[4]) {
  HWY_DYNAMIC_DISPATCH(SampleForTest)(view, u, v, lod, rgba);
}
void sample_points_for_test(const SamplerView& view, const float* u, const float* v, int n, float lod, float* rgba) {
  HWY_DYNAMIC_DISPATCH(SamplePointsForTest)(view, u, v, n, lod, rgba);
}
void sample3_for_test(const SamplerView& view, float u, float v, float w, float lod, float rgba[4]) {
  HWY_DYNAMIC_DISPATCH(Sample3ForTest)(view, u, v, w, lod, rgba);
}
float level_of_detail_for_test(const SamplerView& view, float dudx, float dvdx, float dudy, float dvdy) {
  return HWY_DYNAMIC_DISPATCH(LevelOfDetailForTest)(view, dudx, dvdx, dudy, dvdy);
}

bool rasterize_tile(const TileInputs& in, int tile, Framebuffer& fb) { return HWY_DYNAMIC_DISPATCH(RasterizeTile)(in, tile, fb); }

void coverage_for_test(const RecordHeader& record, int tile_x0, int tile_y0, int tile_w, int tile_h,
                       void (*callback)(void*, int, int, uint32_t), void* user, bool depth_only) {
  HWY_DYNAMIC_DISPATCH(CoverageForTest)(record, tile_x0, tile_y0, tile_w, tile_h, callback, user, depth_only);
}

const char* simd_target() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }

}  // namespace velocity::raster
#endif  // HWY_ONCE
