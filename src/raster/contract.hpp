// The contract between the front end (the triangle stage) and the back end (the tile
// rasterizer): everything one hands the other, in one header. The triangle stage
// includes it and writes records; raster/ reads them and never includes the front end.
//
//   records      RecordHeader, its shape (TriangleEdges, SmallShape, LineShape,
//                ClearShape) and its interpolation planes, in screen space
//   kernels      KernelId, chosen once per draw, and the varying layout of each
//   draw state   DrawState (per draw: object id, specular, textures, pixel state)
//   tile inputs  TileInputs (per frame: the bins, the draw states, the lights, the clears)
//
// Screen space: x to the right, y down, pixel (x, y) covers [x, x+1) x [y, y+1) and is
// sampled at its centre (x + 0.5, y + 0.5). Triangle vertices are snapped to 24.8 fixed
// point (kSubpixelBits = 8, as in Mesa's llvmpipe), so coverage is exact integer
// arithmetic: a shared edge is evaluated bit-identically by both triangles.
//
// A record is a RecordHeader, then its shape (TriangleEdges, LineShape or ClearShape by
// kind), then `num_varyings` interpolation planes. Records live in per-worker arenas
// (raster/bins.hpp) and are read, never written, by the tiles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framebuffer/framebuffer.hpp"
#include "shading/ggx_albedo.hpp"
#include "shading/lighting.hpp"
#include "velocity/material.hpp"
#include "velocity/primitives.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace velocity::raster {

class Bins;

inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelOne = 1 << kSubpixelBits;  // 256
inline constexpr int kSubpixelHalf = kSubpixelOne / 2;   // the pixel centre, 0.5

// Guard band: geometry reaching no further than this many pixels outside the
// framebuffer is rasterised as it is (the bounding box is scissored); anything beyond
// is clipped against the guard-band planes first. With framebuffers up to 16384 pixels
// a side, snapped coordinates stay within +-2^23 (24.8 fixed point), so edge
// coefficients (coordinate differences) stay below 2^24 and fit int32, and edge
// functions (products below 2^48) fit int64.
inline constexpr float kGuardBandPixels = 16384.0f;
static_assert(kGuardBandPixels == float(kMaxFramebufferSide));

// Per-vertex values interpolated across a primitive (colour, normal, eye position, ...).
inline constexpr int kMaxVaryings = 16;

// A linear function of the pixel position, value = c + dx * (x - x0) + dy * (y - y0),
// where (x0, y0) is the centre of the record's first bounding-box pixel (min_x, min_y).
// Anchoring at the box keeps the evaluation free of cancellation far from the origin.
struct Plane {
  float c = 0, dx = 0, dy = 0;
};

enum class RecordKind : uint8_t { Triangle, Small, Line, Rect, Clear };

// RecordHeader::flags.
enum RecordFlags : uint8_t {
  // Every varying has the same value at the three vertices (a flat-shaded or unlit
  // face): the fixed-function kernel without textures shades it once, not per pixel.
  kConstantVaryings = 1,
};

struct RecordHeader {
  RecordKind kind;
  uint8_t kernel;        // shading kernel (KernelId below), chosen once per draw
  uint8_t num_varyings;  // planes after the shape
  uint8_t flags = 0;     // RecordFlags
  uint32_t draw;         // index of the DrawState it came from
  // Inclusive pixel bounding box, clipped to the framebuffer and the draw's scissor.
  int16_t min_x, min_y, max_x, max_y;
  uint32_t flat_color;  // RGBA8 of the flat kernels (a lit face, a line's colour)
  Plane depth;          // window z in [0, 1], affine in screen space
  Plane inv_w;          // 1 / w_clip, for perspective correction (constant 1 when affine)
  float sort_key = 0;   // painter's mode: mean window depth, drawn far to near
};
static_assert(sizeof(RecordHeader) == 48);

