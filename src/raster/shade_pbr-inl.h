// glTF 2.0's metallic-roughness material, per pixel, N pixels at a time: the BRDF of
// the specification's Appendix B — Lambert diffuse and a GGX / Trowbridge-Reitz
// specular lobe with Smith's height-correlated visibility and Schlick's Fresnel, the
// dielectric (f0 = 0.04) and metal (f0 = base) BRDFs mixed by metallic:
//
//   c_diff = base (1 - metallic)        f0 = 0.04 (1 - metallic) + base metallic
//   a = roughness^2                     F = f0 + (1 - f0) (1 - V.H)^5
//   F_d = 0.04 + 0.96 (1 - V.H)^5       (the dielectric's Fresnel)
//   D = a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2)
//   Vis = 0.5 / (N.L sqrt((N.V)^2 (1 - a^2) + a^2) + N.V sqrt((N.L)^2 (1 - a^2) + a^2))
//   M = 1 + f0 (1 / E(roughness, N.V) - 1)   (shading/ggx_albedo.hpp)
//   colour = sum_i ((1 - F_d) c_diff / pi + F D Vis M) radiance_i N.L_i
//          + ambient c_diff occlusion + emissive
//
// M gives the specular lobe the light that bounces between microfacets more than once
// (Turquin's compensation, which three.js applies to punctual lights too): up to 2.5x
// on a rough metal, 1.00-1.05 on smooth or dielectric surfaces. The spec's single-
// scattering lobe without it makes rough metals darker than three.js by that factor.
// The diffuse share is (1 - F_d), not (1 - F): mix(fresnel_mix(F_d, diffuse, specular),
// F_metal specular, metallic) expands to this. The spec's pseudocode had (1 - F) until
// 2024 (KhronosGroup/glTF#2386, a bug it calls so), which differs between metallic 0
// and 1 only; three.js has the corrected form.
//
// with the lights of shading/lighting.hpp (radiance: the light's colour times its
// falloff and cone, detail::punctual). The ambient light is a uniform radiance (so
// Lambert returns c_diff times it), the only light occlusion darkens, as glTF says.
// Roughness is clamped to 0.045 as three.js clamps it (a = 0 is a mirror no point
// light can be seen in). Base colour = factor x vertex colour x texture (sRGB-decoded
// in a Linear frame); metallic and roughness = factors x the texture's B and G; the
// normal map's xy scaled by normal_scale in the tangent frame; each texture through
// its own KHR_texture_transform of the material's uv set.
#if defined(VELOCITY_RASTER_SHADE_PBR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_SHADE_PBR_INL_H_
#undef VELOCITY_RASTER_SHADE_PBR_INL_H_
#else
#define VELOCITY_RASTER_SHADE_PBR_INL_H_
#endif

#include <algorithm>
#include <optional>

#include "raster/output-inl.h"
#include "raster/rasterize.hpp"
#include "raster/sampler-inl.h"
#include "raster/shade_mesh-inl.h"
#include "raster/tile-inl.h"
#include "shading/ggx_albedo.hpp"
#include "shading/lighting-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;
namespace lit = velocity::shading::HWY_NAMESPACE;

// What the Pbr shader returns: linear light (or display values) and alpha.
struct PbrOut {
  VF r, g, b, a;
};

// The specular lobe's directional albedo E(roughness, N.V): shading::ggx_albedo_table
// read bilinearly with clamped edges (shading::ggx_albedo, N pixels at a time).
HWY_INLINE VF ggx_albedo(const float* table, VF roughness, VF nv) {
  const DF d;
  const DI di;
  constexpr int n = shading::kGgxAlbedoSize;
  auto axis = [&](VF v, VI& i0, VF& f) {
    const VF x = hn::Min(hn::Max(hn::MulSub(v, hn::Set(d, float(n)), hn::Set(d, 0.5f)), hn::Zero(d)), hn::Set(d, n - 1.0f));
    const VF lo = hn::Min(hn::Floor(x), hn::Set(d, n - 2.0f));
    f = hn::Sub(x, lo);
    i0 = hn::Min(hn::Max(truncate_in_range(lo), hn::Zero(di)), hn::Set(di, n - 2));  // NaN-proof index
  };
  VI i, j;
  VF fx, fy;
  axis(roughness, i, fx);
  axis(nv, j, fy);
  static_assert(n == 16, "the row index below is j << 4");
  const VI at = hn::Add(hn::ShiftLeft<4>(j), i);
  const VF t00 = hn::GatherIndex(d, table, at), t10 = hn::GatherIndex(d, table, hn::Add(at, hn::Set(di, 1)));
  const VF t01 = hn::GatherIndex(d, table, hn::Add(at, hn::Set(di, n)));
  const VF t11 = hn::GatherIndex(d, table, hn::Add(at, hn::Set(di, n + 1)));
  const VF top = hn::MulAdd(hn::Sub(t10, t00), fx, t00), bottom = hn::MulAdd(hn::Sub(t11, t01), fx, t01);
  return hn::MulAdd(hn::Sub(bottom, top), fy, top);
}

