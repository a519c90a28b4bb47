// The mesh shaders: what a kernel computes for a vector of pixels of a 4x4 block, from
// the record's interpolation planes. Each has begin_block(fx, fy, b) at block b of the
// kernel's list, (fx, fy) its first pixel's offsets from the record's anchor pixel, and
// shade(v) for vector v of the block, returning packed RGBA8; a textured one also
// plan_levels, called with the whole list before the first block. A kPackable one can
// also shade any 16 pixels of the record (at_pixels, then shade(0): tile-inl.h's
// shade_packed). Chosen per draw, as template arguments of the kernel.
#if defined(VELOCITY_RASTER_SHADE_MESH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef VELOCITY_RASTER_SHADE_MESH_INL_H_
#undef VELOCITY_RASTER_SHADE_MESH_INL_H_
#else
#define VELOCITY_RASTER_SHADE_MESH_INL_H_
#endif

#include <algorithm>

#include "raster/coverage-inl.h"
#include "raster/output-inl.h"
#include "raster/rasterize.hpp"
#include "raster/sampler-inl.h"
#include "shading/lighting-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;
namespace lit = velocity::shading::HWY_NAMESPACE;

// N planes evaluated at pixels: value = c + dx x + dy y, (x, y) a pixel's offsets from
// the record's anchor, a lane each: the pixels of a block's vectors (begin), or any
// pixels of the record packed into vector 0 (at_pixels, tile-inl.h's shade_packed).
template <int N>
struct Planes {
  float dx[N], dy[N], c[N];
  float fx = 0, fy = 0;  // the block's first pixel
  VF x[kVectorsPerBlock], y[kVectorsPerBlock];
  void load(int i, const Plane& p) { c[i] = p.c, dx[i] = p.dx, dy[i] = p.dy; }
  void begin(float bx, float by) {
    const DF d;
    fx = bx, fy = by;
    for (int v = 0; v < kVectorsPerBlock; ++v) {
      x[v] = hn::Add(hn::Set(d, bx), block_x(v));
      y[v] = hn::Add(hn::Set(d, by), block_y(v));
    }
  }
  void at_pixels(VF px, VF py) { x[0] = px, y[0] = py; }
  HWY_INLINE VF at(int i, int v) const {
    const DF d;
    return hn::MulAdd(hn::Set(d, dx[i]), x[v], hn::MulAdd(hn::Set(d, dy[i]), y[v], hn::Set(d, c[i])));
  }
  // Scalar value at an offset from the block's first pixel.
  float value(int i, float px, float py) const { return c[i] + dx[i] * (fx + px) + dy[i] * (fy + py); }
};

// Plane 0 is 1/w, planes 1..N are varying/w: varying = plane / (1/w).
template <int N>
struct Perspective {
  Planes<N + 1> p;
  VF w;  // of the current vector
  void load(const RecordHeader& r) {
    p.load(0, r.inv_w);
    const Plane* v = varyings(r);
    for (int i = 0; i < N; ++i) p.load(i + 1, v[i]);
  }
  void begin(float fx, float fy) { p.begin(fx, fy); }
  void at_pixels(VF x, VF y) { p.at_pixels(x, y); }
  HWY_INLINE void at_vector(int v) { w = hn::Div(hn::Set(DF(), 1.0f), p.at(0, v)); }
  HWY_INLINE VF operator()(int i, int v) const { return hn::Mul(p.at(i + 1, v), w); }
  // The derivatives of varying i at the block's centre (1.5, 1.5), for mip-mapping:
  // d(V/Q) = (dV - (V/Q) dQ) / Q.
  void derivatives(int i, float& value, float& ddx, float& ddy) const {
    const float q = p.value(0, 1.5f, 1.5f), vq = p.value(i + 1, 1.5f, 1.5f);
    const float iq = q != 0 ? 1.0f / q : 0.0f;
    value = vq * iq;
    ddx = (p.dx[i + 1] - value * p.dx[0]) * iq;
    ddy = (p.dy[i + 1] - value * p.dy[0]) * iq;
  }
};

