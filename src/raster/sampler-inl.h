// Texture sampling, a vector of pixels at a time: nearest, bilinear and trilinear, with
// repeat, clamp-to-edge, clamp-to-border and mirrored-repeat addressing.
//
// Addressing follows OpenGL: texel i covers [i, i+1) / size in u, so the sample point
// u * size - 0.5 sits between the four nearest texel centres (bilinear); nearest takes
// floor(u * size). Texel addresses and bilinear weights are computed for the whole
// vector, the texels fetched with gathers — or, where a magnified texture puts every
// lane within a texel or two of the first, picked from a 4x4 window of texels loaded
// once (window_texels). No division: coordinates are wrapped in float (u - floor(u))
// first, after which an index is at most one size out of range.
// Any input is safe: NaN and infinite coordinates read texel 0 or the edge, never
// outside the texture.
//
// The level of detail is chosen once per 4x4 block (scalar, level_of_detail below),
// never per pixel: lambda = log2(rho), rho the larger screen-space footprint of a pixel
// in texels at the block's centre.
#if defined(VELOCITY_RASTER_SAMPLER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_SAMPLER_INL_H_
#undef VELOCITY_RASTER_SAMPLER_INL_H_
#else
#define VELOCITY_RASTER_SAMPLER_INL_H_
#endif

#include <algorithm>
#include <cmath>
#include <cstring>

#include "raster/rasterize.hpp"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

struct Rgba {
  VF r, g, b, a;  // [0, 1] (inside the sampler: [0, texel_unit] until the end)
};

// Texels to [0, 255] floats; without kAlpha the alpha channel is left out (opaque).
template <bool kAlpha = true>
HWY_INLINE Rgba unpack255(VU t) {
  return {channel<0>(t), channel<1>(t), channel<2>(t), kAlpha ? channel<3>(t) : hn::Set(DF(), 255.0f)};
}

HWY_INLINE Rgba scale(const Rgba& c, float k) {
  const VF v = hn::Set(DF(), k);
  return {hn::Mul(c.r, v), hn::Mul(c.g, v), hn::Mul(c.b, v), hn::Mul(c.a, v)};
}

// RGBA8 to [0, 1].
HWY_INLINE Rgba unpack(VU t) { return scale(unpack255(t), 1.0f / 255.0f); }

HWY_INLINE Rgba lerp(const Rgba& a, const Rgba& b, VF t) {
  return {hn::MulAdd(hn::Sub(b.r, a.r), t, a.r), hn::MulAdd(hn::Sub(b.g, a.g), t, a.g),
          hn::MulAdd(hn::Sub(b.b, a.b), t, a.b), hn::MulAdd(hn::Sub(b.a, a.a), t, a.a)};
}

// A coordinate made safe for the wrap mode: repeat in [0, 1], mirrored repeat in
// [0, 2], the clamps in [-1, 2] (GL_CLAMP's in [0, 1]); NaN becomes 0 (repeats) or -1
// (clamps; 0 for GL_CLAMP).
HWY_INLINE VF prepare_coord(VF u, Wrap w) {
  const DF d;
  switch (w) {
    case Wrap::ClampHalfBorder: {
      const VF c = hn::IfThenElse(hn::Gt(u, hn::Zero(d)), u, hn::Zero(d));
      return hn::Min(c, hn::Set(d, 1.0f));
    }
    case Wrap::Repeat: {
      VF f = hn::Sub(u, hn::Floor(u));
      return hn::IfThenElseZero(hn::Ge(f, hn::Zero(d)), f);  // NaN (from NaN or infinity) -> 0
    }
    case Wrap::MirroredRepeat: {
      VF f = hn::Sub(u, hn::Mul(hn::Set(d, 2.0f), hn::Floor(hn::Mul(u, hn::Set(d, 0.5f)))));
      return hn::IfThenElseZero(hn::Ge(f, hn::Zero(d)), f);
    }
    default: {
      VF c = hn::IfThenElse(hn::Gt(u, hn::Set(d, -1.0f)), u, hn::Set(d, -1.0f));
      return hn::Min(c, hn::Set(d, 2.0f));
    }
  }
}

