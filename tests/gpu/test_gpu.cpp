// The GPU backend against the CPU pipeline, on whatever OpenGL EGL offers (Mesa's
// llvmpipe through the surfaceless platform on the project's machines): every golden
// scene on both backends, compared by PSNR; object ids, depth, super-sampling, painter's
// mode, per-face colours and materials, vertex colours, two-sided faces; the caches; the
// GLSL lighting against the scalar model; the choice of backend and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <tuple>

#include "context.hpp"
#include "gpu_backend.hpp"
#include "reference/compare.hpp"
#include "reference/reference.hpp"
#include "shaders.hpp"
#include "shading/ggx_albedo.hpp"
#include "shading/lighting.hpp"
#include "velocity/backend.hpp"
#include "velocity/bench_scene.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/renderer.hpp"
#include "velocity/image.hpp"
#include "velocity/view_setup.hpp"

#ifdef VELOCITY_GPU_REALTIME
#include "programs/drive.hpp"
#include "programs/fly.hpp"
#include "programs/viewer.hpp"
#include "runtime/loop.hpp"
#endif

namespace {

using namespace velocity;

vref::Image to_vref(const Image& img) { return {img.width, img.height, img.pixels}; }

struct ParityCase {
  std::string mesh;
  int width, height;
  std::string shade;
  double min_psnr;
  int ssaa = 1;
  int frame = 0, frames = 1;
};

std::string case_name(const ParityCase& c) {
  std::string m = c.mesh.rfind("sphere:", 0) == 0 ? "sphere" + c.mesh.substr(7) : std::filesystem::path(c.mesh).stem().string();
  std::string n = m + "_" + std::to_string(c.width) + "x" + std::to_string(c.height) + "_" + c.shade;
  if (c.ssaa > 1) n += "_ssaa" + std::to_string(c.ssaa);
  if (c.frame) n += "_f" + std::to_string(c.frame);
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

// Both backends draw the frame with object ids on; returns the two renderers.
void draw_both(const ParityCase& c, Renderer& cpu, Renderer& gpu) {
  auto look = bench::make_look(c.shade);
  ASSERT_TRUE(look.has_value());
  Mesh mesh = bench::make_mesh(c.mesh);
  for (Renderer* r : {&cpu, &gpu}) {
    r->options = look->options;
    r->options.ssaa = c.ssaa;
    r->options.object_ids = true;
    // bench::draw_frame's frame, with an object id (it draws with none).
    r->begin_frame(Camera{}, {}, Vec3{0.1f, 0.1f, 0.15f});
    r->draw(mesh, rotate_y(radians(360.0f * float(c.frame) / float(c.frames))), &look->material, 7);
    r->end_frame();
  }
}

class Parity : public ::testing::TestWithParam<ParityCase> {};

// The images agree by PSNR; the object-id masks on at least 99.5% of pixels. Where they
// differ is the silhouette: a pixel centre on a triangle's edge is decided by each
// rasterizer's own fixed-point snapping (the CPU's 24.8 and top-left rule; the GPU's
// subpixel precision), so a sample either side may land on the other object or on none.
TEST_P(Parity, MatchesTheCpuBackend) {
  const ParityCase& c = GetParam();
  Renderer cpu(c.width, c.height, BackendChoice::Cpu), gpu(c.width, c.height, BackendChoice::Gpu);
  ASSERT_STREQ(gpu.stats().backend, "gpu");
  draw_both(c, cpu, gpu);
  const vref::Image a = to_vref(cpu.color_image()), b = to_vref(gpu.color_image());
  const vref::Diff d = vref::compare(a, b);
  const std::vector<uint32_t> ia = cpu.object_ids(), ib = gpu.object_ids();
  ASSERT_EQ(ia.size(), ib.size());
  size_t same = 0, drawn = 0;
  for (size_t i = 0; i < ia.size(); ++i) same += ia[i] == ib[i], drawn += ia[i] != 0;
  const double agree = double(same) / double(ia.size());
  std::printf("[gpu-parity] %-34s psnr=%.2f max_abs=%d ids_agree=%.4f%% drawn=%zu\n", case_name(c).c_str(), d.psnr,
              d.max_abs, agree * 100, drawn);
  EXPECT_GT(drawn, ia.size() / 50) << "the frame must draw something";
  EXPECT_GE(agree, 0.995);
  if (d.psnr < c.min_psnr) {
    const std::string base = std::string(VELOCITY_GPU_OUT) + "/" + case_name(c);
    std::filesystem::create_directories(VELOCITY_GPU_OUT);
    vref::write_png(base + "_cpu.png", a), vref::write_png(base + "_gpu.png", b);
    vref::write_png(base + "_diff.png", vref::diff_image(a, b));
    ADD_FAILURE() << case_name(c) << ": PSNR " << d.psnr << " dB < " << c.min_psnr << " dB; images in " << base << "_*.png";
  }
  // Depth: the same surfaces at the same distances (window depth to float precision of
  // two different pipelines; a pixel where both drew).
  const std::vector<float> za = cpu.view_depth(), zb = gpu.view_depth();
  size_t close = 0, both = 0;
  for (size_t i = 0; i < za.size(); ++i)
    if (za[i] > 0 && zb[i] > 0) both++, close += std::abs(za[i] - zb[i]) < 1e-3f * za[i];
  // (Wireframe: where a front and a back edge cross, which one a pixel shows is a
  // near-tie, so its depth agrees on fewer pixels.)
  EXPECT_GE(double(close), (c.shade == "wire" ? 0.98 : 0.995) * double(both));
}

std::vector<ParityCase> cases() {
  const std::string obj = std::string(VELOCITY_TEST_DATA) + "/models/wuson_x4.obj";
  std::vector<ParityCase> v;
  // The golden scenes (tests/golden/test_golden.cpp), each on both backends.
  for (const std::string& mesh : {std::string("sphere:24"), std::string("sphere:64"), obj})
    for (auto [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
      v.push_back({mesh, w, h, "flat", 40.0});
      v.push_back({mesh, w, h, "gouraud", 40.0});
      v.push_back({mesh, w, h, "phong", 40.0});
      v.push_back({mesh, w, h, "tex", 35.0});
      v.push_back({mesh, w, h, "env", 35.0});
    }
  for (const char* shade : {"flat", "gouraud", "tex"}) v.push_back({"sphere:512", 1920, 1080, shade, shade[0] == 't' ? 35.0 : 40.0});
  // glTF's metallic-roughness (Shading::Pbr, a Linear frame): per-pixel BRDF, and with
  // an sRGB base colour texture.
  for (const std::string& mesh : {std::string("sphere:64"), obj})
    for (auto [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
      v.push_back({mesh, w, h, "pbr", 40.0});
      v.push_back({mesh, w, h, "pbrtex", 35.0});
    }
  v.push_back({obj, 640, 360, "pbr", 40.0, 1, 7, 12});
  v.push_back({obj, 640, 360, "gouraud", 40.0, 1, 5, 12});
  v.push_back({obj, 640, 360, "phong", 40.0, 1, 9, 12});
  // Wireframe: edges as GL lines; the CPU's lines follow GL's diamond-exit rule as Mesa
  // draws them (raster/coverage-inl.h), so the two agree but for a few ties.
  for (const std::string& mesh : {std::string("sphere:24"), std::string("sphere:64"), obj})
    v.push_back({mesh, 640, 360, "wire", 40.0});
  // Super-sampling: a larger framebuffer and the same box resolve.
  v.push_back({obj, 640, 360, "phong", 35.0, 3});
  v.push_back({"sphere:64", 320, 200, "tex", 35.0, 2});
  v.push_back({"sphere:64", 320, 200, "env", 35.0, 4});
  return v;
}

INSTANTIATE_TEST_SUITE_P(Golden, Parity, ::testing::ValuesIn(cases()), [](const auto& p) { return case_name(p.param); });

// Two renderers draw `scene` and the images must agree to `min_psnr`.
double scene_psnr(const Scene& scene, const RenderOptions& options, int w = 320, int h = 240) {
  Renderer cpu(w, h, BackendChoice::Cpu), gpu(w, h, BackendChoice::Gpu);
  cpu.options = gpu.options = options;
  cpu.render(scene), gpu.render(scene);
  return vref::compare(to_vref(cpu.color_image()), to_vref(gpu.color_image())).psnr;
}

// An asymmetric scene: a cube with per-face colours, a torus with per-face materials (one
// flat, one Phong, one textured), a sphere with vertex colours unlit, a two-sided plane
// seen from behind, under a directional and a point light.
Scene mixed_scene() {
  Scene scene;
  scene.camera.position = {0.3f, 0.4f, 4.0f};
  scene.lights.push_back(Light::directional({-0.4f, -0.6f, -1.0f}, {0.9f, 0.85f, 0.8f}));
  scene.lights.push_back(Light::point({1.5f, 1.0f, 1.5f}, {0.6f, 0.6f, 0.9f}));
  Mesh cube = make_cube(0.8f);
  for (size_t f = 0; f < cube.triangles.size(); ++f) cube.face_colors.push_back({float(f % 3) / 2, float(f % 5) / 4, 0.3f});
  Mesh torus = make_torus(0.6f, 0.25f, 24, 12);
  Material flat, phong, textured;
  flat.shading = Shading::Flat, flat.color = {0.9f, 0.3f, 0.2f};
  phong.shading = Shading::Phong, phong.color = {0.2f, 0.7f, 0.3f}, phong.specular = 0.6f, phong.shininess = 20;
  textured.shading = Shading::Gouraud, textured.color = {1, 1, 1};
  textured.texture = std::make_shared<const Texture>(make_checkerboard(64, 8));
  textured.filter = Filter::Bilinear;
  torus.materials = {flat, phong, textured};
  for (size_t f = 0; f < torus.triangles.size(); ++f) torus.face_materials.push_back(uint32_t((f / 7) % 3));
  Mesh sphere = make_sphere(24);
  for (const Vec3& p : sphere.positions) sphere.colors.push_back({0.5f + 0.5f * p.x, 0.5f + 0.5f * p.y, 0.5f - 0.5f * p.z});
  sphere.materials.push_back(Material{});
  sphere.materials[0].shading = Shading::Unlit;
  Mesh plane = make_plane_grid(1.0f, 2);
  plane.materials.push_back(Material{});
  plane.materials[0].two_sided = true, plane.materials[0].shading = Shading::Gouraud;
  plane.materials[0].specular = 0.4f;
  auto add = [&](Mesh m, Vec3 at, Vec3 turn) {
    const ObjectId id = scene.add_object(m.name, std::make_shared<const Mesh>(std::move(m)));
    scene.object(id).transform.translation = at, scene.object(id).transform.rotation = turn;
  };
  add(std::move(cube), {-1.2f, 0.6f, 0}, {0.4f, 0.7f, 0});
  add(std::move(torus), {0.9f, 0.6f, -0.3f}, {1.1f, 0.2f, 0});
  add(std::move(sphere), {-0.9f, -0.8f, 0.2f}, {0, 0.5f, 0});
  add(std::move(plane), {0.9f, -0.8f, 0}, {-1.2f, 0.3f, 0});  // its back towards the camera
  return scene;
}

TEST(GpuScenes, FaceColoursMaterialsVertexColoursTwoSided) {
  const double psnr = scene_psnr(mixed_scene(), RenderOptions{});
  std::printf("[gpu-parity] mixed scene psnr=%.2f\n", psnr);
  EXPECT_GE(psnr, 35.0);
}

TEST(GpuScenes, PaintersMode) {
  Scene scene = mixed_scene();
  // A cube through the sphere: where they cross, the sort decides, not the depth test.
  const ObjectId id = scene.add_object("through", std::make_shared<const Mesh>(make_cube(0.9f)));
  scene.object(id).transform.translation = {-0.7f, -0.7f, 0.4f}, scene.object(id).transform.rotation = {0.3f, 0.8f, 0};
  RenderOptions o;
  o.depth_mode = DepthMode::Painter;
  Renderer zbuffer(320, 240);
  zbuffer.render(scene);
  Renderer cpu(320, 240, BackendChoice::Cpu), gpu(320, 240, BackendChoice::Gpu);
  cpu.options = gpu.options = o;
  cpu.render(scene), gpu.render(scene);
  const double differs = vref::compare(to_vref(zbuffer.color_image()), to_vref(cpu.color_image())).psnr;
  const double psnr = vref::compare(to_vref(cpu.color_image()), to_vref(gpu.color_image())).psnr;
  std::printf("[gpu-parity] painter psnr=%.2f (painter against z-buffer on the CPU: %.2f)\n", psnr, differs);
  EXPECT_LT(differs, 40.0);  // the scene tells the modes apart
  EXPECT_GE(psnr, 35.0);
}

// Two GPU renderers with frames open at once on one thread: each draws into its own
// context, whatever ran in between.
TEST(GpuScenes, TwoRenderersInterleaved) {
  Mesh sphere = make_sphere(16), cube = make_cube(1.2f);
  Material red, blue;
  red.color = {0.9f, 0.2f, 0.1f}, blue.color = {0.1f, 0.3f, 0.9f}, blue.shading = Shading::Flat;
  const Mat4 turn = rotate_y(0.5f);
  Renderer a(96, 64, BackendChoice::Gpu), b(96, 64, BackendChoice::Gpu);
  Renderer ca(96, 64, BackendChoice::Cpu), cb(96, 64, BackendChoice::Cpu);
  a.begin_frame(Camera{}, {}, Vec3{0, 0, 0});
  b.begin_frame(Camera{}, {}, Vec3{1, 1, 1});
  a.draw(sphere, Mat4::identity(), &red, 1);
  b.draw(cube, turn, &blue, 2);
  b.end_frame();
  a.end_frame();
  for (auto [r, mesh, world, mat, bg] : {std::tuple{&ca, &sphere, Mat4::identity(), &red, Vec3{0, 0, 0}},
                                         std::tuple{&cb, &cube, turn, &blue, Vec3{1, 1, 1}}}) {
    r->begin_frame(Camera{}, {}, bg);
    r->draw(*mesh, world, mat, 1);
    r->end_frame();
  }
  EXPECT_GE(vref::compare(to_vref(a.color_image()), to_vref(ca.color_image())).psnr, 40.0);
  EXPECT_GE(vref::compare(to_vref(b.color_image()), to_vref(cb.color_image())).psnr, 40.0);
}

TEST(GpuScenes, AffineTexturesAndNearest) {
  RenderOptions o;
  o.affine = true, o.filter = Filter::Nearest;
  const double psnr = scene_psnr(mixed_scene(), o);
  std::printf("[gpu-parity] affine nearest psnr=%.2f\n", psnr);
  EXPECT_GE(psnr, 30.0);
}

TEST(GpuScenes, Points) {
  RenderOptions o;
  o.shading = Shading::Points;
  const double psnr = scene_psnr(mixed_scene(), o);
  std::printf("[gpu-parity] points psnr=%.2f\n", psnr);
  EXPECT_GE(psnr, 35.0);
  // A point cloud (triangles with one corner three times: never culled) at
  // RenderOptions::point_size, super-sampled too (the size is in output pixels). One
  // colour: where the mixed scene's points of different materials overlap, the GPU's
  // order (by material slot) decides which shows.
  Mesh cloud;
  cloud.positions = make_sphere(24).positions;
  for (uint32_t i = 0; i < cloud.positions.size(); ++i) cloud.triangles.push_back({i, i, i});
  Scene scene;
  scene.camera.position = {0.2f, 0.3f, 3.0f};
  scene.add_object("cloud", std::make_shared<const Mesh>(std::move(cloud)));
  o.point_size = 3.4f;  // (rounded to 3, as the CPU's)
  const double wide = scene_psnr(scene, o);
  o.ssaa = 2;
  const double wide_ssaa = scene_psnr(scene, o);
  o.ssaa = 1, o.point_size = 1;
  Renderer one(320, 240, BackendChoice::Cpu), three(320, 240, BackendChoice::Cpu);
  one.options = o, one.render(scene);
  three.options = o, three.options.point_size = 3, three.render(scene);
  const double sizes = vref::compare(to_vref(one.color_image()), to_vref(three.color_image())).psnr;
  std::printf("[gpu-parity] 3-pixel point cloud psnr=%.2f, at 2x2 super-sampling %.2f (1 against 3 pixels: %.2f)\n",
              wide, wide_ssaa, sizes);
  EXPECT_LT(sizes, 30.0) << "the size must matter";
  EXPECT_GE(wide, 40.0);
  EXPECT_GE(wide_ssaa, 40.0);
}

// The caches: a mesh and its texture are uploaded once, however many frames draw them;
// a change to the mesh's contents is seen and uploaded again.
TEST(GpuCache, UploadsOnceAndAgainOnChange) {
  gpu::GpuBackend b(64, 64, false);
  Mesh mesh = make_sphere(16);
  Material m;
  m.texture = std::make_shared<const Texture>(make_checkerboard(32, 4));
  Camera camera;
  for (int frame = 0; frame < 3; ++frame) {
    b.begin_frame(camera, {}, FrameStart{}, RenderOptions{});
    b.draw(mesh, Mat4::identity(), &m, 1);
    b.end_frame();
  }
  EXPECT_EQ(b.uploads(), 2u);  // the mesh and the texture
  mesh.positions[3].x += 0.25f;
  b.begin_frame(camera, {}, FrameStart{}, RenderOptions{});
  b.draw(mesh, Mat4::identity(), &m, 1);
  b.end_frame();
  EXPECT_EQ(b.uploads(), 3u);  // the mesh again, not the texture
}

// An in-place edit of a cached mesh (its positions, then its uvs) and of a cached
// texture (a new image at the same address) shows in the next frame: each edited frame
// is the frame a fresh backend, with nothing cached, draws of the edited scene, and
// differs from the frame before it. The fingerprints are taken on 3 threads, the
// arrays being over one chunk (1 MiB), so the chunked hash is the one checked.
TEST(GpuCache, InPlaceEditsShowInTheNextFrame) {
  Mesh mesh = make_sphere(512);  // positions over 1 MiB: more than one chunk
  ASSERT_GT(mesh.positions.size() * sizeof(Vec3), size_t(1) << 20);
  auto texture = std::make_shared<Texture>(make_checkerboard(64, 8));
  Material m;
  m.texture = texture;
  RenderOptions o;
  o.threads = 3;
  Camera camera;
  auto frame = [&](gpu::GpuBackend& b) {
    b.begin_frame(camera, {}, FrameStart{}, o);
    b.draw(mesh, rotate_y(0.4f), &m, 1);
    b.end_frame();
    return b.color_image().pixels;
  };
  gpu::GpuBackend cached(96, 80, false);
  std::vector<uint8_t> last = frame(cached);
  EXPECT_EQ(frame(cached), last);
  EXPECT_EQ(cached.uploads(), 2u);
  auto expect_edit_shows = [&](const char* what, size_t uploads) {
    SCOPED_TRACE(what);
    const std::vector<uint8_t> now = frame(cached);
    EXPECT_EQ(cached.uploads(), uploads);
    EXPECT_NE(now, last);  // the edit is visible
    gpu::GpuBackend fresh(96, 80, false);
    EXPECT_EQ(now, frame(fresh));  // and drawn as a new mesh and texture are
    last = now;
  };
  // A band of vertices past the positions' first chunk pushed out.
  const size_t first = (size_t(1) << 20) / sizeof(Vec3) + 100;
  ASSERT_LT(first + 2000, mesh.positions.size());
  for (size_t v = first; v < first + 2000; ++v) mesh.positions[v] = mesh.positions[v] * 1.3f;
  expect_edit_shows("positions", 3);
  for (Vec2& uv : mesh.uvs) uv.x = 1.0f - uv.x;  // mirrored in u
  expect_edit_shows("uvs", 4);
  *texture = Texture(make_checkerboard(64, 16));  // the same Texture object, new texels
  expect_edit_shows("texture", 5);
}

// A marked mesh (Mesh::revision) is trusted: not hashed, not uploaded again until its
// revision changes; an edit without touch() is not seen (the contract, docs/gpu.md). An
// unmarked one is hashed every frame.
TEST(GpuCache, MarkedMeshesAreNotHashed) {
  Mesh mesh = make_sphere(48);
  Material m;
  m.shading = Shading::Gouraud;
  Camera camera;
  RenderOptions o;
  auto frame = [&](gpu::GpuBackend& b) {
    b.begin_frame(camera, {}, FrameStart{}, o);
    b.draw(mesh, rotate_y(0.4f), &m, 1);
    b.end_frame();
    return b.color_image().pixels;
  };
  gpu::GpuBackend cached(96, 80, false);
  std::vector<uint8_t> last = frame(cached);
  EXPECT_EQ(cached.stats().meshes_hashed, 1u);  // unmarked
  mesh.touch();
  ASSERT_NE(mesh.revision, 0u);
  EXPECT_EQ(frame(cached), last);
  EXPECT_EQ(cached.stats().meshes_hashed, 0u);
  EXPECT_EQ(cached.uploads(), 2u);  // marked now: a new key, uploaded once
  EXPECT_EQ(frame(cached), last);
  EXPECT_EQ(cached.stats().meshes_hashed, 0u);
  EXPECT_EQ(cached.uploads(), 2u);
  // Pushed out in place without touch(): the cache keeps what it has.
  for (Vec3& p : mesh.positions) p = p * 1.2f;
  EXPECT_EQ(frame(cached), last);
  EXPECT_EQ(cached.uploads(), 2u);
  // touch(): uploaded again, and drawn as a fresh backend draws it.
  mesh.touch();
  const std::vector<uint8_t> now = frame(cached);
  EXPECT_EQ(cached.uploads(), 3u);
  EXPECT_EQ(cached.stats().meshes_hashed, 0u);
  EXPECT_NE(now, last);
  gpu::GpuBackend fresh(96, 80, false);
  EXPECT_EQ(now, frame(fresh));
  // Back to 0: hashed again, every frame.
  mesh.revision = 0;
  EXPECT_EQ(frame(cached), now);
  EXPECT_EQ(cached.stats().meshes_hashed, 1u);
}

// Loaders, library edits and animation keep the mark honest: what load_model makes is
// marked, normalize_to_unit_sphere gives a marked mesh a new revision, an unmarked one
// stays unmarked, and bench meshes are marked.
TEST(GpuCache, LibraryMarksWhatItMakesAndChanges) {
  Mesh plain = make_sphere(8);
  normalize_to_unit_sphere(plain);
  EXPECT_EQ(plain.revision, 0u);
  Mesh marked = make_sphere(8);
  marked.touch();
  const uint64_t before = marked.revision;
  normalize_to_unit_sphere(marked);
  EXPECT_NE(marked.revision, before);
  EXPECT_NE(marked.revision, 0u);
  compute_normals(marked);
  EXPECT_GT(marked.revision, before);
  EXPECT_NE(bench::make_mesh("sphere:8").revision, 0u);
  EXPECT_NE(bench::make_mesh("sphere:8").revision, bench::make_mesh("sphere:8").revision);  // never reused
}

// Every pass is timed by the GPU itself (GL_TIME_ELAPSED): shadow maps, opaque draws,
// blended draws, and the read-back of the frame before.
TEST(GpuTimers, EveryPassHasItsGpuTime) {
  Renderer r(160, 120, BackendChoice::Gpu);
  Scene scene;
  Mesh sphere = make_sphere(64);
  Material blend;
  blend.shading = Shading::Pbr, blend.alpha = 0.5f, blend.alpha_mode = AlphaMode::Blend;
  Mesh glass = make_cube(0.8f);
  glass.materials = {blend};
  scene.add_object("sphere", std::make_shared<const Mesh>(std::move(sphere)));
  const ObjectId g = scene.add_object("glass", std::make_shared<const Mesh>(std::move(glass)));
  scene.object(g).transform.translation = {0.5f, 0, 0.8f};
  scene.camera.position = {0, 0, 4};
  r.render(scene);
  FrameStats st = r.stats();
  EXPECT_GT(st.gpu_opaque_ms, 0.0);
  EXPECT_GT(st.gpu_blend_ms, 0.0);
  EXPECT_EQ(st.gpu_shadow_ms, 0.0);  // no shadows asked for
  EXPECT_EQ(st.gpu_read_ms, 0.0);    // nothing read yet
  (void)r.color_image();
  r.options.shadows = true;
  r.render(scene);
  st = r.stats();
  EXPECT_GT(st.gpu_shadow_ms, 0.0);
  EXPECT_GT(st.gpu_opaque_ms, 0.0);
  EXPECT_GT(st.gpu_read_ms, 0.0);  // the first frame's read
}

// RGBA rows are read straight from the GPU into the caller's rows, resolved on the GPU
// with super-sampling; RGB rows go through the samples and the CPU. Either way they are
// the CPU pipeline's read of the same frame (color_image), byte for byte, at a row pitch
// wider than the image.
TEST(GpuReadBack, DirectAndResolvedReadsAgree) {
  Mesh mesh = make_sphere(24);
  Material m;
  m.texture = std::make_shared<const Texture>(make_checkerboard(32, 4));
  Camera camera;
  for (int ssaa : {1, 2, 3}) {
    SCOPED_TRACE(ssaa);
    gpu::GpuBackend b(53, 37, false);
    RenderOptions o;
    o.ssaa = ssaa;
    o.threads = 2;
    for (int channels : {4, 3}) {
      b.begin_frame(camera, {}, FrameStart{}, o);
      b.draw(mesh, rotate_y(0.3f), &m, 1);
      b.end_frame();
      const size_t pitch = 53 * 4 + 12;
      std::vector<uint8_t> rows(pitch * 37, 0xAB);
      b.read_color(rows.data(), pitch, channels);  // first read of the frame
      const Image image = b.color_image();
      for (int y = 0; y < 37; ++y)
        for (int x = 0; x < 53; ++x)
          for (int c = 0; c < channels; ++c)
            ASSERT_EQ(rows[size_t(y) * pitch + size_t(x * channels + c)], image.pixels[size_t(y * 53 + x) * 4 + size_t(c)])
                << "at " << x << "," << y;
      EXPECT_EQ(rows[53 * 4 + 11], 0xAB);  // the pitch's padding untouched
    }
    b.begin_frame(camera, {}, FrameStart{}, o);
    EXPECT_GT(b.end_frame().readback_ms, 0.0);  // the reads of the frame before
  }
}

// The GLSL lighting (gpu/shaders.cpp) is the scalar model (shading/lighting.hpp): the
// same random normals, points and lights through both, by transform feedback.
TEST(GpuLighting, GlslIsTheScalarModel) {
  gpu::Context context(false);
  gpu::Current current(context);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  shading::EyeLights lights;
  lights.ambient = {0.1f, 0.15f, 0.2f};
  lights.directional.push_back({normalize(Vec3{0.3f, 0.5f, 1}), {0.9f, 0.8f, 0.7f}});
  lights.directional.push_back({normalize(Vec3{-0.7f, 0.1f, 0.2f}), {0.2f, 0.3f, 0.6f}});
  shading::EyeLights::Point point;
  point.position = {1, 2, -1}, point.color = {0.8f, 0.7f, 0.5f};
  point.constant = 1.0f, point.linear = 0.2f, point.quadratic = 0.05f;
  lights.point.push_back(point);
  // A spot light with KHR_lights_punctual's inverse square and range (lighting.hpp).
  shading::EyeLights::Point spot;
  spot.position = {-0.5f, 1.0f, -1.5f}, spot.color = {2.0f, 1.5f, 1.0f};
  spot.inverse_square = true, spot.inv_range4 = 1.0f / std::pow(4.0f, 4.0f);
  spot.spot = true, spot.spot_axis = normalize(Vec3{0.2f, -1.0f, -0.6f});
  shading::detail::spot_cone(0.3f, 0.9f, spot.spot_scale, spot.spot_offset);
  lights.point.push_back(spot);
  const shading::Specular spec(0.5f, 24.0f);
  const int n = 4096;
  std::vector<Vec3> normals(n), points(n);
  for (int i = 0; i < n; ++i) normals[size_t(i)] = normalize(Vec3{u(rng), u(rng), u(rng)}), points[size_t(i)] = {u(rng), u(rng), u(rng) - 3};

  const GLuint p = gpu::build_lighting_test_program();
  glUseProgram(p);
  auto loc = [&](const char* name) { return glGetUniformLocation(p, name); };
  glUniform3f(loc("u_ambient"), lights.ambient.x, lights.ambient.y, lights.ambient.z);
  glUniform1i(loc("u_directional_count"), 2), glUniform1i(loc("u_point_count"), 2);
  const Vec3 dir[2] = {lights.directional[0].to_light, lights.directional[1].to_light};
  const Vec3 dcol[2] = {lights.directional[0].color, lights.directional[1].color};
  glUniform3fv(loc("u_directional_to_light"), 2, &dir[0].x), glUniform3fv(loc("u_directional_color"), 2, &dcol[0].x);
  const Vec3 ppos[2] = {point.position, spot.position}, pcol[2] = {point.color, spot.color};
  const Vec3 patt[2] = {{1.0f, 0.2f, 0.05f}, {1.0f, 0.0f, 0.0f}};
  const Vec3 pfall[2] = {{0, 0, 0}, {1.0f, spot.inv_range4, 1.0f}}, paxis[2] = {{}, spot.spot_axis};
  const Vec2 pcone[2] = {{0, 1}, {spot.spot_scale, spot.spot_offset}};
  glUniform3fv(loc("u_point_position"), 2, &ppos[0].x), glUniform3fv(loc("u_point_color"), 2, &pcol[0].x);
  glUniform3fv(loc("u_point_attenuation"), 2, &patt[0].x), glUniform3fv(loc("u_point_falloff"), 2, &pfall[0].x);
  glUniform3fv(loc("u_point_spot_axis"), 2, &paxis[0].x), glUniform2fv(loc("u_point_spot_cone"), 2, &pcone[0].x);
  glUniform3f(loc("u_specular"), spec.ks, spec.exponent, spec.cutoff);
  GLuint vao, buffers[4];
  glGenVertexArrays(1, &vao), glGenBuffers(4, buffers);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, n * 12, points.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr), glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ARRAY_BUFFER, n * 12, normals.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr), glEnableVertexAttribArray(1);
  for (int k = 0; k < 2; ++k) {
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[2 + k]);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, n * 12, nullptr, GL_STATIC_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, GLuint(k), buffers[2 + k]);
  }
  // A framebuffer to be complete (a surfaceless context has none), though nothing is drawn.
  GLuint fbo, rb;
  glGenFramebuffers(1, &fbo), glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, n);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<Vec3> diffuse(n), specular(n);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[2]);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, n * 12, diffuse.data());
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[3]);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, n * 12, specular.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  float worst = 0;
  int lit_specular = 0;
  for (int i = 0; i < n; ++i) {
    const shading::LightTerms t = shading::light(lights, normals[size_t(i)], points[size_t(i)], spec);
    const Vec3 dd = t.diffuse - diffuse[size_t(i)], ds = t.specular - specular[size_t(i)];
    worst = std::max({worst, std::abs(dd.x), std::abs(dd.y), std::abs(dd.z), std::abs(ds.x), std::abs(ds.y), std::abs(ds.z)});
    lit_specular += t.specular.x > 0.01f;
  }
  glDeleteBuffers(4, buffers), glDeleteVertexArrays(1, &vao), glDeleteProgram(p);
  glDeleteFramebuffers(1, &fbo), glDeleteRenderbuffers(1, &rb);
  EXPECT_LT(worst, 2e-4f);        // float rounding apart, the same numbers (1/20 of an 8-bit step)
  EXPECT_GT(lit_specular, n / 20);  // and the highlight is exercised
}

