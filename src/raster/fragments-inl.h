// Fragment batching for small triangles. A triangle of a few pixels (a Small record)
// covers one or two pixels of each 4x4 block it touches, so shading it block by block
// would leave most SIMD lanes idle — and at a million triangles on a 1080p screen most
// triangles are like that. Instead, the tile gathers the covered pixels of consecutive
// small triangles of the same draw into one batch of up to 16 fragments (their depth,
// 1/w and varyings evaluated from each triangle's planes), and depth-tests and shades
// them together. Submission order is kept: a batch is flushed before anything else is
// drawn, and before a fragment would land on a pixel already in it.
#if defined(VELOCITY_RASTER_FRAGMENTS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_FRAGMENTS_INL_H_
#undef VELOCITY_RASTER_FRAGMENTS_INL_H_
#else
#define VELOCITY_RASTER_FRAGMENTS_INL_H_
#endif

#include <cstring>

#include "raster/rasterize.hpp"
#include "raster/sampler-inl.h"
#include "raster/shade_mesh-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// Can a record's pixels go into a batch? Small triangles of the flat, smooth and
// per-vertex-textured kernels.
HWY_INLINE bool batchable(const RecordHeader& r) {
  if (r.kind != RecordKind::Small) return false;
  const KernelId k = kernel_family(r.kernel);
  return k == KernelId::Flat || k == KernelId::Smooth || k == KernelId::FlatTex || k == KernelId::SmoothTex;
}

class Fragments {
 public:
  static constexpr int kMax = 16;

  // Adds the record's covered pixels (tile-relative box origin ox, oy). Flushes first
  // when the record does not match the batch, or a pixel is already in it.
  template <class Flush>
  HWY_INLINE void add(const RecordHeader& r, const DrawState& draw, int ox, int oy, const TileBox& box, Flush&& flush) {
    const KernelId family = kernel_family(r.kernel);
    const bool textured = family == KernelId::FlatTex || family == KernelId::SmoothTex;
    LevelChoice level{};
    float lod_frac = 0;
    if (textured) {
      level = record_level(r, draw, family);
      lod_frac = level.frac;
    }
    if (n_ && (r.kernel != kernel_ || r.draw != draw_ ||
               (textured && (level.level0 != level_.level0 || level.level1 != level_.level1 || level.filter != level_.filter))))
      flush();
    if (!n_) kernel_ = r.kernel, draw_ = r.draw, level_ = level, family_ = family;
    const uint64_t mask = shape<SmallShape>(r).mask;
    const Plane* var = varyings(r);
    const int nvar = r.num_varyings;
    for (uint64_t m = mask; m; m &= m - 1) {
      const int k = __builtin_ctzll(m);
      const int x = ox + (k & 7), y = oy + (k >> 3);  // tile pixels
      if (x < box.x0 || x > box.x1 || y < box.y0 || y > box.y1) continue;
      const int pixel = (y >> 2) * 256 + (x >> 2) * 16 + (y & 3) * 4 + (x & 3);  // tiled layout
      if (occupied_[pixel >> 6] >> (pixel & 63) & 1) flush();
      if (n_ == kMax) flush();
      if (!n_) kernel_ = r.kernel, draw_ = r.draw, level_ = level, family_ = family;
      const float fx = float(k & 7), fy = float(k >> 3);  // from the record's anchor
      const int i = n_++;
      occupied_[pixel >> 6] |= uint64_t(1) << (pixel & 63);
      pixel_[i] = uint16_t(pixel);
      z_[i] = r.depth.c + r.depth.dx * fx + r.depth.dy * fy;
      inv_w_[i] = r.inv_w.c + r.inv_w.dx * fx + r.inv_w.dy * fy;
      for (int v = 0; v < nvar; ++v) var_[v][i] = var[v].c + var[v].dx * fx + var[v].dy * fy;
      flat_[i] = r.flat_color;
      frac_[i] = lod_frac;
    }
  }

  bool empty() const { return n_ == 0; }

