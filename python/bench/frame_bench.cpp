// velocity_python_bench: one frame of the shared benchmark scene, timed, rendered by the
// C++ library directly (the baseline for the Python binding's overhead) or by Mesa's
// llvmpipe through the project's OSMesa harness (what pyrender runs on without a GPU).
// python/bench/bench_python.py runs it and the same frame through the Python module,
// in one run, and prints the ratios.
//
//   velocity_python_bench --renderer velocity|llvmpipe --mesh sphere:64 --size 640x480
//                         --frames 60 [--threads N] [--out first.png]
//
// Per frame, velocity: begin_frame / draw / end_frame, then the colour into a buffer
// (read_color) and the metric depth (view_depth): what render() returns in Python.
// llvmpipe: clear + draw + glFinish, then glReadPixels of the colour.
// Prints: renderer=... mesh=... size=WxH frames=N median_ms=...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "velocity/bench_scene.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/renderer.hpp"
#ifdef VELOCITY_HAVE_REFERENCE
#include "reference.hpp"
#endif

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int usage(const char* why) {
  std::fprintf(stderr, "velocity_python_bench: %s\nusage: velocity_python_bench --renderer velocity|llvmpipe "
               "[--mesh sphere:64] [--size 640x480] [--frames 60] [--threads 0] [--out first.png]\n", why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string renderer = "velocity", mesh_spec = "sphere:64", out;
  int width = 640, height = 480, frames = 60, threads = 0;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
    std::string v = argv[++i];
    if (a == "--renderer") renderer = v;
    else if (a == "--mesh") mesh_spec = v;
    else if (a == "--size") {
      if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1) return usage("bad --size");
    } else if (a == "--frames") frames = std::atoi(v.c_str());
    else if (a == "--threads") threads = std::atoi(v.c_str());
    else if (a == "--out") out = v;
    else return usage(("unknown option " + a).c_str());
  }
  if (frames < 1) return usage("--frames must be at least 1");
  std::vector<double> ms;
  using clock = std::chrono::steady_clock;
  try {
    if (renderer == "velocity") {
      // sphere:N exactly as the Python side's Mesh.sphere(N) makes it (radius 1 already).
      velocity::Mesh mesh = mesh_spec.rfind("sphere:", 0) == 0 ? velocity::make_sphere(std::atoi(mesh_spec.c_str() + 7))
                                                               : velocity::bench::make_mesh(mesh_spec);
      auto look = velocity::bench::make_look("gouraud");
      velocity::Renderer r(width, height);
      r.options = look->options;
      r.options.threads = threads;
      std::vector<uint8_t> color(size_t(width) * height * 4);
      for (int f = 0; f < frames; ++f) {
        auto t0 = clock::now();
        velocity::bench::draw_frame(r, mesh, look->material, f, frames);
        r.read_color(color.data(), size_t(width) * 4);
        std::vector<float> depth = r.view_depth();
        ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - t0).count());
        if (f == 0 && !out.empty()) velocity::write_png(out, r.color_image());
        if (depth.empty()) return 1;
      }
    } else if (renderer == "llvmpipe") {
#ifdef VELOCITY_HAVE_REFERENCE
      vref::Scene scene;
      scene.mesh = mesh_spec;
      scene.width = width, scene.height = height;
      scene.shade = vref::Shade::Gouraud;
      vref::Renderer r(scene);
      for (int f = 0; f < frames; ++f) {
        auto t0 = clock::now();
        r.draw_frame(f, frames);
        vref::Image img = r.read_image();
        ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - t0).count());
        if (f == 0 && !out.empty()) {
          velocity::Image v(img.width, img.height);
          v.pixels = img.rgba;
          velocity::write_png(out, v);
        }
      }
#else
      return usage("built without the OSMesa harness (tests/reference)");
#endif
    } else {
      return usage("--renderer must be velocity or llvmpipe");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "velocity_python_bench: %s\n", e.what());
    return 1;
  }
  std::printf("renderer=%s mesh=%s size=%dx%d frames=%d median_ms=%.3f\n", renderer.c_str(), mesh_spec.c_str(), width,
              height, frames, median(ms));
  return 0;
}