// raster/shade_pbr-inl.h's PbrShader::shade for one point, written out in scalar form
// from the kernel, term for term (the test's reference for the GLSL's pbr_light; the
// parity scenes below hold the GLSL to the kernel itself, through whole frames).
Vec3 pbr_kernel_scalar(const shading::EyeLights& lights, Vec3 n, Vec3 view, Vec3 p, Vec3 base, float metallic,
                       float roughness, float ao) {
  const float metal = std::clamp(metallic, 0.0f, 1.0f), rough = std::clamp(roughness, 0.045f, 1.0f);
  const float a = rough * rough, a2 = a * a;
  const Vec3 cdiff = base * (1 - metal);
  const Vec3 f0 = base * metal + Vec3{1, 1, 1} * (0.04f * (1 - metal));
  const float nv = std::max(dot(n, view), 1e-4f), nv_term = std::sqrt(nv * nv * (1 - a2) + a2);
  Vec3 c = cdiff * lights.ambient * ao;
  // Multiple scattering (shading/ggx_albedo.hpp): the lobe times 1 + f0 (1 / E - 1).
  const float lost = 1 / shading::ggx_albedo(rough, nv) - 1;
  const Vec3 ms = Vec3{1, 1, 1} + f0 * lost;
  auto add = [&](Vec3 l, Vec3 radiance) {
    const float nl = dot(n, l);
    if (nl <= 0) return;
    const Vec3 h = normalize(l + view);
    const float nh = std::clamp(dot(n, h), 0.0f, 1.0f), vh = std::clamp(dot(view, h), 0.0f, 1.0f);
    const float q5 = std::pow(1 - vh, 5.0f);
    const float dn = nh * nh * (a2 - 1) + 1;
    const float dist = a2 / float(M_PI) / std::max(dn * dn, 1e-12f);
    const float den = nl * nv_term + nv * std::sqrt(nl * nl * (1 - a2) + a2);
    const float spec = 0.5f * dist / std::max(den, 1e-12f);
    const float f0c[3] = {f0.x, f0.y, f0.z}, cd[3] = {cdiff.x, cdiff.y, cdiff.z}, r[3] = {radiance.x, radiance.y, radiance.z};
    const float msc[3] = {ms.x, ms.y, ms.z};
    const float diffuse_share = 1 - (0.04f + 0.96f * q5);  // 1 - F of the dielectric
    float out[3];
    for (int k = 0; k < 3; ++k) {
      const float f = (f0c[k] + (1 - f0c[k]) * q5) * msc[k];
      out[k] = (f * spec + diffuse_share * cd[k] / float(M_PI)) * r[k] * nl;
    }
    c += Vec3{out[0], out[1], out[2]};
  };
  for (const auto& d : lights.directional) add(d.to_light, d.color);
  for (const auto& pl : lights.point) {
    Vec3 to_light;
    const float att = shading::detail::punctual(pl, p, n, to_light);
    add(to_light, pl.color * att);
  }
  return c;
}