// A texel index from prepare_coord's range into [0, n); `outside` marks indices that
// clamp-to-border replaces by the border colour — unless the level has a border
// (`bordered`), whose texels -1 and n clamp-to-border reads instead.
HWY_INLINE VI wrap_index(VI i, int32_t n, Wrap w, MI& outside, bool bordered) {
  const DI di;
  const VI vn = hn::Set(di, n), zero = hn::Zero(di), last = hn::Set(di, n - 1);
  switch (w) {
    case Wrap::Repeat:  // i in [-1, n]
      i = hn::IfThenElse(hn::Lt(i, zero), hn::Add(i, vn), i);
      return hn::IfThenElse(hn::Lt(i, vn), i, hn::Sub(i, vn));
    case Wrap::MirroredRepeat: {  // i in [-1, 2n]
      const VI n2 = hn::Set(di, 2 * n);
      i = hn::IfThenElse(hn::Lt(i, zero), hn::Add(i, n2), i);
      i = hn::IfThenElse(hn::Lt(i, n2), i, hn::Sub(i, n2));
      return hn::IfThenElse(hn::Lt(i, vn), i, hn::Sub(hn::Sub(n2, hn::Set(di, 1)), i));
    }
    case Wrap::ClampToBorder:
    case Wrap::ClampHalfBorder:
      if (bordered) return hn::Min(hn::Max(i, hn::Set(di, -1)), vn);
      outside = hn::Or(outside, hn::Or(hn::Lt(i, zero), hn::Gt(i, last)));
      return hn::Min(hn::Max(i, zero), last);
    default: return hn::Min(hn::Max(i, zero), last);
  }
}

// The unit the sampler works in until its last step: 255 for RGBA8 texels, 65535 for
// an sRGB view's linear RGBA16 ones.
HWY_INLINE float texel_unit(const SamplerView& s) { return s.srgb ? 65535.0f : 255.0f; }

// Texels outside the image read the border colour ([0, 1], in the sampler's unit).
HWY_INLINE Rgba with_border(const Rgba& c, MI outside, const float* border, float unit) {
  const DF d;
  const MF m = hn::RebindMask(d, outside);
  return {hn::IfThenElse(m, hn::Set(d, unit * border[0]), c.r), hn::IfThenElse(m, hn::Set(d, unit * border[1]), c.g),
          hn::IfThenElse(m, hn::Set(d, unit * border[2]), c.b), hn::IfThenElse(m, hn::Set(d, unit * border[3]), c.a)};
}

// RGBA16 texels' red-green and blue-alpha halves (16 bits each) to [0, 65535] floats.
template <bool kAlpha>
HWY_INLINE Rgba linear_channels(VU rg, VU ba) {
  const DF d;
  const DI di;
  const VU low16 = hn::Set(DU(), 0xffffu);
  auto to_float = [&](VU v) { return hn::ConvertTo(d, hn::BitCast(di, v)); };
  return {to_float(hn::And(rg, low16)), to_float(hn::ShiftRight<16>(rg)), to_float(hn::And(ba, low16)),
          kAlpha ? to_float(hn::ShiftRight<16>(ba)) : hn::Set(d, 65535.0f)};
}

// RGBA16 texels (an sRGB view's linear ones, Texture::linear_levels) to [0, 65535]
// floats: gathered 8 bytes a lane, half a vector at a time, then split into the
// red-green and blue-alpha halves of every lane.
template <bool kAlpha>
HWY_INLINE Rgba unpack_linear(const uint64_t* texels, VI index) {
  const DU du;
#if HWY_TARGET == HWY_SCALAR
  const uint64_t t = texels[hn::GetLane(index)];
  const VU rg = hn::Set(du, uint32_t(t)), ba = hn::Set(du, uint32_t(t >> 32));
#else
  const hn::Half<DI> dh;
  const hn::Repartition<uint64_t, DF> d64;
  const hn::RebindToSigned<decltype(d64)> di64;
  const VU lo = hn::BitCast(du, hn::GatherIndex(d64, texels, hn::PromoteTo(di64, hn::LowerHalf(dh, index))));
  const VU hi = hn::BitCast(du, hn::GatherIndex(d64, texels, hn::PromoteTo(di64, hn::UpperHalf(dh, index))));
  const VU rg = hn::ConcatEven(du, hi, lo), ba = hn::ConcatOdd(du, hi, lo);
#endif
  return linear_channels<kAlpha>(rg, ba);
}

