// velocity-ref: the benchmark scene on Mesa's llvmpipe, timed, with the same flags
// and output line as the reference tools' glref, so the two can stand in for each
// other. Run with LP_NUM_THREADS set to the number of cores the engine may use.
#include "compare.hpp"
#include "reference.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr const char* kUsage = R"(usage: velocity-ref [options]
Renders one mesh spinning about +Y on Mesa's llvmpipe (OSMesa) and prints the
median frame time (clear + draw + glFinish).

  --mesh sphere:SEGS | FILE.obj   mesh (default sphere:64)
  --size WxH                      image size (default 1920x1080)
  --frames N                      frames to time; frame i turns 360*i/N degrees (default 60)
  --shade flat|gouraud|tex|phong|env|wire|pbr|pbrtex   (default gouraud)
  --tex IMAGE                     texture for tex/env/pbrtex (default: 256x256 checkerboard)
  --shadows                       a shadow map for the light (phong, env, pbr, pbrtex; one copy)
  --shadow-map-size N             its side in texels, 16..8192 (default 2048)
  --copies N                      draw the mesh N times per frame in a square grid (default 1)
  --out FILE.png                  write the first frame
  --help                          this text

Prints: renderer=llvmpipe mesh=... tris=... size=WxH shade=... [shadow_map=N] frames=N median_ms=... fps=... tris_per_s=...
)";

// Bad command lines; main() reports them with exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  vref::Scene scene;
  std::string texture_path, out_path;
  int frames = 60;
  bool help = false;
};

std::optional<int> to_int(std::string_view s) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

int positive_int(std::string_view flag, std::string_view value) {
  const std::optional<int> v = to_int(value);
  if (!v || *v < 1) throw UsageError(std::string(flag) + " needs a positive integer, got '" + std::string(value) + "'");
  return *v;
}

void parse_size(std::string_view value, vref::Scene& scene) {
  const size_t x = value.find('x');
  const std::optional<int> w = x == value.npos ? std::nullopt : to_int(value.substr(0, x));
  const std::optional<int> h = x == value.npos ? std::nullopt : to_int(value.substr(x + 1));
  if (!w || !h || *w < 1 || *h < 1) throw UsageError("--size needs WxH, e.g. 1920x1080, got '" + std::string(value) + "'");
  scene.width = *w;
  scene.height = *h;
}

Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      continue;
    }
    if (flag == "--shadows") {
      o.scene.shadows = true;
      continue;
    }
    constexpr std::array<std::string_view, 8> kValueFlags{"--mesh", "--size",   "--frames", "--shade",
                                                          "--tex",  "--copies", "--out",    "--shadow-map-size"};
    if (std::find(kValueFlags.begin(), kValueFlags.end(), flag) == kValueFlags.end())
      throw UsageError("unknown option '" + std::string(flag) + "'");
    if (i + 1 >= argc) throw UsageError(std::string(flag) + " needs a value");
    const std::string_view value = argv[++i];
    if (flag == "--mesh") {
      o.scene.mesh = value;
    } else if (flag == "--size") {
      parse_size(value, o.scene);
    } else if (flag == "--frames") {
      o.frames = positive_int(flag, value);
    } else if (flag == "--shade") {
      const std::optional<vref::Shade> shade = vref::parse_shade(value);
      if (!shade)
        throw UsageError("--shade must be flat, gouraud, tex, phong, env, wire, pbr or pbrtex, got '" + std::string(value) + "'");
      o.scene.shade = *shade;
    } else if (flag == "--tex") {
      o.texture_path = value;
    } else if (flag == "--copies") {
      o.scene.copies = positive_int(flag, value);
    } else if (flag == "--shadow-map-size") {
      o.scene.shadow_map_size = positive_int(flag, value);
    } else {  // --out
      o.out_path = value;
    }
  }
  return o;
}

double median(std::vector<double> xs) {
  std::sort(xs.begin(), xs.end());
  return xs[xs.size() / 2];  // the upper median for an even count, as glref quotes
}

int run(const Options& o) {
  vref::Scene scene = o.scene;
  if (vref::textured(scene.shade) && !o.texture_path.empty()) scene.texture = vref::load_image(o.texture_path);
  vref::Renderer renderer(scene);

  std::vector<double> ms;
  ms.reserve(size_t(o.frames));
  for (int frame = 0; frame < o.frames; ++frame) {
    const auto start = std::chrono::steady_clock::now();
    renderer.draw_frame(frame, o.frames);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (frame == 0 && !o.out_path.empty()) vref::write_png(o.out_path, renderer.read_image());
  }

  const double med = median(ms);
  double total_ms = 0;
  for (double t : ms) total_ms += t;
  const size_t tris = renderer.triangles();
  const std::string shadow_map = scene.shadows ? " shadow_map=" + std::to_string(scene.shadow_map_size) : "";
  std::printf("renderer=llvmpipe mesh=%s tris=%zu size=%dx%d shade=%s%s frames=%d median_ms=%.3f fps=%.1f tris_per_s=%.3e\n",
              scene.mesh.c_str(), tris, scene.width, scene.height, std::string(vref::to_string(scene.shade)).c_str(),
              shadow_map.c_str(),
              o.frames, med, 1000.0 / med, double(tris) * o.frames / (total_ms / 1000.0));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse_args(argc, argv);
    if (options.help) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    return run(options);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "velocity-ref: %s (see --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    // Unreadable meshes or textures and bad mesh specs are bad arguments too.
    std::fprintf(stderr, "velocity-ref: %s\n", e.what());
    return 2;
  }
}
