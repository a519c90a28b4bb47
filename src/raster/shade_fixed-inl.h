// The fixed-function kernel: OpenGL 1.x's per-fragment work for PrimitiveBatch draws,
// in GL's order — texture environments (one per unit), colour sum, fog, (scissor: the
// set-up clipped the box), alpha test, depth test, blending, colour mask.
//
// Templated on what changes the work per pixel most (the texture units, the colour sum,
// fog); the rest of
// PixelState is read per draw and branched on per vector of pixels, never per pixel.
// Colours are floats in [0, 1] until they are packed to the RGBA8 framebuffer.
#if defined(VELOCITY_RASTER_SHADE_FIXED_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_SHADE_FIXED_INL_H_
#undef VELOCITY_RASTER_SHADE_FIXED_INL_H_
#else
#define VELOCITY_RASTER_SHADE_FIXED_INL_H_
#endif

#include "raster/rasterize.hpp"
#include "raster/sampler-inl.h"
#include "raster/shade_mesh-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

HWY_INLINE MF compare(CompareFunc f, VF a, VF b) {
  const DF d;
  switch (f) {
    case CompareFunc::Never: return hn::FirstN(d, 0);
    case CompareFunc::Less: return hn::Lt(a, b);
    case CompareFunc::Equal: return hn::Eq(a, b);
    case CompareFunc::LessEqual: return hn::Le(a, b);
    case CompareFunc::Greater: return hn::Gt(a, b);
    case CompareFunc::NotEqual: return hn::Ne(a, b);
    case CompareFunc::GreaterEqual: return hn::Ge(a, b);
    default: return hn::FirstN(d, kLanes);
  }
}

// --- the stencil buffer: kLanes 8-bit values at a time, worked on as 32-bit lanes.
using DS8 = hn::Rebind<uint8_t, DI>;

HWY_INLINE VI load_stencil(const uint8_t* p) { return hn::PromoteTo(DI(), hn::LoadU(DS8(), p)); }
HWY_INLINE void store_stencil(VI v, uint8_t* p) { hn::StoreU(hn::DemoteTo(DS8(), v), DS8(), p); }

HWY_INLINE MF compare_int(CompareFunc f, VI a, VI b) {
  const DF d;
  switch (f) {
    case CompareFunc::Never: return hn::FirstN(d, 0);
    case CompareFunc::Less: return hn::RebindMask(d, hn::Lt(a, b));
    case CompareFunc::Equal: return hn::RebindMask(d, hn::Eq(a, b));
    case CompareFunc::LessEqual: return hn::RebindMask(d, hn::Not(hn::Gt(a, b)));
    case CompareFunc::Greater: return hn::RebindMask(d, hn::Gt(a, b));
    case CompareFunc::NotEqual: return hn::RebindMask(d, hn::Not(hn::Eq(a, b)));
    case CompareFunc::GreaterEqual: return hn::RebindMask(d, hn::Not(hn::Lt(a, b)));
    default: return hn::FirstN(d, kLanes);
  }
}

// glStencilOp's operation on stencil values s (in [0, 255]).
HWY_INLINE VI stencil_op(StencilOp op, VI s, uint8_t ref) {
  const DI di;
  const VI one = hn::Set(di, 1), max = hn::Set(di, 255);
  switch (op) {
    case StencilOp::Keep: return s;
    case StencilOp::Zero: return hn::Zero(di);
    case StencilOp::Replace: return hn::Set(di, ref);
    case StencilOp::Increment: return hn::Min(hn::Add(s, one), max);
    case StencilOp::Decrement: return hn::Max(hn::Sub(s, one), hn::Zero(di));
    case StencilOp::Invert: return hn::Xor(s, max);
    case StencilOp::IncrementWrap: return hn::And(hn::Add(s, one), max);
    default: return hn::And(hn::Sub(s, one), max);  // DecrementWrap
  }
}

