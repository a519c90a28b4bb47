// `velocity bench`: the reference scene convention of the shared tools (glref), timed.
//
// The same flags and the same one-line output as glref, with renderer=velocity, so the
// two can be run side by side on one machine and compared as ratios.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "velocity/error.hpp"
#include "velocity/bench_scene.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace velocity::cli {

namespace {

struct BenchArgs {
  std::string mesh = "sphere:64";
  std::string size = "1920x1080";
  int frames = 60;
  std::string shade = "gouraud";
  int copies = 1;
  int threads = 0;
  std::string out;
  std::string tex;
  std::string filter;
  bool affine = false;
  int ssaa = 1;
  bool verbose = false;
  std::string backend = "cpu";
  AppearanceArgs appearance;
};

int run_bench(const BenchArgs& a) {
  int w = 0, h = 0;
  parse_size(a.size, w, h);
  if (a.frames < 1) throw Error("--frames must be at least 1");
  if (a.copies < 1) throw Error("--copies must be at least 1");
  if (a.threads < 0) throw Error("--threads must be 0 (every core) or more");
  std::shared_ptr<const Texture> texture = a.tex.empty() ? nullptr : load_texture(a.tex);
  auto look = bench::make_look(a.shade, texture);
  if (!look) throw Error("--shade: expected flat|gouraud|phong|wire|tex|env|pbr|pbrtex, got '" + a.shade + "'");
  apply_appearance(a.appearance, look->options);
  if (a.ssaa < 1 || a.ssaa > 4) throw Error("--ssaa must be 1..4");
  if (!a.filter.empty()) {
    auto f = parse_filter(a.filter);
    if (!f) throw Error("--filter: expected nearest|bilinear|trilinear, got '" + a.filter + "'");
    look->material.filter = *f;
  }
  look->options.affine = a.affine;
  look->options.ssaa = a.ssaa;
  look->options.threads = a.threads;

  Mesh mesh = bench::make_mesh(a.mesh);
  const std::optional<BackendChoice> backend = parse_backend(a.backend);
  if (!backend) throw Error("--backend: expected cpu|gpu|auto, got '" + a.backend + "'");
  Renderer renderer(w, h, *backend);
  renderer.options = look->options;

  std::vector<double> ms, vertex_ms, triangle_ms, tile_ms, shadow_ms, read_ms;
  std::vector<double> upload_ms, submit_ms, gpu_wait_ms, readback_ms;
  std::vector<double> gpu_shadow_ms, gpu_opaque_ms, gpu_blend_ms, gpu_read_ms;  // the GPU's own (timer queries)
  // Each frame is read back as RGBA rows, as a caller that uses the pixels does: the GPU
  // backend reads its framebuffer only when asked, so the frame's time includes it.
  std::vector<uint8_t> pixels(size_t(w) * size_t(h) * 4);
  for (int frame = 0; frame < a.frames; ++frame) {
    auto t0 = std::chrono::steady_clock::now();
    bench::draw_frame(renderer, mesh, look->material, frame, a.frames, a.copies);
    auto t1 = std::chrono::steady_clock::now();
    renderer.read_color(pixels.data(), size_t(w) * 4, 4);
    auto t2 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
    read_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    const FrameStats& st = renderer.stats();
    vertex_ms.push_back(st.vertex_ms), triangle_ms.push_back(st.triangle_ms), tile_ms.push_back(st.tile_ms);
    shadow_ms.push_back(st.shadow_ms);
    upload_ms.push_back(st.upload_ms), submit_ms.push_back(st.submit_ms), gpu_wait_ms.push_back(st.gpu_wait_ms);
    readback_ms.push_back(st.readback_ms);
    gpu_shadow_ms.push_back(st.gpu_shadow_ms), gpu_opaque_ms.push_back(st.gpu_opaque_ms);
    gpu_blend_ms.push_back(st.gpu_blend_ms), gpu_read_ms.push_back(st.gpu_read_ms);
    if (frame == 0 && !a.out.empty()) write_image(a.out, renderer.color_image());
  }
  auto median_of = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  double median = median_of(ms), total = 0;
  for (double x : ms) total += x;
  size_t tris = mesh.triangles.size() * size_t(a.copies);
  std::printf("renderer=velocity mesh=%s tris=%zu size=%dx%d shade=%s frames=%d median_ms=%.3f fps=%.1f tris_per_s=%.3e%s%s\n",
              a.mesh.c_str(), tris, w, h, a.shade.c_str(), a.frames, median, 1000.0 / median,
              double(tris) * a.frames / (total / 1000.0), *backend == BackendChoice::Cpu ? "" : " backend=",
              *backend == BackendChoice::Cpu ? "" : renderer.stats().backend);
  if (a.verbose) {
    const FrameStats& st = renderer.stats();
    std::printf("backend=%s (%s)\n", st.backend, st.backend_reason);
    std::printf("simd=%s threads=%d objects=%zu culled=%zu triangles=%zu rejected=%zu clipped=%zu "
                "backface_or_empty=%zu nonfinite=%zu rasterized=%zu lines=%zu points=%zu\n",
                simd_target(), a.threads, st.objects, st.objects_culled, st.triangles, st.triangles_rejected,
                st.triangles_clipped, st.triangles_culled, st.triangles_nonfinite, st.triangles_rasterized, st.lines,
                st.points);
    std::printf("median stage ms: shadow=%.3f vertex=%.3f triangle=%.3f tile=%.3f read=%.3f\n", median_of(shadow_ms),
                median_of(vertex_ms), median_of(triangle_ms), median_of(tile_ms), median_of(read_ms));
    if (std::string(st.backend) == "gpu")
      std::printf("median gpu stage ms: upload=%.3f submit=%.3f gpu_wait=%.3f readback=%.3f\n", median_of(upload_ms),
                  median_of(submit_ms), median_of(gpu_wait_ms), median_of(readback_ms));
    if (std::string(st.backend) == "gpu")
      std::printf("median gpu pass ms (timer queries): shadow=%.3f opaque=%.3f blend=%.3f read=%.3f meshes_hashed=%zu\n",
                  median_of(gpu_shadow_ms), median_of(gpu_opaque_ms), median_of(gpu_blend_ms), median_of(gpu_read_ms),
                  st.meshes_hashed);
  }
  return 0;
}

}  // namespace

