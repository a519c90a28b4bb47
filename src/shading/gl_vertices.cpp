// pGL's vertex stage for runs of vertices (gl_vertices.hpp), compiled once per
// instruction set and dispatched at run time. Every sum is written in the scalar
// path's order (Mat4 * Vec4, transform_vector, normalize, dot, light_gl) and the file
// is compiled with -ffp-contract=off, so each lane rounds as the scalar code does.
#include "shading/gl_vertices.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/gl_vertices.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::shading {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// a0 * x + a1 * y + a2 * z (+ a3 * w), summed left to right.
HWY_INLINE VF row3(const float* a, VF x, VF y, VF z) {
  const DF d;
  return hn::Add(hn::Add(hn::Mul(hn::Set(d, a[0]), x), hn::Mul(hn::Set(d, a[1]), y)), hn::Mul(hn::Set(d, a[2]), z));
}
HWY_INLINE VF row4(const float* a, VF x, VF y, VF z, VF w) {
  return hn::Add(row3(a, x, y, z), hn::Mul(hn::Set(DF(), a[3]), w));
}

// unit(): v > 0 ? min(v, 1) : 0, NaN to 0, as the scalar clamp.
HWY_INLINE VF unit(VF v) {
  const DF d;
  const VF one = hn::Set(d, 1.0f);
  return hn::IfThenElseZero(hn::Gt(v, hn::Zero(d)), hn::IfThenElse(hn::Lt(v, one), v, one));
}

void GlVertices(const GlVertexRun& run) {
  const DF d;
  constexpr size_t N = kLanes;
  const GlMaterial& m = run.material;
  // What is the same at every vertex: the ambient terms (light_gl's t.ambient, the
  // model's then each light's, and the material's share), in light_gl's order.
  Vec3 ambient = run.model_ambient;
  for (int k = 0; k < run.light_count; ++k) ambient += run.lights[k].colors.ambient;
  const Vec3 base = m.emission.xyz() + m.ambient.xyz() * ambient;
  const float alpha = m.diffuse.w > 0 ? (m.diffuse.w < 1 ? m.diffuse.w : 1.0f) : 0.0f;
  for (size_t i = 0; i < run.count; i += N) {
    const size_t k = std::min(N, run.count - i);
    // Whole vectors straight from the caller's arrays; the last, partial one through a
    // copy padded with zeros.
    const bool whole = k == N;
    alignas(64) float tail_p[4 * N] = {}, tail_n[3 * N] = {};
    if (!whole) {
      std::memcpy(tail_p, run.position + i, k * sizeof(Vec4));
      std::memcpy(tail_n, run.normal + i, k * sizeof(Vec3));
    }
    VF px, py, pz, pw, ox, oy, oz;
    hn::LoadInterleaved4(d, whole ? reinterpret_cast<const float*>(run.position + i) : tail_p, px, py, pz, pw);
    hn::LoadInterleaved3(d, whole ? reinterpret_cast<const float*>(run.normal + i) : tail_n, ox, oy, oz);
    const Mat4& mvp = run.mvp;
    const VF cx = row4(mvp.m[0], px, py, pz, pw), cy = row4(mvp.m[1], px, py, pz, pw);
    const VF cz = row4(mvp.m[2], px, py, pz, pw), cw = row4(mvp.m[3], px, py, pz, pw);
    VF nx = row3(run.normal_matrix.m[0], ox, oy, oz), ny = row3(run.normal_matrix.m[1], ox, oy, oz);
    VF nz = row3(run.normal_matrix.m[2], ox, oy, oz);
    if (run.normalize) {  // normalize(): n / length(n), or zero
      const VF len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
      const MF some = hn::Gt(len, hn::Zero(d));
      nx = hn::IfThenElseZero(some, hn::Div(nx, len)), ny = hn::IfThenElseZero(some, hn::Div(ny, len));
      nz = hn::IfThenElseZero(some, hn::Div(nz, len));
    }
    // Each light's diffuse and specular (add_light<Blinn> with the light's half vector):
    // a term is added only where the scalar code adds it (adding zero elsewhere changes
    // no sum: they start at +0 and never become -0).
    VF dr = hn::Zero(d), dg = hn::Zero(d), db = hn::Zero(d), sr = hn::Zero(d), sg = hn::Zero(d), sb = hn::Zero(d);
    for (int l = 0; l < run.light_count; ++l) {
      const GlLight& light = run.lights[l];
      const float to_light[3] = {light.direction.x, light.direction.y, light.direction.z};
      const float half[3] = {light.half.x, light.half.y, light.half.z};
      const VF nl = row3(to_light, nx, ny, nz);  // dot(n, to_light): n's components first, the same products
      const MF lit = hn::Gt(nl, hn::Zero(d));
      const Vec3& cd = light.colors.diffuse;
      dr = hn::Add(dr, hn::IfThenElseZero(lit, hn::Mul(hn::Set(d, cd.x), nl)));
      dg = hn::Add(dg, hn::IfThenElseZero(lit, hn::Mul(hn::Set(d, cd.y), nl)));
      db = hn::Add(db, hn::IfThenElseZero(lit, hn::Mul(hn::Set(d, cd.z), nl)));
      const VF nh = row3(half, nx, ny, nz);
      const MF shine = hn::And(lit, hn::Gt(nh, hn::Zero(d)));
      VF f = hn::Set(d, 1.0f);
      if (m.shininess != 0) {  // pow lane by lane: std::pow's own rounding
        alignas(64) float h[N];
        hn::Store(nh, d, h);
        for (size_t j = 0; j < N; ++j) h[j] = h[j] > 0 ? std::pow(h[j], m.shininess) : 0.0f;
        f = hn::Load(d, h);
      }
      const Vec3& cs = light.colors.specular;
      sr = hn::Add(sr, hn::IfThenElseZero(shine, hn::Mul(hn::Set(d, cs.x), f)));
      sg = hn::Add(sg, hn::IfThenElseZero(shine, hn::Mul(hn::Set(d, cs.y), f)));
      sb = hn::Add(sb, hn::IfThenElseZero(shine, hn::Mul(hn::Set(d, cs.z), f)));
    }
    // emission + ambient_m * ambient + diffuse_m * diffuse + specular_m * specular.
    auto channel = [&](float b, float md, float ms, VF dsum, VF ssum) {
      return unit(hn::Add(hn::Add(hn::Set(d, b), hn::Mul(hn::Set(d, md), dsum)), hn::Mul(hn::Set(d, ms), ssum)));
    };
    const VF r = channel(base.x, m.diffuse.x, m.specular.x, dr, sr);
    const VF g = channel(base.y, m.diffuse.y, m.specular.y, dg, sg);
    const VF b = channel(base.z, m.diffuse.z, m.specular.z, db, sb);
    const VF a = hn::Set(d, alpha);
    if (whole) {
      hn::StoreInterleaved4(cx, cy, cz, cw, d, reinterpret_cast<float*>(run.clip + i));
      hn::StoreInterleaved4(r, g, b, a, d, reinterpret_cast<float*>(run.color + i));
    } else {
      hn::StoreInterleaved4(cx, cy, cz, cw, d, tail_p);
      std::memcpy(run.clip + i, tail_p, k * sizeof(Vec4));
      hn::StoreInterleaved4(r, g, b, a, d, tail_p);
      std::memcpy(run.color + i, tail_p, k * sizeof(Vec4));
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::shading
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::shading {

HWY_EXPORT(GlVertices);

void gl_vertices(const GlVertexRun& run) { HWY_DYNAMIC_DISPATCH(GlVertices)(run); }

}  // namespace velocity::shading
#endif