// The stencil test on the fragments `m`, and the depth test after it (`depth` are the
// fragments that pass it; all when there is none): updates the stencil values at `sp`
// as the ops of each outcome say, under the write mask, and returns the fragments that
// passed both.
HWY_INLINE MF stencil_and_depth(const PixelState& p, MF m, MF depth, uint8_t* sp) {
  const DI di;
  const VI s = load_stencil(sp);
  const VI vm = hn::Set(di, p.stencil_value_mask);
  const MF pass = hn::And(m, compare_int(p.stencil_func, hn::Set(di, p.stencil_ref & p.stencil_value_mask), hn::And(s, vm)));
  const MF fail = hn::AndNot(pass, m);
  const MF both = hn::And(pass, depth), depth_fail = hn::AndNot(depth, pass);
  if (p.stencil_write_mask) {
    const DF d;
    VI next = s;
    if (!hn::AllFalse(d, fail)) next = hn::IfThenElse(hn::RebindMask(di, fail), stencil_op(p.stencil_fail, s, p.stencil_ref), next);
    if (!hn::AllFalse(d, depth_fail))
      next = hn::IfThenElse(hn::RebindMask(di, depth_fail), stencil_op(p.stencil_depth_fail, s, p.stencil_ref), next);
    if (!hn::AllFalse(d, both)) next = hn::IfThenElse(hn::RebindMask(di, both), stencil_op(p.stencil_pass, s, p.stencil_ref), next);
    const VI wm = hn::Set(di, p.stencil_write_mask);
    store_stencil(hn::Or(hn::AndNot(wm, s), hn::And(next, wm)), sp);
  }
  return both;
}

// GL_COMBINE's argument i of the RGB (`rgb`) or alpha function: its source's colour
// channel `ch` (0-2) or alpha, or one minus it, as the operand says. The texel as the
// Texture stores it is already the spec's source colour for its format (Alpha: RGB 0;
// Luminance, Rgb: alpha 1; Intensity: all four I).
HWY_INLINE VF combine_arg(const TexCombine& k, bool rgb, int i, int ch, const Rgba* src[4]) {
  const DF d;
  const Rgba& s = *src[int(rgb ? k.source_rgb[i] : k.source_alpha[i])];
  const CombineOperand op = rgb ? k.operand_rgb[i] : k.operand_alpha[i];
  const bool use_alpha = op == CombineOperand::SrcAlpha || op == CombineOperand::OneMinusSrcAlpha;
  const VF v = use_alpha ? s.a : ch == 0 ? s.r : ch == 1 ? s.g : s.b;
  return op == CombineOperand::OneMinusSrcColor || op == CombineOperand::OneMinusSrcAlpha ? hn::Sub(hn::Set(d, 1.0f), v) : v;
}

// One channel of GL_COMBINE's function `op` (not the dot products), before its scale.
HWY_INLINE VF combine_channel(const TexCombine& k, CombineOp op, bool rgb, int ch, const Rgba* src[4]) {
  const DF d;
  const VF a0 = combine_arg(k, rgb, 0, ch, src);
  if (op == CombineOp::Replace) return a0;
  const VF a1 = combine_arg(k, rgb, 1, ch, src);
  switch (op) {
    case CombineOp::Modulate: return hn::Mul(a0, a1);
    case CombineOp::Add: return hn::Add(a0, a1);
    case CombineOp::AddSigned: return hn::Sub(hn::Add(a0, a1), hn::Set(d, 0.5f));
    case CombineOp::Subtract: return hn::Sub(a0, a1);
    default: {  // Interpolate: a0 a2 + a1 (1 - a2) = (a0 - a1) a2 + a1
      const VF a2 = combine_arg(k, rgb, 2, ch, src);
      return hn::MulAdd(hn::Sub(a0, a1), a2, a1);
    }
  }
}