std::function<int()> add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Time the reference scene convention (../shared/tools/README.md); prints one key=value line");
  cmd->add_option("--mesh", args->mesh, "sphere:SEGS or FILE.obj")->capture_default_str();
  cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
  cmd->add_option("--frames", args->frames, "Frames to render (the median is quoted)")->capture_default_str();
  cmd->add_option("--shade", args->shade, "flat|gouraud|phong|wire|tex|env|pbr|pbrtex")->capture_default_str();
  cmd->add_option("--tex", args->tex, "Texture for tex and env (default: the 256x256 checkerboard)");
  cmd->add_option("--filter", args->filter, "Texture filter: nearest|bilinear|trilinear (default trilinear)");
  cmd->add_flag("--affine", args->affine, "Affine (screen-linear) interpolation: cheaper, bends on large polygons");
  cmd->add_option("--ssaa", args->ssaa, "Super-sampling factor per side, 1..4")->capture_default_str();
  cmd->add_option("--copies", args->copies, "Draw the mesh N times per frame, in a square grid")->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads rasterizing tiles (0: every core)")->capture_default_str();
  cmd->add_option("--out", args->out, "Write the first frame to this image");
  cmd->add_option("--backend", args->backend, "What draws: cpu, gpu (OpenGL 3.3 through EGL) or auto (a hardware GPU, else cpu)")
      ->capture_default_str();
  add_appearance_options(cmd, args->appearance);
  cmd->add_flag("--verbose", args->verbose, "Also print the instruction set, what the last frame did and the median time of each stage");
  return [args] { return run_bench(*args); };
}

}  // namespace velocity::cli