// Edge functions E_i(px, py) = a_i * px + b_i * py + c_i over 24.8 fixed-point
// pixel-centre coordinates; a pixel is covered when all three are >= 0. The top-left
// rule is folded into c_i: non-top-left edges had 1 subtracted, so a centre exactly on
// such an edge is left to the neighbour that shares it.
struct TriangleEdges {
  int32_t a[3], b[3];
  int64_t c[3];
};

// A line `width` pixels wide: for each pixel column (x-major) or row (y-major) whose
// centre lies in [start, end) along the major axis, the `width` pixels across it
// centred where the segment crosses that centre line (OpenGL's aliased wide lines; the
// half-open range is the diamond-exit rule in effect, so lines that meet at a vertex
// do not both draw it).
struct LineShape {
  float x0, y0, x1, y1;
  int32_t width;
  int32_t x_major;
};

// A small triangle (its pixel centres within 8x8): the pixels it covers, found exactly
// at set-up (or by the triangle stage's first pass), as an 8x8 mask at (min_x, min_y),
// bit y * 8 + x. No edges.
struct SmallShape {
  uint64_t mask;
};
inline constexpr int kSmallSide = 8;

// A 4x4 mask (bit y * 4 + x) as an 8x8 one (bit y * 8 + x).
inline constexpr uint64_t small_mask_from_4x4(uint32_t m) {
  uint64_t out = 0;
  for (int row = 0; row < 4; ++row) out |= uint64_t((m >> (4 * row)) & 0xf) << (8 * row);
  return out;
}

// A clear of the bounding box (the record's min/max): the colour value under
// `color_mask` and/or the depth value.
struct ClearShape {
  uint32_t color;
  float depth;
  uint32_t color_mask;  // RGBA8 bits that are written (0 when colour is not cleared)
  uint32_t clear_depth;
  uint8_t stencil, stencil_mask;  // stencil bits written (0 when stencil is not cleared)
};

// Rect records (points, and a fully covered box) have no shape: the bounding box is the
// coverage.

inline constexpr size_t shape_bytes(RecordKind k) {
  switch (k) {
    case RecordKind::Triangle: return sizeof(TriangleEdges);
    case RecordKind::Small: return sizeof(SmallShape);
    case RecordKind::Line: return sizeof(LineShape);
    case RecordKind::Clear: return sizeof(ClearShape);
    default: return 0;
  }
}
inline constexpr size_t record_bytes(RecordKind k, int num_varyings) {
  return (sizeof(RecordHeader) + shape_bytes(k) + sizeof(Plane) * size_t(num_varyings) + 7) / 8 * 8;
}
template <class Shape>
inline const Shape& shape(const RecordHeader& r) {
  return *reinterpret_cast<const Shape*>(reinterpret_cast<const std::byte*>(&r) + sizeof(RecordHeader));
}
template <class Shape>
inline Shape& shape(RecordHeader& r) {
  return *reinterpret_cast<Shape*>(reinterpret_cast<std::byte*>(&r) + sizeof(RecordHeader));
}
inline const Plane* varyings(const RecordHeader& r) {
  return reinterpret_cast<const Plane*>(reinterpret_cast<const std::byte*>(&r) + sizeof(RecordHeader) +
                                        shape_bytes(r.kind));
}
inline Plane* varyings(RecordHeader& r) {
  return reinterpret_cast<Plane*>(reinterpret_cast<std::byte*>(&r) + sizeof(RecordHeader) + shape_bytes(r.kind));
}

// Packs a colour in [0, 1] to RGBA8 as OpenGL does: clamp, scale by 255, round.
inline uint32_t pack_rgba(float r, float g, float b, float a = 1.0f) {
  auto q = [](float v) {
    v = v > 0 ? (v < 1 ? v : 1) : 0;  // NaN (a degenerate normal, say) becomes 0, not UB
    return uint32_t(v * 255.0f + 0.5f);
  };
  return q(r) | (q(g) << 8) | (q(b) << 16) | (q(a) << 24);
}

