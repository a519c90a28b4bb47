// velocity_png_write_bench: the engine's PNG writer (velocity::write_png) timed on a
// rendered frame: the shared benchmark scene's first frame (sphere:64, Gouraud) at the
// size asked, written `--repeats` times to `--out`. The time is the writing thread's
// CPU time (compression and the write calls), so a loaded machine changes it little.
//
//   velocity_png_write_bench --size 1920x1080 --repeats 20 --out /dev/shm/bench.png
//
// Prints: size=WxH repeats=N bytes=... median_cpu_ms=...
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "velocity/bench_scene.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/renderer.hpp"

namespace {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

int usage(const char* why) {
  std::fprintf(stderr, "velocity_png_write_bench: %s\nusage: velocity_png_write_bench [--size 256x256] "
               "[--repeats 20] [--out /dev/shm/velocity_png_write_bench.png]\n", why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  int width = 256, height = 256, repeats = 20;
  std::string out = "/dev/shm/velocity_png_write_bench.png";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + a).c_str());
    std::string v = argv[++i];
    if (a == "--size") {
      if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1) return usage("bad --size");
    } else if (a == "--repeats") repeats = std::atoi(v.c_str());
    else if (a == "--out") out = v;
    else return usage(("unknown option " + a).c_str());
  }
  if (repeats < 1) return usage("--repeats must be at least 1");
  try {
    velocity::Mesh mesh = velocity::make_sphere(64);
    auto look = velocity::bench::make_look("gouraud");
    velocity::Renderer r(width, height);
    r.options = look->options;
    velocity::bench::draw_frame(r, mesh, look->material, 0, 60);
    velocity::Image image = r.color_image();
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
      double t0 = thread_cpu_ms();
      velocity::write_png(out, image);
      ms.push_back(thread_cpu_ms() - t0);
    }
    std::sort(ms.begin(), ms.end());
    FILE* f = std::fopen(out.c_str(), "rb");
    long bytes = -1;
    if (f && std::fseek(f, 0, SEEK_END) == 0) bytes = std::ftell(f);
    if (f) std::fclose(f);
    std::printf("size=%dx%d repeats=%d bytes=%ld median_cpu_ms=%.3f\n", width, height, repeats, bytes,
                ms[ms.size() / 2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "velocity_png_write_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
