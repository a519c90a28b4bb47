// The visibility of shadow.hpp N points at a time (one per lane): the same offsets,
// projection and bilinear percentage-closer filter, with the four texels gathered. A point
// light's cube picks a face per point, so its lanes are looked up one by one with the
// scalar form (the one map of a directional or spot light is the fast path).
#if defined(VELOCITY_SHADING_SHADOW_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_SHADING_SHADOW_INL_H_
#undef VELOCITY_SHADING_SHADOW_INL_H_
#else
#define VELOCITY_SHADING_SHADOW_INL_H_
#endif

#include "shading/shadow.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::shading {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// map_visibility of shadow.hpp at N points; only the lanes in `live` are looked up (the
// others give 1).
HWY_INLINE VF map_visibility(const ShadowMap& m, const V3& p, const V3& n, const V3& to_light, MF live) {
  const DF d;
  const DI di;
  const Mat4& M = m.eye_to_clip;
  auto row = [&](int r, const V3& q) {
    return hn::MulAdd(hn::Set(d, M.m[r][0]), q.x,
                      hn::MulAdd(hn::Set(d, M.m[r][1]), q.y, hn::MulAdd(hn::Set(d, M.m[r][2]), q.z, hn::Set(d, M.m[r][3]))));
  };
  VF texel = hn::Set(d, m.texel);
  if (m.perspective) texel = hn::Mul(texel, row(3, p));
  const VF kn = hn::Mul(texel, hn::Set(d, kNormalOffset)), kl = hn::Mul(texel, hn::Set(d, kLightOffset));
  const V3 q{hn::MulAdd(n.x, kn, hn::MulAdd(to_light.x, kl, p.x)), hn::MulAdd(n.y, kn, hn::MulAdd(to_light.y, kl, p.y)),
             hn::MulAdd(n.z, kn, hn::MulAdd(to_light.z, kl, p.z))};
  const VF one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f), s = hn::Set(d, float(m.size));
  // Clip to normalised device coordinates: a directional light's map (orthographic, w = 1)
  // needs no divide. The point's code (shadow.hpp) is linear in z (orthographic) or w.
  VF w = one, cx = row(0, q), cy = row(1, q), z;
  if (m.perspective) {
    w = row(3, q);
    const VF iw = hn::Div(one, w);
    cx = hn::Mul(cx, iw), cy = hn::Mul(cy, iw);
    z = hn::MulAdd(w, hn::Set(d, m.code_scale), hn::Set(d, m.code_offset));
  } else {
    z = hn::MulAdd(row(2, q), hn::Set(d, m.code_scale), hn::Set(d, m.code_offset));
  }
  const VF x = hn::Mul(hn::MulAdd(cx, half, half), s);
  const VF y = hn::Mul(hn::NegMulAdd(cy, half, half), s);
  // Comparisons with a NaN are false: such a lane is outside, and lit.
  const MF inside = hn::And(live, hn::And(hn::And(hn::And(hn::Gt(w, hn::Zero(d)), hn::Le(z, hn::Set(d, kShadowFar))),
                                                hn::And(hn::Ge(x, hn::Zero(d)), hn::Lt(x, s))),
                                        hn::And(hn::Ge(y, hn::Zero(d)), hn::Lt(y, s))));
  if (hn::AllFalse(d, inside)) return one;
  // The four texel centres around (x, y) and the bilinear weights (clamped to the map).
  const VF gx = hn::Sub(hn::IfThenElseZero(inside, x), half), gy = hn::Sub(hn::IfThenElseZero(inside, y), half);
  const VF fx0 = hn::Floor(gx), fy0 = hn::Floor(gy);
  const VF fx = hn::Sub(gx, fx0), fy = hn::Sub(gy, fy0);
  const VI ix = hn::ConvertTo(di, fx0), iy = hn::ConvertTo(di, fy0);
  const VI lo = hn::Zero(di), hi = hn::Set(di, m.size - 1), k1 = hn::Set(di, 1);
  const VI x0 = hn::Max(ix, lo), y0 = hn::Max(iy, lo), x1 = hn::Min(hn::Add(ix, k1), hi), y1 = hn::Min(hn::Add(iy, k1), hi);
  // framebuffer.hpp's index, split into its row part (tile row, block row, row in the
  // block) and its column part.
  const VI row_stride = hn::Set(di, m.tiles_x * 4096), k15 = hn::Set(di, 15), k3 = hn::Set(di, 3);
  auto row_of = [&](VI ty) {
    return hn::Add(hn::Mul(hn::ShiftRight<6>(ty), row_stride),
                   hn::Add(hn::ShiftLeft<8>(hn::And(hn::ShiftRight<2>(ty), k15)), hn::ShiftLeft<2>(hn::And(ty, k3))));
  };
  auto column_of = [&](VI tx) {
    return hn::Add(hn::ShiftLeft<12>(hn::ShiftRight<6>(tx)), hn::Add(hn::ShiftLeft<4>(hn::And(hn::ShiftRight<2>(tx), k15)), hn::And(tx, k3)));
  };
  const VI r0 = row_of(y0), r1 = row_of(y1), c0 = column_of(x0), c1 = column_of(x1);
  // Lane by lane rather than with a gather instruction: on this project's AMD EPYC the
  // gather is microcoded and no faster (the Phong bench frame with a 2048^2 map: 13.2 ms
  // of CPU this way, 14.6 ms gathered, docs/appearance.md). Only the lanes inside the map
  // that the caller needs: a triangle's edge blocks are partly covered, and the pixels
  // facing away from the light need no lookup.
  alignas(64) int32_t index[4][kLanes];
  alignas(64) int32_t stored[4][kLanes];
  hn::Store(hn::Add(r0, c0), di, index[0]);
  // First the nearest of each lane's four codes, one load: a point nearer than that is
  // lit by all four (the filter gives exactly 1), and most lit points are (the bias
  // lifts them 2-3 texels, the filter's reach is 1.4).
  for (int t = 0; t < 4; ++t) hn::Store(hn::Zero(di), di, stored[t]);
  for (uint32_t bits = lane_bits(d, inside); bits; bits &= bits - 1) {
    const size_t k = hwy::Num0BitsBelowLS1Bit_Nonzero32(bits);
    stored[0][k] = m.nearest[index[0][k]];
  }
  const MF rest = hn::AndNot(hn::Le(z, hn::ConvertTo(d, hn::Load(di, stored[0]))), inside);
  if (hn::AllFalse(d, rest)) return one;
  hn::Store(hn::Add(r0, c1), di, index[1]);
  hn::Store(hn::Add(r1, c0), di, index[2]);
  hn::Store(hn::Add(r1, c1), di, index[3]);
  for (uint32_t bits = lane_bits(d, rest); bits; bits &= bits - 1) {
    const size_t k = hwy::Num0BitsBelowLS1Bit_Nonzero32(bits);
    for (int t = 0; t < 4; ++t) stored[t][k] = m.depth[index[t][k]];
  }
  auto lit = [&](int t) { return hn::IfThenElseZero(hn::Le(z, hn::ConvertTo(d, hn::Load(di, stored[t]))), one); };
  const VF l00 = lit(0), l10 = lit(1), l01 = lit(2), l11 = lit(3);
  const VF top = hn::MulAdd(hn::Sub(l10, l00), fx, l00), bottom = hn::MulAdd(hn::Sub(l11, l01), fx, l01);
  return hn::IfThenElse(rest, hn::MulAdd(hn::Sub(bottom, top), fy, top), one);
}

