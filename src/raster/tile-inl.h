// What a tile's shading kernels share: where the tile's pixels are, and the kernel
// tables, one per translation unit (so that the heavy kernels compile in parallel):
// kernels_basic.cpp (flat, smooth and their per-vertex-textured forms),
// kernels_phong.cpp (per-pixel lighting, textures, environment maps), kernels_pbr.cpp
// (glTF's metallic-roughness) and
// kernels_fixed.cpp (the fixed-function kernel). Per instruction set, like the rest.
#if defined(VELOCITY_RASTER_TILE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_TILE_INL_H_
#undef VELOCITY_RASTER_TILE_INL_H_
#else
#define VELOCITY_RASTER_TILE_INL_H_
#endif

#include "raster/coverage-inl.h"
#include "raster/rasterize.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

// Where a tile's pixels are, and what the frame asks of it.
struct TileTarget {
  const TileInputs& frame;
  uint32_t* color;  // the tile's first pixel (tiled layout, framebuffer.hpp)
  float* depth;
  uint8_t* stencil;  // null in a shadow map's depth pass, which keeps none
  uint32_t* ids;  // null when the frame keeps no object ids
  int x0, y0;     // the tile's first pixel in the framebuffer
};

// The pixel offsets of a block from the record's anchor (its box's first pixel).
HWY_INLINE void block_origin(const RecordHeader& r, const TileTarget& t, uint16_t index, float& fx, float& fy) {
  block_origin(r, t.x0, t.y0, index, fx, fy);
}

// A record's depth plane at a block's pixels, as every kernel computes it (so that a
// pixel's depth is the same whichever kernel, or packed or not, draws it): the block's
// base at its first pixel (fx, fy from block_origin), then vector v's pixels from it.
struct DepthPlane {
  float c, dx, dy;
  VF vdx, vdy;
  explicit DepthPlane(const RecordHeader& r)
      : c(r.depth.c), dx(r.depth.dx), dy(r.depth.dy), vdx(hn::Set(DF(), dx)), vdy(hn::Set(DF(), dy)) {}
  HWY_INLINE VF block(float fx, float fy) const { return hn::Set(DF(), c + dx * fx + dy * fy); }
  HWY_INLINE VF at(VF block, int v) const { return hn::MulAdd(vdx, block_x(v), hn::MulAdd(vdy, block_y(v), block)); }
};

using KernelFn = void (*)(const RecordHeader&, const Block*, int, const TileTarget&);

// The kernels of each translation unit, indexed from the first KernelId it holds.
const KernelFn* basic_kernels();  // KernelId::Flat .. Phong (exclusive)
const KernelFn* phong_kernels();  // KernelId::Phong .. Pbr (exclusive)
const KernelFn* pbr_kernels();    // KernelId::Pbr .. Fixed (exclusive)
const KernelFn* fixed_kernels();  // KernelId::Fixed .. Count (exclusive)

// Shading in whole vectors. A triangle's blocks along its edges leave lanes idle (the
// bench's sphere:64 at 1920x1080 fills 11.6 of 16 lanes a vector), and a per-pixel
// shader costs the same per vector however many lanes it writes. On AVX-512 (a block is
// one vector; compress and expand are instructions there) the Phong and PBR kernels
// depth-test a run of blocks first, pack the pixels that passed 16 to a vector (their
// offsets from the record's anchor), shade those, and expand the colours back into each
// block. The last vector's spare lanes repeat its last pixel: every lane a shader sees is
// a pixel of the triangle. A run's blocks choose the same texture levels (a block whose
// levels differ starts a new run); the weight between two levels travels with each pixel.
// The planes are evaluated at each pixel as in a block (Planes), so a pixel's colour does
// not depend on how it was packed.
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
inline constexpr bool kPackPixels = true;
#else
inline constexpr bool kPackPixels = false;
#endif