// 1 / E - 1 along N.V for one roughness (a draw without a metallic-roughness texture):
// PbrState::lost_energy, the row plan_pbr computed once for the draw, so a pixel reads
// two entries, not four, and divides by nothing. Linear in N.V between the rows'
// centres, clamped at the ends. Where a vector holds half the row or more, the row is
// kept in registers and read by lane permutes: the two gathers they replace were 15 %
// of the plain PBR kernel's time.
struct LostEnergyRow {
  static constexpr int n = shading::kGgxAlbedoSize;
  static constexpr size_t kLanes = hn::MaxLanes(DF());
  const float* lost;
  VF lo, hi;  // the row's first and last kLanes entries
  explicit LostEnergyRow(const float* row)
      : lost(row), lo(hn::LoadU(DF(), row)), hi(hn::LoadU(DF(), row + (n - kLanes))) {}
  HWY_INLINE VF at(VI j) const {
    const DF d;
    const DI di;
    if constexpr (kLanes == n) {
      return hn::TableLookupLanes(lo, hn::IndicesFromVec(d, j));
    } else if constexpr (2 * kLanes == n) {
      const auto k = hn::IndicesFromVec(d, hn::And(j, hn::Set(di, int32_t(kLanes) - 1)));
      const MF upper = hn::RebindMask(d, hn::Gt(j, hn::Set(di, int32_t(kLanes) - 1)));
      return hn::IfThenElse(upper, hn::TableLookupLanes(hi, k), hn::TableLookupLanes(lo, k));
    } else {
      return hn::GatherIndex(d, lost, j);
    }
  }
  HWY_INLINE VF operator()(VF nv) const {
    const DF d;
    const DI di;
    const VF x = hn::Min(hn::Max(hn::MulSub(nv, hn::Set(d, float(n)), hn::Set(d, 0.5f)), hn::Zero(d)), hn::Set(d, n - 1.0f));
    const VF lo_x = hn::Min(hn::Floor(x), hn::Set(d, n - 2.0f));
    const VI j = hn::Min(hn::Max(truncate_in_range(lo_x), hn::Zero(di)), hn::Set(di, n - 2));  // NaN-proof index
    const VF a = at(j), b = at(hn::Add(j, hn::Set(di, 1)));
    return hn::MulAdd(hn::Sub(b, a), hn::Sub(x, lo_x), a);
  }
};

// One PBR texture of a draw: its view, uv map and the levels chosen for the block.
struct PbrTexture {
  const SamplerView* view = nullptr;
  UvAffine uv;
  LevelChoice level{};
  VF frac;  // the weight of level.level1, per lane (packed pixels come from several blocks)
  explicit operator bool() const { return view != nullptr; }
  // The level of detail at N blocks from the derivatives of the material's uv set.
  HWY_INLINE VF level_of_detail(VF dudx, VF dvdx, VF dudy, VF dvdy) const {
    const DF d;
    auto map = [&](float a, float b, VF du, VF dv) { return hn::MulAdd(hn::Set(d, b), dv, hn::Mul(hn::Set(d, a), du)); };
    return raster::HWY_NAMESPACE::level_of_detail(*view, map(uv.a, uv.b, dudx, dvdx), map(uv.d, uv.e, dudx, dvdx),
                                                  map(uv.a, uv.b, dudy, dvdy), map(uv.d, uv.e, dudy, dvdy));
  }
  template <bool kAlpha>
  HWY_INLINE Rgba operator()(VF u, VF v) const {
    const DF d;
    const VF tu = hn::MulAdd(hn::Set(d, uv.a), u, hn::MulAdd(hn::Set(d, uv.b), v, hn::Set(d, uv.c)));
    const VF tv = hn::MulAdd(hn::Set(d, uv.d), u, hn::MulAdd(hn::Set(d, uv.e), v, hn::Set(d, uv.f)));
    return sample<kAlpha>(*view, level, tu, tv, frac);
  }
};