// visibility of shadow.hpp at N points: 0 where N.L <= 0, and nothing looked up for those
// lanes nor for the lanes outside `live` (pixels the caller does not write: their value
// is unspecified); `s` null (the light casts no shadow): 1.
HWY_INLINE VF visibility(const LightShadow* s, const V3& p, const V3& n, const V3& to_light, MF live) {
  const DF d;
  if (!s) return hn::Set(d, 1.0f);
  const MF facing = hn::Gt(dot(n, to_light), hn::Zero(d));
  if (hn::AllFalse(d, hn::And(facing, live))) return hn::Zero(d);
  if (s->faces == 1) return hn::IfThenElseZero(facing, map_visibility(s->face[0], p, n, to_light, hn::And(facing, live)));
  alignas(64) float in[9][kLanes], out[kLanes];
  const VF* v[9] = {&p.x, &p.y, &p.z, &n.x, &n.y, &n.z, &to_light.x, &to_light.y, &to_light.z};
  for (int i = 0; i < 9; ++i) hn::Store(*v[i], d, in[i]);
  hn::Store(hn::Zero(d), d, out);
  for (uint32_t bits = lane_bits(d, hn::And(facing, live)); bits; bits &= bits - 1) {
    const size_t k = hwy::Num0BitsBelowLS1Bit_Nonzero32(bits);
    out[k] = shading::visibility(*s, {in[0][k], in[1][k], in[2][k]}, {in[3][k], in[4][k], in[5][k]},
                                 {in[6][k], in[7][k], in[8][k]});
  }
  return hn::Load(d, out);
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::shading
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_SHADING_SHADOW_INL_H_ toggle