// The GLSL's metallic-roughness BRDF against the kernel's, on 4096 random points,
// normals, views, base colours and metallic/roughness/occlusion values, under two
// directional lights, an attenuated point light and a spot light with range.
TEST(GpuLighting, PbrGlslIsTheKernelModel) {
  gpu::Context context(false);
  gpu::Current current(context);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1), u01(0, 1);
  shading::EyeLights lights;
  lights.ambient = {0.1f, 0.15f, 0.2f};
  lights.directional.push_back({normalize(Vec3{0.3f, 0.5f, 1}), {2.9f, 2.8f, 2.7f}});
  lights.directional.push_back({normalize(Vec3{-0.7f, 0.1f, 0.2f}), {0.2f, 0.3f, 0.6f}});
  shading::EyeLights::Point point;
  point.position = {1, 2, -1}, point.color = {3.8f, 3.7f, 3.5f};
  point.constant = 1.0f, point.linear = 0.2f, point.quadratic = 0.05f;
  lights.point.push_back(point);
  shading::EyeLights::Point spot;
  spot.position = {-0.5f, 1.0f, -1.5f}, spot.color = {6.0f, 5.5f, 5.0f};
  spot.inverse_square = true, spot.inv_range4 = 1.0f / std::pow(4.0f, 4.0f);
  spot.spot = true, spot.spot_axis = normalize(Vec3{0.2f, -1.0f, -0.6f});
  shading::detail::spot_cone(0.3f, 0.9f, spot.spot_scale, spot.spot_offset);
  lights.point.push_back(spot);
  const int n = 4096;
  std::vector<Vec3> points(n), normals(n), views(n), bases(n), materials(n);
  for (size_t i = 0; i < size_t(n); ++i) {
    points[i] = {u(rng), u(rng), u(rng) - 3};
    normals[i] = normalize(Vec3{u(rng), u(rng), u(rng)});
    // Views mostly facing the normal (the visible side), some grazing or behind.
    views[i] = normalize(normals[i] * (u(rng) + 0.8f) + Vec3{u(rng), u(rng), u(rng)} * 0.7f);
    bases[i] = {u01(rng), u01(rng), u01(rng)};
    // Roughness from below the kernel's clamp (0.045) to 1; metallic 0..1; occlusion.
    materials[i] = {u01(rng), u01(rng) * u01(rng), 0.3f + 0.7f * u01(rng)};
  }

  const GLuint p = gpu::build_pbr_test_program();
  glUseProgram(p);
  auto loc = [&](const char* name) { return glGetUniformLocation(p, name); };
  glUniform3f(loc("u_ambient"), lights.ambient.x, lights.ambient.y, lights.ambient.z);
  glUniform1fv(loc("u_ggx_albedo[0]"), shading::kGgxAlbedoSize * shading::kGgxAlbedoSize, shading::ggx_albedo_table());
  glUniform1i(loc("u_directional_count"), 2), glUniform1i(loc("u_point_count"), 2);
  const Vec3 dir[2] = {lights.directional[0].to_light, lights.directional[1].to_light};
  const Vec3 dcol[2] = {lights.directional[0].color, lights.directional[1].color};
  glUniform3fv(loc("u_directional_to_light"), 2, &dir[0].x), glUniform3fv(loc("u_directional_color"), 2, &dcol[0].x);
  const Vec3 ppos[2] = {point.position, spot.position}, pcol[2] = {point.color, spot.color};
  const Vec3 patt[2] = {{1.0f, 0.2f, 0.05f}, {1.0f, 0.0f, 0.0f}};
  const Vec3 pfall[2] = {{0, 0, 0}, {1.0f, spot.inv_range4, 1.0f}}, paxis[2] = {{}, spot.spot_axis};
  const Vec2 pcone[2] = {{0, 1}, {spot.spot_scale, spot.spot_offset}};
  glUniform3fv(loc("u_point_position"), 2, &ppos[0].x), glUniform3fv(loc("u_point_color"), 2, &pcol[0].x);
  glUniform3fv(loc("u_point_attenuation"), 2, &patt[0].x), glUniform3fv(loc("u_point_falloff"), 2, &pfall[0].x);
  glUniform3fv(loc("u_point_spot_axis"), 2, &paxis[0].x), glUniform2fv(loc("u_point_spot_cone"), 2, &pcone[0].x);
  GLuint vao, buffers[6];
  glGenVertexArrays(1, &vao), glGenBuffers(6, buffers);
  glBindVertexArray(vao);
  const std::vector<Vec3>* inputs[5] = {&points, &normals, &views, &bases, &materials};
  for (GLuint k = 0; k < 5; ++k) {
    glBindBuffer(GL_ARRAY_BUFFER, buffers[k]);
    glBufferData(GL_ARRAY_BUFFER, n * 12, inputs[k]->data(), GL_STATIC_DRAW);
    glVertexAttribPointer(k, 3, GL_FLOAT, GL_FALSE, 0, nullptr), glEnableVertexAttribArray(k);
  }
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[5]);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, n * 12, nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[5]);
  GLuint fbo, rb;  // (a complete framebuffer; nothing is drawn)
  glGenFramebuffers(1, &fbo), glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, n);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<Vec3> colors(n);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, n * 12, colors.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteBuffers(6, buffers), glDeleteVertexArrays(1, &vao), glDeleteProgram(p);
  glDeleteFramebuffers(1, &fbo), glDeleteRenderbuffers(1, &rb);
  // Relative above 1 (highlights of a smooth surface reach hundreds). Near the GGX peak
  // of the smoothest surfaces the denominator 1 - (N.H)^2 (1 - a^2) cancels to about a^2
  // (4e-6 at roughness 0.045), where one float step of N.H moves D by a per cent: the
  // two programs' rounding may differ there, so all points are held to 5e-3 and 99 % of
  // them to 2e-4.
  float worst = 0;
  int highlights = 0, tight = 0;
  for (size_t i = 0; i < size_t(n); ++i) {
    const Vec3 m = materials[i];
    const Vec3 want = pbr_kernel_scalar(lights, normals[i], views[i], points[i], bases[i], m.x, m.y, m.z);
    const Vec3 d = want - colors[i];
    const float scale = std::max({1.0f, want.x, want.y, want.z});
    const float e = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) / scale;
    worst = std::max(worst, e);
    tight += e < 2e-4f;
    highlights += std::max({want.x, want.y, want.z}) > 1.0f;
  }
  std::printf("[gpu-pbr] worst %.3g, %d of %d within 2e-4, %d over 1\n", worst, tight, n, highlights);
  EXPECT_LT(worst, 5e-3f);
  EXPECT_GE(tight, n * 99 / 100);
  EXPECT_GT(highlights, n / 100);  // the specular lobe is exercised
}