// Blocks [0, n) of a kernel's list, kLanes at a time (a lane per block): each(b, fx, fy)
// for blocks b to b + kLanes - 1 (past n: copies of the last block), (fx, fy) their first
// pixels' offsets from the record's anchor (block_origin's). (x0, y0): the tile's first pixel.
template <class Each>
HWY_INLINE void for_block_vectors(const RecordHeader& r, int x0, int y0, const Block* blocks, int n, Each&& each) {
  const DF d;
  alignas(64) float ox[kLanes], oy[kLanes];
  for (int b = 0; b < n; b += int(kLanes)) {
    for (size_t k = 0; k < kLanes; ++k) block_origin(r, x0, y0, blocks[std::min(b + int(k), n - 1)].index, ox[k], oy[k]);
    each(b, hn::Load(d, ox), hn::Load(d, oy));
  }
}

// Plane i of `p` at offset (x, y) from the first pixels (fx, fy) of N blocks: Planes::begin
// then Planes::value, a lane per block.
template <int M>
HWY_INLINE VF plane_at(const Planes<M>& p, int i, VF fx, VF fy, float x, float y) {
  const DF d;
  const VF base = hn::MulAdd(hn::Set(d, p.dy[i]), fy, hn::MulAdd(hn::Set(d, p.dx[i]), fx, hn::Set(d, p.c[i])));
  return hn::MulAdd(hn::Set(d, p.dy[i]), hn::Set(d, y), hn::MulAdd(hn::Set(d, p.dx[i]), hn::Set(d, x), base));
}

// Perspective::derivatives at the centres of N blocks (first pixels fx, fy), a lane per
// block: varying i's value and screen-space derivatives there.
template <int M>
struct BlockCentres {
  const Planes<M>& p;
  VF fx, fy, iq;  // iq: 1 / (1/w) at the centres (0 where 1/w is 0)
  BlockCentres(const Planes<M>& planes, VF x, VF y) : p(planes), fx(x), fy(y) {
    const DF d;
    const VF q = plane_at(p, 0, fx, fy, 1.5f, 1.5f);
    iq = hn::IfThenElseZero(hn::Ne(q, hn::Zero(d)), hn::Div(hn::Set(d, 1.0f), q));
  }
  HWY_INLINE void derivatives(int i, VF& value, VF& ddx, VF& ddy) const {
    const DF d;
    value = hn::Mul(plane_at(p, i + 1, fx, fy, 1.5f, 1.5f), iq);
    ddx = hn::Mul(hn::NegMulAdd(value, hn::Set(d, p.dx[0]), hn::Set(d, p.dx[i + 1])), iq);
    ddy = hn::Mul(hn::NegMulAdd(value, hn::Set(d, p.dy[0]), hn::Set(d, p.dy[i + 1])), iq);
  }
};

// The derivatives of varyings iu and iu + 1 (a texture's u and v) at the centres of
// blocks [0, n) of a kernel's list, kLanes blocks at a time, as Perspective::derivatives
// computes them for one: each(b, dudx, dvdx, dudy, dvdy) (for_block_vectors' blocks).
template <int N, class Each>
HWY_INLINE void uv_derivatives(const Perspective<N>& in, int iu, const RecordHeader& r, int x0, int y0,
                               const Block* blocks, int n, Each&& each) {
  const Planes<N + 1>& p = in.p;
  for_block_vectors(r, x0, y0, blocks, n, [&](int b, VF fx, VF fy) {
    const BlockCentres c(p, fx, fy);
    VF u, ux, uy, v, vx, vy;
    c.derivatives(iu, u, ux, uy);
    c.derivatives(iu + 1, v, vx, vy);
    each(b, ux, vx, uy, vy);
  });
}

// Each block's level of detail for one texture, found for a kernel's whole list of
// blocks before it shades any (plan_levels): the scalar divide and logarithm of
// level_of_detail per block held up the block's texture reads, a tenth of the textured
// PBR kernel's time (docs/performance.md).
struct BlockLods {
  alignas(64) float lod[kMaxBlocks];  // uv_derivatives stores whole vectors: kMaxBlocks % kLanes == 0
};

