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
  // The four texel centres around (x, y) and the bilinear weights. The first, (ix, iy),
  // lies in -1..size-1 and the map's border repeats its edges (shadow.hpp), so the four
  // are (ix, iy) and its right neighbour, one 32-bit load, and the same a row below.
  const VF gx = hn::Sub(hn::IfThenElseZero(inside, x), half), gy = hn::Sub(hn::IfThenElseZero(inside, y), half);
  const VF fx0 = hn::Floor(gx), fy0 = hn::Floor(gy);
  const VF fx = hn::Sub(gx, fx0), fy = hn::Sub(gy, fy0);
  // shadow_texel(ix, iy), in float while that is exact (every index below 2^24: maps up
  // to 4093 texels a side): one conversion, and no integer multiply's latency.
  const VI index = shadow_texel_exact_in_float(m.size)
                       ? truncate_in_range(hn::MulAdd(fy0, hn::Set(d, float(m.stride)), hn::Add(fx0, hn::Set(d, float(m.stride + 1)))))
                       : hn::Add(hn::Mul(truncate_in_range(fy0), hn::Set(di, m.stride)),
                                 hn::Add(truncate_in_range(fx0), hn::Set(di, m.stride + 1)));
  // Both pairs of every lane with two gathers (lanes outside the map read texel (-1, -1),
  // and give 1 below). Measured on this project's 2-core AMD EPYC (Zen 3, AVX2), the
  // bench's Phong frame with the map: the two gathers cost the kernel about what the one
  // nearest-of-four load of the tiled map did (485 against 487 ms of samples over 41
  // frames), the same pairs loaded lane by lane 14 % more (553): docs/appearance.md.
  const DU du;
  const VI offset = hn::ShiftLeft<1>(index);  // bytes
  const uint32_t* pairs = reinterpret_cast<const uint32_t*>(m.depth);
  const VU top_pair = hn::GatherOffset(du, pairs, offset);
  const VU bottom_pair = hn::GatherOffset(du, pairs, hn::Add(offset, hn::Set(di, 2 * m.stride)));
  // Each pair holds the left texel's code in its low half (little-endian).
  const VU low = hn::Set(du, 0xffffu);
  auto lit = [&](VU code) { return hn::IfThenElseZero(hn::Le(z, hn::ConvertTo(d, hn::BitCast(di, code))), one); };
  const VF l00 = lit(hn::And(top_pair, low)), l10 = lit(hn::ShiftRight<16>(top_pair));
  const VF l01 = lit(hn::And(bottom_pair, low)), l11 = lit(hn::ShiftRight<16>(bottom_pair));
  const VF top = hn::MulAdd(hn::Sub(l10, l00), fx, l00), bottom = hn::MulAdd(hn::Sub(l11, l01), fx, l01);
  return hn::IfThenElse(inside, hn::MulAdd(hn::Sub(bottom, top), fy, top), one);
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
