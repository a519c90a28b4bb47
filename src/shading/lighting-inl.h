// The lighting model of lighting.hpp for N points at a time (one per lane): the same
// terms in the same order, written against the SIMD layer. The vertex stage calls it
// for N vertices, the Phong kernels for N pixels. Compiled once per instruction set,
// hence the toggling include guard (simd-inl.h).
#if defined(VELOCITY_SHADING_LIGHTING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_SHADING_LIGHTING_INL_H_
#undef VELOCITY_SHADING_LIGHTING_INL_H_
#else
#define VELOCITY_SHADING_LIGHTING_INL_H_
#endif

#include "shading/lighting.hpp"
#include "shading/shadow-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::shading {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// The light arriving at N points (LightTerms, a lane per point).
struct LightTermsN {
  V3 diffuse;   // ambient + sum of diffuse
  V3 specular;  // sum of specular, already scaled by Ks
};

// detail::punctual of lighting.hpp: a point or spot light's attenuation at N points, and
// the unit directions to it.
HWY_INLINE VF punctual(const EyeLights::Point& l, const V3& p, const V3& n, V3& to_light) {
  const DF d;
  const V3 v{hn::Sub(hn::Set(d, l.position.x), p.x), hn::Sub(hn::Set(d, l.position.y), p.y),
             hn::Sub(hn::Set(d, l.position.z), p.z)};
  const VF d2 = dot(v, v);
  const VF il = rsqrt(d2);
  // A light at the surface point lights it along the normal.
  const MF here = hn::Eq(d2, hn::Zero(d));
  to_light = {hn::IfThenElse(here, n.x, hn::Mul(v.x, il)), hn::IfThenElse(here, n.y, hn::Mul(v.y, il)),
              hn::IfThenElse(here, n.z, hn::Mul(v.z, il))};
  VF att;
  if (l.inverse_square) {
    att = hn::Div(hn::Set(d, 1.0f), hn::Max(d2, hn::Set(d, 0.01f)));
  } else {
    const VF dist = hn::Mul(d2, il);
    att = hn::MulAdd(hn::MulAdd(hn::Set(d, l.quadratic), dist, hn::Set(d, l.linear)), dist, hn::Set(d, l.constant));
    att = hn::Div(hn::Set(d, 1.0f), hn::Max(att, hn::Set(d, 1e-6f)));
  }
  if (l.inv_range4 > 0) {
    const VF w = saturate(hn::NegMulAdd(hn::Mul(d2, d2), hn::Set(d, l.inv_range4), hn::Set(d, 1.0f)));
    att = hn::Mul(att, hn::Mul(w, w));
  }
  if (l.spot) {
    const V3 axis{hn::Set(d, l.spot_axis.x), hn::Set(d, l.spot_axis.y), hn::Set(d, l.spot_axis.z)};
    const VF a = saturate(hn::MulAdd(hn::Neg(dot(axis, to_light)), hn::Set(d, l.spot_scale), hn::Set(d, l.spot_offset)));
    att = hn::Mul(att, hn::Mul(a, a));
  }
  return att;
}

// `n` unit normals and `p` positions, eye space. `p` is read only for the specular term
// (s.ks > 0), point lights and shadows (lights.shadows); otherwise it may be left zero.
// `live`: the lanes whose result is used (the others may skip their shadow lookups).
HWY_INLINE LightTermsN light(const EyeLights& lights, V3 n, V3 p, const Specular& s, MF live) {
  const DF d;
  LightTermsN t{{hn::Set(d, lights.ambient.x), hn::Set(d, lights.ambient.y), hn::Set(d, lights.ambient.z)},
                {hn::Zero(d), hn::Zero(d), hn::Zero(d)}};
  V3 to_eye{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
  if (s.ks > 0) {
    const VF il = rsqrt(dot(p, p));
    to_eye = {hn::Neg(hn::Mul(p.x, il)), hn::Neg(hn::Mul(p.y, il)), hn::Neg(hn::Mul(p.z, il))};
  }
  // detail::add_light of lighting.hpp.
  auto add_light = [&](const V3& l, VF cr, VF cg, VF cb) {
    const VF nl = dot(n, l);
    const VF k = hn::ZeroIfNegative(nl);
    t.diffuse = {hn::MulAdd(cr, k, t.diffuse.x), hn::MulAdd(cg, k, t.diffuse.y), hn::MulAdd(cb, k, t.diffuse.z)};
    if (s.ks > 0) {
      // R = 2 (N.L) N - L; as the reference computes it, not gated on N.L.
      const VF two_nl = hn::Add(nl, nl);
      const V3 r{hn::MulSub(two_nl, n.x, l.x), hn::MulSub(two_nl, n.y, l.y), hn::MulSub(two_nl, n.z, l.z)};
      const VF rv = dot(r, to_eye);
      const MF lit = hn::Gt(rv, hn::Set(d, s.cutoff));
      if (!hn::AllFalse(d, lit)) {
        const VF base = hn::Min(hn::IfThenElse(lit, rv, hn::Set(d, 1.0f)), hn::Set(d, 1.0f));
        const VF e = hn::Mul(hn::Set(d, s.ks), hn::IfThenElseZero(lit, pow01(base, hn::Set(d, s.exponent))));
        t.specular = {hn::MulAdd(cr, e, t.specular.x), hn::MulAdd(cg, e, t.specular.y), hn::MulAdd(cb, e, t.specular.z)};
      }
    }
  };
  for (const auto& l : lights.directional) {
    const V3 dir{hn::Set(d, l.to_light.x), hn::Set(d, l.to_light.y), hn::Set(d, l.to_light.z)};
    const VF vis = visibility(l.shadow, p, n, dir, live);
    add_light(dir, hn::Mul(hn::Set(d, l.color.x), vis), hn::Mul(hn::Set(d, l.color.y), vis),
              hn::Mul(hn::Set(d, l.color.z), vis));
  }
  for (const auto& l : lights.point) {
    V3 dir;
    VF att = punctual(l, p, n, dir);
    if (l.shadow) att = hn::Mul(att, visibility(l.shadow, p, n, dir, live));
    add_light(dir, hn::Mul(hn::Set(d, l.color.x), att), hn::Mul(hn::Set(d, l.color.y), att),
              hn::Mul(hn::Set(d, l.color.z), att));
  }
  return t;
}

// base * diffuse + specular, per channel (apply of lighting.hpp).
HWY_INLINE V3 apply(const LightTermsN& t, const V3& base) {
  return {hn::MulAdd(base.x, t.diffuse.x, t.specular.x), hn::MulAdd(base.y, t.diffuse.y, t.specular.y),
          hn::MulAdd(base.z, t.diffuse.z, t.specular.z)};
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::shading
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_SHADING_LIGHTING_INL_H_ toggle
