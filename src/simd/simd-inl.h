// The thin SIMD layer the kernels are written against: Google Highway's portable
// vectors, capped at 16 lanes of 32 bits (one 4x4 pixel block), plus the few helpers
// every kernel needs. This header is compiled once per instruction set (AVX-512,
// AVX2, SSE4 and, with VELOCITY_SIMD=OFF or on other processors, plain C++) by the
// files that include it after hwy/foreach_target.h; hence the toggling include guard.
//
// A 4x4 block is processed as kVectorsPerBlock vectors of N lanes: with AVX-512 one
// vector holds the whole block, with AVX2 two vectors hold two rows each, with SSE4
// four vectors hold a row each, in scalar mode sixteen vectors hold a pixel each. Lane
// i of vector v is pixel k = v * N + i of the block: column k & 3, row k >> 2.
#if defined(VELOCITY_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_SIMD_INL_H_
#undef VELOCITY_SIMD_INL_H_
#else
#define VELOCITY_SIMD_INL_H_
#endif

#include <cstdint>
#include <cstring>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace velocity::simd {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::CappedTag<float, 16>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using VU = hn::Vec<DU>;
using MF = hn::Mask<DF>;
using MI = hn::Mask<DI>;

inline constexpr size_t kLanes = hn::MaxLanes(DF());
inline constexpr int kVectorsPerBlock = int(16 / kLanes);
static_assert(16 % kLanes == 0, "a 4x4 block must be a whole number of vectors");

// Column and row of each pixel of a 4x4 block, in lane order.
alignas(64) inline constexpr float kBlockX[16] = {0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3};
alignas(64) inline constexpr float kBlockY[16] = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3};
alignas(64) inline constexpr int32_t kBlockXi[16] = {0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3};
alignas(64) inline constexpr int32_t kBlockYi[16] = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3};

HWY_INLINE VF block_x(int v) { return hn::Load(DF(), kBlockX + v * kLanes); }
HWY_INLINE VF block_y(int v) { return hn::Load(DF(), kBlockY + v * kLanes); }

// The lanes of vector v that a block's 16-bit coverage mask (bit k = pixel k) selects.
HWY_INLINE MF lane_mask(uint32_t mask16, int v) {
  uint64_t bits = uint64_t(mask16 >> (v * int(kLanes)));
  uint8_t bytes[8];
  std::memcpy(bytes, &bits, sizeof(bytes));
  return hn::LoadMaskBits(DF(), bytes);
}

// Whether vector v of a block has no lane in `mask16`: tested on the bits, before
// lane_mask builds the vector, so that the branch resolves a few instructions sooner
// (for a small triangle whether half a block is empty is a coin toss to the predictor).
HWY_INLINE bool vector_empty(uint32_t mask16, int v) {
  return ((mask16 >> (v * int(kLanes))) & ((uint32_t(1) << kLanes) - 1)) == 0;
}

// The lanes of any mask as bits, lane i in bit i. (To walk the set lanes with a scalar
// loop: Highway 1.0's Compress on AVX2 copies a 1 KiB table onto the stack at every
// call, which cost more than the rest of the triangle cull pass together.)
template <class D>
HWY_INLINE uint32_t lane_bits(D d, hn::Mask<D> m) {
  uint8_t bytes[8] = {};
  hn::StoreMaskBits(d, m, bytes);
  uint32_t bits = uint32_t(bytes[0]) | (uint32_t(bytes[1]) << 8);
  if (hn::MaxLanes(d) < 16) bits &= (1u << hn::MaxLanes(d)) - 1;
  return bits;
}

// The bits of `m` as a 16-bit mask in lane order (for vector v of a block).
HWY_INLINE uint32_t mask_bits(MF m, int v) { return lane_bits(DF(), m) << (v * int(kLanes)); }

// Stores the lanes of `v` that `m` selects at `p`, leaving the others as they are, in
// memory no other thread writes meanwhile (a tile's colour, depth and ids). AVX2's
// masked stores (vpmaskmovd, vmaskmovps: Highway's BlendedStore there) are microcoded
// on AMD's Zen cores and cost the kernels about half their time in a depth pass
// (docs/appearance.md); a load, a blend and a whole store are three plain instructions.
// AVX-512's masked stores are native: kept there.
template <class D>
HWY_INLINE void store_masked(hn::Vec<D> v, hn::Mask<D> m, D d, hn::TFromD<D>* HWY_RESTRICT p) {
#if HWY_TARGET <= HWY_AVX3
  hn::BlendedStore(v, m, d, p);
#else
  hn::StoreU(hn::IfThenElse(m, v, hn::LoadU(d, p)), d, p);
#endif
}

// Three vectors as one: N 3D points or directions, a lane each.
struct V3 {
  VF x, y, z;
};

HWY_INLINE VF dot(const V3& a, const V3& b) { return hn::MulAdd(a.x, b.x, hn::MulAdd(a.y, b.y, hn::Mul(a.z, b.z))); }

// x clamped to [0, 1]; NaN becomes 0 (comparisons with NaN are false).
HWY_INLINE VF saturate(VF x) {
  const DF d;
  return hn::Min(hn::IfThenElseZero(hn::Gt(x, hn::Zero(d)), x), hn::Set(d, 1.0f));
}

// Float to int32 by truncation, for lanes known to be finite and within int32's range
// (clamped colours, texel indices, depth codes). Highway's ConvertTo also mends lanes out
// of range (x86's conversion gives INT_MIN for them): four more instructions a vector on
// every x86 target (AVX-512's too: and-not, shift, shift, ternary logic), a third of
// packing a colour. Here the conversion alone.
HWY_INLINE VI truncate_in_range(VF v) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
  static_assert(kLanes == 16, "a whole 512-bit vector");
  return VI{_mm512_cvttps_epi32(v.raw)};
