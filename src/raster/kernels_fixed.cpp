// The fixed-function kernel of pre-transformed batches (OpenGL 1.x's per-fragment work).
// Compiled once per instruction set; see raster/tile-inl.h.
#include "raster/rasterize.hpp"

#include <type_traits>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/kernels_fixed.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/shade_fixed-inl.h"
#include "raster/tile-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// glLogicOp on packed RGBA8 colours: s the fragment's, d the pixel's.
HWY_INLINE VU logic_op(LogicOp op, VU s, VU d) {
  const VU ones = hn::Set(DU(), 0xffffffffu);
  switch (op) {
    case LogicOp::Clear: return hn::Zero(DU());
    case LogicOp::And: return hn::And(s, d);
    case LogicOp::AndReverse: return hn::AndNot(d, s);
    case LogicOp::Copy: return s;
    case LogicOp::AndInverted: return hn::AndNot(s, d);
    case LogicOp::Noop: return d;
    case LogicOp::Xor: return hn::Xor(s, d);
    case LogicOp::Or: return hn::Or(s, d);
    case LogicOp::Nor: return hn::Xor(hn::Or(s, d), ones);
    case LogicOp::Equiv: return hn::Xor(hn::Xor(s, d), ones);
    case LogicOp::Invert: return hn::Xor(d, ones);
    case LogicOp::OrReverse: return hn::Or(s, hn::Xor(d, ones));
    case LogicOp::CopyInverted: return hn::Xor(s, ones);
    case LogicOp::OrInverted: return hn::Or(hn::Xor(s, ones), d);
    case LogicOp::Nand: return hn::Xor(hn::And(s, d), ones);
    default: return ones;  // Set
  }
}

// The 4x4 block at framebuffer pixel (x, y) (x a multiple of 4) as the polygon stipple
// keeps it, in a block mask's layout (bit row * 4 + column).
HWY_INLINE uint16_t stipple_mask(const PixelState& p, int x, int y) {
  uint32_t m = 0;
  for (int row = 0; row < 4; ++row) m |= ((p.stipple[(y + row) & 31] >> (x & 31)) & 0xfu) << (4 * row);
  return uint16_t(m);
}