// What shade_packed asks of a shader: plan_levels done; level_count() textures whose
// levels block b chooses (block_levels(b, out)); use_levels(levels, weights) and
// at_pixels(x, y) before each vector. `shade(live)`: the vector's packed colours.
template <class Shader, class Shade>
HWY_INLINE void shade_packed(const RecordHeader& r, const Block* blocks, int n, const TileTarget& t, Shader& shader,
                             Shade&& shade) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  const DF d;
  const DU du;
  constexpr int kRun = 32;  // blocks at most in a run: the buffers stay in the L1 cache
  constexpr int kLevels = 5;  // textures at most (a PBR material's)
  constexpr int kPixels = kRun * 16 + 16;  // and room for a vector's spare lanes
  alignas(64) float xs[kPixels], ys[kPixels], weights[kLevels][kPixels];
  alignas(64) uint32_t colors[kPixels];
  uint16_t masks[kRun];
  LevelChoice run_levels[kLevels], levels[kLevels];
  const int nl = shader.level_count();
  const bool depth_test = t.frame.depth_test;
  const DepthPlane depth(r);
  const VU id = hn::Set(du, (*t.frame.draws)[r.draw].object_id);
  const MF all = hn::FirstN(d, kLanes);
  int first = 0, count = 0;  // the run's first block, and its pixels so far
  // Shades the run's pixels and writes them into blocks first..end-1.
  auto finish_run = [&](int end) {
    if (count) {
      auto pad = [&](float* v) { hn::StoreU(hn::Set(d, v[count - 1]), d, v + count); };
      pad(xs), pad(ys);
      for (int k = 0; k < nl; ++k) pad(weights[k]);
      for (int i = 0; i < count; i += int(kLanes)) {
        VF w[kLevels];
        for (int k = 0; k < nl; ++k) w[k] = hn::Load(d, weights[k] + i);
        shader.use_levels(run_levels, w);
        shader.at_pixels(hn::Load(d, xs + i), hn::Load(d, ys + i));
        hn::Store(shade(all), du, colors + i);
      }
      int at = 0;
      for (int b = first; b < end; ++b) {
        const uint32_t bits = masks[b - first];
        if (!bits) continue;
        const VU c{_mm512_maskz_expandloadu_epi32(__mmask16(bits), colors + at)};
        store_masked(c, hn::RebindMask(du, lane_mask(bits, 0)), du, t.color + size_t(blocks[b].index) * 16);
        at += int(hwy::PopCount(bits));
      }
    }
    first = end, count = 0;
  };
  auto same = [&] {
    for (int k = 0; k < nl; ++k)
      if (levels[k].level0 != run_levels[k].level0 || levels[k].level1 != run_levels[k].level1 ||
          levels[k].filter != run_levels[k].filter)
        return false;
    return true;
  };
  for (int b = 0; b < n; ++b) {
    if (nl) shader.block_levels(b, levels);
    if (b - first == kRun || (nl && b > first && !same())) finish_run(b);
    if (b == first) std::copy_n(levels, nl, run_levels);
    const Block& blk = blocks[b];
    float fx, fy;
    block_origin(r, t, blk.index, fx, fy);
    MF m = lane_mask(blk.mask, 0);
    const size_t at = size_t(blk.index) * 16;
    if (depth_test) {
      const VF z = depth.at(depth.block(fx, fy), 0);
      m = hn::And(m, hn::Lt(z, hn::Load(d, t.depth + at)));
      store_masked(z, m, d, t.depth + at);
    }
    const uint32_t bits = lane_bits(d, m);
    masks[b - first] = uint16_t(bits);
    if (!bits) continue;
    hn::StoreU(hn::Compress(hn::Add(hn::Set(d, fx), block_x(0)), m), d, xs + count);
    hn::StoreU(hn::Compress(hn::Add(hn::Set(d, fy), block_y(0)), m), d, ys + count);
    for (int k = 0; k < nl; ++k) hn::StoreU(hn::Set(d, levels[k].frac), d, weights[k] + count);
    if (t.ids) store_masked(id, hn::RebindMask(du, m), du, t.ids + at);
    count += int(hwy::PopCount(bits));
  }
  finish_run(n);