// Both backends draw `scene` with object ids: the images' PSNR and the share of pixels
// whose ids agree.
std::pair<double, double> scene_parity(const Scene& scene, const RenderOptions& options, int w, int h,
                                       const std::string& name) {
  Renderer cpu(w, h, BackendChoice::Cpu), gpu(w, h, BackendChoice::Gpu);
  cpu.options = gpu.options = options;
  cpu.options.object_ids = gpu.options.object_ids = true;
  cpu.render(scene), gpu.render(scene);
  const vref::Image a = to_vref(cpu.color_image()), b = to_vref(gpu.color_image());
  const double psnr = vref::compare(a, b).psnr;
  const std::vector<uint32_t> ia = cpu.object_ids(), ib = gpu.object_ids();
  size_t same = 0;
  for (size_t i = 0; i < ia.size() && i < ib.size(); ++i) same += ia[i] == ib[i];
  const double agree = ia.empty() || ia.size() != ib.size() ? 0.0 : double(same) / double(ia.size());
  std::printf("[gpu-parity] %-34s psnr=%.2f ids_agree=%.4f%%\n", name.c_str(), psnr, agree * 100);
  if (psnr < 35) {
    std::filesystem::create_directories(VELOCITY_GPU_OUT);
    const std::string base = std::string(VELOCITY_GPU_OUT) + "/" + name;
    vref::write_png(base + "_cpu.png", a), vref::write_png(base + "_gpu.png", b);
  }
  return {psnr, agree};
}