// OpenGL 1.3's GL_COMBINE environment (TexCombine): `f` the previous unit's result, `t`
// the texel, `primary` the fragment's interpolated colour.
inline HWY_NOINLINE Rgba texture_combine(const TextureStage& st, const Rgba& f, const Rgba& t, const Rgba& primary) {
  const DF d;
  const TexCombine& k = st.combine;
  const Rgba constant{hn::Set(d, st.env_color.x), hn::Set(d, st.env_color.y), hn::Set(d, st.env_color.z),
                      hn::Set(d, st.env_color.w)};
  const Rgba* src[4] = {&t, &constant, &primary, &f};  // in CombineSource's order
  const VF rgb_scale = hn::Set(d, k.rgb_scale);
  Rgba o;
  if (k.rgb == CombineOp::Dot3Rgb || k.rgb == CombineOp::Dot3Rgba) {
    const VF half = hn::Set(d, 0.5f);
    VF dot = hn::Zero(d);
    for (int ch = 0; ch < 3; ++ch)
      dot = hn::MulAdd(hn::Sub(combine_arg(k, true, 0, ch, src), half), hn::Sub(combine_arg(k, true, 1, ch, src), half), dot);
    o.r = o.g = o.b = saturate(hn::Mul(hn::Mul(dot, hn::Set(d, 4.0f)), rgb_scale));
    if (k.rgb == CombineOp::Dot3Rgba) {
      o.a = o.r;
      return o;
    }
  } else {
    o.r = saturate(hn::Mul(combine_channel(k, k.rgb, true, 0, src), rgb_scale));
    o.g = saturate(hn::Mul(combine_channel(k, k.rgb, true, 1, src), rgb_scale));
    o.b = saturate(hn::Mul(combine_channel(k, k.rgb, true, 2, src), rgb_scale));
  }
  o.a = saturate(hn::Mul(combine_channel(k, k.alpha, false, 3, src), hn::Set(d, k.alpha_scale)));
  return o;
}

// The texture environment of one unit (OpenGL 1.x's table of texture functions). `f`
// is the fragment's colour (the previous unit's result), `t` the texel as the Texture
// stores it for its format. (TexEnvMode::Combine: texture_combine.)
HWY_INLINE Rgba texture_environment(const TextureStage& st, const Rgba& f, const Rgba& t) {
  const DF d;
  const VF one = hn::Set(d, 1.0f);
  const bool color = st.format != TexFormat::Alpha;  // does the texture bring a colour?
  const bool alpha = st.format == TexFormat::Rgba || st.format == TexFormat::LuminanceAlpha ||
                     st.format == TexFormat::Alpha || st.format == TexFormat::Intensity;
  Rgba o = f;
  switch (st.env) {
    case TexEnvMode::Replace:
      if (color) o.r = t.r, o.g = t.g, o.b = t.b;
      if (alpha) o.a = t.a;
      break;
    case TexEnvMode::Modulate:
      if (color) o.r = hn::Mul(f.r, t.r), o.g = hn::Mul(f.g, t.g), o.b = hn::Mul(f.b, t.b);
      if (alpha) o.a = hn::Mul(f.a, t.a);
      break;
    case TexEnvMode::Decal:  // defined for RGB and RGBA: Cf (1 - At) + Ct At, alpha kept
      if (st.format == TexFormat::Rgb || st.format == TexFormat::Rgba) {
        o.r = hn::MulAdd(hn::Sub(t.r, f.r), t.a, f.r), o.g = hn::MulAdd(hn::Sub(t.g, f.g), t.a, f.g);
        o.b = hn::MulAdd(hn::Sub(t.b, f.b), t.a, f.b);
      }
      break;
    case TexEnvMode::Blend: {  // Cf (1 - Ct) + Cc Ct
      if (color) {
        o.r = hn::MulAdd(hn::Sub(hn::Set(d, st.env_color.x), f.r), t.r, f.r);
        o.g = hn::MulAdd(hn::Sub(hn::Set(d, st.env_color.y), f.g), t.g, f.g);
        o.b = hn::MulAdd(hn::Sub(hn::Set(d, st.env_color.z), f.b), t.b, f.b);
      }
      if (st.format == TexFormat::Intensity) o.a = hn::MulAdd(hn::Sub(hn::Set(d, st.env_color.w), f.a), t.a, f.a);
      else if (alpha) o.a = hn::Mul(f.a, t.a);
      break;
    }
    case TexEnvMode::Add:
      if (color) o.r = hn::Min(hn::Add(f.r, t.r), one), o.g = hn::Min(hn::Add(f.g, t.g), one), o.b = hn::Min(hn::Add(f.b, t.b), one);
      if (st.format == TexFormat::Intensity) o.a = hn::Min(hn::Add(f.a, t.a), one);
      else if (alpha) o.a = hn::Mul(f.a, t.a);
      break;
    case TexEnvMode::Combine: break;  // (texture_combine, which needs the primary colour)
  }
  return o;
}

