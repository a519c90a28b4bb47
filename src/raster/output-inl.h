// The mesh kernels' last step (OutputTransform, contract.hpp): light to pixels. Display
// packs the values as they are; Linear multiplies by the exposure, tone maps (none,
// ACES as three.js's ACESFilmicToneMapping, Khronos PBR Neutral) and encodes to sRGB.
#if defined(VELOCITY_RASTER_OUTPUT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_OUTPUT_INL_H_
#undef VELOCITY_RASTER_OUTPUT_INL_H_
#else
#define VELOCITY_RASTER_OUTPUT_INL_H_
#endif

#include "raster/contract.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// ACES filmic, as three.js writes it (Stephen Hill's fit of the RRT and ODT), its
// exposure already applied: the input matrix, the fit, the output matrix, clamped.
HWY_INLINE V3 tone_map_aces(V3 c) {
  const DF d;
  auto mat = [&](const V3& v, const float m[9]) {
    return V3{hn::MulAdd(hn::Set(d, m[0]), v.x, hn::MulAdd(hn::Set(d, m[1]), v.y, hn::Mul(hn::Set(d, m[2]), v.z))),
              hn::MulAdd(hn::Set(d, m[3]), v.x, hn::MulAdd(hn::Set(d, m[4]), v.y, hn::Mul(hn::Set(d, m[5]), v.z))),
              hn::MulAdd(hn::Set(d, m[6]), v.x, hn::MulAdd(hn::Set(d, m[7]), v.y, hn::Mul(hn::Set(d, m[8]), v.z)))};
  };
  static constexpr float kIn[9] = {0.59719f, 0.35458f, 0.04823f, 0.07600f, 0.90834f, 0.01566f, 0.02840f, 0.13383f, 0.83777f};
  static constexpr float kOut[9] = {1.60475f, -0.53108f, -0.07367f, -0.10208f, 1.10813f, -0.00605f, -0.00327f, -0.07276f, 1.07602f};
  auto fit = [&](VF v) {
    const VF a = hn::MulSub(v, hn::Add(v, hn::Set(d, 0.0245786f)), hn::Set(d, 0.000090537f));
    const VF b = hn::MulAdd(v, hn::MulAdd(hn::Set(d, 0.983729f), v, hn::Set(d, 0.4329510f)), hn::Set(d, 0.238081f));
    return hn::Div(a, b);
  };
  const VF k = hn::Set(d, 1.0f / 0.6f);  // three.js's exposure / 0.6
  V3 t = mat({hn::Mul(c.x, k), hn::Mul(c.y, k), hn::Mul(c.z, k)}, kIn);
  t = mat({fit(t.x), fit(t.y), fit(t.z)}, kOut);
  return {saturate(t.x), saturate(t.y), saturate(t.z)};
}

// Khronos PBR Neutral (the reference GLSL of the Khronos 3D Commerce group, as three.js
// ships it as NeutralToneMapping).
HWY_INLINE V3 tone_map_neutral(V3 c) {
  const DF d;
  constexpr float kStart = 0.8f - 0.04f, kDesaturation = 0.15f;
  const VF x = hn::Min(c.x, hn::Min(c.y, c.z));
  const VF offset = hn::IfThenElse(hn::Lt(x, hn::Set(d, 0.08f)), hn::NegMulAdd(hn::Set(d, 6.25f), hn::Mul(x, x), x),
                                   hn::Set(d, 0.04f));
  c = {hn::Sub(c.x, offset), hn::Sub(c.y, offset), hn::Sub(c.z, offset)};
  const VF peak = hn::Max(c.x, hn::Max(c.y, c.z));
  const MF compress = hn::Ge(peak, hn::Set(d, kStart));
  if (hn::AllFalse(d, compress)) return c;
  constexpr float kD = 1.0f - kStart;
  const VF new_peak = hn::Sub(hn::Set(d, 1.0f), hn::Div(hn::Set(d, kD * kD), hn::Add(peak, hn::Set(d, kD - kStart))));
  const VF k = hn::Div(new_peak, hn::Max(peak, hn::Set(d, 1e-6f)));
  const VF g = hn::Sub(hn::Set(d, 1.0f),
                       hn::Div(hn::Set(d, 1.0f), hn::MulAdd(hn::Set(d, kDesaturation), hn::Sub(peak, new_peak), hn::Set(d, 1.0f))));
  auto one = [&](VF v) {
    const VF s = hn::Mul(v, k);
    return hn::IfThenElse(compress, hn::MulAdd(hn::Sub(new_peak, s), g, s), v);
  };
  return {one(c.x), one(c.y), one(c.z)};
}