// Shadows (RenderOptions::shadows): a box and a torus on a plane, seen in perspective
// from an oblique camera, under one light of each kind, drawn by both backends in each
// shading that lights per pixel, per vertex or per face. The CPU's shadows are held to
// the scene's geometry by tests/unit/test_shadows.cpp; here the GPU's maps (its own
// depth passes) and lookup (kLightingGlsl's visibility) are held to the CPU's.
struct ShadowFrames {
  vref::Image cpu, gpu, cpu_off;
};

ShadowFrames shadow_frames(const Light& light, Shading shading, int map_size) {
  const Mesh plane = make_plane_grid(12.0f, 4), box = make_cube(2.0f), torus = make_torus(1.0f, 0.35f, 48, 24);
  Material m;
  m.color = {0.85f, 0.75f, 0.6f};
  m.shading = shading;
  m.specular = 0.3f;
  if (shading == Shading::Pbr) m.pbr.metallic = 0, m.pbr.roughness = 0.6f;
  Camera camera;
  camera.position = {4.0f, 7.5f, 9.0f};
  camera.look_at({0.5f, 0.0f, 0.0f});
  const std::vector<Light> lights = {Light::ambient({0.15f, 0.15f, 0.15f}), light};
  auto draw = [&](BackendChoice backend, bool shadows) {
    Renderer r(256, 192, backend);
    r.options.color = ColorPipeline::Display;
    r.options.shadows = shadows;
    r.options.shadow_map_size = map_size;
    r.begin_frame(camera, lights, {0, 0, 0});
    r.draw(plane, Mat4::identity(), &m);
    r.draw(box, translate({-1.0f, 1.0f, -0.5f}), &m);
    r.draw(torus, translate({2.0f, 0.6f, 1.5f}) * rotate_x(radians(60.0f)), &m);
    r.end_frame();
    return to_vref(r.color_image());
  };
  return {draw(BackendChoice::Cpu, true), draw(BackendChoice::Gpu, true), draw(BackendChoice::Cpu, false)};
}

// The two images agree to 40 dB (the floor for untextured shading; measured on
// llvmpipe: 55-86 dB): the lookup is the same arithmetic on the same kind of map, but
// each map is rasterized by its own backend, so a caster's silhouette texel may fall
// either side (the CPU's 24.8 snapping and top-left rule; the driver's subpixel grid),
// which moves a shadow's one-texel PCF ramp by up to a texel along its edges (and, in
// flat shading, may turn a whole face lit at its centroid). That the shadow is there
// is checked too: the CPU's image with shadows differs from the one without on many
// pixels, and the GPU's is below 37 dB against the one without, so the 40 dB could not
// be met without drawing the shadows.
TEST(GpuShadows, EveryLightKindMatchesTheCpu) {
  const Vec3 at{3.5f, 5.0f, 2.0f};
  Light spot = Light::spot(at, at, {40, 40, 40}, 0.7f, 0.95f);  // pointing at the origin
  spot.falloff = Falloff::InverseSquare;
  Light point = Light::point({1.0f, 4.0f, -2.5f}, {30, 30, 30});
  point.falloff = Falloff::InverseSquare;
  const Light sun = Light::directional(normalize({1.0f, 0.9f, 0.45f}), {0.8f, 0.8f, 0.8f});
  const struct {
    const char* name;
    Light light;
  } kinds[] = {{"directional", sun}, {"spot", spot}, {"point", point}};
  for (const auto& k : kinds)
    for (Shading s : {Shading::Phong, Shading::Pbr, Shading::Gouraud, Shading::Flat}) {
      const ShadowFrames f = shadow_frames(k.light, s, 1024);
      const std::string name = std::string("shadows_") + k.name + "_" + std::string(to_string(s));
      size_t shadowed = 0;
      for (size_t i = 0; i < f.cpu.rgba.size(); i += 4)
        shadowed += std::abs(int(f.cpu.rgba[i + 1]) - int(f.cpu_off.rgba[i + 1])) > 24;
      const vref::Diff d = vref::compare(f.cpu, f.gpu);
      const double without = vref::compare(f.cpu_off, f.gpu).psnr;
      std::printf("[gpu-parity] %-34s psnr=%.2f max_abs=%d (gpu against the cpu without shadows: %.2f) shadowed=%zu\n",
                  name.c_str(), d.psnr, d.max_abs, without, shadowed);
      EXPECT_GT(shadowed, size_t(500)) << name << ": the scene must have shadows";
      EXPECT_LT(without, 37.0) << name << ": the shadows must matter";
      EXPECT_GE(d.psnr, 40.0) << name;
      if (d.psnr < 40.0) {
        std::filesystem::create_directories(VELOCITY_GPU_OUT);
        const std::string base = std::string(VELOCITY_GPU_OUT) + "/" + name;
        vref::write_png(base + "_cpu.png", f.cpu), vref::write_png(base + "_gpu.png", f.gpu);
        vref::write_png(base + "_diff.png", vref::diff_image(f.cpu, f.gpu));
      }
    }
}

// The map size is checked as on the CPU.
TEST(GpuShadows, MapSizeIsChecked) {
  Renderer r(64, 48, BackendChoice::Gpu);
  r.options.shadows = true;
  r.options.shadow_map_size = 8;
  try {
    r.begin_frame(Camera{}, {}, {0, 0, 0});
    ADD_FAILURE() << "a map of 8 texels was taken";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "shadow map size 8 is out of range (16..8192)");
  }
}

// An asymmetric texture: four quadrants of different colours, a gradient in alpha
// from left to right (MASK and BLEND read it), a mark in one corner.
std::shared_ptr<const Texture> quadrant_texture(int size) {
  Image img(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const bool right = x >= size / 2, bottom = y >= size / 2;
      uint8_t* p = &img.pixels[(size_t(y) * size_t(size) + size_t(x)) * 4];
      p[0] = right ? 230 : 40, p[1] = bottom ? 210 : 60, p[2] = right != bottom ? 200 : 30;
      p[3] = uint8_t(255 * x / (size - 1));
      if (x < size / 8 && y < size / 8) p[0] = p[1] = p[2] = 255;
    }
  return std::make_shared<const Texture>(img);
}

// A texture from a function of (u, v) in [0, 1) to RGB bytes.
template <class F>
std::shared_ptr<const Texture> function_texture(int size, F f) {
  Image img(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      uint8_t* p = &img.pixels[(size_t(y) * size_t(size) + size_t(x)) * 4];
      f((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size), p);
      p[3] = 255;
    }
  return std::make_shared<const Texture>(img);
}

