// velocity_soak: a long run of a changing scene, to show that memory does not grow.
//
//   velocity_soak [--frames N] [--warmup N] [--size WxH] [--threads N] [--tolerance PCT]
//
// Renders N frames (default 100,000) of small images (default 160x120) of a scene that
// never settles: objects move and turn; every few frames one is added (a freshly made
// mesh: sphere, torus, cube, grid, a model parsed from text, sometimes with NaN
// vertices) and the oldest is removed; textures are remade; the shading mode cycles
// through every mode, with and without textures and environment maps; super-sampling
// cycles 1..3; the framebuffer is resized; painter's mode and the depth buffer take
// turns. Every change comes round within the first 100 frames, so after the warm-up
// (default: 10% of the frames, at least 100 and at most 5,000) the process has seen
// every allocation pattern it will see.
//
// It prints resident memory (VmRSS from /proc/self/status) after the warm-up and at the
// end, and exits 1 when the end is more than --tolerance percent (default 5) above the
// warm-up figure, or when a frame throws.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"
#include "velocity/texture.hpp"

using namespace velocity;

namespace {

// Resident set size in KiB, from /proc/self/status; 0 when unknown.
long rss_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  return 0;
}

struct Args {
  long frames = 100000;
  long warmup = -1;  // -1: 10% of the frames, clamped to [100, 5000]
  int width = 160, height = 120;
  int threads = 1;
  double tolerance = 5.0;
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "velocity_soak: %s\nusage: velocity_soak [--frames N] [--warmup N] [--size WxH] [--threads N] "
               "[--tolerance PCT]\n",
               why);
  std::exit(2);
}

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    std::string opt = argv[i];
    if (opt == "--help" || opt == "-h") usage("a long run of a changing scene; fails if memory grows");
    if (i + 1 >= argc) usage(("missing value after " + opt).c_str());
    const char* v = argv[++i];
    char* end = nullptr;
    if (opt == "--frames") a.frames = std::strtol(v, &end, 10);
    else if (opt == "--warmup") a.warmup = std::strtol(v, &end, 10);
    else if (opt == "--threads") a.threads = int(std::strtol(v, &end, 10));
    else if (opt == "--tolerance") a.tolerance = std::strtod(v, &end);
    else if (opt == "--size") {
      if (std::sscanf(v, "%dx%d", &a.width, &a.height) != 2) usage("--size: expected WxH");
      end = const_cast<char*>(v + std::strlen(v));
    } else {
      usage(("unknown option " + opt).c_str());
    }
    if (!end || *end) usage(("bad value for " + opt + ": " + v).c_str());
  }
  if (a.frames < 1) usage("--frames must be at least 1");
  if (a.warmup < 0) a.warmup = std::clamp(a.frames / 10, 100L, 5000L);
  if (a.warmup >= a.frames) usage("--warmup must be below --frames");
  return a;
}