struct FlatShader {
  static constexpr bool kConstant = true;
  uint32_t color;
  FlatShader(const RecordHeader& r, const DrawState&, const TileInputs&) : color(r.flat_color) {}
  void begin_block(float, float, int) {}
  HWY_INLINE VU shade(int) const { return hn::Set(DU(), color); }
};

// (Not packed: tile-inl.h's shade_packed cost a Gouraud frame more than the lanes it filled.)
struct SmoothShader {
  static constexpr bool kConstant = false;
  Perspective<kSmoothVaryings> in;
  const OutputTransform& out;
  SmoothShader(const RecordHeader& r, const DrawState&, const TileInputs& f) : out(f.output) { in.load(r); }
  void begin_block(float fx, float fy, int) { in.begin(fx, fy); }
  HWY_INLINE VU shade(int v) {
    in.at_vector(v);
    return finish(out, in(varying::kColor, v), in(varying::kColor + 1, v), in(varying::kColor + 2, v));
  }
};

// A texture addressed by two varyings, its level chosen per block (the levels of detail
// of all the kernel's blocks found first, plan).
template <int N>
struct UvTexture {
  const SamplerView& tex;
  int iu;
  LevelChoice level{};
  VF frac;  // the weight of level.level1, per lane (packed pixels come from several blocks)
  bool one_level = single_level(tex);  // then no derivatives, no log2 per block
  BlockLods lods;  // (written by plan before it is read: not initialised)
  UvTexture(const SamplerView& t, int first_varying) : tex(t), iu(first_varying) {}
  void plan(const Perspective<N>& in, const RecordHeader& r, const Block* blocks, int n, int x0, int y0) {
    if (one_level) return;
    uv_derivatives(in, iu, r, x0, y0, blocks, n, [&](int b, VF ux, VF vx, VF uy, VF vy) {
      hn::Store(level_of_detail(tex, ux, vx, uy, vy), DF(), lods.lod + b);
    });
  }
  LevelChoice block_level(int b) const {
    return one_level ? LevelChoice{tex.mag, 0, 0, 0} : choose_levels(tex, lods.lod[b]);
  }
  void begin(int b) {
    const LevelChoice l = block_level(b);
    use(l, hn::Set(DF(), l.frac));
  }
  void use(const LevelChoice& l, VF f) { level = l, frac = f; }
  HWY_INLINE Rgba operator()(const Perspective<N>& in, int v) const {
    return sample<false>(tex, level, in(iu, v), in(iu + 1, v), frac);
  }
};

// The flat colour (a lit face, or white for "replace") times the texture.
struct FlatTexShader {
  static constexpr bool kConstant = false;
  Perspective<kFlatTexVaryings> in;
  UvTexture<kFlatTexVaryings> tex;
  const OutputTransform& out;
  float r, g, b;
  FlatTexShader(const RecordHeader& rec, const DrawState& d, const TileInputs& f)
      : tex{d.texture ? d.texture : d.env_map, varying::kFlatUv}, out(f.output) {
    in.load(rec);
    r = float(rec.flat_color & 0xff) / 255.0f, g = float((rec.flat_color >> 8) & 0xff) / 255.0f;
    b = float((rec.flat_color >> 16) & 0xff) / 255.0f;
  }
  void plan_levels(const RecordHeader& r, const Block* blocks, int n, int x0, int y0) { tex.plan(in, r, blocks, n, x0, y0); }
  void begin_block(float fx, float fy, int b) { in.begin(fx, fy), tex.begin(b); }
  static constexpr bool kPackable = true;  // tile-inl.h's shade_packed
  static constexpr int level_count() { return 1; }
  void block_levels(int b, LevelChoice* out) const { *out = tex.block_level(b); }
  void use_levels(const LevelChoice* levels, const VF* frac) { tex.use(*levels, *frac); }
  void at_pixels(VF x, VF y) { in.at_pixels(x, y); }
  HWY_INLINE VU shade(int v) {
    const DF d;
    in.at_vector(v);
    Rgba t = tex(in, v);
    return finish(out, hn::Mul(hn::Set(d, r), t.r), hn::Mul(hn::Set(d, g), t.g), hn::Mul(hn::Set(d, b), t.b));
  }
};