// The fog factor f from the fog coordinate c, clamped to [0, 1].
HWY_INLINE VF fog_factor(const PixelState& s, VF c) {
  const DF d;
  switch (s.fog_mode) {
    case FogMode::Linear: {
      const float range = s.fog_end - s.fog_start;
      if (range == 0) return hn::Set(d, 1.0f);
      return saturate(hn::Mul(hn::Sub(hn::Set(d, s.fog_end), c), hn::Set(d, 1.0f / range)));
    }
    case FogMode::Exp:  // exp(-density c) = 2^(-density c log2(e))
      return saturate(exp2_neg(hn::Min(hn::Mul(c, hn::Set(d, -s.fog_density * 1.44269504f)), hn::Zero(d))));
    default: {  // exp(-(density c)^2)
      const VF dc = hn::Mul(c, hn::Set(d, s.fog_density));
      return saturate(exp2_neg(hn::Mul(hn::Mul(dc, dc), hn::Set(d, -1.44269504f))));
    }
  }
}

// One blend factor for colour channel `ch` (3 = alpha).
HWY_INLINE VF blend_factor(BlendFactor f, int ch, const Rgba& s, const Rgba& dst, const Vec4& k) {
  const DF d;
  const VF one = hn::Set(d, 1.0f);
  const VF sc = ch == 0 ? s.r : ch == 1 ? s.g : ch == 2 ? s.b : s.a;
  const VF dc = ch == 0 ? dst.r : ch == 1 ? dst.g : ch == 2 ? dst.b : dst.a;
  const float kc = ch == 0 ? k.x : ch == 1 ? k.y : ch == 2 ? k.z : k.w;
  switch (f) {
    case BlendFactor::Zero: return hn::Zero(d);
    case BlendFactor::One: return one;
    case BlendFactor::SrcColor: return sc;
    case BlendFactor::OneMinusSrcColor: return hn::Sub(one, sc);
    case BlendFactor::DstColor: return dc;
    case BlendFactor::OneMinusDstColor: return hn::Sub(one, dc);
    case BlendFactor::SrcAlpha: return s.a;
    case BlendFactor::OneMinusSrcAlpha: return hn::Sub(one, s.a);
    case BlendFactor::DstAlpha: return dst.a;
    case BlendFactor::OneMinusDstAlpha: return hn::Sub(one, dst.a);
    case BlendFactor::SrcAlphaSaturate: return ch == 3 ? one : hn::Min(s.a, hn::Sub(one, dst.a));
    case BlendFactor::ConstantColor: return hn::Set(d, kc);
    case BlendFactor::OneMinusConstantColor: return hn::Set(d, 1.0f - kc);
    case BlendFactor::ConstantAlpha: return hn::Set(d, k.w);
    default: return hn::Set(d, 1.0f - k.w);  // OneMinusConstantAlpha
  }
}