// Shading kernels and their varyings (interpolated perspective-correct, in this order):
//   Flat          none: the record's flat colour
//   Smooth        0-2 colour (Gouraud's lit colour, or vertex colours)
//   FlatTex<F>    0-1 uv; the flat colour times the texture
//   SmoothTex<F>  0-2 colour, 3-4 uv; colour times the texture
//   Phong         0-2 base colour, 3-5 eye-space normal, 6-8 eye-space position
//   PhongTex<F>, PhongEnv<F>, PhongTexEnv<F>
//                 as Phong, plus 9-10 uv for the base texture; the environment map is
//                 addressed per pixel by the normal
//   Pbr<T, C, F>  glTF 2.0 metallic-roughness, per pixel: 0-2 eye-space normal, 3-5
//                 eye-space position, 6-7 uv (the material's uv set), then with a
//                 normal map (T) 4 more: the eye-space tangent and its handedness, then
//                 with vertex colours (C) 4 more: r, g, b, a (linear)
//   Fixed<U, G, S> the fixed-function (OpenGL) kernel: 0-3 RGBA, then 3 more per
//                 texture unit (U of them, 0-2): s, t, q (the texture reads s/q, t/q),
//                 then with a colour sum (S) the secondary colour's r, g, b, then with
//                 fog (G) the fog coordinate; the rest of PixelState is read per draw.
// <F> is the texture filter (nearest, bilinear, trilinear).
enum class KernelId : uint8_t {
  Flat,
  Smooth,
  FlatTex,         // + filter (3 ids)
  SmoothTex = FlatTex + 3,
  Phong = SmoothTex + 3,
  PhongTex,        // + filter
  PhongEnv = PhongTex + 3,
  PhongTexEnv = PhongEnv + 3,
  Pbr = PhongTexEnv + 3,    // + 6 * tangents + 3 * vertex colours + filter (12 ids)
  Fixed = Pbr + 12,         // + fixed_kernel (28 ids)
  Count = Fixed + 28,
};
// The varying layouts above, by name: the triangle stage writes them
// (triangle/) and the shaders read them.
namespace varying {
inline constexpr int kColor = 0;        // Smooth, SmoothTex, Phong*: r, g, b (Phong: the base colour)
inline constexpr int kSmoothUv = 3;     // SmoothTex: u, v
inline constexpr int kFlatUv = 0;       // FlatTex: u, v
inline constexpr int kNormal = 3;       // Phong*: eye-space normal x, y, z
inline constexpr int kEye = 6;          // Phong*: eye-space position x, y, z
inline constexpr int kPhongUv = 9;      // PhongTex*: u, v
inline constexpr int kFixedColor = 0;   // Fixed: r, g, b, a
inline constexpr int kFixedTex = 4;     // Fixed, textured: s, t, q (a 3-D texture: s, t, r, q), then unit 1's
inline constexpr int kPbrNormal = 0;    // Pbr: eye-space normal
inline constexpr int kPbrEye = 3;       // Pbr: eye-space position
inline constexpr int kPbrUv = 6;        // Pbr: u, v
inline constexpr int kPbrTangent = 8;   // Pbr with a normal map: tangent x, y, z, handedness
}  // namespace varying
inline constexpr int pbr_varyings(bool tangents, bool colors) { return 8 + (tangents ? 4 : 0) + (colors ? 4 : 0); }
inline constexpr uint8_t pbr_kernel(bool tangents, bool colors, Filter f) {
  return uint8_t(uint8_t(KernelId::Pbr) + 6 * tangents + 3 * colors + uint8_t(f));
}
inline constexpr int kSmoothVaryings = 3;
inline constexpr int kSmoothTexVaryings = 5;
inline constexpr int kFlatTexVaryings = 2;
inline constexpr int kPhongVaryings = 9;
inline constexpr int kPhongTexVaryings = 11;
// The family of a kernel id: Flat, Smooth, FlatTex, SmoothTex, Phong (untextured), or
// PhongTex for any textured or environment-mapped Phong, Pbr, or Fixed.
inline constexpr KernelId kernel_family(uint8_t id) {
  if (id < uint8_t(KernelId::FlatTex)) return KernelId(id);
  if (id < uint8_t(KernelId::SmoothTex)) return KernelId::FlatTex;
  if (id < uint8_t(KernelId::Phong)) return KernelId::SmoothTex;
  if (id == uint8_t(KernelId::Phong)) return KernelId::Phong;
  if (id < uint8_t(KernelId::Pbr)) return KernelId::PhongTex;
  if (id < uint8_t(KernelId::Fixed)) return KernelId::Pbr;
  return KernelId::Fixed;
}
inline constexpr uint8_t kernel_with_filter(KernelId k, Filter f) { return uint8_t(uint8_t(k) + uint8_t(f)); }
// A fixed-function kernel by the texture units it reads (0-2), which of them are 3-D
// (`volumes`: bit u for unit u), the colour sum and fog: 4 ids without units, 8 with
// one (2-D, 3-D), 16 with two (each 2-D or 3-D); each x colour sum x fog.
inline constexpr uint8_t fixed_kernel(int units, bool fog, bool color_sum, int volumes = 0) {
  const int base = units == 0 ? 0 : units == 1 ? 4 : 12;
  return uint8_t(uint8_t(KernelId::Fixed) + base + 4 * volumes + 2 * color_sum + fog);
}
// The texture coordinates units 0 .. units - 1 interpolate: s t q each, or (3-D) s t r q.
inline constexpr int fixed_tex_varyings(int units, int volumes) {
  int n = 0;
  for (int u = 0; u < units; ++u) n += (volumes >> u & 1) ? 4 : 3;
  return n;
}
inline constexpr int fixed_varyings(int units, bool fog, bool color_sum, int volumes = 0) {
  return 4 + fixed_tex_varyings(units, volumes) + (color_sum ? 3 : 0) + (fog ? 1 : 0);
}