// Gouraud's lit colour times the texture (OpenGL's GL_MODULATE).
struct SmoothTexShader {
  static constexpr bool kConstant = false;
  Perspective<kSmoothTexVaryings> in;
  UvTexture<kSmoothTexVaryings> tex;
  const OutputTransform& out;
  SmoothTexShader(const RecordHeader& rec, const DrawState& d, const TileInputs& f)
      : tex{d.texture ? d.texture : d.env_map, varying::kSmoothUv}, out(f.output) {
    in.load(rec);
  }
  void plan_levels(const RecordHeader& r, const Block* blocks, int n, int x0, int y0) { tex.plan(in, r, blocks, n, x0, y0); }
  void begin_block(float fx, float fy, int b) { in.begin(fx, fy), tex.begin(b); }
  static constexpr bool kPackable = true;  // tile-inl.h's shade_packed
  static constexpr int level_count() { return 1; }
  void block_levels(int b, LevelChoice* out) const { *out = tex.block_level(b); }
  void use_levels(const LevelChoice* levels, const VF* frac) { tex.use(*levels, *frac); }
  void at_pixels(VF x, VF y) { in.at_pixels(x, y); }
  HWY_INLINE VU shade(int v) {
    in.at_vector(v);
    Rgba t = tex(in, v);
    return finish(out, hn::Mul(in(varying::kColor, v), t.r), hn::Mul(in(varying::kColor + 1, v), t.g),
                  hn::Mul(in(varying::kColor + 2, v), t.b));
  }
};

// Per-pixel lighting (shading/lighting-inl.h); optionally a base texture (uv) and a
// sphere environment map addressed by the normal: u = 0.5 + 0.5 Nx, v = 0.5 - 0.5 Ny
// (the image's top row at Ny = 1).
template <bool kTex, bool kEnv>
struct PhongShader {
  static constexpr bool kConstant = false;
  static constexpr bool kPackable = true;  // tile-inl.h's shade_packed
  static constexpr int N = (kTex || kEnv) ? kPhongTexVaryings : kPhongVaryings;
  Perspective<N> in;
  const DrawState& draw;
  const shading::EyeLights& lights;
  UvTexture<N> tex;
  LevelChoice env_level{};
  VF env_frac;  // the weight of env_level.level1, per lane
  BlockLods env_lods;  // (written by plan_levels before it is read: not initialised)
  const OutputTransform& out;

  PhongShader(const RecordHeader& r, const DrawState& d, const TileInputs& f)
      : draw(d), lights(*f.lights), tex{d.texture, varying::kPhongUv}, out(f.output) {
    in.load(r);
  }

  // The environment map's uv at offset (x, y) from the first pixels (fx, fy) of N blocks:
  // the normal there (its planes: normal / w, 1/w first), normalised as
  // velocity::normalize does (zero stays zero).
  HWY_INLINE void env_uv(VF fx, VF fy, float x, float y, VF& u, VF& v) const {
    const DF d;
    constexpr int n0 = varying::kNormal + 1;
    const V3 n{plane_at(in.p, n0, fx, fy, x, y), plane_at(in.p, n0 + 1, fx, fy, x, y), plane_at(in.p, n0 + 2, fx, fy, x, y)};
    const VF len = hn::Sqrt(dot(n, n));
    const MF some = hn::Gt(len, hn::Zero(d));
    const VF half = hn::Set(d, 0.5f);
    u = hn::MulAdd(half, hn::IfThenElseZero(some, hn::Div(n.x, len)), half);
    v = hn::NegMulAdd(half, hn::IfThenElseZero(some, hn::Div(n.y, len)), half);
  }

