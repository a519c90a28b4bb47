// The tile rasterizer: for one tile, clear it, then run its bin's commands in order
// through the shading kernel each primitive was set up with.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/bins.hpp"
#include "raster/raster_types.hpp"

namespace velocity {
struct Framebuffer;
namespace geometry {
struct EyeLights;
}
}  // namespace velocity

namespace velocity::raster {

// Shading kernels. Which one a triangle uses is decided once, at set-up, from its
// draw's shading mode: the inner loops never branch on it.
enum class Kernel : uint8_t {
  Flat,    // constant colour (flat shading, and unlit constant colours)
  Smooth,  // three varyings: a colour, interpolated perspective-correct (Gouraud, vertex colour)
  Phong,   // nine varyings: base colour, eye-space normal, eye-space position
};
inline constexpr int kPhongVaryings = 9;

// Per-draw parameters the per-pixel kernels need.
struct DrawState {
  float specular = 0;
  float shininess = 32;
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