HWY_INLINE VF blend_channel(const PixelState& p, int ch, const Rgba& s, const Rgba& dst) {
  const VF sc = ch == 0 ? s.r : ch == 1 ? s.g : ch == 2 ? s.b : s.a;
  const VF dc = ch == 0 ? dst.r : ch == 1 ? dst.g : ch == 2 ? dst.b : dst.a;
  if (p.blend_op == BlendOp::Min) return hn::Min(sc, dc);
  if (p.blend_op == BlendOp::Max) return hn::Max(sc, dc);
  const VF fs = blend_factor(ch == 3 ? p.blend_src_alpha : p.blend_src_rgb, ch, s, dst, p.blend_color);
  const VF fd = blend_factor(ch == 3 ? p.blend_dst_alpha : p.blend_dst_rgb, ch, s, dst, p.blend_color);
  const VF a = hn::Mul(sc, fs), b = hn::Mul(dc, fd);
  switch (p.blend_op) {
    case BlendOp::Subtract: return hn::Sub(a, b);
    case BlendOp::ReverseSubtract: return hn::Sub(b, a);
    default: return hn::Add(a, b);
  }
}

// Interpolated RGBA (planes 0-3), then per texture unit (kUnits of them) s, t, q — for a
// 3-D texture (bit u of kVolumes) s, t, r, q —, then with kSpec the secondary colour's
// RGB, then with kFog the fog coordinate.
template <int kUnits, bool kFog, bool kSpec, int kVolumes = 0>
struct FixedShader {
  static constexpr int N = fixed_varyings(kUnits, kFog, kSpec, kVolumes);
  static constexpr int kSpecAt = varying::kFixedTex + fixed_tex_varyings(kUnits, kVolumes);
  static constexpr int kFogAt = kSpecAt + (kSpec ? 3 : 0);
  static constexpr bool volume(int u) { return (kVolumes >> u & 1) != 0; }
  // Unit u's first plane (s; then t, r for a 3-D texture, q last).
  static constexpr int tex_at(int u) { return varying::kFixedTex + fixed_tex_varyings(u, kVolumes); }
  Perspective<N> in;
  const DrawState& draw;
  LevelChoice level[kUnits > 0 ? kUnits : 1]{};
  BlockLods lods[kUnits > 0 ? kUnits : 1];  // the 2-D units' (plan_levels; not initialised)

  FixedShader(const RecordHeader& r, const DrawState& d) : draw(d) { in.load(r); }

  const SamplerView& view(int unit) const { return unit == 0 ? draw.texture : draw.texture1; }
  const TextureStage& stage(int unit) const { return unit == 0 ? draw.pixel.texture : draw.pixel.texture1; }

  // The 2-D units' levels of detail at every block of the kernel's list, before the
  // first is shaded (BlockLods, shade_mesh-inl.h): u = s/q, v = t/q, the derivatives of
  // the quotients at each block's centre, a lane per block.
  void plan_levels(const RecordHeader& r, const Block* blocks, int n, int x0, int y0) {
    if constexpr (kUnits > 0) {
      for_block_vectors(r, x0, y0, blocks, n, [&](int b, VF fx, VF fy) {
        const DF d;
        const BlockCentres c(in.p, fx, fy);
        for (int u = 0; u < kUnits; ++u) {
          if (volume(u)) continue;
          VF s, sx, sy, t, tx, ty, q, qx, qy;
          const int st = tex_at(u);
          c.derivatives(st, s, sx, sy), c.derivatives(st + 1, t, tx, ty), c.derivatives(st + 2, q, qx, qy);
          const VF iq = hn::IfThenElseZero(hn::Ne(q, hn::Zero(d)), hn::Div(hn::Set(d, 1.0f), q));
          const VF uu = hn::Mul(s, iq), vv = hn::Mul(t, iq);
          auto quotient = [&](VF num, VF value, VF dq) { return hn::Mul(hn::NegMulAdd(value, dq, num), iq); };
          hn::Store(level_of_detail(view(u), quotient(sx, uu, qx), quotient(tx, vv, qx), quotient(sy, uu, qy), quotient(ty, vv, qy)),
                    d, lods[u].lod + b);
        }
      });
    }
  }