// glTF metallic-roughness materials with every texture (each through its own
// KHR_texture_transform), the second uv set, generated tangents, vertex colours with
// alpha, MASK and BLEND, double-sided faces seen from behind, under a directional, a
// point (inverse square, range) and a spot light.
Scene pbr_scene() {
  Scene scene;
  scene.camera.position = {0.2f, 0.5f, 4.2f};
  scene.lights.push_back(Light::ambient({0.08f, 0.08f, 0.1f}));
  scene.lights.push_back(Light::directional({-0.4f, -0.6f, -1.0f}, {2.2f, 2.0f, 1.8f}));
  Light point = Light::point({1.5f, 1.0f, 1.5f}, {6, 6, 9});
  point.falloff = Falloff::InverseSquare, point.range = 6;
  scene.lights.push_back(point);
  Light spot = Light::spot({-1.5f, 2.0f, 2.0f}, {-1.5f, 2.0f, 2.0f}, {14, 12, 10}, 0.2f, 0.5f);
  spot.falloff = Falloff::InverseSquare;
  scene.lights.push_back(spot);

  const auto base = quadrant_texture(64);
  const auto mr = function_texture(64, [](float u, float v, uint8_t* p) {
    p[0] = 0, p[1] = uint8_t(40 + 215 * v), p[2] = uint8_t(255 * u);  // G roughness, B metallic
  });
  const auto bumps = function_texture(64, [](float u, float v, uint8_t* p) {
    const float x = std::sin(u * 6.2832f * 4) * 0.5f, y = std::cos(v * 6.2832f * 3) * 0.4f;
    const float l = std::sqrt(1 + x * x + y * y);
    p[0] = uint8_t(127.5f + 127.5f * x / l), p[1] = uint8_t(127.5f + 127.5f * y / l), p[2] = uint8_t(127.5f + 127.5f / l);
  });
  const auto occlusion = function_texture(32, [](float u, float v, uint8_t* p) { p[0] = uint8_t(255 * (0.3f + 0.7f * u * v)); p[1] = p[2] = 0; });
  const auto glow = function_texture(32, [](float u, float v, uint8_t* p) {
    const bool on = (int(u * 4) + int(v * 4)) % 2;
    p[0] = on ? 255 : 0, p[1] = on ? 120 : 0, p[2] = 0;
  });

  // A sphere with all five textures, each its own transform.
  Mesh sphere = make_sphere(48);
  Material a;
  a.shading = Shading::Pbr, a.color = {1, 0.9f, 0.8f}, a.texture = base, a.filter = Filter::Trilinear;
  a.texture_uv.offset = {0.1f, 0.05f}, a.texture_uv.rotation = 0.3f, a.texture_uv.scale = {2, 1};
  a.pbr.metallic = 0.9f, a.pbr.roughness = 0.8f;
  a.pbr.metallic_roughness = {mr, {}, {}};
  a.pbr.metallic_roughness.uv.scale = {1, 2};
  a.pbr.normal = {bumps, {}, {}};
  a.pbr.normal.uv.rotation = 1.5708f, a.pbr.normal.uv.offset = {0, 1};
  a.pbr.normal_scale = 0.8f;
  a.pbr.occlusion = {occlusion, {}, {}};
  a.pbr.occlusion_strength = 0.7f;
  a.pbr.emissive = {0.6f, 0.5f, 0.4f};
  a.pbr.emissive_map = {glow, {}, {}};
  a.pbr.emissive_map.uv.scale = {3, 3};
  sphere.materials = {a};
  // A torus on its second uv set, cut out by the texture's alpha (MASK), double-sided.
  Mesh torus = make_torus(0.6f, 0.25f, 32, 16);
  for (const Vec2& uv : torus.uvs) torus.uvs1.push_back({uv.y * 2, uv.x});
  Material b;
  b.shading = Shading::Pbr, b.color = {0.9f, 0.9f, 1}, b.texture = base, b.filter = Filter::Bilinear;
  b.texture_uv.uv_set = 1, b.texture_uv.rotation = -0.4f;
  b.alpha_mode = AlphaMode::Mask, b.alpha_cutoff = 0.45f, b.two_sided = true;
  b.pbr.metallic = 0.1f, b.pbr.roughness = 0.35f;
  b.pbr.normal = {bumps, {}, {}};
  b.pbr.normal.uv.uv_set = 1;
  torus.materials = {b};
  // A cube with vertex colours and alphas, blended, and a blended quad behind it.
  Mesh cube = make_cube(0.7f);
  for (const Vec3& p : cube.positions) {
    cube.colors.push_back({0.5f + 0.7f * p.x, 0.5f + 0.7f * p.y, 0.5f - 0.7f * p.z});
    cube.alphas.push_back(0.4f + 0.5f * (p.x + 0.35f));
  }
  Material c;
  c.shading = Shading::Pbr, c.color = {1, 1, 1}, c.alpha = 0.9f, c.alpha_mode = AlphaMode::Blend;
  c.pbr.metallic = 0.0f, c.pbr.roughness = 0.5f;
  cube.materials = {c};
  Mesh quad = make_plane_grid(1.6f, 2);
  Material d;
  d.shading = Shading::Pbr, d.color = {0.2f, 0.4f, 0.9f}, d.alpha = 0.5f, d.alpha_mode = AlphaMode::Blend, d.two_sided = true;
  d.pbr.metallic = 0, d.pbr.roughness = 0.9f, d.pbr.unlit = true;
  quad.materials = {d};
  auto add = [&](Mesh m, Vec3 at, Vec3 turn) {
    const ObjectId id = scene.add_object(m.name, std::make_shared<const Mesh>(std::move(m)));
    scene.object(id).transform.translation = at, scene.object(id).transform.rotation = turn;
  };
  add(std::move(sphere), {-1.0f, 0.5f, 0}, {0.3f, 0.8f, 0});
  add(std::move(torus), {1.0f, 0.6f, -0.3f}, {2.2f, 0.2f, 0});  // partly its inside towards the camera
  add(std::move(quad), {0.3f, -0.5f, -1.2f}, {1.2f, 0, 0});
  add(std::move(cube), {-0.3f, -0.8f, 0.4f}, {0.5f, 0.6f, 0});
  return scene;
}

TEST(GpuPbr, TexturedMaterialsAlphaLightsToneMaps) {
  const Scene scene = pbr_scene();
  RenderOptions o;
  auto check = [&](const std::string& name) {
    const auto [psnr, agree] = scene_parity(scene, o, 480, 320, name);
    EXPECT_GE(psnr, 35.0) << name;
    EXPECT_GE(agree, 0.995) << name;
  };
  check("pbr_scene");
  o.tone_map = ToneMap::Aces, o.exposure = 1.6f;
  check("pbr_scene_aces");
  o.tone_map = ToneMap::KhronosNeutral, o.exposure = 0.7f;
  check("pbr_scene_neutral");
  o.tone_map = ToneMap::None, o.exposure = 1, o.ssaa = 2;
  check("pbr_scene_ssaa2");
  o.ssaa = 1, o.color = ColorPipeline::Display;  // PBR lit in the 8-bit values as they are
  check("pbr_scene_display");
}

// Untextured PBR (the 40 dB class): the same scene with its textures taken away.
TEST(GpuPbr, UntexturedMaterials) {
  Scene scene = pbr_scene();
  for (size_t i = 0; i < scene.objects().size(); ++i) {
    auto mesh = std::make_shared<Mesh>(*scene.object(ObjectId(i)).mesh);
    for (Material& m : mesh->materials) {
      m.texture = nullptr, m.pbr.metallic_roughness = {}, m.pbr.normal = {}, m.pbr.occlusion = {}, m.pbr.emissive_map = {};
      if (m.alpha_mode == AlphaMode::Mask) m.alpha_mode = AlphaMode::Opaque;
    }
    scene.object(ObjectId(i)).mesh = mesh;
  }
  const auto [psnr, agree] = scene_parity(scene, RenderOptions{}, 480, 320, "pbr_untextured");
  EXPECT_GE(psnr, 40.0);
  EXPECT_GE(agree, 0.995);
}

// The seed's shading modes in a Linear frame: sRGB-decoded colours and textures, light
// in linear, the output exposed, tone mapped and encoded.
TEST(GpuPbr, SeedModesInALinearFrame) {
  for (const char* shade : {"flat", "gouraud", "phong", "tex", "env"}) {
    auto look = bench::make_look(shade);
    ASSERT_TRUE(look.has_value());
    Scene scene;
    scene.lights.push_back(Light::directional({-0.4f, -0.6f, -1.0f}, {1.2f, 1.1f, 1.0f}));
    Mesh sphere = make_sphere(48);
    for (size_t i = 0; i < sphere.positions.size(); ++i)
      if (std::string(shade) == "gouraud") sphere.colors.push_back({0.2f + 0.6f * sphere.uvs[i].x, 0.5f, 0.8f});
    sphere.materials = {look->material};
    scene.add_object("sphere", std::make_shared<const Mesh>(std::move(sphere)));
    RenderOptions o = look->options;
    o.color = ColorPipeline::Linear, o.tone_map = ToneMap::Aces, o.exposure = 1.3f;
    const auto [psnr, agree] = scene_parity(scene, o, 320, 240, std::string("linear_") + shade);
    const bool textured = shade[0] == 't' || shade[0] == 'e';
    EXPECT_GE(psnr, textured ? 35.0 : 40.0) << shade;
    EXPECT_GE(agree, 0.995) << shade;
  }
}

#ifdef VELOCITY_GPU_REALTIME
// `velocity view|fly|drive --backend gpu`: the real-time loop with the GPU backend
// renders offscreen and shows the read-back frame. The same scripted frames (a fixed
// step) on both backends, recorded as PNGs, agree as the parity scenes do.
TEST(GpuRealtime, ViewFlyDriveFramesMatchTheCpu) {
  const std::string dir = std::string(VELOCITY_GPU_OUT) + "/realtime";
  auto run = [&](const std::string& name, BackendChoice backend) {
    std::unique_ptr<realtime::Program> program;
    if (name == "view") program = std::make_unique<realtime::ViewerProgram>(realtime::ViewerOptions{});
    else if (name == "fly") program = std::make_unique<realtime::FlyProgram>();
    else program = std::make_unique<realtime::DriveProgram>();
    realtime::LoopOptions o;
    o.width = 320, o.height = 240, o.frames = 4, o.fixed_step = true, o.overlay = false, o.quiet = true;
    o.backend = backend;
    o.record_dir = dir + "/" + name + (backend == BackendChoice::Gpu ? "_gpu" : "_cpu");
    std::filesystem::remove_all(o.record_dir);
    realtime::run_loop(*program, nullptr, o);
    return o.record_dir;
  };
  for (const std::string name : {"view", "fly", "drive"}) {
    const std::string cpu = run(name, BackendChoice::Cpu), gpu = run(name, BackendChoice::Gpu);
    for (int frame = 0; frame < 4; ++frame) {
      char file[32];
      std::snprintf(file, sizeof file, "/frame_%05d.png", frame);
      const vref::Image a = to_vref(read_image(cpu + file)), b = to_vref(read_image(gpu + file));
      const vref::Diff d = vref::compare(a, b);
      std::printf("[gpu-parity] %s frame %d psnr=%.2f\n", name.c_str(), frame, d.psnr);
      // (Their scenes are textured: the textured threshold.)
      EXPECT_GE(d.psnr, 35.0) << name << " frame " << frame;
    }
  }
}
#endif  // VELOCITY_GPU_REALTIME

