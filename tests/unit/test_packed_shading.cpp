// Shading in whole vectors (raster/tile-inl.h's shade_packed, on AVX-512): every pixel
// gets the colour, depth and object id that shading block by block gives it, whatever
// the kernel (Phong, environment map, per-vertex and flat texturing, PBR with and
// without its five textures), with shadows, super-sampling and the painter's mode.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>

#include "raster/rasterize.hpp"
#include "velocity/bench_scene.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;

namespace {

struct Frame {
  Image color;
  std::vector<float> depth;
  std::vector<uint32_t> ids;
};

// Two spheres, the second nearer and overlapping the first on screen (so the depth test
// decides pixels inside packed runs), seen by the convention's camera.
Frame draw(const Material& m, RenderOptions options, bool packed) {
  static const Mesh sphere = bench::make_mesh("sphere:32");
  raster::set_pixel_packing_for_test(packed);
  Renderer r(320, 240);
  options.object_ids = true;
  r.options = options;
  r.begin_frame(Camera{}, {}, {0.1f, 0.1f, 0.15f});
  r.draw(sphere, rotate_y(0.4f), &m, 1);
  r.draw(sphere, translate({0.45f, 0.25f, 0.5f}) * scale({0.5f, 0.5f, 0.5f}) * rotate_y(-0.7f), &m, 2);
  r.end_frame();
  raster::set_pixel_packing_for_test(true);
  return {r.color_image(), r.window_depth(), r.object_ids()};
}

// The number of pixels (or samples) whose colour, depth or id differ.
int differing(const Frame& a, const Frame& b) {
  int n = 0;
  for (size_t i = 0; i + 4 <= a.color.pixels.size(); i += 4) n += std::memcmp(&a.color.pixels[i], &b.color.pixels[i], 4) != 0;
  for (size_t i = 0; i < a.depth.size(); ++i) n += std::memcmp(&a.depth[i], &b.depth[i], sizeof(float)) != 0;
  for (size_t i = 0; i < a.ids.size(); ++i) n += a.ids[i] != b.ids[i];
  return n;
}

std::shared_ptr<const Texture> checker(int size, int square) {
  return std::make_shared<const Texture>(make_checkerboard(size, square));
}

void expect_same(const std::string& what, const Material& m, const RenderOptions& o) {
  const Frame block = draw(m, o, false), packed = draw(m, o, true);
  ASSERT_EQ(block.color.pixels.size(), packed.color.pixels.size());
  ASSERT_EQ(block.depth.size(), packed.depth.size());
  ASSERT_EQ(block.ids.size(), packed.ids.size());
  int drawn = 0;
  for (uint32_t id : block.ids) drawn += id != 0;
  EXPECT_GT(drawn, 10000) << what;  // the spheres are on screen
  EXPECT_EQ(differing(block, packed), 0) << what;
}

}  // namespace

TEST(PackedShading, SamePixelsAsBlockByBlock) {
  if (std::string(raster::simd_target()).rfind("AVX3", 0) != 0)
    GTEST_SKIP() << "shade_packed runs on AVX-512 only; this machine's kernels are " << raster::simd_target();
  for (const char* shade : {"phong", "env", "tex", "pbr", "pbrtex"}) {
    const bench::Look look = *bench::make_look(shade);
    expect_same(shade, look.material, look.options);
    RenderOptions shadows = look.options;
    shadows.shadows = true;
    expect_same(std::string(shade) + " with shadows", look.material, shadows);
  }
  // A flat-lit face times a trilinear texture (the flat textured kernel).
  Material flat = bench::make_look("tex")->material;
  flat.shading = Shading::Flat;
  expect_same("flat textured", flat, {});
  // PBR with all five textures, each at its own size (so their levels change at
  // different blocks), and a normal map.
  bench::Look pbr = *bench::make_look("pbrtex");
  pbr.material.pbr.metallic_roughness.texture = checker(64, 4);
  pbr.material.pbr.normal.texture = checker(128, 8);
  pbr.material.pbr.occlusion.texture = checker(32, 2);
  pbr.material.pbr.emissive_map.texture = checker(16, 2);
  pbr.material.pbr.emissive = {0.2f, 0.1f, 0.05f};
  expect_same("pbr, five textures", pbr.material, pbr.options);
  // Super-sampled, and the painter's mode (no depth test: every covered pixel shaded).
  RenderOptions ssaa = pbr.options;
  ssaa.ssaa = 2;
  expect_same("pbr, five textures, 2x2 super-sampling", pbr.material, ssaa);
  RenderOptions painter = bench::make_look("phong")->options;
  painter.depth_mode = DepthMode::Painter;
  expect_same("phong, painter's mode", bench::make_look("phong")->material, painter);
}
