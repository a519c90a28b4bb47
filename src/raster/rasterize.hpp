// The tile rasterizer: for one tile, clear it, then run its bin's commands in order
// through the shading kernel each primitive was set up with.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/bins.hpp"
#include "geometry/lighting.hpp"
#include "raster/raster_types.hpp"
#include "velocity/texture.hpp"

namespace velocity {
struct Framebuffer;
namespace geometry {
struct EyeLights;
}
}  // namespace velocity

namespace velocity::raster {

// Shading kernels. Which one a triangle uses is decided once, at set-up, from its
// draw's shading mode: the inner loops never branch on it.
//
// Varyings (interpolated perspective-correct) per kernel:
//   Flat         none: the set-up's constant colour
//   Smooth       0-2 colour (Gouraud's lit colour, or vertex colours)
//   Phong        0-2 base colour, 3-5 eye-space normal, 6-8 eye-space position
//   FlatTex      0-1 uv; the constant colour times the texture
//   SmoothTex    0-2 colour, 3-4 uv; colour times the texture
//   Phong*       as Phong, plus 9-10 uv for the base texture; the environment map is
//                addressed per pixel by the normal
enum class Kernel : uint8_t { Flat, Smooth, Phong, FlatTex, SmoothTex, PhongTex, PhongEnv, PhongTexEnv, Count };
inline constexpr int kPhongVaryings = 9;
inline constexpr int kPhongTexVaryings = 11;

// Kernel and filter as one index into the kernel tables (the filter only matters for the
// textured kernels).
inline constexpr uint8_t kernel_id(Kernel k, Filter f) { return uint8_t(uint8_t(k) * 3 + uint8_t(f)); }

// Per-draw parameters the per-pixel kernels need.
struct DrawState {
  geometry::Specular specular;
  const Texture* texture = nullptr;
  const Texture* env_map = nullptr;
  float env_mix = 1;
  bool repeat = true;
};

struct FramePrimitives {
  std::vector<TriangleSetup> triangles;
  std::vector<LineSetup> lines;
  std::vector<PointSetup> points;
  std::vector<DrawState> draws;
  // Every primitive's command in submission order (painter's mode sorts it).
  std::vector<uint32_t> order;
  const geometry::EyeLights* lights = nullptr;

  void clear() {
    triangles.clear(), lines.clear(), points.clear(), draws.clear(), order.clear();
  }
};

struct TileSettings {
  bool depth_test = true;  // false: painter's mode, no depth test and no depth write
  uint32_t clear_color = 0;
};

// Rasterizes tile `tile` of `bins` into `fb`. Reads only shared, immutable frame data
// and writes only the tile's own pixels: tiles may run concurrently.
void rasterize_tile(const FramePrimitives& frame, const Bins& bins, int tile, const TileSettings& settings,
                    Framebuffer& fb);

}  // namespace velocity::raster