template <bool kTangent, bool kColor>
struct PbrShader {
  static constexpr int N = pbr_varyings(kTangent, kColor);
  static constexpr int kCol = varying::kPbrTangent + (kTangent ? 4 : 0);
  Perspective<N> in;
  const PbrState& m;
  const shading::EyeLights& lights;
  const bool ortho;
  const float* albedo = shading::ggx_albedo_table();
  PbrTexture base, mr, normal, occlusion, emissive;
  std::optional<LostEnergyRow> lost_row;  // the roughness is the factor's everywhere
  PbrTexture* textures[5];  // the ones the material has, and their levels of detail (plan_levels)
  int texture_count = 0;
  BlockLods lods[5];

  PbrShader(const RecordHeader& r, const DrawState& d, const TileInputs& f)
      : m(d.pbr), lights(*f.lights), ortho(f.orthographic) {
    in.load(r);
    auto use = [](PbrTexture& t, const SamplerView& v, const UvAffine& a) {
      if (v) t.view = &v, t.uv = a;
    };
    use(base, d.texture, m.base_uv);
    if (!m.unlit) {
      use(mr, m.metallic_roughness, m.mr_uv);
      if (kTangent) use(normal, m.normal, m.normal_uv);
      use(occlusion, m.occlusion, m.occlusion_uv);
      use(emissive, m.emissive_map, m.emissive_uv);
      if (!mr) lost_row.emplace(m.lost_energy);
    }
    for (PbrTexture* t : {&base, &mr, &normal, &occlusion, &emissive})
      if (*t) textures[texture_count++] = t;
  }
  PbrShader(const PbrShader&) = delete;  // `textures` points into this one

  // The levels of detail of every texture at every block of the kernel's list, before
  // the first is shaded (BlockLods, shade_mesh-inl.h).
  void plan_levels(const RecordHeader& r, const Block* blocks, int n, int x0, int y0) {
    if (!texture_count) return;
    uv_derivatives(in, varying::kPbrUv, r, x0, y0, blocks, n, [&](int b, VF ux, VF vx, VF uy, VF vy) {
      for (int k = 0; k < texture_count; ++k) hn::Store(textures[k]->level_of_detail(ux, vx, uy, vy), DF(), lods[k].lod + b);
    });
  }
  void begin_block(float fx, float fy, int b) {
    in.begin(fx, fy);
    for (int k = 0; k < texture_count; ++k) {
      PbrTexture& t = *textures[k];
      t.level = choose_levels(*t.view, lods[k].lod[b]), t.frac = hn::Set(DF(), t.level.frac);
    }
  }
  // Packed pixels (tile-inl.h's shade_packed): the levels block b chooses, the run's
  // levels and each lane's weights, and the pixels.
  int level_count() const { return texture_count; }
  void block_levels(int b, LevelChoice* out) const {
    for (int k = 0; k < texture_count; ++k) out[k] = choose_levels(*textures[k]->view, lods[k].lod[b]);
  }
  void use_levels(const LevelChoice* levels, const VF* frac) {
    for (int k = 0; k < texture_count; ++k) textures[k]->level = levels[k], textures[k]->frac = frac[k];
  }
  void at_pixels(VF x, VF y) { in.at_pixels(x, y); }

  HWY_INLINE V3 unit(V3 a) const {
    const VF il = rsqrt(dot(a, a));
    return {hn::Mul(a.x, il), hn::Mul(a.y, il), hn::Mul(a.z, il)};
  }

