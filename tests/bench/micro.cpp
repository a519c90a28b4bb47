// velocity_micro: Google Benchmark micro-benchmarks of the pipeline's stages, one at a
// time, on the benchmark convention's sphere at 1920x1080:
//
//   VertexStage        transform, project, snap and light a mesh's vertices
//   TriangleFirstPass  the triangle stage's SIMD culling pass over a million triangles
//   SetUp              set-up of the triangles that survive it (edges, planes, records)
//   Binning            records into tile lists
//   PixelLoop/<mode>   a screen-filling quad through every shading kernel: pixels/s
//   Frame/<scene>      whole frames, for reference
//
//   build/tests/bench/velocity_micro [--benchmark_filter=...] [--benchmark_min_time=...]
//
// Times are the machine's, this run's: compare stages and versions, not machines.
#include <benchmark/benchmark.h>

#include <vector>

#include "triangle/cull.hpp"
#include "geometry/vertex_stage.hpp"
#include "raster/bins.hpp"
#include "triangle/setup.hpp"
#include "velocity/bench_scene.hpp"
#include "velocity/renderer.hpp"

namespace {

using namespace velocity;

constexpr int kW = 1920, kH = 1080;

// The convention's camera and light, and the vertex stage's inputs for a mesh.
struct Stage {
  Mesh mesh;
  shading::EyeLights lights;
  geometry::MeshVertexJob job;
  std::vector<geometry::ProjectedVertex> projected;
  std::vector<uint32_t> codes;
  std::vector<Vec3> color;
  Vec3 base{0.8f, 0.7f, 0.6f};

  explicit Stage(int segments) : mesh(bench::make_mesh("sphere:" + std::to_string(segments))) {
    Camera cam;
    const Mat4 view = cam.view(), proj = cam.projection_matrix(float(kW) / float(kH));
    shading::eye_lights(view, {}, lights);  // no lights: the convention's
    const size_t n = mesh.positions.size();
    projected.resize(n), codes.resize(n), color.resize(n);
    job.positions = mesh.positions.data(), job.normals = mesh.normals.data();
    job.begin = 0, job.end = n;
    job.model_view = view * rotate_y(0.3f);
    job.mvp = proj * job.model_view;
    job.normal_matrix = normal_matrix(job.model_view);
    job.viewport = {kW * 0.5f, 0, kH * 0.5f, float(kH), 0.5f, 0.5f, geometry::GuardBand::for_viewport(kW, kH)};
    job.lights = &lights;
    job.base_color = &base;
    job.out.projected = projected.data(), job.out.codes = codes.data(), job.out.diffuse = color.data();
  }
};

void VertexStage(benchmark::State& state) {
  Stage s(int(state.range(0)));
  for (auto _ : state) geometry::transform_mesh_vertices(s.job);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.mesh.positions.size()));
}
BENCHMARK(VertexStage)->Arg(256)->Arg(1024);

triangle::CullJob cull_job(const Stage& s) {
  triangle::CullJob job;
  job.triangles = s.mesh.triangles.data(), job.begin = 0, job.end = uint32_t(s.mesh.triangles.size());
  job.projected = s.projected.data(), job.codes = s.codes.data();
  job.x1 = kW - 1, job.y1 = kH - 1;
  return job;
}

void TriangleFirstPass(benchmark::State& state) {
  Stage s(int(state.range(0)));
  geometry::transform_mesh_vertices(s.job);
  const triangle::CullJob job = cull_job(s);
  std::vector<uint32_t> direct(job.end), info(job.end), clip(job.end);
  for (auto _ : state) {
    size_t nd, nc;
    triangle::CullCounts counts;
    triangle::cull_triangles(job, direct.data(), info.data(), nd, clip.data(), nc, counts);
    benchmark::DoNotOptimize(nd);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(job.end));
}
BENCHMARK(TriangleFirstPass)->Arg(256)->Arg(1024);

