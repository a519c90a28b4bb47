// The geometry stage for one mesh: transform its vertices, light them, assemble
// triangles, reject, cull and clip them, and set up what survives for the rasterizer.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/clip.hpp"
#include "geometry/lighting.hpp"
#include "raster/rasterize.hpp"
#include "raster/setup.hpp"
#include "velocity/renderer.hpp"

namespace velocity::geometry {

// Everything that stays fixed for a frame.
struct FrameParams {
  Mat4 view, projection;
  int width = 0, height = 0;
  GuardBand guard{};
  EyeLights lights;
  RenderOptions options;
};

// Per-vertex scratch arrays, reused across draws and frames (no allocation in steady
// state once they have grown to the largest mesh).
struct VertexScratch {
  std::vector<Vec4> clip;
  std::vector<uint32_t> codes;
  std::vector<raster::ScreenVertex> screen;
  std::vector<Vec3> eye_pos, eye_normal;
  std::vector<LightTerms> light;
  std::vector<Vec3> averaged_normals;  // for meshes that bring none
  std::vector<uint64_t> eye_stamp, light_stamp;  // which draw (and material) filled them
  uint64_t generation = 0;
};

void draw_mesh(const FrameParams& params, const Mesh& mesh, const Mat4& world, const Material* override_material,
               VertexScratch& scratch, raster::FramePrimitives& out, FrameStats& stats);

}  // namespace velocity::geometry