// `auto` never takes a software OpenGL: on llvmpipe it draws on the CPU and says why.
TEST(BackendChoice, AutoRefusesSoftwareGl) {
  Renderer r(32, 32, BackendChoice::Auto);
  const std::string reason = r.stats().backend_reason;
  if (std::string(r.stats().backend) == "gpu") {
    EXPECT_FALSE(gpu::is_software_renderer(reason)) << reason;
  } else {
    EXPECT_NE(reason.find("auto: "), std::string::npos) << reason;
    gpu::Context software(false);  // a GL there is: then it must be a software one that was refused
    EXPECT_TRUE(software.software()) << software.description();
    EXPECT_NE(reason.find("software"), std::string::npos) << reason;
  }
  r.render(Scene{});
  EXPECT_EQ(std::string(r.stats().backend_reason), reason);  // kept across frames
}

// The windowed path's API (docs/gpu.md, "In a window"): only a renderer made on a
// window's context presents; a context that cannot be bound is an error naming why.
TEST(BackendChoice, WindowContextErrors) {
  Renderer cpu(16, 16);
  EXPECT_THROW(cpu.present_window(64, 64), Error);
  Renderer gpu(16, 16, BackendChoice::Gpu);
  gpu.render(Scene{});
  try {
    gpu.present_window(64, 64);
    ADD_FAILURE() << "an offscreen GPU renderer presented";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not made on a window's OpenGL context"), std::string::npos) << e.what();
  }
  struct Unbindable final : GlContextProvider {
    bool make_current(std::string& error) override {
      error = "test: no such window";
      return false;
    }
    bool is_current() const override { return false; }
    std::string name() const override { return "test context"; }
  } unbindable;
  try {
    Renderer windowed(16, 16, unbindable);
    ADD_FAILURE() << "a renderer was made on a context that cannot be bound";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("could not be made current (test: no such window)"), std::string::npos)
        << e.what();
  }
}

TEST(BackendChoice, NamesAndStats) {
  EXPECT_EQ(parse_backend("gpu"), BackendChoice::Gpu);
  EXPECT_EQ(parse_backend("GPU"), std::nullopt);
  Renderer cpu(16, 16);
  EXPECT_STREQ(cpu.stats().backend, "cpu");
  EXPECT_STREQ(cpu.stats().backend_reason, "asked for");
  Renderer gpu(16, 16, BackendChoice::Gpu);
  EXPECT_STREQ(gpu.stats().backend, "gpu");
  EXPECT_NE(std::string(gpu.stats().backend_reason).find("OpenGL"), std::string::npos);
}

// Real files: the seeds' 3D Studio ASC and PLG models (../shared/data), as `velocity
// render` shows them (scene_from_model), Z-buffered and Gouraud, and in painter's mode
// flat (seed 001's look), on both backends.
TEST(GpuScenes, RealModels) {
  const std::filesystem::path root = std::filesystem::path(VELOCITY_SHARED_DATA) / "models";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << root << " is absent";
  int files = 0;
  for (const char* folder : {"asc", "plg"})
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      Scene scene;
      try {
        scene = scene_from_model(entry.path().string(), LoadOptions{}, false, 4.0f / 3.0f);
      } catch (const Error&) {
        continue;  // (the corpus holds files the loaders refuse on purpose)
      }
      for (DepthMode mode : {DepthMode::ZBuffer, DepthMode::Painter}) {
        RenderOptions o;
        o.depth_mode = mode;
        if (mode == DepthMode::Painter) o.shading = Shading::Flat;
        const double psnr = scene_psnr(scene, o, 320, 240);
        EXPECT_GE(psnr, mode == DepthMode::Painter ? 40.0 : 35.0) << entry.path() << (mode == DepthMode::Painter ? " painter" : "");
        std::printf("[gpu-parity] %-24s %-8s psnr=%.2f\n", entry.path().filename().c_str(),
                    mode == DepthMode::Painter ? "painter" : "zbuffer", psnr);
      }
      files++;
    }
  EXPECT_GT(files, 10);
}

// pGL's path: pre-transformed batches with fixed-function pixel state, on both
// backends. Asymmetric on purpose: every primitive is placed off-centre and coloured
// per vertex, so that a flip or a swapped channel shows.
struct BatchScene {
  std::vector<Vec4> position, color, texcoord;
  std::vector<float> fog;
  std::shared_ptr<const Texture> texture = std::make_shared<const Texture>(make_checkerboard(16, 4));

  // A quad (two triangles) from (x0, y0) to (x1, y1) in NDC at depth z.
  void quad(float x0, float y0, float x1, float y1, float z, Vec4 c0, Vec4 c1) {
    const Vec4 p[4] = {{x0, y0, z, 1}, {x1, y0, z, 1}, {x1, y1, z, 1}, {x0, y1, z, 1}};
    const Vec4 t[4] = {{0, 0, 0, 1}, {2, 0, 0, 1}, {2, 2, 0, 1}, {0, 2, 0, 1}};
    for (int i : {0, 1, 2, 0, 2, 3}) {
      position.push_back(p[i]), texcoord.push_back(t[i]);
      color.push_back(i < 2 ? c0 : c1), fog.push_back(float(i) * 0.5f);
    }
  }

  BatchScene() {
    quad(-0.9f, -0.8f, 0.2f, 0.6f, 0.2f, {1, 0.2f, 0.1f, 1}, {0.1f, 0.9f, 0.3f, 0.5f});        // 0: opaque
    quad(-0.3f, -0.5f, 0.8f, 0.9f, 0.4f, {0.9f, 0.9f, 0.2f, 0.3f}, {0.2f, 0.3f, 1, 0.8f});      // 6: blended, behind
    quad(-0.95f, 0.65f, 0.95f, 0.95f, 0.0f, {1, 1, 1, 1}, {0.5f, 0.5f, 1, 1});                  // 12: textured, fog
    quad(0.3f, -0.95f, 0.95f, -0.2f, -0.1f, {0.8f, 0.4f, 0.9f, 0.2f}, {0.8f, 0.4f, 0.9f, 0.9f});  // 18: alpha test, scissor
    quad(-0.6f, -0.2f, 0.6f, 0.1f, 0.1f, {0, 1, 1, 1}, {1, 0, 1, 1});                          // 24: masked
    quad(-0.7f, -0.6f, -0.1f, 0.2f, 0.2f, {0, 0, 0, 1}, {1, 1, 1, 1});                        // 30: on quad 0, offset
  }

  // (The arrays stay unchanged until end_frame: the CPU backend reads them there.)
  void draw(Renderer& r) {
    r.begin_frame(Camera{}, {}, Vec3{0.2f, 0.1f, 0.3f});
    PrimitiveBatch b;
    PixelState s;
    auto submit = [&](size_t first, size_t count, const PixelState& st, PrimitiveKind kind = PrimitiveKind::Triangles) {
      b.kind = kind, b.position = &position[first], b.color = &color[first], b.texcoord = &texcoord[first];
      b.fog = &fog[first], b.vertex_count = uint32_t(count);
      r.draw(b, st);
    };
    submit(0, 6, s);
    PixelState blend = s;
    blend.blend = true, blend.blend_src_rgb = blend.blend_src_alpha = BlendFactor::SrcAlpha;
    blend.blend_dst_rgb = blend.blend_dst_alpha = BlendFactor::OneMinusSrcAlpha;
    submit(6, 6, blend);
    PixelState tex = s;
    tex.texture.texture = texture.get();
    tex.texture.sampler.mag = tex.texture.sampler.min = SamplerState::Texel::Nearest;
    tex.texture.sampler.mip = SamplerState::Mip::None;
    tex.fog = true, tex.fog_mode = FogMode::Linear, tex.fog_start = 0, tex.fog_end = 3, tex.fog_color = {0.6f, 0.6f, 0.7f, 1};
    submit(12, 6, tex);
    PixelState cut = s;
    cut.alpha_test = true, cut.alpha_func = CompareFunc::Greater, cut.alpha_ref = 0.5f;
    cut.scissor = true, cut.scissor_x0 = 40, cut.scissor_y0 = 30, cut.scissor_x1 = 150, cut.scissor_y1 = 110;
    submit(18, 6, cut);
    PixelState mask = s;
    mask.color_mask = 0x5, mask.depth_write = false, mask.depth_func = CompareFunc::LessEqual;
    submit(24, 6, mask);
    PixelState offset = s;  // in quad 0's plane: shown only by the offset towards the eye
    offset.polygon_offset = true, offset.offset_units = -2;
    submit(30, 6, offset);
    PixelState points = s;  // quad 18's corners, 3 pixels wide, not depth tested
    points.depth_test = false;
    b.point_size = 3;
    submit(18, 6, points, PrimitiveKind::Points);
    r.end_frame();
  }
};