  void plan_levels(const RecordHeader& r, const Block* blocks, int n, int x0, int y0) {
    if constexpr (kTex) tex.plan(in, r, blocks, n, x0, y0);
    if constexpr (kEnv) {
      if (single_level(draw.env_map)) return;
      // Finite differences across each block's centre, as a GPU's pixel quad would.
      for_block_vectors(r, x0, y0, blocks, n, [&](int b, VF fx, VF fy) {
        VF u, v, ux, vx, uy, vy;
        env_uv(fx, fy, 1.5f, 1.5f, u, v), env_uv(fx, fy, 2.5f, 1.5f, ux, vx), env_uv(fx, fy, 1.5f, 2.5f, uy, vy);
        const VF lod = level_of_detail(draw.env_map, hn::Sub(ux, u), hn::Sub(vx, v), hn::Sub(uy, u), hn::Sub(vy, v));
        hn::Store(lod, DF(), env_lods.lod + b);
      });
    }
  }
  LevelChoice env_block_level(int b) const {
    return single_level(draw.env_map) ? LevelChoice{draw.env_map.mag, 0, 0, 0} : choose_levels(draw.env_map, env_lods.lod[b]);
  }
  void begin_block(float fx, float fy, int b) {
    in.begin(fx, fy);
    if constexpr (kTex) tex.begin(b);
    if constexpr (kEnv) env_level = env_block_level(b), env_frac = hn::Set(DF(), env_level.frac);
  }
  // Packed pixels (shade_packed): the levels block b chooses, the run's levels and each
  // lane's weights, and the pixels.
  static constexpr int level_count() { return int(kTex) + int(kEnv); }
  void block_levels(int b, LevelChoice* out) const {
    if constexpr (kTex) *out++ = tex.block_level(b);
    if constexpr (kEnv) *out = env_block_level(b);
  }
  void use_levels(const LevelChoice* levels, const VF* frac) {
    if constexpr (kTex) tex.use(*levels++, *frac++);
    if constexpr (kEnv) env_level = *levels, env_frac = *frac;
  }
  void at_pixels(VF x, VF y) { in.at_pixels(x, y); }

  // `live`: the lanes the kernel writes (the others skip their shadow lookups).
  HWY_INLINE VU shade(int v, MF live) {
    const DF d;
    in.at_vector(v);
    VF br = in(varying::kColor, v), bg = in(varying::kColor + 1, v), bb = in(varying::kColor + 2, v);
    // The normal / w (planes: 1/w first): w cancels in normalising.
    constexpr int n0 = varying::kNormal + 1;
    VF nx = in.p.at(n0, v), ny = in.p.at(n0 + 1, v), nz = in.p.at(n0 + 2, v);
    const VF inv_len = rsqrt(hn::MulAdd(nx, nx, hn::MulAdd(ny, ny, hn::Mul(nz, nz))));
    nx = hn::Mul(nx, inv_len), ny = hn::Mul(ny, inv_len), nz = hn::Mul(nz, inv_len);
    if constexpr (kTex) {
      Rgba t = tex(in, v);
      br = hn::Mul(br, t.r), bg = hn::Mul(bg, t.g), bb = hn::Mul(bb, t.b);
    }
    if constexpr (kEnv) {
      const VF half = hn::Set(d, 0.5f);
      Rgba e = sample<false>(draw.env_map, env_level, hn::MulAdd(half, nx, half), hn::NegMulAdd(half, ny, half), env_frac);
      const VF mix = hn::Set(d, draw.env_mix);
      br = hn::MulAdd(hn::Sub(e.r, br), mix, br), bg = hn::MulAdd(hn::Sub(e.g, bg), mix, bg);
      bb = hn::MulAdd(hn::Sub(e.b, bb), mix, bb);
    }
    const shading::Specular& s = draw.specular;
    // The eye-space position: only the highlight, point lights and shadows read it.
    V3 p{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
    if (s.ks > 0 || !lights.point.empty() || lights.shadows) p = {in(varying::kEye, v), in(varying::kEye + 1, v), in(varying::kEye + 2, v)};
    const V3 c = lit::apply(lit::light(lights, {nx, ny, nz}, p, s, live), {br, bg, bb});
    return finish(out, c.x, c.y, c.z);
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();

#endif  // VELOCITY_RASTER_SHADE_MESH_INL_H_ toggle