// The survivors of the first pass, set up into records (and, with binning, binned).
void SetUpAndBin(benchmark::State& state, bool bin) {
  Stage s(int(state.range(0)));
  geometry::transform_mesh_vertices(s.job);
  const triangle::CullJob job = cull_job(s);
  std::vector<uint32_t> direct(job.end), info(job.end), clip(job.end);
  size_t nd, nc;
  triangle::CullCounts counts;
  triangle::cull_triangles(job, direct.data(), info.data(), nd, clip.data(), nc, counts);
  raster::Bins bins;
  bins.resize(kW, kH, 1);
  geometry::SetupParams p;
  p.x1 = p.px1 = kW - 1, p.y1 = p.py1 = kH - 1;
  auto sv = [&](uint32_t v) { return triangle::ScreenVertex::projected(s.projected[v], 0); };
  for (auto _ : state) {
    bins.clear();
    raster::WorkerBins& w = bins.worker(0);
    for (size_t i = 0; i < nd; ++i) {
      const Triangle& t = s.mesh.triangles[direct[i]];
      const float* c[3] = {&s.color[t.v[0]].x, &s.color[t.v[1]].x, &s.color[t.v[2]].x};
      uint32_t ref;
      raster::RecordHeader* r =
          info[i] & triangle::kKnownSmall
              ? triangle::setup_small_triangle(w, sv(t.v[0]), sv(t.v[1]), sv(t.v[2]), c[0], c[1], c[2], 3, info[i] & 0xffff,
                                             {}, p, ref)
              : triangle::setup_triangle(w, sv(t.v[0]), sv(t.v[1]), sv(t.v[2]), c[0], c[1], c[2], 3, {}, p, ref);
      if (r && bin) w.emit(0, *r, ref, 0);
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(nd));
}
void SetUp(benchmark::State& state) { SetUpAndBin(state, false); }
void SetUpAndBinning(benchmark::State& state) { SetUpAndBin(state, true); }
BENCHMARK(SetUp)->Arg(256)->Arg(1024);
BENCHMARK(SetUpAndBinning)->Arg(256)->Arg(1024);

// A quad filling the screen, facing the camera, with uvs across it: every pixel is
// shaded once by the kernel of `shade` (the convention's looks).
void PixelLoop(benchmark::State& state, const char* shade) {
  Mesh quad;
  quad.positions = {{-4, -2.25f, 0}, {4, -2.25f, 0}, {4, 2.25f, 0}, {-4, 2.25f, 0}};
  quad.normals.assign(4, {0, 0, 1});
  quad.uvs = {{0, 1}, {4, 1}, {4, 0}, {0, 0}};
  quad.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  auto look = bench::make_look(shade);
  Renderer r(kW, kH);
  r.options = look->options;
  r.options.threads = 1;
  Camera cam;
  cam.position = {0, 0, 2.7f};
  for (auto _ : state) {
    r.begin_frame(cam, {}, {0.1f, 0.1f, 0.15f});
    r.draw(quad, Mat4::identity(), &look->material);
    r.end_frame();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * kW * kH);
}
BENCHMARK_CAPTURE(PixelLoop, flat, "flat");
BENCHMARK_CAPTURE(PixelLoop, gouraud, "gouraud");
BENCHMARK_CAPTURE(PixelLoop, tex, "tex");
BENCHMARK_CAPTURE(PixelLoop, phong, "phong");
BENCHMARK_CAPTURE(PixelLoop, env, "env");

void Frame(benchmark::State& state, const char* mesh, const char* shade, int copies) {
  Mesh m = bench::make_mesh(mesh);
  auto look = bench::make_look(shade);
  Renderer r(kW, kH);
  r.options = look->options;
  r.options.threads = 1;
  int frame = 0;
  for (auto _ : state) bench::draw_frame(r, m, look->material, frame++, 60, copies);
}
BENCHMARK_CAPTURE(Frame, sphere1024_gouraud, "sphere:1024", "gouraud", 1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Frame, sphere16x1000_gouraud, "sphere:16", "gouraud", 1000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Frame, sphere64_tex, "sphere:64", "tex", 1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