// pGL's stencil buffer and user clip planes on both backends, super-sampled (the read
// functions resolve the samples): a clear to 3 under a mask, a scissored clear, quads
// that replace, increment and invert it where the stencil test passes (one failing
// its depth test), one drawn only where the stencil is 3, and a quad and a point set
// clipped by two planes. The stencil values agree exactly; the images to 40 dB (edges).
TEST(GpuBatches, StencilAndClipPlanesMatchTheCpu) {
  BatchScene scene;
  std::vector<float> clip;  // per vertex: x + 0.3 >= 0 and 0.7 - y - 0.5 x >= 0
  for (const Vec4& p : scene.position) clip.push_back(p.x + 0.3f), clip.push_back(0.7f - p.y - 0.5f * p.x);
  auto draw = [&](Renderer& r) {
    r.options.ssaa = 2;
    FrameStart start;
    start.color = {0.1f, 0.2f, 0.3f, 1}, start.stencil = 3;
    r.begin_frame(Camera{}, {}, start);
    ClearRequest c;
    c.color = c.depth = false, c.stencil = true, c.stencil_value = 0x41, c.stencil_mask = 0x0f;
    c.scissor = true, c.x0 = 10, c.y0 = 20, c.x1 = 90, c.y1 = 70;
    r.clear(c);
    PrimitiveBatch b;
    auto submit = [&](size_t first, size_t count, const PixelState& st, bool clipped = false,
                      PrimitiveKind kind = PrimitiveKind::Triangles) {
      b.kind = kind, b.position = &scene.position[first], b.color = &scene.color[first];
      b.vertex_count = uint32_t(count);
      b.clip_planes = clipped ? 2 : 0, b.clip_distance = clipped ? &clip[first * 2] : nullptr;
      r.draw(b, st);
    };
    PixelState replace;
    replace.stencil_test = true, replace.stencil_func = CompareFunc::Always, replace.stencil_ref = 7;
    replace.stencil_pass = StencilOp::Replace;
    submit(0, 6, replace);
    PixelState incr = replace;
    incr.stencil_func = CompareFunc::Equal, incr.stencil_ref = 3, incr.stencil_value_mask = 0x0f;
    incr.stencil_fail = StencilOp::IncrementWrap, incr.stencil_pass = StencilOp::Increment;
    incr.stencil_depth_fail = StencilOp::Invert, incr.stencil_write_mask = 0x3f;
    submit(6, 6, incr);  // behind quad 0 where they overlap: its depth fails there
    PixelState only = incr;
    only.stencil_func = CompareFunc::Equal, only.stencil_ref = 4, only.stencil_value_mask = 0xff;
    only.stencil_fail = only.stencil_depth_fail = only.stencil_pass = StencilOp::Keep;
    only.depth_test = false;
    submit(12, 6, only);
    PixelState plain;
    submit(24, 6, plain, true);
    b.point_size = 3;
    submit(18, 6, plain, true, PrimitiveKind::Points);
    r.end_frame();
  };
  Renderer cpu(160, 120, BackendChoice::Cpu), gpu(160, 120, BackendChoice::Gpu);
  draw(cpu), draw(gpu);
  std::vector<uint8_t> sa(160 * 120), sb(160 * 120);
  cpu.read_stencil(sa.data()), gpu.read_stencil(sb.data());
  size_t same = 0, values[256] = {};
  for (size_t i = 0; i < sa.size(); ++i) same += sa[i] == sb[i], values[sa[i]]++;
  size_t kinds = 0;
  for (size_t v : values) kinds += v > 0;
  const vref::Diff d = vref::compare(to_vref(cpu.color_image()), to_vref(gpu.color_image()));
  std::printf("[gpu-parity] stencil and clip planes psnr=%.2f stencil agrees on %zu of %zu, %zu values\n", d.psnr, same,
              sa.size(), kinds);
  EXPECT_GE(kinds, size_t(4)) << "the scene must write several stencil values";
  // (A sample on a quad's edge may go either way: a few pixels.)
  EXPECT_GE(same, sa.size() - sa.size() / 200);
  EXPECT_GE(d.psnr, 40.0);
}

TEST(GpuBatches, FixedFunctionStateMatchesTheCpu) {
  BatchScene scene;
  Renderer cpu(200, 150, BackendChoice::Cpu), gpu(200, 150, BackendChoice::Gpu);
  scene.draw(cpu);
  BatchScene again;
  again.draw(gpu);
  const vref::Image a = to_vref(cpu.color_image()), b = to_vref(gpu.color_image());
  const vref::Diff d = vref::compare(a, b);
  std::printf("[gpu-parity] batches psnr=%.2f max_abs=%d\n", d.psnr, d.max_abs);
  if (d.psnr < 35.0) {
    std::filesystem::create_directories(VELOCITY_GPU_OUT);
    vref::write_png(std::string(VELOCITY_GPU_OUT) + "/batches_cpu.png", a);
    vref::write_png(std::string(VELOCITY_GPU_OUT) + "/batches_gpu.png", b);
  }
  EXPECT_GE(d.psnr, 35.0);
  const std::vector<float> za = cpu.window_depth(), zb = gpu.window_depth();
  size_t close = 0;
  for (size_t i = 0; i < za.size(); ++i) close += std::abs(za[i] - zb[i]) < 1e-4f;
  EXPECT_GE(double(close), 0.99 * double(za.size()));
}

// Errors, not crashes: sizes the GPU backend cannot hold.
TEST(GpuErrors, ClearMessages) {
  Renderer r(16, 16, BackendChoice::Gpu);
  EXPECT_THROW(r.resize(0, 10), Error);
  r.options.ssaa = 5;
  EXPECT_THROW(r.render(Scene{}), Error);
  r.options.ssaa = 1;
  r.render(Scene{});
  EXPECT_EQ(r.width(), 16);

  // A texture wider than the device takes: an error that says so, and the renderer
  // goes on drawing.
  GLint max = 0;
  {
    gpu::Context c(false);
    gpu::Current current(c);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  }
  Image wide(max + 1, 1, 0xffc8c8c8u);
  Material m;
  m.texture = std::make_shared<const Texture>(wide);
  Mesh mesh = make_sphere(8);
  r.begin_frame(Camera{}, {}, Vec3{});
  try {
    r.draw(mesh, Mat4::identity(), &m, 1);
    ADD_FAILURE() << "a texture over GL_MAX_TEXTURE_SIZE was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the GPU takes"), std::string::npos) << e.what();
  }
  r.end_frame();

  // The same texture as part of a PBR material: the same error, at the draw.
  Material pbr;
  pbr.shading = Shading::Pbr;
  pbr.pbr.occlusion.texture = m.texture;
  r.begin_frame(Camera{}, {}, Vec3{});
  try {
    r.draw(mesh, Mat4::identity(), &pbr, 1);
    ADD_FAILURE() << "an occlusion texture over GL_MAX_TEXTURE_SIZE was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the GPU takes"), std::string::npos) << e.what();
  }
  r.end_frame();

  // More lights than the program holds.
  std::vector<Light> lights(40, Light::directional({0, 0, -1}, {0.01f, 0.01f, 0.01f}));
  EXPECT_THROW(r.begin_frame(Camera{}, lights, Vec3{}), Error);
  r.render(Scene{});  // and the next frame is fine
}

// GPU memory is bounded: a mesh or texture over the budget (here 2 MiB, set by
// VELOCITY_GPU_MEMORY_MB), or a frame whose meshes and textures together are, is an
// error that names what and how much; the renderer goes on drawing frames that fit.
TEST(GpuErrors, MemoryBudget) {
  setenv("VELOCITY_GPU_MEMORY_MB", "2", 1);
  std::unique_ptr<Renderer> made;
  try {
    made = std::make_unique<Renderer>(64, 48, BackendChoice::Gpu);
  } catch (...) {
    unsetenv("VELOCITY_GPU_MEMORY_MB");
    throw;
  }
  unsetenv("VELOCITY_GPU_MEMORY_MB");
  Renderer& r = *made;
  auto error_of = [&](auto&& frame) -> std::string {
    try {
      frame();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  // An 80 601-vertex sphere: 4.3 MiB.
  Mesh big = make_sphere(400);
  big.name = "big sphere";
  std::string e = error_of([&] {
    r.begin_frame(Camera{}, {}, Vec3{});
    r.draw(big, Mat4::identity(), nullptr, 1);
  });
  r.end_frame();
  EXPECT_NE(e.find("mesh 'big sphere' needs 5 MiB of GPU memory, more than the GPU backend's budget of 2 MiB "
                   "(VELOCITY_GPU_MEMORY_MB)"),
            std::string::npos)
      << e;
  // A 1024x1024 texture and its mip levels: 5.3 MiB (said when the frame uploads it).
  Material textured;
  textured.texture = std::make_shared<const Texture>(make_checkerboard(1024, 64));
  Mesh small = make_sphere(16);
  e = error_of([&] {
    r.begin_frame(Camera{}, {}, Vec3{});
    r.draw(small, Mat4::identity(), &textured, 1);
    r.end_frame();
  });
  EXPECT_NE(e.find("a 1024x1024 texture needs 6 MiB of GPU memory, more than the GPU backend's budget of 2 MiB"),
            std::string::npos)
      << e;
  // Two meshes of 1.1 MiB each fit alone, not together.
  Mesh a = make_sphere(200), b = make_sphere(201);
  a.name = "a", b.name = "b";
  e = error_of([&] {
    r.begin_frame(Camera{}, {}, Vec3{});
    r.draw(a, Mat4::identity(), nullptr, 1);
    r.draw(b, Mat4::identity(), nullptr, 2);
  });
  r.end_frame();
  EXPECT_NE(e.find("the frame's meshes and textures need over 3 MiB of GPU memory (at mesh 'b')"), std::string::npos) << e;
  // Frames that fit draw (and one mesh after the other is fine: the cache is trimmed).
  for (const Mesh* m : {&a, &b, &small}) {
    r.begin_frame(Camera{}, {}, Vec3{});
    r.draw(*m, Mat4::identity(), nullptr, 1);
    r.end_frame();
    EXPECT_GT(r.stats().triangles, 0u);
  }
  // A budget that is not a number is refused, naming the variable.
  setenv("VELOCITY_GPU_MEMORY_MB", "lots", 1);
  e = error_of([&] { Renderer bad(8, 8, BackendChoice::Gpu); });
  unsetenv("VELOCITY_GPU_MEMORY_MB");
  EXPECT_NE(e.find("VELOCITY_GPU_MEMORY_MB: expected a number of MiB"), std::string::npos) << e;
}

}  // namespace