// The texels at `index` (y * stride + x) in the sampler's unit (texel_unit).
template <bool kAlpha>
HWY_INLINE Rgba fetch_at(const SamplerView& s, const SamplerLevel& l, VI index) {
  if (s.srgb) return unpack_linear<kAlpha>(l.linear, index);
  return unpack255<kAlpha>(hn::BitCast(DU(), hn::GatherIndex(DI(), reinterpret_cast<const int32_t*>(l.texels), index)));
}

// One texel, at `index`, for every lane.
template <bool kAlpha>
HWY_INLINE Rgba fetch_one(const SamplerView& s, const SamplerLevel& l, int32_t index) {
  const DU du;
  if (s.srgb) {
    const uint64_t t = l.linear[index];
    return linear_channels<kAlpha>(hn::Set(du, uint32_t(t)), hn::Set(du, uint32_t(t >> 32)));
  }
  return unpack255<kAlpha>(hn::Set(du, l.texels[index]));
}

HWY_INLINE VI texel_index(const SamplerLevel& l, VI x, VI y) { return hn::Add(hn::Mul(y, hn::Set(DI(), l.stride)), x); }

// The texels at (x, y) in the sampler's unit (texel_unit).
template <bool kAlpha>
HWY_INLINE Rgba fetch(const SamplerView& s, const SamplerLevel& l, VI x, VI y) {
  return fetch_at<kAlpha>(s, l, texel_index(l, x, y));
}

// Whether a wrap mode reads the border colour (the bilinear filter's view of GL_CLAMP).
HWY_INLINE bool reads_border(Wrap w) { return w == Wrap::ClampToBorder || w == Wrap::ClampHalfBorder; }