#elif HWY_TARGET == HWY_AVX2
  return VI{_mm256_cvttps_epi32(v.raw)};
#elif HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3
  return VI{_mm_cvttps_epi32(v.raw)};
#else
  return hn::ConvertTo(DI(), v);  // the plain C++ fallback clamps
#endif
}

// RGBA in [0, 1] to RGBA8 as OpenGL does: clamp, scale by 255, round half up.
HWY_INLINE VU pack_colors(VF r, VF g, VF b, VF a) {
  const DF d;
  const VF k = hn::Set(d, 255.0f), half = hn::Set(d, 0.5f);
  auto q = [&](VF c) { return hn::BitCast(DU(), truncate_in_range(hn::MulAdd(saturate(c), k, half))); };
  return hn::Or(hn::Or(q(r), hn::ShiftLeft<8>(q(g))), hn::Or(hn::ShiftLeft<16>(q(b)), hn::ShiftLeft<24>(q(a))));
}

// Channel c (0 red .. 3 alpha) of RGBA8 texels, in [0, 255].
template <int c>
HWY_INLINE VF channel(VU t) {
  const VU byte = hn::And(hn::ShiftRight<8 * c>(t), hn::Set(DU(), 0xffu));
  return hn::ConvertTo(DF(), hn::BitCast(DI(), byte));
}

// 1 / sqrt(x) to about 23 bits: the hardware estimate and one Newton step. 0 for x <= 0.
HWY_INLINE VF rsqrt(VF x) {
  const DF d;
  const MF ok = hn::Gt(x, hn::Zero(d));
  const VF safe = hn::IfThenElse(ok, x, hn::Set(d, 1.0f));
  VF y = hn::ApproximateReciprocalSqrt(safe);
  y = hn::Mul(y, hn::NegMulAdd(hn::Mul(hn::Set(d, 0.5f), safe), hn::Mul(y, y), hn::Set(d, 1.5f)));
  return hn::IfThenElseZero(ok, y);
}

// sqrt(x) as x / sqrt(x), to about 23 bits (0 for x <= 0): on AVX-512 a square root
// instruction blocks its unit for 5 to 10 cycles a vector, the estimate for one.
HWY_INLINE VF sqrt_fast(VF x) { return hn::Mul(x, rsqrt(x)); }

// 1 / x for finite x != 0, to about 23 bits: the estimate and one Newton step, for the
// same reason.
HWY_INLINE VF recip(VF x) {
  const VF r = hn::ApproximateReciprocal(x);
  return hn::Mul(r, hn::NegMulAdd(x, r, hn::Set(DF(), 2.0f)));
}

// 2^x for x in [-126, 0] (what the specular power needs), from the exponent bits and a
// degree-5 polynomial for the fraction: relative error below 2e-7.
HWY_INLINE VF exp2_neg(VF x) {
  const DF d;
  const DI di;
  x = hn::Max(x, hn::Set(d, -126.0f));
  const VF xi = hn::Floor(x);
  const VF f = hn::Sub(x, xi);  // [0, 1)
  VF p = hn::Set(d, 1.8775767e-3f);
  p = hn::MulAdd(p, f, hn::Set(d, 8.9893397e-3f));
  p = hn::MulAdd(p, f, hn::Set(d, 5.5826318e-2f));
  p = hn::MulAdd(p, f, hn::Set(d, 2.4015361e-1f));
  p = hn::MulAdd(p, f, hn::Set(d, 6.9315308e-1f));
  p = hn::MulAdd(p, f, hn::Set(d, 9.9999994e-1f));
  const VI e = hn::ShiftLeft<23>(hn::Add(hn::ConvertTo(di, xi), hn::Set(di, 127)));
  return hn::Mul(p, hn::BitCast(d, e));
}

// log2(x) for x > 0 (normal numbers): exponent bits plus a polynomial in the mantissa
// over [sqrt(1/2), sqrt(2)); absolute error below 1e-6.
HWY_INLINE VF log2_pos(VF x) {
  const DF d;
  const DI di;
  VI bits = hn::BitCast(di, x);
  // Split x = m * 2^e with m in [sqrt(1/2), sqrt(2)).
  const VI offset = hn::Set(di, 0x3f3504f3);  // sqrt(1/2)
  const VI e = hn::ShiftRight<23>(hn::Sub(bits, offset));
  const VF m = hn::BitCast(d, hn::Sub(bits, hn::ShiftLeft<23>(e)));
  const VF t = hn::Div(hn::Sub(m, hn::Set(d, 1.0f)), hn::Add(m, hn::Set(d, 1.0f)));  // (m-1)/(m+1)
  const VF t2 = hn::Mul(t, t);
  // log2(m) = 2/ln2 * atanh(t) = 2/ln2 * (t + t^3/3 + t^5/5 + t^7/7 + t^9/9)
  VF p = hn::Set(d, 0.3205972f);  // 2/(9 ln2)
  p = hn::MulAdd(p, t2, hn::Set(d, 0.4121985f));   // 2/(7 ln2)
  p = hn::MulAdd(p, t2, hn::Set(d, 0.5770780f));   // 2/(5 ln2)
  p = hn::MulAdd(p, t2, hn::Set(d, 0.9617967f));   // 2/(3 ln2)
  p = hn::MulAdd(p, t2, hn::Set(d, 2.8853901f));   // 2/ln2
  return hn::MulAdd(p, t, hn::ConvertTo(d, e));
}

// x^n for x in (0, 1] and n > 0: the specular highlight.
HWY_INLINE VF pow01(VF x, VF n) { return exp2_neg(hn::Mul(n, log2_pos(x))); }

}  // namespace HWY_NAMESPACE
}  // namespace velocity::simd
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_SIMD_INL_H_ toggle