#else
  (void)r, (void)blocks, (void)n, (void)t, (void)shader, (void)shade;
#endif
}

// The depth test and the writes of the mesh kernels: LESS before shading (none in
// painter's mode), opaque colour, object ids.
template <class Shader>
HWY_NOINLINE void mesh_kernel(const RecordHeader& r, const Block* blocks, int n, const TileTarget& t) {
  const DF d;
  const DU du;
  const DrawState& draw = (*t.frame.draws)[r.draw];
  Shader shader(r, draw, t.frame);
  if constexpr (requires { shader.plan_levels(r, blocks, n, t.x0, t.y0); }) shader.plan_levels(r, blocks, n, t.x0, t.y0);
  if constexpr (kPackPixels && requires { requires Shader::kPackable; }) {
    if (pixel_packing())
      return shade_packed(r, blocks, n, t, shader, [&](MF live) {
        if constexpr (requires { shader.shade(0, live); }) return shader.shade(0, live);
        else return shader.shade(0);
      });
  }
  const bool depth_test = t.frame.depth_test;
  const DepthPlane depth(r);
  const VU id = hn::Set(du, draw.object_id);
  for (int b = 0; b < n; ++b) {
    const Block& blk = blocks[b];
    float fx, fy;
    block_origin(r, t, blk.index, fx, fy);
    const VF z0 = depth.block(fx, fy);
    shader.begin_block(fx, fy, b);
    const size_t at = size_t(blk.index) * 16;
    for (int v = 0; v < kVectorsPerBlock; ++v) {
      if (kVectorsPerBlock > 1 && vector_empty(blk.mask, v)) continue;
      MF m = lane_mask(blk.mask, v);
      float* zp = t.depth + at + v * kLanes;
      if (depth_test) {
        const VF z = depth.at(z0, v);
        m = hn::And(m, hn::Lt(z, hn::Load(d, zp)));
        if (hn::AllFalse(d, m)) continue;
        store_masked(z, m, d, zp);
      }
      const auto mu = hn::RebindMask(du, m);
      // A shader that can skip work for the lanes not written (shadow lookups) is told them.
      if constexpr (requires { shader.shade(v, m); })
        store_masked(shader.shade(v, m), mu, du, t.color + at + v * kLanes);
      else
        store_masked(shader.shade(v), mu, du, t.color + at + v * kLanes);
      if (t.ids) store_masked(id, mu, du, t.ids + at + v * kLanes);
    }
  }
}

// A depth-only draw's triangle (a shadow map's opaque caster: TileInputs::depth_only with
// the flat kernel, whose colour goes nowhere): mesh_kernel's depth test and write, with
// the same depths, done for each 4x4 block as the coverage finds it, with no list of
// blocks, no shader and no colour.
HWY_INLINE void depth_only_triangle(const RecordHeader& r, const TileBox& box, const TileTarget& t) {
  const DF d;
  const DepthPlane depth(r);
  auto write = [&](uint16_t index, uint32_t mask) {
    if (!mask) return;
    float fx, fy;
    block_origin(r, t, index, fx, fy);
    const VF z0 = depth.block(fx, fy);
    float* zp = t.depth + size_t(index) * 16;
    for (int v = 0; v < kVectorsPerBlock; ++v) {
      const VF z = depth.at(z0, v);
      const VF old = hn::Load(d, zp + v * kLanes);
      // A plain store of the blend: no other thread writes the tile, and a masked store
      // is far slower on AMD's cores (about half the flat kernel's samples sat after them).
      hn::Store(hn::IfThenElse(hn::And(lane_mask(mask, v), hn::Lt(z, old)), z, old), d, zp + v * kLanes);
    }
  };
  triangle_cover<true>(r, t.x0, t.y0, box, write);
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_TILE_INL_H_ toggle