// The bilinear filter's four texels when a vector's lanes lie close together, as they
// do magnified: if every lane's texels fall in the 4x4 window of texels whose second
// row and column hold lane 0's first texel (x0, y0: floor(x - 1/2), floor(y - 1/2)
// before wrapping), and the window lies inside the level (so that no lane wraps,
// clamps or reads a border), its four rows are loaded and each lane's texels picked
// from them by lane permutes instead of gathered. Vectors of 16 lanes hold the window
// in one table (two for an sRGB view's red-green and blue-alpha halves), 8 lanes in
// two. False when the lanes are farther apart: the caller gathers.
template <bool kAlpha>
HWY_INLINE bool window_texels(const SamplerView& s, const SamplerLevel& l, VI x0, VI y0, Rgba& t00, Rgba& t10,
                              Rgba& t01, Rgba& t11) {
#if HWY_TARGET == HWY_SCALAR
  (void)s, (void)l, (void)x0, (void)y0, (void)t00, (void)t10, (void)t01, (void)t11;
  return false;
#else
  if constexpr (kLanes != 8 && kLanes != 16) {
    return false;
  } else {
    const DI di;
    const DU du;
    const int32_t ax = hn::GetLane(x0) - 1, ay = hn::GetLane(y0) - 1;
    if (ax < 0 || ay < 0 || ax > l.width - 4 || ay > l.height - 4) return false;
    const VI dx = hn::Sub(x0, hn::Set(di, ax)), dy = hn::Sub(y0, hn::Set(di, ay));
    const MI near = hn::And(hn::Gt(hn::Min(dx, dy), hn::Set(di, -1)), hn::Lt(hn::Max(dx, dy), hn::Set(di, 3)));
    if (!hn::AllTrue(di, near)) return false;
    const VI at = hn::Add(hn::ShiftLeft<2>(dy), dx);  // (x0, y0) in the window, row by row
    const size_t stride = size_t(l.stride), first = size_t(ay) * stride + size_t(ax);
    // A table of the window's sixteen 32-bit values (8 lanes: rows 0-1 in lo, 2-3 in
    // hi), looked up at window index i.
    struct Table {
      VU lo, hi;
      HWY_INLINE VU operator()(VI i) const {
        const DU du;
        if constexpr (kLanes == 16) {
          return hn::TableLookupLanes(lo, hn::IndicesFromVec(du, hn::BitCast(du, i)));
        } else {
          const DI di;
          const auto k = hn::IndicesFromVec(du, hn::BitCast(du, hn::And(i, hn::Set(di, 7))));
          const auto upper = hn::RebindMask(du, hn::Gt(i, hn::Set(di, 7)));
          return hn::IfThenElse(upper, hn::TableLookupLanes(hi, k), hn::TableLookupLanes(lo, k));
        }
      }
    };
    // The four texels of every lane: (x0, y0), (x0 + 1, y0), (x0, y0 + 1), (x0 + 1, y0 + 1).
    auto taps = [&](auto texel) {
      t00 = texel(at), t10 = texel(hn::Add(at, hn::Set(di, 1)));
      t01 = texel(hn::Add(at, hn::Set(di, 4))), t11 = texel(hn::Add(at, hn::Set(di, 5)));
    };
    if (s.srgb) {
      // Each row is four RGBA16 texels: eight 32-bit halves, red-green then blue-alpha.
      const uint32_t* p = reinterpret_cast<const uint32_t*>(l.linear + first);
      Table rg, ba;
      if constexpr (kLanes == 16) {
        const hn::Half<DU> dh;
        const VU rows01 = hn::Combine(du, hn::LoadU(dh, p + 2 * stride), hn::LoadU(dh, p));
        const VU rows23 = hn::Combine(du, hn::LoadU(dh, p + 6 * stride), hn::LoadU(dh, p + 4 * stride));
        rg.lo = hn::ConcatEven(du, rows23, rows01), ba.lo = hn::ConcatOdd(du, rows23, rows01);
      } else {
        const VU r0 = hn::LoadU(du, p), r1 = hn::LoadU(du, p + 2 * stride);
        const VU r2 = hn::LoadU(du, p + 4 * stride), r3 = hn::LoadU(du, p + 6 * stride);
        rg.lo = hn::ConcatEven(du, r1, r0), rg.hi = hn::ConcatEven(du, r3, r2);
        ba.lo = hn::ConcatOdd(du, r1, r0), ba.hi = hn::ConcatOdd(du, r3, r2);
      }
      taps([&](VI i) { return linear_channels<kAlpha>(rg(i), ba(i)); });
    } else {
      const uint32_t* p = l.texels + first;
      Table rgba;
      const hn::Half<DU> dh;
      if constexpr (kLanes == 16) {
        const hn::Half<decltype(dh)> dq;
        rgba.lo = hn::Combine(du, hn::Combine(dh, hn::LoadU(dq, p + 3 * stride), hn::LoadU(dq, p + 2 * stride)),
                              hn::Combine(dh, hn::LoadU(dq, p + stride), hn::LoadU(dq, p)));
      } else {
        rgba.lo = hn::Combine(du, hn::LoadU(dh, p + stride), hn::LoadU(dh, p));
        rgba.hi = hn::Combine(du, hn::LoadU(dh, p + 3 * stride), hn::LoadU(dh, p + 2 * stride));
      }
      taps([&](VI i) { return unpack255<kAlpha>(rgba(i)); });
    }
    return true;
  }
#endif
}