// A small deterministic generator (xorshift32), so every run is the same run.
struct Rng {
  uint32_t s = 0x9e3779b9u;
  uint32_t next() {
    s ^= s << 13, s ^= s >> 17, s ^= s << 5;
    return s;
  }
  float unit() { return float(next() >> 8) / float(1u << 24); }
  float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

// A cube in 3D Studio ASCII, parsed from memory: the loaders churn too.
const char* kAscCube =
    "Named object: \"box\"\r\nTri-mesh, Vertices: 8     Faces: 12\r\nVertex list:\r\n"
    "Vertex 0:  X: -1 Y: -1 Z: -1\r\nVertex 1:  X: 1 Y: -1 Z: -1\r\nVertex 2:  X: 1 Y: 1 Z: -1\r\n"
    "Vertex 3:  X: -1 Y: 1 Z: -1\r\nVertex 4:  X: -1 Y: -1 Z: 1\r\nVertex 5:  X: 1 Y: -1 Z: 1\r\n"
    "Vertex 6:  X: 1 Y: 1 Z: 1\r\nVertex 7:  X: -1 Y: 1 Z: 1\r\nFace list:\r\n"
    "Face 0:    A:0 B:2 C:1 AB:1 BC:1 CA:1\r\nMaterial:\"r255g0b0a0\"\r\nSmoothing:  1\r\n"
    "Face 1:    A:0 B:3 C:2 AB:1 BC:1 CA:1\r\nFace 2:    A:4 B:5 C:6 AB:1 BC:1 CA:1\r\n"
    "Face 3:    A:4 B:6 C:7 AB:1 BC:1 CA:1\r\nFace 4:    A:0 B:1 C:5 AB:1 BC:1 CA:1\r\n"
    "Face 5:    A:0 B:5 C:4 AB:1 BC:1 CA:1\r\nFace 6:    A:1 B:2 C:6 AB:1 BC:1 CA:1\r\n"
    "Material:\"r0g255b0a255\"\r\nFace 7:    A:1 B:6 C:5 AB:1 BC:1 CA:1\r\n"
    "Face 8:    A:2 B:3 C:7 AB:1 BC:1 CA:1\r\nFace 9:    A:2 B:7 C:6 AB:1 BC:1 CA:1\r\n"
    "Face 10:   A:3 B:0 C:4 AB:1 BC:1 CA:1\r\nFace 11:   A:3 B:4 C:7 AB:1 BC:1 CA:1\r\n";

// One thing in the world: a mesh (shared with nobody else, so removing the entity frees
// it), where it is and how it moves.
struct Entity {
  std::shared_ptr<const Mesh> mesh;
  Material material;
  Vec3 position, spin;
  float phase = 0;
};

class World {
 public:
  explicit World(Rng& rng) : rng_(rng) { remake_textures(0); }

  void step(long frame) {
    if (frame % 5 == 0) add(frame);
    while (entities_.size() > 10) entities_.pop_front();
    if (frame % 20 == 0) remake_textures(frame);
  }

  Scene scene(float t) const {
    Scene s;
    s.camera.position = {0, 1.0f + 0.5f * std::sin(t * 0.3f), 6};
    s.camera.look_at({0, 0, 0});
    s.lights.push_back(Light::ambient({0.2f, 0.2f, 0.2f}));
    s.lights.push_back(Light::directional({0.3f, 0.6f, 1}, {0.8f, 0.8f, 0.8f}));
    s.lights.push_back(Light::point({2 * std::sin(t), 2, 2 * std::cos(t)}, {0.5f, 0.4f, 0.3f}, 0.1f, 0.01f));
    // A parent that turns everything, and the entities as its children.
    ObjectId root = s.add_object("root", nullptr);
    s.object(root).transform.rotation.y = t * 0.2f;
    for (const Entity& e : entities_) {
      ObjectId id = s.add_object(e.mesh->name, e.mesh, root);
      Object& o = s.object(id);
      o.transform.translation = e.position + Vec3{0, 0.3f * std::sin(t * 2 + e.phase), 0};
      o.transform.rotation = e.spin * t;
      o.material = e.material;
    }
    return s;
  }

  std::shared_ptr<const Texture> texture() const { return texture_; }
  std::shared_ptr<const Texture> env() const { return env_; }

 private:
  void add(long frame) {
    auto mesh = std::make_shared<Mesh>();
    switch ((frame / 5) % 6) {
      case 0: *mesh = make_sphere(8 + int(rng_.next() % 24)); break;
      case 1: *mesh = make_torus(0.6f, 0.25f, 12 + int(rng_.next() % 20), 6 + int(rng_.next() % 10)); break;
      case 2: *mesh = make_cube(rng_.range(0.5f, 1.5f)); break;
      case 3: *mesh = make_plane_grid(2, 1 + int(rng_.next() % 8)); break;
      case 4: {
        Model m = parse_asc(kAscCube, "soak.asc");
        *mesh = *m.nodes.at(0).mesh;
        break;
      }
      case 5: {
        // A mesh with a NaN and an infinite vertex: its triangles are dropped, with one
        // warning per mesh.
        *mesh = make_sphere(10);
        mesh->positions[3].x = std::numeric_limits<float>::quiet_NaN();
        mesh->positions[7].y = std::numeric_limits<float>::infinity();
        break;
      }
    }
    mesh->name = "e" + std::to_string(frame);
    Entity e;
    e.mesh = std::move(mesh);
    e.position = {rng_.range(-2.5f, 2.5f), rng_.range(-1, 1), rng_.range(-2, 1)};
    e.spin = {rng_.range(-1, 1), rng_.range(-1, 1), rng_.range(-1, 1)};
    e.phase = rng_.range(0, 6.28f);
    e.material.color = {rng_.unit(), rng_.unit(), rng_.unit()};
    e.material.specular = (frame / 5) % 2 ? 0.5f : 0.0f;
    e.material.two_sided = (frame / 5) % 3 == 0;
    if ((frame / 5) % 4 == 1) e.material.texture = texture_;
    if ((frame / 5) % 4 == 2) e.material.env_map = env_;
    entities_.push_back(std::move(e));
  }

