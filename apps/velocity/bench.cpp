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

namespace velocity::cli {

namespace {

struct BenchArgs {
  std::string mesh = "sphere:64";
  std::string size = "1920x1080";
  int frames = 60;
  std::string shade = "gouraud";
  int copies = 1;
  int threads = 1;
  std::string out;
};

int run_bench(const BenchArgs& a) {
  int w = 0, h = 0;
  parse_size(a.size, w, h);
  if (a.frames < 1) throw Error("--frames must be at least 1");
  if (a.copies < 1) throw Error("--copies must be at least 1");
  if (a.threads < 1) throw Error("--threads must be at least 1");
  auto shading = parse_shading(a.shade);
  if (!shading || *shading == Shading::VertexColor || *shading == Shading::Points)
    throw Error("--shade: expected flat|gouraud|phong|wire, got '" + a.shade + "'");

  Mesh mesh = bench::make_mesh(a.mesh);
  Material material = bench::make_material(*shading);
  Renderer renderer(w, h);
  renderer.options = bench::make_options(*shading);

  std::vector<double> ms;
  ms.reserve(size_t(a.frames));
  for (int frame = 0; frame < a.frames; ++frame) {
    auto t0 = std::chrono::steady_clock::now();
    bench::draw_frame(renderer, mesh, material, frame, a.frames, a.copies);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (frame == 0 && !a.out.empty()) write_image(a.out, renderer.color_image());
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  double median = sorted[sorted.size() / 2], total = 0;
  for (double x : ms) total += x;
  size_t tris = mesh.triangles.size() * size_t(a.copies);
  std::printf("renderer=velocity mesh=%s tris=%zu size=%dx%d shade=%s frames=%d median_ms=%.3f fps=%.1f tris_per_s=%.3e\n",
              a.mesh.c_str(), tris, w, h, a.shade.c_str(), a.frames, median, 1000.0 / median,
              double(tris) * a.frames / (total / 1000.0));
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
  cmd->add_option("--shade", args->shade, "flat|gouraud|phong|wire")->capture_default_str();
  cmd->add_option("--copies", args->copies, "Draw the mesh N times per frame, in a square grid")->capture_default_str();
  cmd->add_option("--threads", args->threads, "Rendering threads (the renderer runs on one thread for now)")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Write the first frame to this image");
  return [args] { return run_bench(*args); };
}

}  // namespace velocity::cli