template <bool kAlpha>
HWY_INLINE Rgba nearest(const SamplerView& s, const SamplerLevel& l, VF u, VF v) {
  const DF d;
  const DI di;
  // GL_CLAMP's nearest texel is the edge one: the border is never nearest (s = 1 too).
  const Wrap ws = s.wrap_s == Wrap::ClampHalfBorder ? Wrap::Clamp : s.wrap_s;
  const Wrap wt = s.wrap_t == Wrap::ClampHalfBorder ? Wrap::Clamp : s.wrap_t;
  const VF x = hn::Mul(prepare_coord(u, ws), hn::Set(d, float(l.width)));
  const VF y = hn::Mul(prepare_coord(v, wt), hn::Set(d, float(l.height)));
  MI outside = hn::FirstN(di, 0);
  const VI ix = wrap_index(truncate_in_range(hn::Floor(x)), l.width, ws, outside, l.bordered);
  const VI iy = wrap_index(truncate_in_range(hn::Floor(y)), l.height, wt, outside, l.bordered);
  Rgba c = fetch<kAlpha>(s, l, ix, iy);
  if (ws == Wrap::ClampToBorder || wt == Wrap::ClampToBorder) c = with_border(c, outside, s.border, texel_unit(s));
  return c;
}

// The four nearest texels weighted by the sample point's position between their centres.
template <bool kAlpha>
HWY_INLINE Rgba bilinear(const SamplerView& s, const SamplerLevel& l, VF u, VF v) {
  const DF d;
  const DI di;
  const VF x = hn::MulSub(prepare_coord(u, s.wrap_s), hn::Set(d, float(l.width)), hn::Set(d, 0.5f));
  const VF y = hn::MulSub(prepare_coord(v, s.wrap_t), hn::Set(d, float(l.height)), hn::Set(d, 0.5f));
  const VF fx = hn::Floor(x), fy = hn::Floor(y);
  const VF a = hn::Sub(x, fx), b = hn::Sub(y, fy);
  const VI x0i = truncate_in_range(fx), y0i = truncate_in_range(fy);
  Rgba t00, t10, t01, t11;
  if (window_texels<kAlpha>(s, l, x0i, y0i, t00, t10, t01, t11)) return lerp(lerp(t00, t10, a), lerp(t01, t11, a), b);
  const VI one = hn::Set(di, 1);
  MI out0 = hn::FirstN(di, 0), out1 = out0, outy0 = out0, outy1 = out0;
  const bool rb = l.bordered;
  const VI x0 = wrap_index(x0i, l.width, s.wrap_s, out0, rb), x1 = wrap_index(hn::Add(x0i, one), l.width, s.wrap_s, out1, rb);
  const VI y0 = wrap_index(y0i, l.height, s.wrap_t, outy0, rb), y1 = wrap_index(hn::Add(y0i, one), l.height, s.wrap_t, outy1, rb);
  const VI i00 = texel_index(l, x0, y0), i11 = texel_index(l, x1, y1);
  // Narrower vectors (no window above): magnified, every lane often lies between the
  // same four texel centres (an index names one texel: x and y are within a row's
  // stride); then the four are read once and broadcast instead of gathered.
  const int32_t a00 = hn::GetLane(i00), a11 = hn::GetLane(i11);
  if (kLanes < 8 && hn::AllTrue(di, hn::And(hn::Eq(i00, hn::Set(di, a00)), hn::Eq(i11, hn::Set(di, a11))))) {
    const int32_t y0s = hn::GetLane(y0), y1s = hn::GetLane(y1);
    t00 = fetch_one<kAlpha>(s, l, a00), t11 = fetch_one<kAlpha>(s, l, a11);
    t10 = fetch_one<kAlpha>(s, l, a11 - (y1s - y0s) * l.stride);  // (x1, y0)
    t01 = fetch_one<kAlpha>(s, l, a00 + (y1s - y0s) * l.stride);  // (x0, y1)
  } else {
    t00 = fetch_at<kAlpha>(s, l, i00), t10 = fetch<kAlpha>(s, l, x1, y0);
    t01 = fetch<kAlpha>(s, l, x0, y1), t11 = fetch_at<kAlpha>(s, l, i11);
  }
  if (reads_border(s.wrap_s) || reads_border(s.wrap_t)) {
    const float k = texel_unit(s);
    t00 = with_border(t00, hn::Or(out0, outy0), s.border, k), t10 = with_border(t10, hn::Or(out1, outy0), s.border, k);
    t01 = with_border(t01, hn::Or(out0, outy1), s.border, k), t11 = with_border(t11, hn::Or(out1, outy1), s.border, k);
  }
  return lerp(lerp(t00, t10, a), lerp(t01, t11, a), b);
}

