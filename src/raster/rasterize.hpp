// The tile rasterizer: for one tile, clear it (or keep what the last frame left), then
// run its records in submission order, each through its coverage (triangle edges, a
// line, a rectangle) and the shading kernel it was set up with.
//
// Kernels are chosen once per draw (a KernelId in each record), never per pixel. They
// run on 4x4-pixel blocks, written once against Google Highway and compiled for
// AVX-512, AVX2, SSE4 and plain C++; the best the processor has is picked at run time
// (raster/rasterize.cpp, simd/simd.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "shading/lighting.hpp"
#include "raster/bins.hpp"
#include "raster/raster_types.hpp"
#include "velocity/primitives.hpp"
#include "velocity/texture.hpp"

namespace velocity {
struct Framebuffer;
}

namespace velocity::raster {

// Shading kernels and their varyings (interpolated perspective-correct, in this order):
//   Flat          none: the record's flat colour
//   Smooth        0-2 colour (Gouraud's lit colour, or vertex colours)
//   FlatTex<F>    0-1 uv; the flat colour times the texture
//   SmoothTex<F>  0-2 colour, 3-4 uv; colour times the texture
//   Phong         0-2 base colour, 3-5 eye-space normal, 6-8 eye-space position
//   PhongTex<F>, PhongEnv<F>, PhongTexEnv<F>
//                 as Phong, plus 9-10 uv for the base texture; the environment map is
//                 addressed per pixel by the normal
//   Fixed<T, G>   the fixed-function (OpenGL) kernel: 0-3 RGBA, then with a texture
//                 (T) 3 more: s, t, q (the texture reads s/q, t/q), then with fog (G)
//                 the fog coordinate; the rest of PixelState is read per draw.
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
  Fixed = PhongTexEnv + 3,  // + 2 * textured + fog (4 ids)
  Count = Fixed + 4,
};
// The varying layouts above, by name: the triangle stage writes them
// (geometry/mesh_stage.cpp, batch_stage.cpp) and the shaders read them.
namespace varying {
inline constexpr int kColor = 0;        // Smooth, SmoothTex, Phong*: r, g, b (Phong: the base colour)
inline constexpr int kSmoothUv = 3;     // SmoothTex: u, v
inline constexpr int kFlatUv = 0;       // FlatTex: u, v
inline constexpr int kNormal = 3;       // Phong*: eye-space normal x, y, z
inline constexpr int kEye = 6;          // Phong*: eye-space position x, y, z
inline constexpr int kPhongUv = 9;      // PhongTex*: u, v
inline constexpr int kFixedColor = 0;   // Fixed: r, g, b, a
inline constexpr int kFixedTex = 4;     // Fixed, textured: s, t, q
}  // namespace varying
inline constexpr int kSmoothVaryings = 3;
inline constexpr int kSmoothTexVaryings = 5;
inline constexpr int kFlatTexVaryings = 2;
inline constexpr int kPhongVaryings = 9;
inline constexpr int kPhongTexVaryings = 11;
// The family of a kernel id: Flat, Smooth, FlatTex, SmoothTex, Phong (untextured), or
// PhongTex for any textured or environment-mapped Phong, or Fixed.
inline constexpr KernelId kernel_family(uint8_t id) {
  if (id < uint8_t(KernelId::FlatTex)) return KernelId(id);
  if (id < uint8_t(KernelId::SmoothTex)) return KernelId::FlatTex;
  if (id < uint8_t(KernelId::Phong)) return KernelId::SmoothTex;
  if (id == uint8_t(KernelId::Phong)) return KernelId::Phong;
  if (id < uint8_t(KernelId::Fixed)) return KernelId::PhongTex;
  return KernelId::Fixed;
}
inline constexpr uint8_t kernel_with_filter(KernelId k, Filter f) { return uint8_t(uint8_t(k) + uint8_t(f)); }
inline constexpr uint8_t fixed_kernel(bool textured, bool fog) { return uint8_t(uint8_t(KernelId::Fixed) + 2 * textured + fog); }
inline constexpr int fixed_varyings(bool textured, bool fog) { return 4 + (textured ? 3 : 0) + (fog ? 1 : 0); }

// A texture as the SIMD sampler reads it: each mip level's texels, size and the
// addressing, resolved once per draw.
struct SamplerLevel {
  const uint32_t* texels = nullptr;
  int32_t width = 1, height = 1;
};
struct SamplerView {
  static constexpr int kMaxLevels = 17;  // 65536 down to 1
  SamplerLevel levels[kMaxLevels];
  int level_count = 0;
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  SamplerState::Texel mag = SamplerState::Texel::Linear, min = SamplerState::Texel::Linear;
  SamplerState::Mip mip = SamplerState::Mip::Linear;
  float border[4] = {0, 0, 0, 0};

  SamplerView() = default;
  // The mesh path: a Filter and one wrap mode for both axes.
  SamplerView(const Texture& t, Filter f, Wrap w);
  // The fixed-function path.
  SamplerView(const Texture& t, const SamplerState& s);
  explicit operator bool() const { return level_count > 0; }
};

// Per-draw parameters the per-pixel kernels need.
struct DrawState {
  uint32_t object_id = 0;
  // Mesh kernels.
  shading::Specular specular;
  SamplerView texture, env_map;
  float env_mix = 1;
  // The fixed-function kernel (PrimitiveBatch draws).
  PixelState pixel;
  // 0..1 multipliers the kernel uses for the texture environment, per TexFormat (see
  // raster/shade_fixed-inl.h).
  float tex_rgb = 1, tex_alpha = 1;
};

// Everything the tiles read, immutable while they run.
struct FrameData {
  const Bins* bins = nullptr;
  const std::vector<DrawState>* draws = nullptr;
  const shading::EyeLights* lights = nullptr;
  bool depth_test = true;       // false: painter's mode (meshes: no depth test, no depth write)
  bool clear_color = true, clear_depth = true;
  uint32_t color = 0;           // the clear values
  float depth = 1.0f;
};

// Rasterizes tile `tile` into `fb`. Reads only shared, immutable frame data and writes
// only the tile's own pixels: tiles may run concurrently.
void rasterize_tile(const FrameData& frame, int tile, Framebuffer& fb);

// Coverage of one record in one tile, for tests: calls back with every 4x4 block
// (its top-left pixel) and the 16-bit mask of covered pixels (bit y * 4 + x).
void coverage_for_test(const RecordHeader& record, int tile_x0, int tile_y0, int tile_w, int tile_h,
                       void (*callback)(void* user, int x, int y, uint32_t mask), void* user);

// For tests: the kernels' sampler at (u, v) with level of detail `lod`, RGBA in [0, 1];
// and their level of detail for the given screen-space derivatives of (u, v).
void sample_for_test(const SamplerView& view, float u, float v, float lod, float rgba[4]);
float level_of_detail_for_test(const SamplerView& view, float dudx, float dvdx, float dudy, float dvdy);

// The instruction set the kernels run with ("AVX3", "AVX2", "SSE4", "EMU128", ...).
const char* simd_target();

}  // namespace velocity::raster