  void begin_block(float fx, float fy, int b) {
    in.begin(fx, fy);
    for (int u = 0; u < kUnits; ++u) {
      const SamplerView& tex = view(u);
      if (!volume(u)) {
        level[u] = choose_levels(tex, lods[u].lod[b]);
        continue;
      }
      // A 3-D texture, here: u = s/q, v = t/q, w = r/q, derivatives of the quotients at
      // the block's centre.
      float s, sx, sy, t, tx, ty, q, qx, qy, r, rx, ry;
      const int st = tex_at(u);
      in.derivatives(st, s, sx, sy), in.derivatives(st + 1, t, tx, ty), in.derivatives(st + 3, q, qx, qy);
      in.derivatives(st + 2, r, rx, ry);
      const float iq = q != 0 ? 1.0f / q : 0.0f;
      const float uu = s * iq, vv = t * iq, ww = r * iq;
      level[u] = choose_levels(tex, level_of_detail3(tex, (sx - uu * qx) * iq, (tx - vv * qx) * iq, (rx - ww * qx) * iq,
                                                     (sy - uu * qy) * iq, (ty - vv * qy) * iq, (ry - ww * qy) * iq));
    }
  }

  HWY_INLINE Rgba shade(int v) {
    in.at_vector(v);
    return shade_from([&](int k) { return in(k, v); });
  }

  // The colour of a record whose varyings are the same at every pixel (kConstantVaryings:
  // constant planes, 1 / w = 1) when no texture varies it: every pixel's.
  Rgba constant_color(const RecordHeader& r) const {
    static_assert(kUnits == 0);
    const DF d;
    const Plane* var = varyings(r);
    return shade_from([&](int k) { return hn::Set(d, var[k].c); });
  }

 private:
  // The fixed-function colour from the interpolated varyings, at(k) varying k of vector v.
  template <class At>
  HWY_INLINE Rgba shade_from(const At& at) const {
    const DF d;
    constexpr int c0 = varying::kFixedColor;
    Rgba c{saturate(at(c0)), saturate(at(c0 + 1)), saturate(at(c0 + 2)), saturate(at(c0 + 3))};
    for (int u = 0; u < kUnits; ++u) {  // the units in order, each on the last one's colour
      const int st = tex_at(u);
      const VF iq = hn::Div(hn::Set(d, 1.0f), at(st + (volume(u) ? 3 : 2)));
      Rgba t;
      if (volume(u)) t = sample3(view(u), level[u], hn::Mul(at(st), iq), hn::Mul(at(st + 1), iq), hn::Mul(at(st + 2), iq));
      else t = sample(view(u), level[u], hn::Mul(at(st), iq), hn::Mul(at(st + 1), iq));
      // GL_COMBINE's primary colour is interpolated again, not kept alive through the
      // units, so the other environments hold no more registers.
      const TextureStage& stg = stage(u);
      if (stg.env == TexEnvMode::Combine) {
        const Rgba primary{saturate(at(c0)), saturate(at(c0 + 1)), saturate(at(c0 + 2)), saturate(at(c0 + 3))};
        c = texture_combine(stg, c, t, primary);
      } else {
        c = texture_environment(stg, c, t);
      }
    }
    if constexpr (kSpec) {  // the colour sum: the secondary colour after texturing
      const VF one = hn::Set(d, 1.0f);
      c.r = hn::Min(hn::Add(c.r, saturate(at(kSpecAt))), one);
      c.g = hn::Min(hn::Add(c.g, saturate(at(kSpecAt + 1))), one);
      c.b = hn::Min(hn::Add(c.b, saturate(at(kSpecAt + 2))), one);
    }
    if constexpr (kFog) {
      const PixelState& p = draw.pixel;
      const VF f = fog_factor(p, at(kFogAt));
      c.r = hn::MulAdd(hn::Sub(c.r, hn::Set(d, p.fog_color.x)), f, hn::Set(d, p.fog_color.x));
      c.g = hn::MulAdd(hn::Sub(c.g, hn::Set(d, p.fog_color.y)), f, hn::Set(d, p.fog_color.y));
      c.b = hn::MulAdd(hn::Sub(c.b, hn::Set(d, p.fog_color.z)), f, hn::Set(d, p.fog_color.z));
    }
    return c;
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_SHADE_FIXED_INL_H_ toggle