template <bool kAlpha>
HWY_INLINE Rgba texel_filter(const SamplerView& s, const SamplerLevel& l, VF u, VF v, SamplerState::Texel f) {
  return f == SamplerState::Texel::Nearest ? nearest<kAlpha>(s, l, u, v) : bilinear<kAlpha>(s, l, u, v);
}

// --- 3-D textures (SamplerView::volume): the same addressing on a third axis, r, over
// a level's slices. GL_LINEAR within a level blends the eight nearest texels.

// The texels at (x, y, z): slice z's row y.
template <bool kAlpha>
HWY_INLINE Rgba fetch3(const SamplerView& s, const SamplerLevel& l, VI x, VI y, VI z) {
  const DI di;
  return fetch<kAlpha>(s, l, x, hn::Add(hn::Mul(z, hn::Set(di, l.rows)), y));
}

template <bool kAlpha>
HWY_INLINE Rgba nearest3(const SamplerView& s, const SamplerLevel& l, VF u, VF v, VF w) {
  const DF d;
  const DI di;
  MI outside = hn::FirstN(di, 0);
  auto index = [&](VF c, Wrap wrap, int32_t n) {
    if (wrap == Wrap::ClampHalfBorder) wrap = Wrap::Clamp;  // (GL_CLAMP's nearest texel: the edge one)
    const VF x = hn::Mul(prepare_coord(c, wrap), hn::Set(d, float(n)));
    return wrap_index(truncate_in_range(hn::Floor(x)), n, wrap, outside, l.bordered);
  };
  const VI ix = index(u, s.wrap_s, l.width), iy = index(v, s.wrap_t, l.height), iz = index(w, s.wrap_r, l.depth);
  Rgba c = fetch3<kAlpha>(s, l, ix, iy, iz);
  if (s.wrap_s == Wrap::ClampToBorder || s.wrap_t == Wrap::ClampToBorder || s.wrap_r == Wrap::ClampToBorder)
    c = with_border(c, outside, s.border, texel_unit(s));
  return c;
}

template <bool kAlpha>
HWY_INLINE Rgba linear3(const SamplerView& s, const SamplerLevel& l, VF u, VF v, VF w) {
  const DF d;
  const DI di;
  struct Axis {
    VI i0, i1;
    MI out0, out1;
    VF frac;
  };
  auto axis = [&](VF c, Wrap wrap, int32_t n) {
    const VF x = hn::MulSub(prepare_coord(c, wrap), hn::Set(d, float(n)), hn::Set(d, 0.5f));
    const VF fx = hn::Floor(x);
    const VI i = truncate_in_range(fx);
    Axis a{i, i, hn::FirstN(di, 0), hn::FirstN(di, 0), hn::Sub(x, fx)};
    a.i0 = wrap_index(i, n, wrap, a.out0, l.bordered), a.i1 = wrap_index(hn::Add(i, hn::Set(di, 1)), n, wrap, a.out1, l.bordered);
    return a;
  };
  const Axis ax = axis(u, s.wrap_s, l.width), ay = axis(v, s.wrap_t, l.height), az = axis(w, s.wrap_r, l.depth);
  const bool border = reads_border(s.wrap_s) || reads_border(s.wrap_t) || reads_border(s.wrap_r);
  const float k = texel_unit(s);
  auto tap = [&](bool x1, bool y1, bool z1) {
    Rgba t = fetch3<kAlpha>(s, l, x1 ? ax.i1 : ax.i0, y1 ? ay.i1 : ay.i0, z1 ? az.i1 : az.i0);
    if (border) t = with_border(t, hn::Or(x1 ? ax.out1 : ax.out0, hn::Or(y1 ? ay.out1 : ay.out0, z1 ? az.out1 : az.out0)), s.border, k);
    return t;
  };
  auto slice = [&](bool z1) {
    return lerp(lerp(tap(false, false, z1), tap(true, false, z1), ax.frac), lerp(tap(false, true, z1), tap(true, true, z1), ax.frac),
                ay.frac);
  };
  return lerp(slice(false), slice(true), az.frac);
}