  // `live`: the lanes the kernel may write (the others skip their shadow lookups).
  HWY_INLINE PbrOut shade(int v, MF live) {
    const DF d;
    in.at_vector(v);
    const VF one = hn::Set(d, 1.0f);
    const VF u = in(varying::kPbrUv, v), tv = in(varying::kPbrUv + 1, v);
    // Base colour and alpha.
    V3 c{hn::Set(d, m.base[0]), hn::Set(d, m.base[1]), hn::Set(d, m.base[2])};
    VF alpha = hn::Set(d, m.base[3]);
    if constexpr (kColor) {
      c = {hn::Mul(c.x, in(kCol, v)), hn::Mul(c.y, in(kCol + 1, v)), hn::Mul(c.z, in(kCol + 2, v))};
      alpha = hn::Mul(alpha, in(kCol + 3, v));
    }
    if (base) {
      const Rgba t = base.operator()<true>(u, tv);
      c = {hn::Mul(c.x, t.r), hn::Mul(c.y, t.g), hn::Mul(c.z, t.b)};
      alpha = hn::Mul(alpha, t.a);
    }
    if (m.unlit) return {c.x, c.y, c.z, alpha};

    // The normal (w cancels in normalising), through the normal map.
    constexpr int n0 = varying::kPbrNormal + 1;  // planes: 1/w first
    V3 n = unit({in.p.at(n0, v), in.p.at(n0 + 1, v), in.p.at(n0 + 2, v)});
    if constexpr (kTangent) {
      if (normal) {
        const Rgba t = normal.operator()<false>(u, tv);
        const VF two = hn::Set(d, 2.0f), s = hn::Set(d, m.normal_scale);
        const VF tx = hn::Mul(hn::MulSub(t.r, two, one), s), ty = hn::Mul(hn::MulSub(t.g, two, one), s);
        const VF tz = hn::MulSub(t.b, two, one);
        constexpr int t0 = varying::kPbrTangent;
        V3 tan{in(t0, v), in(t0 + 1, v), in(t0 + 2, v)};
        const VF nt = dot(n, tan);
        tan = unit({hn::NegMulAdd(n.x, nt, tan.x), hn::NegMulAdd(n.y, nt, tan.y), hn::NegMulAdd(n.z, nt, tan.z)});
        const VF w = hn::IfThenElse(hn::Lt(in(t0 + 3, v), hn::Zero(d)), hn::Set(d, -1.0f), one);
        const V3 bit{hn::Mul(w, hn::MulSub(n.y, tan.z, hn::Mul(n.z, tan.y))),
                     hn::Mul(w, hn::MulSub(n.z, tan.x, hn::Mul(n.x, tan.z))),
                     hn::Mul(w, hn::MulSub(n.x, tan.y, hn::Mul(n.y, tan.x)))};
        n = unit({hn::MulAdd(tan.x, tx, hn::MulAdd(bit.x, ty, hn::Mul(n.x, tz))),
                  hn::MulAdd(tan.y, tx, hn::MulAdd(bit.y, ty, hn::Mul(n.y, tz))),
                  hn::MulAdd(tan.z, tx, hn::MulAdd(bit.z, ty, hn::Mul(n.z, tz)))});
      }
    }
    // Metallic and roughness.
    VF metal = hn::Set(d, m.metallic), rough = hn::Set(d, m.roughness);
    if (mr) {
      const Rgba t = mr.operator()<false>(u, tv);
      metal = hn::Mul(metal, t.b), rough = hn::Mul(rough, t.g);
    }
    metal = saturate(metal);
    rough = hn::Min(hn::Max(rough, hn::Set(d, 0.045f)), one);
    const VF a = hn::Mul(rough, rough), a2 = hn::Mul(a, a), one_a2 = hn::Sub(one, a2);
    const VF dielectric = hn::Sub(one, metal);
    const V3 cdiff{hn::Mul(c.x, dielectric), hn::Mul(c.y, dielectric), hn::Mul(c.z, dielectric)};
    const VF f0d = hn::Mul(hn::Set(d, 0.04f), dielectric);
    const V3 f0{hn::MulAdd(c.x, metal, f0d), hn::MulAdd(c.y, metal, f0d), hn::MulAdd(c.z, metal, f0d)};

    // The eye-space position and the direction to the eye.
    const V3 p{in(varying::kPbrEye, v), in(varying::kPbrEye + 1, v), in(varying::kPbrEye + 2, v)};
    const V3 view = ortho ? V3{hn::Zero(d), hn::Zero(d), one} : unit({hn::Neg(p.x), hn::Neg(p.y), hn::Neg(p.z)});
    const VF nv = hn::Max(dot(n, view), hn::Set(d, 1e-4f));
    const VF nv_term = sqrt_fast(hn::MulAdd(hn::Mul(nv, nv), one_a2, a2));

    // Ambient, darkened by occlusion.
    VF ao = one;
    if (occlusion) {
      const Rgba t = occlusion.operator()<false>(u, tv);
      ao = hn::MulAdd(hn::Set(d, m.occlusion_strength), hn::Sub(t.r, one), one);
    }
    V3 out{hn::Mul(hn::Mul(cdiff.x, hn::Set(d, lights.ambient.x)), ao),
           hn::Mul(hn::Mul(cdiff.y, hn::Set(d, lights.ambient.y)), ao),
           hn::Mul(hn::Mul(cdiff.z, hn::Set(d, lights.ambient.z)), ao)};

    // Multiple scattering: the specular lobe times M = 1 + f0 (1 / E - 1), per channel.
    V3 ms{one, one, one};
    if (!lights.directional.empty() || !lights.point.empty()) {
      const VF lost = lost_row ? (*lost_row)(nv) : hn::Sub(hn::Div(one, ggx_albedo(albedo, rough, nv)), one);
      ms = {hn::MulAdd(f0.x, lost, one), hn::MulAdd(f0.y, lost, one), hn::MulAdd(f0.z, lost, one)};
    }

    constexpr float kInvPi = 0.318309886f;
    auto add_light = [&](const V3& l, VF rr, VF rg, VF rb) {
      const VF nl = dot(n, l);
      const MF lit_m = hn::Gt(nl, hn::Zero(d));
      if (hn::AllFalse(d, lit_m)) return;
      const VF nlc = hn::ZeroIfNegative(nl);
      const V3 h = unit({hn::Add(l.x, view.x), hn::Add(l.y, view.y), hn::Add(l.z, view.z)});
      const VF nh = saturate(dot(n, h)), vh = saturate(dot(view, h));
      const VF q = hn::Sub(one, vh), q2 = hn::Mul(q, q), q5 = hn::Mul(hn::Mul(q2, q2), q);
      const VF diffuse_share = hn::NegMulAdd(hn::Set(d, 0.96f), q5, hn::Set(d, 0.96f));  // 1 - F_d
      const VF dn = hn::MulAdd(hn::Mul(nh, nh), hn::Neg(one_a2), one);  // (N.H)^2 (a^2 - 1) + 1
      // D Vis = (a^2 / pi) / dn^2 * 0.5 / den, in one reciprocal.
      const VF den = hn::MulAdd(nlc, nv_term, hn::Mul(nv, sqrt_fast(hn::MulAdd(hn::Mul(nlc, nlc), one_a2, a2))));
      const VF spec = hn::Mul(hn::Mul(a2, hn::Set(d, 0.5f * kInvPi)),
                              recip(hn::Mul(hn::Max(hn::Mul(dn, dn), hn::Set(d, 1e-12f)), hn::Max(den, hn::Set(d, 1e-12f)))));
      auto channel_of = [&](VF f0c, VF msc, VF cd, VF radiance, VF acc) {
        const VF f = hn::Mul(hn::MulAdd(hn::Sub(one, f0c), q5, f0c), msc);  // Schlick, times M
        const VF brdf = hn::MulAdd(f, spec, hn::Mul(diffuse_share, hn::Mul(cd, hn::Set(d, kInvPi))));
        return hn::MulAdd(brdf, hn::Mul(radiance, nlc), acc);
      };
      out = {channel_of(f0.x, ms.x, cdiff.x, rr, out.x), channel_of(f0.y, ms.y, cdiff.y, rg, out.y),
             channel_of(f0.z, ms.z, cdiff.z, rb, out.z)};
    };
    for (const auto& l : lights.directional) {
      const V3 dir{hn::Set(d, l.to_light.x), hn::Set(d, l.to_light.y), hn::Set(d, l.to_light.z)};
      const VF vis = lit::visibility(l.shadow, p, n, dir, live);  // shading/shadow.hpp
      add_light(dir, hn::Mul(hn::Set(d, l.color.x), vis), hn::Mul(hn::Set(d, l.color.y), vis),
                hn::Mul(hn::Set(d, l.color.z), vis));
    }
    for (const auto& l : lights.point) {
      V3 dir;
      VF att = lit::punctual(l, p, n, dir);
      if (l.shadow) att = hn::Mul(att, lit::visibility(l.shadow, p, n, dir, live));
      add_light(dir, hn::Mul(hn::Set(d, l.color.x), att), hn::Mul(hn::Set(d, l.color.y), att),
                hn::Mul(hn::Set(d, l.color.z), att));
    }
    // Emission.
    V3 e{hn::Set(d, m.emissive[0]), hn::Set(d, m.emissive[1]), hn::Set(d, m.emissive[2])};
    if (emissive) {
      const Rgba t = emissive.operator()<false>(u, tv);
      e = {hn::Mul(e.x, t.r), hn::Mul(e.y, t.g), hn::Mul(e.z, t.b)};
    }
    return {hn::Add(out.x, e.x), hn::Add(out.y, e.y), hn::Add(out.z, e.z), alpha};
  }
};