// Linear [0, 1] to 8-bit sRGB: the linear segment near black, above it a degree-6
// polynomial in sqrt(x) fitted (least squares) to 1.055 x^(1/2.4) - 0.055 over
// [0.0031308, 1], within 0.09 of an 8-bit step before rounding. Cheaper than a table
// (a gather per channel) or pow's log and exp.
HWY_INLINE VU encode_srgb(VF x) {
  const DF d;
  x = saturate(x);
  // sqrt(x): x times the reciprocal square root's estimate, and a Newton step. The
  // estimate is of at least 1e-6, which keeps it finite where the linear segment below
  // applies (sqrt_fast's masks for x <= 0 are not needed). Without the step (AVX-512's
  // estimate is good to 2^-14) linear 0.5 encodes to 187, not 188.
  const VF y = hn::ApproximateReciprocalSqrt(hn::Max(x, hn::Set(d, 1e-6f)));
  const VF s0 = hn::Mul(x, y);
  const VF s = hn::Mul(s0, hn::NegMulAdd(hn::Mul(hn::Set(d, 0.5f), s0), y, hn::Set(d, 1.5f)));
  VF p = hn::Set(d, -0.904863438f);
  p = hn::MulAdd(p, s, hn::Set(d, 3.23747163f));
  p = hn::MulAdd(p, s, hn::Set(d, -4.72147221f));
  p = hn::MulAdd(p, s, hn::Set(d, 3.6933027f));
  p = hn::MulAdd(p, s, hn::Set(d, -1.8270792f));
  p = hn::MulAdd(p, s, hn::Set(d, 1.56393955f));
  p = hn::MulAdd(p, s, hn::Set(d, -0.0416483619f));
  const VF e = hn::IfThenElse(hn::Le(x, hn::Set(d, 0.0031308f)), hn::Mul(x, hn::Set(d, 12.92f)), p);
  return hn::BitCast(DU(), truncate_in_range(hn::MulAdd(e, hn::Set(d, 255.0f), hn::Set(d, 0.5f))));
}

// Light (or display values) to RGBA8, as the frame's OutputTransform says.
HWY_INLINE VU finish(const OutputTransform& o, VF r, VF g, VF b, VF a) {
  if (!o.linear) return pack_colors(r, g, b, a);
  const DF d;
  V3 c{r, g, b};
  if (o.exposure != 1) {
    const VF e = hn::Set(d, o.exposure);
    c = {hn::Mul(c.x, e), hn::Mul(c.y, e), hn::Mul(c.z, e)};
  }
  if (o.tone_map == ToneMap::Aces) c = tone_map_aces(c);
  else if (o.tone_map == ToneMap::KhronosNeutral) c = tone_map_neutral(c);
  const VU alpha = hn::BitCast(DU(), truncate_in_range(hn::MulAdd(saturate(a), hn::Set(d, 255.0f), hn::Set(d, 0.5f))));
  return hn::Or(hn::Or(encode_srgb(c.x), hn::ShiftLeft<8>(encode_srgb(c.y))),
                hn::Or(hn::ShiftLeft<16>(encode_srgb(c.z)), hn::ShiftLeft<24>(alpha)));
}
HWY_INLINE VU finish(const OutputTransform& o, VF r, VF g, VF b) { return finish(o, r, g, b, hn::Set(DF(), 1.0f)); }

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_OUTPUT_INL_H_ toggle