template <bool kAlpha>
HWY_INLINE Rgba texel_filter3(const SamplerView& s, const SamplerLevel& l, VF u, VF v, VF w, SamplerState::Texel f) {
  return f == SamplerState::Texel::Nearest ? nearest3<kAlpha>(s, l, u, v, w) : linear3<kAlpha>(s, l, u, v, w);
}

// How a block samples: the filter and the level(s), chosen once per block.
struct LevelChoice {
  SamplerState::Texel filter;
  int level0, level1;  // level1 == level0: one level
  float frac;          // weight of level1
};

// Whether choose_levels gives one answer whatever the lod: one level (no mip-maps, or
// only one), and the same filter magnifying and minifying. Then the kernels take
// {s.mag, 0, 0, 0} once, not a level of detail per block or small triangle.
HWY_INLINE bool single_level(const SamplerView& s) {
  return (s.mip == SamplerState::Mip::None || s.level_count <= 1) && s.min == s.mag;
}

HWY_INLINE LevelChoice choose_levels(const SamplerView& s, float lod) {
  // The bias, then the clamp (as GL orders them; a NaN bound leaves it unbounded).
  lod = std::min(std::max(lod + s.lod_bias, s.min_lod), s.max_lod);
  const int last = s.level_count - 1;
  if (!(lod > 0) || s.mip == SamplerState::Mip::None || last == 0)
    return {!(lod > 0) ? s.mag : s.min, 0, 0, 0};
  if (s.mip == SamplerState::Mip::Nearest) {
    // OpenGL: level ceil(lambda + 1/2) - 1 for lambda > 1/2, else 0.
    int l = lod <= 0.5f ? 0 : std::min(int(std::ceil(lod + 0.5f)) - 1, last);
    return {s.min, l, l, 0};
  }
  if (lod >= float(last)) return {s.min, last, last, 0};
  const int l0 = int(lod);
  return {s.min, l0, l0 + 1, lod - float(l0)};
}

// RGBA in [0, 1]; without kAlpha, alpha is 1 (for kernels that do not read it).
// `frac`: the weight of level1 per lane (the fragments of several small triangles
// share levels, not weights).
template <bool kAlpha = true>
HWY_INLINE Rgba sample(const SamplerView& s, const LevelChoice& c, VF u, VF v, VF frac) {
  Rgba a = texel_filter<kAlpha>(s, s.levels[c.level0], u, v, c.filter);
  if (c.level1 != c.level0) a = lerp(a, texel_filter<kAlpha>(s, s.levels[c.level1], u, v, c.filter), frac);
  return scale(a, 1.0f / texel_unit(s));
}
template <bool kAlpha = true>
HWY_INLINE Rgba sample(const SamplerView& s, const LevelChoice& c, VF u, VF v) {
  return sample<kAlpha>(s, c, u, v, hn::Set(DF(), c.frac));
}

// A 3-D texture's sample at (u, v, w); mip-mapped, the two levels' samples blended as
// sample's are (GL_LINEAR_MIPMAP_LINEAR: "trilinear" between two trilinear samples).
template <bool kAlpha = true>
HWY_INLINE Rgba sample3(const SamplerView& s, const LevelChoice& c, VF u, VF v, VF w) {
  Rgba a = texel_filter3<kAlpha>(s, s.levels[c.level0], u, v, w, c.filter);
  if (c.level1 != c.level0) a = lerp(a, texel_filter3<kAlpha>(s, s.levels[c.level1], u, v, w, c.filter), hn::Set(DF(), c.frac));
  return scale(a, 1.0f / texel_unit(s));
}

// log2(x) for a positive normal float, to about 0.002 (enough to choose and blend mip
// levels): the exponent, plus a cubic in the mantissa.
inline float fast_log2(float x) {
  uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const float e = float(int((bits >> 23) & 0xff) - 127);
  bits = (bits & 0x007fffffu) | 0x3f800000u;
  float m;
  std::memcpy(&m, &bits, sizeof m);  // [1, 2)
  return e + (((0.153914771f * m - 1.02950006f) * m + 3.01074372f) * m - 2.13515843f);
}

