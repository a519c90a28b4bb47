// The vertex stage, compiled once per instruction set and dispatched at run time.
#include "geometry/vertex_stage.hpp"

#include <algorithm>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "geometry/vertex_stage.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "shading/lighting-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::geometry {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;
namespace lit = velocity::shading::HWY_NAMESPACE;

HWY_INLINE V3 transform_point(const Mat4& m, const V3& p) {
  const DF d;
  auto row = [&](int r) {
    return hn::MulAdd(hn::Set(d, m.m[r][0]), p.x,
                      hn::MulAdd(hn::Set(d, m.m[r][1]), p.y, hn::MulAdd(hn::Set(d, m.m[r][2]), p.z, hn::Set(d, m.m[r][3]))));
  };
  return {row(0), row(1), row(2)};
}

HWY_INLINE V3 transform_vector(const Mat4& m, const V3& p) {
  const DF d;
  auto row = [&](int r) {
    return hn::MulAdd(hn::Set(d, m.m[r][0]), p.x, hn::MulAdd(hn::Set(d, m.m[r][1]), p.y, hn::Mul(hn::Set(d, m.m[r][2]), p.z)));
  };
  return {row(0), row(1), row(2)};
}

// Region code bits (clip.hpp) of N clip-space positions.
HWY_INLINE VU outcodes(VF x, VF y, VF z, VF w, const GuardBand& g) {
  const DF d;
  const DU du;
  VU c = hn::Zero(du);
  auto bit = [&](MF m, uint32_t b) { c = hn::Or(c, hn::IfThenElseZero(hn::RebindMask(du, m), hn::Set(du, b))); };
  const VF nw = hn::Neg(w);
  bit(hn::Lt(x, nw), kOutLeft), bit(hn::Gt(x, w), kOutRight);
  bit(hn::Lt(y, nw), kOutBottom), bit(hn::Gt(y, w), kOutTop);
  bit(hn::Lt(z, nw), kOutNear), bit(hn::Gt(z, w), kOutFar);
  const VF gx = hn::Mul(hn::Set(d, g.x), w), gy = hn::Mul(hn::Set(d, g.y), w);
  bit(hn::Lt(x, hn::Neg(gx)), kOutGuardLeft), bit(hn::Gt(x, gx), kOutGuardRight);
  bit(hn::Lt(y, hn::Neg(gy)), kOutGuardBottom), bit(hn::Gt(y, gy), kOutGuardTop);
  // Non-finite: x - x is NaN for NaN and for infinities.
  const VF inf_test = hn::Add(hn::Add(hn::Sub(x, x), hn::Sub(y, y)), hn::Add(hn::Sub(z, z), hn::Sub(w, w)));
  const MF finite = hn::Eq(inf_test, inf_test);
  return hn::IfThenElse(hn::RebindMask(du, finite), c, hn::Set(du, kOutNonFinite));
}

// Perspective divide, viewport transform and snap; stores projected vertices and codes
// for `count` (<= N) lanes at out + i.
HWY_INLINE void project(VF x, VF y, VF z, VF w, const ViewportMap& vp, const VertexOutputs& out, size_t i, size_t count) {
  const DF d;
  const DI di;
  const DU du;
  VU code = outcodes(x, y, z, w, vp.guard);
  const VF one = hn::Set(d, 1.0f);
  const VF inv_w = hn::Div(one, w);
  const VF sx = hn::MulAdd(hn::MulAdd(x, inv_w, one), hn::Set(d, vp.scale_x), hn::Set(d, vp.offset_x));
  const VF sy = hn::NegMulAdd(hn::MulAdd(y, inv_w, one), hn::Set(d, vp.scale_y), hn::Set(d, vp.offset_y));
  const VF sz = hn::MulAdd(hn::Mul(z, inv_w), hn::Set(d, vp.scale_z), hn::Set(d, vp.offset_z));
  // Snappable: |x|, |y| <= 2^20 pixels (false for NaN).
  const VF limit = hn::Set(d, 1048576.0f);
  const MF ok = hn::And(hn::Le(hn::Abs(sx), limit), hn::Le(hn::Abs(sy), limit));
  const VF k = hn::Set(d, 256.0f);
  const VI fx = hn::IfThenElseZero(hn::RebindMask(di, ok), hn::NearestInt(hn::IfThenElseZero(ok, hn::Mul(sx, k))));
  const VI fy = hn::IfThenElseZero(hn::RebindMask(di, ok), hn::NearestInt(hn::IfThenElseZero(ok, hn::Mul(sy, k))));
  code = hn::Or(code, hn::IfThenZeroElse(hn::RebindMask(du, ok), hn::Set(du, kOutUnsnapped)));
  constexpr size_t N = kLanes;
  if (count == N) {
    hn::StoreInterleaved4(hn::BitCast(d, fx), hn::BitCast(d, fy), sz, inv_w, d, reinterpret_cast<float*>(out.projected + i));
    hn::StoreU(code, du, out.codes + i);
    return;
  }
  alignas(64) float proj[4 * N];
  alignas(64) uint32_t codes[N];
  hn::StoreInterleaved4(hn::BitCast(d, fx), hn::BitCast(d, fy), sz, inv_w, d, proj);
  hn::Store(code, du, codes);
  std::memcpy(out.projected + i, proj, count * sizeof(ProjectedVertex));
  std::memcpy(out.codes + i, codes, count * sizeof(uint32_t));
}