// The Pbr kernels' depth test and writes: LESS before shading; MASK drops the pixels
// whose alpha is under the cut-off (before the depth write); BLEND mixes the finished
// colour over the pixel's by alpha (over: in the output's encoding, as three.js does
// drawing to a canvas) and leaves depth alone, as glTF's BLEND materials are drawn.
template <class Shader>
HWY_NOINLINE void pbr_kernel(const RecordHeader& r, const Block* blocks, int n, const TileTarget& t) {
  const DF d;
  const DU du;
  const DrawState& draw = (*t.frame.draws)[r.draw];
  Shader shader(r, draw, t.frame);
  const bool depth_test = t.frame.depth_test;
  const AlphaMode mode = draw.pbr.alpha_mode;
  const VF cutoff = hn::Set(d, draw.pbr.alpha_cutoff);
  const DepthPlane depth(r);
  const VU id = hn::Set(du, draw.object_id);
  const OutputTransform& output = t.frame.output;
  shader.plan_levels(r, blocks, n, t.x0, t.y0);
  if (kPackPixels && mode == AlphaMode::Opaque && pixel_packing()) {
    return shade_packed(r, blocks, n, t, shader, [&](MF live) {
      const PbrOut c = shader.shade(0, live);
      return finish(output, c.r, c.g, c.b);
    });
  }
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
      const VF z = depth.at(z0, v);
      if (depth_test) {
        m = hn::And(m, hn::Lt(z, hn::Load(d, zp)));
        if (hn::AllFalse(d, m)) continue;
      }
      const PbrOut c = shader.shade(v, m);
      if (mode == AlphaMode::Mask) {
        m = hn::And(m, hn::Ge(c.a, cutoff));
        if (hn::AllFalse(d, m)) continue;
      }
      uint32_t* cp = t.color + at + v * kLanes;
      VU px;
      if (mode == AlphaMode::Blend) {
        const VF a = saturate(c.a);
        const VU src = finish(output, c.r, c.g, c.b);
        const VU dst = hn::Load(du, cp);
        auto mix = [&](VF s, VF dd) { return hn::MulAdd(hn::Sub(s, dd), a, dd); };
        const VF k = hn::Set(d, 1.0f / 255.0f);
        px = pack_colors(hn::Mul(mix(channel<0>(src), channel<0>(dst)), k), hn::Mul(mix(channel<1>(src), channel<1>(dst)), k),
                         hn::Mul(mix(channel<2>(src), channel<2>(dst)), k),
                         hn::MulAdd(hn::Mul(channel<3>(dst), k), hn::Sub(hn::Set(d, 1.0f), a), a));
      } else {
        if (depth_test) store_masked(z, m, d, zp);
        px = finish(output, c.r, c.g, c.b);
      }
      const auto mu = hn::RebindMask(du, m);
      store_masked(px, mu, du, cp);
      if (t.ids) store_masked(id, mu, du, t.ids + at + v * kLanes);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_SHADE_PBR_INL_H_ toggle