  // Depth-tests and shades the batch into the tile, then empties it.
  HWY_INLINE void draw(const TileInputs& frame, uint32_t* color, float* depth, uint32_t* ids) {
    if (!n_) return;
    const DF d;
    const DU du;
    const DrawState& st = (*frame.draws)[draw_];
    static_assert(Fragments::kMax == 16);
    for (int v = 0; v < kVectorsPerBlock; ++v) {
      const int base = v * int(kLanes);
      if (base >= n_) break;
      MF m = hn::FirstN(d, size_t(n_ - base));
      alignas(64) float zb[kLanes];
      for (size_t l = 0; l < kLanes; ++l) zb[l] = int(base + l) < n_ ? depth[pixel_[base + l]] : 0.0f;
      const VF z = hn::Load(d, z_ + base);
      if (frame.depth_test) m = hn::And(m, hn::Lt(z, hn::Load(d, zb)));
      if (hn::AllFalse(d, m)) continue;
      const VF w = hn::Div(hn::Set(d, 1.0f), hn::Load(d, inv_w_ + base));
      auto in = [&](int k) { return hn::Mul(hn::Load(d, var_[k] + base), w); };
      VU c;
      switch (family_) {
        case KernelId::Flat: c = hn::Load(du, flat_ + base); break;
        case KernelId::Smooth: c = finish(frame.output, in(0), in(1), in(2)); break;
        case KernelId::FlatTex: {
          const SamplerView& tex = st.texture ? st.texture : st.env_map;
          const Rgba t = sample<false>(tex, level_, in(varying::kFlatUv), in(varying::kFlatUv + 1), hn::Load(d, frac_ + base));
          const Rgba f = unpack(hn::Load(du, flat_ + base));
          c = finish(frame.output, hn::Mul(f.r, t.r), hn::Mul(f.g, t.g), hn::Mul(f.b, t.b));
          break;
        }
        default: {  // SmoothTex
          const SamplerView& tex = st.texture ? st.texture : st.env_map;
          const Rgba t = sample<false>(tex, level_, in(varying::kSmoothUv), in(varying::kSmoothUv + 1), hn::Load(d, frac_ + base));
          c = finish(frame.output, hn::Mul(in(0), t.r), hn::Mul(in(1), t.g), hn::Mul(in(2), t.b));
          break;
        }
      }
      alignas(64) uint32_t out[kLanes];
      hn::Store(c, du, out);
      const uint32_t bits = mask_bits(m, 0);
      for (uint32_t b = bits; b; b &= b - 1) {
        const int l = __builtin_ctz(b), p = pixel_[base + l];
        if (frame.depth_test) depth[p] = z_[base + l];
        color[p] = out[l];
        if (ids) ids[p] = st.object_id;
      }
    }
    for (int i = 0; i < n_; ++i) occupied_[pixel_[i] >> 6] = 0;
    n_ = 0;
  }

 private:
  // The level of detail of a small triangle: its uv derivatives at its first pixel.
  static LevelChoice record_level(const RecordHeader& r, const DrawState& st, KernelId family) {
    const SamplerView& tex = st.texture ? st.texture : st.env_map;
    if (single_level(tex)) return {tex.mag, 0, 0, 0};
    const int iu = family == KernelId::FlatTex ? varying::kFlatUv : varying::kSmoothUv;
    const Plane* var = varyings(r);
    const Plane& q = r.inv_w;
    const float iq = q.c != 0 ? 1.0f / q.c : 0.0f;
    const float u = var[iu].c * iq, v = var[iu + 1].c * iq;
    return choose_levels(tex, level_of_detail(tex, (var[iu].dx - u * q.dx) * iq, (var[iu + 1].dx - v * q.dx) * iq,
                                              (var[iu].dy - u * q.dy) * iq, (var[iu + 1].dy - v * q.dy) * iq));
  }

  int n_ = 0;
  uint8_t kernel_ = 0;
  uint32_t draw_ = 0;
  KernelId family_ = KernelId::Flat;
  LevelChoice level_{};
  alignas(64) float z_[kMax], inv_w_[kMax], var_[kSmoothTexVaryings][kMax], frac_[kMax];
  alignas(64) uint32_t flat_[kMax];
  uint16_t pixel_[kMax];
  uint64_t occupied_[kTileSize * kTileSize / 64] = {};
};

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_FRAGMENTS_INL_H_ toggle