// The level of detail from the screen-space derivatives of (u, v), scalar, per block.
inline float level_of_detail(const SamplerView& s, float dudx, float dvdx, float dudy, float dvdy) {
  const float w = float(s.levels[0].width), h = float(s.levels[0].height);
  const float rx = (dudx * w) * (dudx * w) + (dvdx * h) * (dvdx * h);
  const float ry = (dudy * w) * (dudy * w) + (dvdy * h) * (dvdy * h);
  const float rho2 = std::max(rx, ry);
  return rho2 > 1e-30f && rho2 < 1e30f ? 0.5f * fast_log2(rho2) : (rho2 > 0 ? (rho2 < 1 ? -100.0f : 50.0f) : -100.0f);
}

// fast_log2 and level_of_detail for N blocks at a time (a lane per block), with the
// same arithmetic: a kernel finds the levels of all its blocks before it shades any
// (uv_derivatives and BlockLods, shade_mesh-inl.h), so that no block's texture reads
// wait on a scalar divide and logarithm of its own.
HWY_INLINE VF fast_log2(VF x) {
  const DF d;
  const DI di;
  const VI bits = hn::BitCast(di, x);
  const VF e = hn::ConvertTo(d, hn::Sub(hn::And(hn::ShiftRight<23>(bits), hn::Set(di, 0xff)), hn::Set(di, 127)));
  const VF m = hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(di, 0x007fffff)), hn::Set(di, 0x3f800000)));  // [1, 2)
  const VF cubic = hn::MulAdd(hn::MulAdd(hn::MulAdd(hn::Set(d, 0.153914771f), m, hn::Set(d, -1.02950006f)), m, hn::Set(d, 3.01074372f)),
                              m, hn::Set(d, -2.13515843f));
  return hn::Add(e, cubic);
}
HWY_INLINE VF level_of_detail(const SamplerView& s, VF dudx, VF dvdx, VF dudy, VF dvdy) {
  const DF d;
  const VF w = hn::Set(d, float(s.levels[0].width)), h = hn::Set(d, float(s.levels[0].height));
  auto rho2_of = [&](VF du, VF dv) {
    const VF a = hn::Mul(du, w), b = hn::Mul(dv, h);
    return hn::MulAdd(b, b, hn::Mul(a, a));
  };
  const VF rho2 = hn::Max(rho2_of(dudx, dvdx), rho2_of(dudy, dvdy));
  const MF normal = hn::And(hn::Gt(rho2, hn::Set(d, 1e-30f)), hn::Lt(rho2, hn::Set(d, 1e30f)));
  // Out of that range, as the scalar form: huge (or infinite) 50, else (tiny, zero, NaN) -100.
  const VF edge = hn::IfThenElse(hn::Ge(rho2, hn::Set(d, 1.0f)), hn::Set(d, 50.0f), hn::Set(d, -100.0f));
  return hn::IfThenElse(normal, hn::Mul(hn::Set(d, 0.5f), fast_log2(rho2)), edge);
}

// A 3-D texture's level of detail: rho from the derivatives of (u, v, w) (GL 1.5,
// equation 3.17, the larger of the two screen axes).
inline float level_of_detail3(const SamplerView& s, float dudx, float dvdx, float dwdx, float dudy, float dvdy,
                              float dwdy) {
  const float w = float(s.levels[0].width), h = float(s.levels[0].height), dp = float(s.levels[0].depth);
  const float rx = (dudx * w) * (dudx * w) + (dvdx * h) * (dvdx * h) + (dwdx * dp) * (dwdx * dp);
  const float ry = (dudy * w) * (dudy * w) + (dvdy * h) * (dvdy * h) + (dwdy * dp) * (dwdy * dp);
  const float rho2 = std::max(rx, ry);
  return rho2 > 1e-30f && rho2 < 1e30f ? 0.5f * fast_log2(rho2) : (rho2 > 0 ? (rho2 < 1 ? -100.0f : 50.0f) : -100.0f);
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_SAMPLER_INL_H_ toggle