// A texture as the SIMD sampler reads it: each mip level's texels, size and the
// addressing, resolved once per draw.
struct SamplerLevel {
  const uint32_t* texels = nullptr;  // texel (0, 0) of the image (inside a border)
  int32_t width = 1, height = 1;
  int32_t depth = 1;  // a 3-D texture's slices (SamplerView::volume)
  const uint64_t* linear = nullptr;  // srgb views: Texture::linear_levels(), RGBA16
  // Rows are `stride` texels apart, slices `rows` rows apart: the image's width and
  // height, two more each with a border (Texture::Level::border), whose texels -1 and
  // width (height, depth) clamp-to-border then reads instead of the border colour.
  int32_t stride = 1, rows = 1;
  bool bordered = false;
};
struct SamplerView {
  static constexpr int kMaxLevels = 17;  // 65536 down to 1
  SamplerLevel levels[kMaxLevels];
  int level_count = 0;
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  // A 3-D texture (Texture::volume): sampled at (s, t, r), r addressed by wrap_r.
  bool volume = false;
  Wrap wrap_r = Wrap::Repeat;
  SamplerState::Texel mag = SamplerState::Texel::Linear, min = SamplerState::Texel::Linear;
  SamplerState::Mip mip = SamplerState::Mip::Linear;
  float lod_bias = 0, min_lod = -1000, max_lod = 1000;  // (SamplerState's)
  float border[4] = {0, 0, 0, 0};
  // sRGB-encoded texels, decoded to linear light before filtering as a GPU's sRGB
  // texture is: the sampler reads the levels' `linear` texels, decoded once per
  // texture (read_as_srgb); false: `texels`, the values as they are.
  bool srgb = false;
  const Texture* texture = nullptr;  // what the levels point into