// --- the fixed-function kernel (PrimitiveBatch draws).
template <int kUnits, bool kFog, bool kSpec, int kVolumes>
HWY_NOINLINE void fixed_kernel(const RecordHeader& r, const Block* blocks, int n, const TileTarget& t) {
  const DF d;
  const DU du;
  const DrawState& draw = (*t.frame.draws)[r.draw];
  const PixelState& p = draw.pixel;
  FixedShader<kUnits, kFog, kSpec, kVolumes> shader(r, draw);
  // A flat-shaded face without textures: one colour for every pixel.
  const bool constant = kUnits == 0 && (r.flags & kConstantVaryings);
  Rgba flat{};
  if constexpr (kUnits == 0)
    if (constant) flat = shader.constant_color(r);
  const DepthPlane z_plane(r);
  const VU id = hn::Set(du, draw.object_id);
  const bool stencil = p.stencil_test;
  const bool writes_depth = p.depth_test && p.depth_write;
  const bool writes_stencil = stencil && p.stencil_write_mask &&
                              (p.stencil_fail != StencilOp::Keep || p.stencil_depth_fail != StencilOp::Keep ||
                               p.stencil_pass != StencilOp::Keep);
  const uint32_t keep = ~(((p.color_mask & 1) ? 0xffu : 0) | ((p.color_mask & 2) ? 0xff00u : 0) |
                          ((p.color_mask & 4) ? 0xff0000u : 0) | ((p.color_mask & 8) ? 0xff000000u : 0));
  if (keep == 0xffffffffu && !writes_depth && !writes_stencil && !t.ids && !p.samples_passed) return;  // nothing would be written
  uint64_t passed = 0;  // fragments past the depth and stencil tests, for an occlusion query
  // What each fragment does besides the depth test; all zero: a plain draw.
  struct Extras {
    bool stipple = false, alpha_test = false, stencil = false, query = false, blend = false, logic = false;
    uint32_t kept = 0;         // colour channels the mask keeps
    uint32_t* ids = nullptr;   // object ids written
    bool none() const { return !stipple && !alpha_test && !stencil && !query && !blend && !logic && !kept && !ids; }
  };
  const Extras extras{p.polygon_stipple, p.alpha_test, stencil, p.samples_passed != nullptr, p.blend && !p.logic_op,
                      p.logic_op, keep, t.ids};
  shader.plan_levels(r, blocks, n, t.x0, t.y0);  // the textures' levels of detail, every block's
  // The loop, compiled for any state (kDepth 0) and, for an untextured draw, once more for
  // each of the usual states (kDepth: CompareFunc::Less or LessEqual): a depth test with
  // that function and no Extras. Those are then known where the loop is compiled, not
  // asked of every vector (a quarter of pGL's mesh frames is this loop).
  auto run = [&](auto depth_tag) {
    constexpr int kDepth = decltype(depth_tag)::value;
    constexpr bool kPlain = kDepth != 0;
    const Extras x = kPlain ? Extras{} : extras;
    const bool depth_test = kPlain || p.depth_test;
    // With no alpha or stencil test, the depth test can come first and spare the shading.
    const bool early = !x.alpha_test && !x.stencil;
    auto depth_passes = [&](VF z, VF zb) {
      if constexpr (kDepth == int(CompareFunc::Less)) return hn::Lt(z, zb);
      else if constexpr (kDepth == int(CompareFunc::LessEqual)) return hn::Le(z, zb);
      else return compare(p.depth_func, z, zb);
    };
    for (int b = 0; b < n; ++b) {
      Block blk = blocks[b];
      if (x.stipple) {
        blk.mask &= stipple_mask(p, t.x0 + (blk.index & 15) * 4, t.y0 + (blk.index >> 4) * 4);
        if (!blk.mask) continue;
      }
      float fx, fy;
      block_origin(r, t, blk.index, fx, fy);
      const VF z0 = z_plane.block(fx, fy);
      shader.begin_block(fx, fy, b);
      const size_t at = size_t(blk.index) * 16;
      for (int v = 0; v < kVectorsPerBlock; ++v) {
        if (kVectorsPerBlock > 1 && vector_empty(blk.mask, v)) continue;
        MF m = lane_mask(blk.mask, v);
        float* zp = t.depth + at + v * kLanes;
        uint32_t* cp = t.color + at + v * kLanes;
        // Window depth is clamped to [0, 1] (a polygon offset may push it out).
        const VF z = saturate(z_plane.at(z0, v));
        // (Zero when unused: GCC's -Wmaybe-uninitialized cannot see that every read below is
        // under depth_test, and fails the ASan build's -Werror.)
        const VF zb = depth_test ? hn::Load(d, zp) : hn::Zero(d);
        if (depth_test && early) {
          m = hn::And(m, depth_passes(z, zb));
          if (hn::AllFalse(d, m)) continue;
        }
        Rgba c = constant ? flat : shader.shade(v);
        if (x.alpha_test) m = hn::And(m, compare(p.alpha_func, c.a, hn::Set(d, p.alpha_ref)));
        if (x.stencil) {
          if (hn::AllFalse(d, m)) continue;
          const MF depth = depth_test ? depth_passes(z, zb) : hn::FirstN(d, kLanes);
          m = stencil_and_depth(p, m, depth, t.stencil + at + v * kLanes);
          if (hn::AllFalse(d, m)) continue;
        } else if (!early) {
          if (depth_test) m = hn::And(m, depth_passes(z, zb));
          if (hn::AllFalse(d, m)) continue;
        }
        if (x.query) passed += hn::CountTrue(d, m);
        if (writes_depth) store_masked(z, m, d, zp);
        const VU dst = hn::Load(du, cp);
        if (x.blend) {
          const Rgba dc = unpack(dst);
          c = {blend_channel(p, 0, c, dc), blend_channel(p, 1, c, dc), blend_channel(p, 2, c, dc), blend_channel(p, 3, c, dc)};
        }
        VU out = pack_colors(c.r, c.g, c.b, c.a);
        if (x.logic) out = logic_op(p.logic, out, dst);
        if (x.kept) out = hn::Or(hn::AndNot(hn::Set(du, x.kept), out), hn::And(dst, hn::Set(du, x.kept)));
        const auto mu = hn::RebindMask(du, m);
        store_masked(out, mu, du, cp);
        if (x.ids) store_masked(id, mu, du, x.ids + at + v * kLanes);
      }
    }
  };
  using Generic = std::integral_constant<int, 0>;
  if constexpr (kUnits == 0 && !kFog && !kSpec && kVolumes == 0) {
    const bool plain = p.depth_test && extras.none();
    if (plain && p.depth_func == CompareFunc::Less) return run(std::integral_constant<int, int(CompareFunc::Less)>());
    if (plain && p.depth_func == CompareFunc::LessEqual)
      return run(std::integral_constant<int, int(CompareFunc::LessEqual)>());
  }
  run(Generic());
  if (passed) p.samples_passed->fetch_add(passed, std::memory_order_relaxed);
}

const KernelFn* fixed_kernels() {
  // Indexed as raster::fixed_kernel says: no units (4), one 2-D or 3-D (8), two with
  // each 2-D or 3-D (16); each with and without the colour sum and fog.
#define VELOCITY_FIXED4(units, volumes)                                                                    \
  fixed_kernel<units, false, false, volumes>, fixed_kernel<units, true, false, volumes>,                   \
      fixed_kernel<units, false, true, volumes>, fixed_kernel<units, true, true, volumes>
  static const KernelFn table[] = {VELOCITY_FIXED4(0, 0), VELOCITY_FIXED4(1, 0), VELOCITY_FIXED4(1, 1),
                                   VELOCITY_FIXED4(2, 0), VELOCITY_FIXED4(2, 1), VELOCITY_FIXED4(2, 2),
                                   VELOCITY_FIXED4(2, 3)};
#undef VELOCITY_FIXED4
  static_assert(sizeof(table) / sizeof(table[0]) == size_t(KernelId::Count) - size_t(KernelId::Fixed));
  return table;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();