  void remake_textures(long frame) {
    int size = 16 << ((frame / 20) % 4);  // 16..128: the mip chains change size too
    texture_ = std::make_shared<const Texture>(make_checkerboard(size, size / 8));
    env_ = std::make_shared<const Texture>(make_environment_map(size));
  }

  Rng& rng_;
  std::deque<Entity> entities_;
  std::shared_ptr<const Texture> texture_, env_;
};

const std::optional<Shading> kModes[] = {std::nullopt,     Shading::Flat,      Shading::Gouraud, Shading::Phong,
                                         Shading::Unlit, Shading::Wireframe, Shading::Points};

}  // namespace

int main(int argc, char** argv) {
  Args args = parse_args(argc, argv);
  long warnings = 0;
  set_warning_handler([&](std::string_view) { ++warnings; });

  Rng rng;
  World world(rng);
  Renderer renderer(args.width, args.height);
  long rss_warm = 0;
  size_t triangles = 0;
  auto start = std::chrono::steady_clock::now();
  try {
    for (long frame = 0; frame < args.frames; ++frame) {
      world.step(frame);
      RenderOptions& o = renderer.options;
      o.threads = args.threads;
      o.shading = kModes[frame % 7];
      o.texture = frame % 11 == 3 ? world.texture() : nullptr;
      o.env_map = frame % 13 == 5 ? world.env() : nullptr;
      o.filter = frame % 3 == 0 ? std::optional<Filter>() : Filter(frame % 3);
      o.ssaa = 1 + int((frame / 10) % 3);
      o.depth_mode = frame % 17 == 0 ? DepthMode::Painter : DepthMode::ZBuffer;
      o.affine = frame % 19 == 0;
      // Every 30 frames the framebuffer changes size, then changes back.
      if (frame % 30 == 0) {
        bool small = (frame / 30) % 2;
        renderer.resize(small ? args.width / 2 + 1 : args.width, small ? args.height / 2 + 1 : args.height);
      }
      Scene scene = world.scene(float(frame) * 0.02f);
      triangles += renderer.render(scene).triangles_rasterized;
      if (frame % 50 == 0) {
        Image img = renderer.color_image();  // resolve too, now and then
        if (img.width != renderer.width()) throw Error("color_image has the wrong size");
      }
      if (frame + 1 == args.warmup) rss_warm = rss_kib();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "velocity_soak: frame failed: %s\n", e.what());
    return 1;
  }
  long rss_end = rss_kib();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double growth = rss_warm > 0 ? 100.0 * double(rss_end - rss_warm) / double(rss_warm) : 0.0;
  std::printf(
      "velocity_soak: frames=%ld warmup=%ld size=%dx%d threads=%d seconds=%.1f fps=%.0f triangles=%zu "
      "warnings=%ld rss_warmup_kib=%ld rss_end_kib=%ld growth=%.2f%% limit=%.1f%%\n",
      args.frames, args.warmup, args.width, args.height, args.threads, seconds, double(args.frames) / seconds,
      triangles, warnings, rss_warm, rss_end, growth, args.tolerance);
  if (rss_warm <= 0) {
    std::fprintf(stderr, "velocity_soak: cannot read VmRSS from /proc/self/status\n");
    return 1;
  }
  if (growth > args.tolerance) {
    std::fprintf(stderr, "velocity_soak: FAIL: resident memory grew %.2f%% after the warm-up (limit %.1f%%)\n", growth,
                 args.tolerance);
    return 1;
  }
  std::printf("velocity_soak: PASS\n");
  return 0;
}