  SamplerView() = default;
  // The mesh path: a Filter and one wrap mode for both axes.
  SamplerView(const Texture& t, Filter f, Wrap w);
  // The fixed-function path.
  SamplerView(const Texture& t, const SamplerState& s);
  // Sets srgb; on, points the levels at the texture's linear_levels() (decoding the
  // texture on its first use so).
  void read_as_srgb(bool on);
  explicit operator bool() const { return level_count > 0; }
};

// A texture's KHR_texture_transform as an affine map of the kernel's uv:
// u' = a u + b v + c, v' = d u + e v + f.
struct UvAffine {
  float a = 1, b = 0, c = 0, d = 0, e = 1, f = 0;
};

// What the Pbr kernels read per draw: glTF's metallic-roughness parameters, linear.
struct PbrState {
  float base[4] = {1, 1, 1, 1};  // base colour factor, rgba
  float metallic = 1, roughness = 1, normal_scale = 1, occlusion_strength = 1;
  float emissive[3] = {0, 0, 0};
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool unlit = false;
  // The textures (DrawState::texture is the base colour) and their uv maps.
  SamplerView metallic_roughness, normal, occlusion, emissive_map;
  UvAffine base_uv, mr_uv, normal_uv, occlusion_uv, emissive_uv;
  // Without a metallic-roughness texture the roughness is the factor everywhere:
  // 1 / E - 1 at N.V = (j + 0.5) / size for it (shading/ggx_albedo.hpp), computed
  // once a draw by plan_pbr for the kernel's multiple-scattering term.
  float lost_energy[shading::kGgxAlbedoSize] = {};
};

// Per-draw parameters the per-pixel kernels need.
struct DrawState {
  uint32_t object_id = 0;
  // Mesh kernels.
  shading::Specular specular;
  SamplerView texture, env_map;
  float env_mix = 1;
  PbrState pbr;  // Pbr kernels
  // The fixed-function kernel (PrimitiveBatch draws): `texture` is unit 0's, this
  // unit 1's.
  PixelState pixel;
  SamplerView texture1;
  // 0..1 multipliers the kernel uses for the texture environment, per TexFormat (see
  // raster/shade_fixed-inl.h).
  float tex_rgb = 1, tex_alpha = 1;
};

// How the mesh kernels turn the light they compute into pixels (docs/appearance.md):
// Display writes values as they are (clamped); Linear scales by the exposure, tone
// maps and encodes to sRGB (raster/output-inl.h).
struct OutputTransform {
  bool linear = false;
  float exposure = 1;
  ToneMap tone_map = ToneMap::None;
};

// Everything the tiles read, immutable while they run.
struct TileInputs {
  const Bins* bins = nullptr;
  const std::vector<DrawState>* draws = nullptr;
  const shading::EyeLights* lights = nullptr;
  OutputTransform output;
  bool orthographic = false;  // the eye direction is +z everywhere (else towards the origin)
  bool depth_test = true;       // false: painter's mode (meshes: no depth test, no depth write)
  bool clear_color_buffer = true, clear_depth_buffer = true;
  bool clear_stencil_buffer = true;
  // Depth only (a shadow map's pass, src/shadows.hpp): the framebuffer's colour is never
  // cleared, written or read; the kernels' colour goes to a scratch tile.
  bool depth_only = false;
  // With depth_only, a shadow map: the tile's depth is drawn in a scratch tile and stored
  // here as 16-bit codes, in shading/shadow.hpp's layout (rows with a border) for a map
  // `shadow_size` texels a side whose projection is perspective or not, between planes
  // near and far (clip w).
  uint16_t* shadow_codes = nullptr;
  int shadow_size = 0;
  bool shadow_perspective = false;
  float shadow_near = 0, shadow_far = 1;
  uint32_t color = 0;           // the clear values
  float depth = 1.0f;
  uint8_t stencil = 0;
};

}  // namespace velocity::raster
