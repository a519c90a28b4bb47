// The triangle stage's first pass, compiled once per instruction set.
#include "triangle/cull.hpp"

#include <algorithm>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "triangle/cull.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "triangle/clip.hpp"
#include "raster/contract.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::triangle {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

// Is pixel centre (px, py) (24.8) inside the triangle wound positively (as set-up winds
// it), by the exact edge functions with the top-left rule? Coordinates are relative to
// the centre, so for small triangles every product fits int32.
HWY_INLINE MI centre_inside(const VI rx[3], const VI ry[3], const VI dx[3], const VI dy[3], const MI top_left[3]) {
  const DI di;
  MI in = hn::FirstN(di, kLanes);
  for (int i = 0; i < 3; ++i) {
    // E = -dy (px - Xi) + dx (py - Yi) = dy * rx_i - dx * ry_i, minus 1 off a top-left edge.
    VI e = hn::Sub(hn::Mul(dy[i], rx[i]), hn::Mul(dx[i], ry[i]));
    e = hn::IfThenElse(top_left[i], e, hn::Sub(e, hn::Set(di, 1)));
    in = hn::And(in, hn::Gt(e, hn::Set(di, -1)));
  }
  return in;
}

void CullTriangles(const CullJob& job, uint32_t* direct, uint32_t* info, size_t& direct_count, uint32_t* clip,
                   size_t& clip_count, CullCounts& counts) {
  const DF df;
  const DI di;
  const DU du;
  constexpr size_t N = kLanes;
  const int32_t* proj = reinterpret_cast<const int32_t*>(job.projected);
  const VU view_planes = hn::Set(du, geometry::kViewPlanes), must_clip = hn::Set(du, geometry::kMustClipPlanes);
  const VU nonfinite_bit = hn::Set(du, geometry::kOutNonFinite), unsnapped_bit = hn::Set(du, geometry::kOutUnsnapped);
  const VI zero = hn::Zero(di), half = hn::Set(di, raster::kSubpixelHalf), one_px = hn::Set(di, raster::kSubpixelOne);
  const VI box_x0 = hn::Set(di, job.x0), box_y0 = hn::Set(di, job.y0), box_x1 = hn::Set(di, job.x1), box_y1 = hn::Set(di, job.y1);
  direct_count = clip_count = 0;
  alignas(64) uint32_t idx_buf[3 * N];
  for (uint32_t t = job.begin; t < job.end; t += uint32_t(N)) {
    const size_t count = std::min<size_t>(N, job.end - t);
    const auto valid = hn::RebindMask(du, hn::FirstN(di, count));
    VU i0, i1, i2;
    if (count == N) {
      hn::LoadInterleaved3(du, reinterpret_cast<const uint32_t*>(job.triangles + t), i0, i1, i2);
    } else {
      std::memset(idx_buf, 0, sizeof(idx_buf));
      std::memcpy(idx_buf, job.triangles + t, count * sizeof(Triangle));
      hn::LoadInterleaved3(du, idx_buf, i0, i1, i2);
    }
    const VU idx[3] = {i0, i1, i2};
    VU code[3];
    VI X[3], Y[3];
    for (int k = 0; k < 3; ++k) {
      const VI vi = hn::BitCast(di, idx[k]);
      code[k] = hn::BitCast(du, hn::GatherIndex(di, reinterpret_cast<const int32_t*>(job.codes), vi));
      const VI at = hn::ShiftLeft<2>(vi);  // geometry::ProjectedVertex is four 32-bit words
      X[k] = hn::GatherIndex(di, proj, at);
      Y[k] = hn::GatherIndex(di, proj + 1, at);
    }
    const VU any = hn::Or(hn::Or(code[0], code[1]), code[2]);
    const VU all = hn::And(hn::And(code[0], code[1]), code[2]);
    auto set = [&](VU v, VU bits) { return hn::And(hn::Ne(hn::And(v, bits), hn::Zero(du)), valid); };
    const auto nonfinite = set(any, nonfinite_bit);
    const auto rejected = hn::AndNot(nonfinite, set(all, view_planes));
    const auto to_clip = hn::AndNot(hn::Or(nonfinite, rejected), set(any, must_clip));
    const auto unsnapped = hn::AndNot(hn::Or(hn::Or(nonfinite, rejected), to_clip), set(any, unsnapped_bit));
    auto open = hn::AndNot(hn::Or(hn::Or(nonfinite, rejected), hn::Or(to_clip, unsnapped)), valid);

    // Orientation, in float with an error bound: deltas below 2^25 convert with a
    // relative error of 2^-24 and each product adds as much, so a magnitude over 2^-20
    // of the terms' sum is a sure sign; the rest go to the exact scalar set-up.
    const VF dx1 = hn::ConvertTo(df, hn::Sub(X[1], X[0])), dy1 = hn::ConvertTo(df, hn::Sub(Y[1], Y[0]));
    const VF dx2 = hn::ConvertTo(df, hn::Sub(X[2], X[0])), dy2 = hn::ConvertTo(df, hn::Sub(Y[2], Y[0]));
    const VF t1 = hn::Mul(dx1, dy2), t2 = hn::Mul(dx2, dy1);
    const VF area = hn::Sub(t1, t2);
    const VF bound = hn::Mul(hn::Add(hn::Abs(t1), hn::Abs(t2)), hn::Set(df, 1.0f / 1048576.0f));
    const auto sure = hn::RebindMask(du, hn::Gt(hn::Abs(area), bound));
    const auto front = hn::And(sure, hn::RebindMask(du, hn::Lt(area, hn::Zero(df))));  // y down: negative is CCW
    const auto back = hn::AndNot(front, sure);
    auto culled = hn::And(open, hn::FirstN(du, 0));
    if (job.cull_back) culled = hn::And(open, back);

    VU learnt = hn::Or(hn::IfThenElseZero(front, hn::Set(du, kKnownFront)), hn::IfThenElseZero(back, hn::Set(du, kKnownBack)));
    if (job.drop_empty) {
      // The box of pixel centres inside the triangle's box, within the drawable box.
      const VI minx = hn::Min(hn::Min(X[0], X[1]), X[2]), maxx = hn::Max(hn::Max(X[0], X[1]), X[2]);
      const VI miny = hn::Min(hn::Min(Y[0], Y[1]), Y[2]), maxy = hn::Max(hn::Max(Y[0], Y[1]), Y[2]);
      const VI up = hn::Set(di, raster::kSubpixelOne - 1 - raster::kSubpixelHalf);
      const VI ux0 = hn::ShiftRight<8>(hn::Add(minx, up)), uy0 = hn::ShiftRight<8>(hn::Add(miny, up));
      const VI ux1 = hn::ShiftRight<8>(hn::Sub(maxx, half)), uy1 = hn::ShiftRight<8>(hn::Sub(maxy, half));
      const VI bx0 = hn::Max(ux0, box_x0), by0 = hn::Max(uy0, box_y0);
      const VI bx1 = hn::Min(ux1, box_x1), by1 = hn::Min(uy1, box_y1);
      const auto empty = hn::RebindMask(du, hn::Or(hn::Gt(bx0, bx1), hn::Gt(by0, by1)));
      culled = hn::Or(culled, hn::And(open, empty));
      // Small (centres within 4x4) and surely oriented: find the centres it covers
      // here, exactly, in the winding set-up gives it (front faces have their last two
      // vertices swapped). Within 5 pixels of each other, every product fits int32.
      // (Small by the triangle's own box: one that the drawable box cuts small may still
      // reach far, and then its products would not fit int32.)
      const VI four = hn::Set(di, 4);
      const auto small = hn::AndNot(empty, hn::And(sure, hn::RebindMask(du, hn::And(hn::Lt(hn::Sub(ux1, ux0), four),
                                                                                     hn::Lt(hn::Sub(uy1, uy0), four)))));
      const auto candidates = hn::AndNot(culled, hn::And(open, small));
      if (!hn::AllFalse(du, candidates)) {
        const MI swap = hn::RebindMask(di, front);
        const VI x[3] = {X[0], hn::IfThenElse(swap, X[2], X[1]), hn::IfThenElse(swap, X[1], X[2])};
        const VI y[3] = {Y[0], hn::IfThenElse(swap, Y[2], Y[1]), hn::IfThenElse(swap, Y[1], Y[2])};
        VI dx[3], dy[3];
        MI top_left[3];
        for (int i = 0; i < 3; ++i) {
          const int j = (i + 1) % 3;
          dx[i] = hn::Sub(x[j], x[i]), dy[i] = hn::Sub(y[j], y[i]);
          top_left[i] = hn::Or(hn::Lt(dy[i], zero), hn::And(hn::Eq(dy[i], zero), hn::Gt(dx[i], zero)));
        }
        // The first centre, relative to each vertex; then one pixel step at a time.
        const VI px0 = hn::Add(hn::Mul(bx0, one_px), half), py0 = hn::Add(hn::Mul(by0, one_px), half);
        VU mask = hn::Zero(du);
        // Only as many rows and columns as the widest candidate needs (most are 1 or 2).
        const MI cand = hn::RebindMask(di, candidates);
        const int w = int(hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElseZero(cand, hn::Sub(bx1, bx0))))) + 1;
        const int h = int(hn::GetLane(hn::MaxOfLanes(di, hn::IfThenElseZero(cand, hn::Sub(by1, by0))))) + 1;
        for (int oy = 0; oy < h; ++oy)
          for (int ox = 0; ox < w; ++ox) {
            const VI cx = hn::Add(bx0, hn::Set(di, ox)), cy = hn::Add(by0, hn::Set(di, oy));
            const MI in_box = hn::And(hn::Not(hn::Gt(cx, bx1)), hn::Not(hn::Gt(cy, by1)));
            const VI px = hn::Add(px0, hn::Set(di, ox * raster::kSubpixelOne));
            const VI py = hn::Add(py0, hn::Set(di, oy * raster::kSubpixelOne));
            const VI rx[3] = {hn::Sub(x[0], px), hn::Sub(x[1], px), hn::Sub(x[2], px)};
            const VI ry[3] = {hn::Sub(y[0], py), hn::Sub(y[1], py), hn::Sub(y[2], py)};
            const MI in = hn::And(in_box, centre_inside(rx, ry, dx, dy, top_left));
            mask = hn::Or(mask, hn::IfThenElseZero(hn::RebindMask(du, in), hn::Set(du, 1u << (oy * 4 + ox))));
          }
        const auto none = hn::Eq(mask, hn::Zero(du));
        culled = hn::Or(culled, hn::And(none, candidates));
        learnt = hn::Or(learnt, hn::IfThenElseZero(candidates, hn::Or(mask, hn::Set(du, kKnownSmall))));
      }
    }
    open = hn::AndNot(culled, open);

    counts.nonfinite += hn::CountTrue(du, nonfinite);
    counts.rejected += hn::CountTrue(du, rejected);
    counts.culled += hn::CountTrue(du, hn::Or(culled, unsnapped));
    // Survivors are a minority (a fifth at a million triangles): walk their bits.
    alignas(64) uint32_t learnt_lanes[N];
    hn::Store(learnt, du, learnt_lanes);
    for (uint32_t bits = lane_bits(du, open); bits; bits &= bits - 1) {
      const int lane = __builtin_ctz(bits);
      info[direct_count] = learnt_lanes[lane];
      direct[direct_count++] = t + uint32_t(lane);
    }
    for (uint32_t bits = lane_bits(du, to_clip); bits; bits &= bits - 1)
      clip[clip_count++] = t + uint32_t(__builtin_ctz(bits));
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::triangle
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::triangle {

HWY_EXPORT(CullTriangles);

void cull_triangles(const CullJob& job, uint32_t* direct, uint32_t* info, size_t& direct_count, uint32_t* clip,
                    size_t& clip_count, CullCounts& counts) {
  HWY_DYNAMIC_DISPATCH(CullTriangles)(job, direct, info, direct_count, clip, clip_count, counts);
}

}  // namespace velocity::triangle
#endif  // HWY_ONCE