HWY_INLINE void store3(const V3& v, Vec3* out, size_t count) {
  const DF d;
  constexpr size_t N = kLanes;
  if (count == N) return hn::StoreInterleaved3(v.x, v.y, v.z, d, reinterpret_cast<float*>(out));
  alignas(64) float tmp[3 * N];
  hn::StoreInterleaved3(v.x, v.y, v.z, d, tmp);
  std::memcpy(out, tmp, count * sizeof(Vec3));
}

HWY_INLINE V3 load3(const Vec3* in, size_t count) {
  const DF d;
  constexpr size_t N = kLanes;
  V3 v;
  if (count == N) {
    hn::LoadInterleaved3(d, reinterpret_cast<const float*>(in), v.x, v.y, v.z);
    return v;
  }
  alignas(64) float tmp[3 * N] = {};
  std::memcpy(tmp, in, count * sizeof(Vec3));
  hn::LoadInterleaved3(d, tmp, v.x, v.y, v.z);
  return v;
}

void TransformMeshVertices(const MeshVertexJob& job) {
  const DF d;
  constexpr size_t N = kLanes;
  const Mat4& m = job.mvp;
  const bool eye_space = job.lights || job.out.normal || job.out.eye;
  for (size_t i = job.begin; i < job.end; i += N) {
    const size_t count = std::min(N, job.end - i);
    const V3 p = load3(job.positions + i, count);
    auto row = [&](int r) {
      return hn::MulAdd(hn::Set(d, m.m[r][0]), p.x,
                        hn::MulAdd(hn::Set(d, m.m[r][1]), p.y, hn::MulAdd(hn::Set(d, m.m[r][2]), p.z, hn::Set(d, m.m[r][3]))));
    };
    project(row(0), row(1), row(2), row(3), job.viewport, job.out, i, count);
    if (!eye_space) continue;
    const V3 e = transform_point(job.model_view, p);
    V3 n = transform_vector(job.normal_matrix, load3(job.normals + i, count));
    const VF il = rsqrt(dot(n, n));  // a zero normal stays zero
    n = {hn::Mul(n.x, il), hn::Mul(n.y, il), hn::Mul(n.z, il)};
    if (job.out.normal) store3(n, job.out.normal + i, count);
    if (job.out.eye) store3(e, job.out.eye + i, count);
    if (job.lights) {
      const lit::LightTermsN t = lit::light(*job.lights, n, e, job.specular, hn::FirstN(d, kLanes));
      if (job.base_color) {
        const Vec3 b = *job.base_color;
        const V3 c = lit::apply(t, {hn::Set(d, b.x), hn::Set(d, b.y), hn::Set(d, b.z)});
        store3({saturate(c.x), saturate(c.y), saturate(c.z)}, job.out.diffuse + i, count);
      } else {
        store3(t.diffuse, job.out.diffuse + i, count);
        if (job.out.specular) store3(t.specular, job.out.specular + i, count);
      }
    }
  }
}

void ProjectClipVertices(const ClipVertexJob& job) {
  const DF d;
  constexpr size_t N = kLanes;
  for (size_t i = job.begin; i < job.end; i += N) {
    const size_t count = std::min(N, job.end - i);
    VF x, y, z, w;
    if (count == N) {
      hn::LoadInterleaved4(d, reinterpret_cast<const float*>(job.positions + i), x, y, z, w);
    } else {
      alignas(64) float tmp[4 * N] = {};
      std::memcpy(tmp, job.positions + i, count * sizeof(Vec4));
      hn::LoadInterleaved4(d, tmp, x, y, z, w);
    }
    project(x, y, z, w, job.viewport, job.out, i, count);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::geometry
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::geometry {

HWY_EXPORT(TransformMeshVertices);
HWY_EXPORT(ProjectClipVertices);

void transform_mesh_vertices(const MeshVertexJob& job) { HWY_DYNAMIC_DISPATCH(TransformMeshVertices)(job); }
void project_clip_vertices(const ClipVertexJob& job) { HWY_DYNAMIC_DISPATCH(ProjectClipVertices)(job); }

}  // namespace velocity::geometry
#endif  // HWY_ONCE
