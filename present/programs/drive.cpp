#include "programs/drive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

#include "programs/shapes.hpp"
#include "runtime/loop.hpp"
#include "runtime/synth.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/texture.hpp"

namespace velocity::realtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Vec3 forward(float heading) { return {-std::sin(heading), 0, -std::cos(heading)}; }

// Generated textures (nothing to ship): grass, asphalt with white edges and a dashed
// centre line, kerbs, the start line, a wall of windows, dial faces.
uint8_t to8(float v) { return uint8_t(std::lrint(std::clamp(v, 0.0f, 1.0f) * 255)); }

void put(Image& img, int x, int y, Vec3 c) {
  uint8_t* p = img.pixel(x, y);
  p[0] = to8(c.x), p[1] = to8(c.y), p[2] = to8(c.z), p[3] = 255;
}

std::shared_ptr<const Texture> grass_texture() {
  Image img(256, 256);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      float blotch = 0.5f + 0.25f * std::sin(float(x) * 0.0491f * 2) * std::cos(float(y) * 0.0491f * 3);
      float n = u(rng) * 0.08f;
      put(img, x, y, {0.22f + 0.1f * blotch + n, 0.42f + 0.14f * blotch + n, 0.16f + n * 0.5f});
    }
  return std::make_shared<const Texture>(img);
}

std::shared_ptr<const Texture> road_texture() {
  Image img(64, 256);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 64; ++x) {
      float g = 0.3f + u(rng) * 0.04f;
      bool edge = x < 3 || x >= 61;
      bool centre = (x == 31 || x == 32) && (y % 128) < 64;
      if (edge || centre) g = 0.9f;
      put(img, x, y, {g, g, g});
    }
  return std::make_shared<const Texture>(img);
}

std::shared_ptr<const Texture> kerb_texture() {
  Image img(8, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 8; ++x) put(img, x, y, y < 32 ? Vec3{0.85f, 0.1f, 0.08f} : Vec3{0.95f, 0.95f, 0.95f});
  return std::make_shared<const Texture>(img);
}

std::shared_ptr<const Texture> chequer_texture() {
  Image img(64, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 64; ++x) {
      float g = ((x / 4 + y / 4) % 2) ? 0.95f : 0.05f;
      put(img, x, y, {g, g, g});
    }
  return std::make_shared<const Texture>(img);
}

std::shared_ptr<const Texture> windows_texture() {
  Image img(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      bool window = (x % 16) >= 4 && (x % 16) < 12 && (y % 16) >= 4 && (y % 16) < 12;
      bool lit = window && ((x / 16 + y / 16 * 3) % 4 == 0);
      put(img, x, y, lit ? Vec3{0.95f, 0.85f, 0.5f} : window ? Vec3{0.25f, 0.35f, 0.5f} : Vec3{0.75f, 0.72f, 0.68f});
    }
  return std::make_shared<const Texture>(img);
}

// A dial: dark face, a white scale over 270 degrees (from lower left, clockwise), a red
// zone from `red` (0..1 of the scale), numbers every `label_every` ticks.
constexpr float kDialStart = 225.0f, kDialSweep = 270.0f;  // degrees, anticlockwise from +x

std::shared_ptr<const Texture> dial_texture(int ticks, int label_every, int label_step, float red) {
  const int n = 128;
  Image img(n, n, 0xff000000u);
  Canvas canvas{img.pixels.data(), n, n, size_t(n) * 4};
  const float c = (n - 1) / 2.0f;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      float dx = float(x) - c, dy = c - float(y), r = std::sqrt(dx * dx + dy * dy) / c;
      float a = std::atan2(dy, dx) * 180.0f / kPi;
      float f = std::fmod(kDialStart - a + 720.0f, 360.0f) / kDialSweep;  // 0..1 along the scale
      Vec3 col = r > 1.0f ? Vec3{0.08f, 0.08f, 0.09f} : r > 0.93f ? Vec3{0.6f, 0.6f, 0.65f} : Vec3{0.05f, 0.05f, 0.07f};
      if (r < 0.9f && r > 0.68f && f <= 1.0f) {
        float tick = f * float(ticks);
        float off = std::abs(tick - std::round(tick)) * kDialSweep / float(ticks) * kPi / 180.0f * r * c;
        bool major = int(std::round(tick)) % label_every == 0;
        if (off < (major ? 1.3f : 0.7f) && (major || r > 0.78f)) col = f >= red ? Vec3{0.95f, 0.2f, 0.1f} : Vec3{0.95f, 0.95f, 0.95f};
      }
      if (r < 0.9f && r > 0.86f && f >= red && f <= 1.0f) col = {0.85f, 0.15f, 0.1f};
      put(img, x, y, col);
    }
  for (int t = 0; t <= ticks; t += label_every) {
    float a = (kDialStart - kDialSweep * float(t) / float(ticks)) * kPi / 180.0f;
    std::string label = std::to_string(t / label_every * label_step);
    int w = text_width(label, 1), h = text_height(label, 1);
    int x = int(c + std::cos(a) * c * 0.5f) - w / 2, y = int(c - std::sin(a) * c * 0.5f) - h / 2;
    draw_text(canvas, x, y, label, {230, 230, 230, 255}, 1);
  }
  return std::make_shared<const Texture>(img);
}

Material material(Vec3 color, Shading shading, float specular = 0, float shininess = 32) {
  Material m;
  m.color = color;
  m.shading = shading;
  m.specular = specular;
  m.shininess = shininess;
  return m;
}

Material textured(std::shared_ptr<const Texture> t, Shading shading = Shading::Gouraud) {
  Material m = material({1, 1, 1}, shading);
  m.texture = std::move(t);
  return m;
}

// A strip along the circuit between two lateral offsets (metres right of the line),
// `lift` metres over the road surface, u across and v along (one repeat every `repeat` m).
// Only the samples `keep` accepts; a new strip starts after each gap.
template <typename Keep>
Mesh road_strip(const Circuit& c, float from, float to, float lift, float repeat, Keep&& keep) {
  Mesh m;
  const auto& samples = c.samples();
  const size_t n = samples.size();
  bool open = false;
  for (size_t k = 0; k <= n; ++k) {
    size_t i = k % n;
    if (!keep(i) && !(open && keep((i + n - 1) % n))) {
      open = false;
      continue;
    }
    const Circuit::Sample& s = samples[i];
    float v = (k == n ? c.length() : s.s) / repeat;
    for (float lat : {from, to}) {
      Vec3 p = s.centre + s.right * lat + Vec3{0, s.bank * lat + lift, 0};
      m.positions.push_back(p);
      m.uvs.push_back({lat == from ? 0.0f : 1.0f, v});
      m.normals.push_back(normalize(Vec3{-s.right.x * s.bank, 1, -s.right.z * s.bank}));
    }
    if (open) {
      uint32_t a = uint32_t(m.positions.size() - 4);
      m.triangles.push_back({{a, a + 2, a + 1}});
      m.triangles.push_back({{a + 1, a + 2, a + 3}});
    }
    open = keep(i);
  }
  // Wind the strip upwards whichever way it went.
  for (Triangle& tri : m.triangles) {
    Vec3 a = m.positions[tri.v[0]], b = m.positions[tri.v[1]], d = m.positions[tri.v[2]];
    if (cross(b - a, d - a).y < 0) std::swap(tri.v[1], tri.v[2]);
  }
  return m;
}

// One square chunk of the ground's height field (`cells` x `cells` grid cells from
// (ix0, iz0)), triangulated as Circuit::ground_height interpolates it.
Mesh ground_chunk(const Circuit& c, int ix0, int iz0, int cells) {
  Mesh m;
  const float step = Circuit::kGroundCell;
  for (int iz = 0; iz <= cells; ++iz)
    for (int ix = 0; ix <= cells; ++ix) {
      int gx = ix0 + ix, gz = iz0 + iz;
      float x = -Circuit::kGroundHalf + float(gx) * step, z = -Circuit::kGroundHalf + float(gz) * step;
      m.positions.push_back({x, c.ground_vertex(gx, gz), z});
      m.uvs.push_back({x / 10.0f, z / 10.0f});
    }
  auto at = [&](int ix, int iz) { return uint32_t(iz * (cells + 1) + ix); };
  for (int iz = 0; iz < cells; ++iz)
    for (int ix = 0; ix < cells; ++ix) {
      // Split along (0,0)-(1,1), facing up.
      m.triangles.push_back({{at(ix, iz), at(ix + 1, iz + 1), at(ix + 1, iz)}});
      m.triangles.push_back({{at(ix, iz), at(ix, iz + 1), at(ix + 1, iz + 1)}});
    }
  compute_normals(m);
  return m;
}

std::string lap_clock(long ticks) {
  double t = double(ticks) * Race::kTick;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%d:%05.2f", int(t / 60), std::fmod(t, 60.0));
  return buf;
}

}  // namespace

std::string default_best_lap_file() {
  const char* xdg = std::getenv("XDG_DATA_HOME");
  std::string base;
  if (xdg && *xdg) base = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home) base = std::string(home) + "/.local/share";
  else return {};
  return base + "/velocity/drive/best_lap.txt";
}

float DriveProgram::engine_hz(float speed) { return 55.0f + 6.5f * std::abs(speed); }

float DriveProgram::engine_rpm(float speed) {
  // Gears change at these speeds (m/s); within each, revs rise from 3,000 to 7,000.
  static constexpr float kShift[] = {0, 12, 22, 32, 42, 70};
  float v = std::abs(speed);
  if (v < 1) return 900 + 2100 * v;
  for (int g = 0; g < 5; ++g)
    if (v < kShift[g + 1]) return 3000 + 4000 * (v - kShift[g]) / (kShift[g + 1] - kShift[g]);
  return 7000;
}

DriveProgram::DriveProgram(DriveOptions o)
    : circuit_(std::make_shared<const Circuit>()), race_(*circuit_, o.opponents), options_(std::move(o)) {
  hq_ = options_.high_quality;
  build_world();
  cars_.push_back(build_car("", &options_, {0.78f, 0.06f, 0.05f}, true));
  for (int i = 0; i < options_.opponents; ++i)
    cars_.push_back(build_car("opponent ", nullptr, i % 2 ? Vec3{0.95f, 0.75f, 0.1f} : Vec3{0.1f, 0.25f, 0.8f}, true));
  ghost_ = build_car("ghost ", nullptr, {0.55f, 0.9f, 1.0f}, false);
  build_dashboard();
  build_ground();
  // The best lap from disk, if it is one of this circuit's (a bad file is ignored with a
  // word: it is rewritten at the next best lap).
  if (!options_.best_lap_file.empty() && std::filesystem::exists(options_.best_lap_file)) {
    std::ifstream in(options_.best_lap_file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    try {
      race_.set_best_lap(parse_lap(ss.str(), circuit_->length(), options_.best_lap_file));
    } catch (const Error& e) {
      std::fprintf(stderr, "velocity: ignoring the best lap: %s\n", e.what());
    }
  }
  restart();
}

void DriveProgram::restart() {
  race_.reset();
  recording_ = {};
  clock_ = 0;
  controls_ = {};
  message_.clear();
  chase_yaw_ = race_.car(0).state.heading;
  pose_scene();
  place_camera(0);
}

bool DriveProgram::finished() const {
  return options_.replay && race_.tick() >= long(options_.replay->ticks.size());
}

std::string DriveProgram::help() const {
  auto k = [&](Action a) { return key_label(settings_.key(a)); };
  std::string h = "DRIVE\n\n";
  h += k(Action::Throttle) + "  THROTTLE     " + k(Action::Brake) + "  BRAKE / REVERSE\n";
  h += k(Action::Left) + " / " + k(Action::Right) + "  STEER\n";
  h += k(Action::Camera) + "  CAMERA: CHASE, COCKPIT, TRACKSIDE\n";
  h += "[ ]  FOCAL LENGTH    Q E  SWIVEL\nPGUP PGDN  PITCH    , .  ROLL\n";
  h += k(Action::ResetCamera) + "  CAMERA BACK AS IT WAS\n";
  h += k(Action::HighQuality) + "  HIGH QUALITY (3X3 SSAA)\n";
  h += "P  PAUSE     ESC  MENU (RESUME, RESTART, OPTIONS)\n\n";
  h += "A LAP COUNTS WHEN YOU PASS EVERY\nCHECKPOINT ON THE ROAD. BEAT THE GHOST\nOF YOUR BEST LAP AND THE BLUE CAR.\n";
  h += "GAMEPAD: STICK STEERS, TRIGGERS DRIVE";
  return h;
}

void DriveProgram::build_ground() {
  const Circuit& c = *circuit_;
  // The ground in chunks (so that what is out of view is skipped whole), drawn last:
  // what stands on it and the road over it hide most of it, and hidden pixels cost less.
  Material grass = textured(grass_texture());
  const int chunk = 15, cells = c.ground_cells();  // 90 cells across: 6 x 6 chunks
  static_assert(int(2 * Circuit::kGroundHalf / Circuit::kGroundCell) % 15 == 0);
  for (int z = 0; z < cells; z += chunk)
    for (int x = 0; x < cells; x += chunk) {
      auto m = std::make_shared<Mesh>(ground_chunk(c, x, z, chunk));
      m->materials.push_back(grass);
      scene_.add_object("ground", m);
    }
}

void DriveProgram::build_world() {
  const Circuit& c = *circuit_;
  // The road, kerbs in the bends and the start line.
  auto road = std::make_shared<Mesh>(road_strip(c, -Circuit::kHalfWidth, Circuit::kHalfWidth, 0.0f, 12.0f,
                                                [](size_t) { return true; }));
  road->materials.push_back(textured(road_texture()));
  scene_.add_object("road", road);
  Material kerb = textured(kerb_texture(), Shading::Flat);
  for (float side : {-1.0f, 1.0f}) {
    float a = side * Circuit::kHalfWidth, b = side * (Circuit::kHalfWidth + Circuit::kKerbWidth);
    auto m = std::make_shared<Mesh>(road_strip(c, std::min(a, b), std::max(a, b), 0.03f, 4.0f,
                                               [&](size_t i) { return c.kerbed(i); }));
    if (m->triangles.empty()) continue;
    m->materials.push_back(kerb);
    scene_.add_object("kerb", m);
  }
  {
    Mesh line;
    const Circuit::Sample s = c.at(0);
    for (float along : {-0.8f, 0.8f})
      for (float lat : {-Circuit::kHalfWidth, Circuit::kHalfWidth}) {
        line.positions.push_back(s.centre + s.tangent * along + s.right * lat + Vec3{0, s.bank * lat + 0.02f, 0});
        line.uvs.push_back({lat < 0 ? 0.0f : 1.0f, along < 0 ? 0.0f : 1.0f});
      }
    line.triangles = {{{0, 1, 2}}, {{1, 3, 2}}};
    for (Triangle& tri : line.triangles) {
      Vec3 a = line.positions[tri.v[0]], b = line.positions[tri.v[1]], d = line.positions[tri.v[2]];
      if (cross(b - a, d - a).y < 0) std::swap(tri.v[1], tri.v[2]);
    }
    compute_normals(line);
    auto m = std::make_shared<Mesh>(std::move(line));
    m->materials.push_back(textured(chequer_texture(), Shading::Flat));
    scene_.add_object("start line", m);
  }
  // The start gantry: two posts beside the road and a beam over it.
  auto box = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) { return p; }));
  auto add_box = [&](const char* name, Vec3 centre, Vec3 size, float yaw, const Material& m) {
    ObjectId id = scene_.add_object(name, box);
    scene_.object(id).transform.translation = centre;
    scene_.object(id).transform.scale = size;
    scene_.object(id).transform.rotation = {0, yaw, 0};
    scene_.object(id).material = m;
    return id;
  };
  {
    const Circuit::Sample s = c.at(0);
    float yaw = std::atan2(-s.tangent.x, -s.tangent.z);
    Material steel = material({0.55f, 0.57f, 0.62f}, Shading::Flat);
    for (float side : {-1.0f, 1.0f}) {
      Vec3 p = c.point(0, side * (Circuit::kHalfWidth + 2.5f));
      add_box("gantry post", p + Vec3{0, 3.5f, 0}, {0.5f, 7.0f, 0.5f}, yaw, steel);
      race_.add_solid(p, 0.5f);
    }
    add_box("gantry beam", s.centre + Vec3{0, 7.2f, 0}, {2 * Circuit::kHalfWidth + 6, 1.2f, 0.6f}, yaw,
            textured(chequer_texture(), Shading::Flat));
    // A grandstand along the outside of the start straight, its rows of seats stepped.
    Material seats = material({0.25f, 0.35f, 0.65f}, Shading::Flat);
    for (int row = 0; row < 4; ++row) {
      Vec3 p = c.point(-30, Circuit::kHalfWidth + 14.0f + 2.0f * float(row));
      add_box("grandstand", p + Vec3{0, 0.6f + 1.0f * float(row), 0}, {2.0f, 1.2f + 2.0f * float(row), 40.0f}, yaw, seats);
      race_.add_solid(p + s.tangent * -12.0f, 2.0f), race_.add_solid(p, 2.0f), race_.add_solid(p + s.tangent * 12.0f, 2.0f);
    }
    add_box("grandstand roof", c.point(-30, Circuit::kHalfWidth + 17.0f) + Vec3{0, 9.5f, 0}, {9.0f, 0.4f, 42.0f}, yaw,
            material({0.85f, 0.85f, 0.9f}, Shading::Flat));
  }

  // Trees, away from the road; buildings out beyond them.
  std::mt19937 rng(3);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
  auto foliage = std::make_shared<const Mesh>(make_cone(8));
  auto trunk = std::make_shared<const Mesh>(make_wheel(6, {0.35f, 0.22f, 0.1f}, {0.3f, 0.2f, 0.1f}, {0.3f, 0.2f, 0.1f},
                                                       {0.3f, 0.2f, 0.1f}));
  for (int placed = 0, tries = 0; placed < 90 && tries < 4000; ++tries) {
    Vec3 p{uniform(-400, 400), 0, uniform(-400, 400)};
    if (c.locate(p).distance < Circuit::kHalfWidth + 14) continue;
    p.y = c.height(p.x, p.z) - 0.2f;
    float h = uniform(6, 11);
    ObjectId t = scene_.add_object("tree", trunk);
    scene_.object(t).transform.translation = p + Vec3{0, h * 0.15f, 0};
    scene_.object(t).transform.rotation = {0, 0, kPi / 2};  // the cylinder's axis up
    scene_.object(t).transform.scale = {h * 0.3f, 0.35f, 0.35f};
    ObjectId f = scene_.add_object("foliage", foliage);
    scene_.object(f).transform.translation = p + Vec3{0, h * 0.25f, 0};
    scene_.object(f).transform.scale = {h * 0.3f, h * 0.8f, h * 0.3f};
    Vec3 green{0.12f + uniform(0, 0.08f), 0.35f + uniform(0, 0.15f), 0.12f};
    scene_.object(f).material = material(green, Shading::Flat);
    race_.add_solid(p, 0.6f);
    ++placed;
  }
  Material wall = textured(windows_texture(), Shading::Flat);
  for (int i = 0, placed = 0; i < 40 && placed < 10; ++i) {
    float angle = float(i) / 40 * 2 * kPi * 3.0f;
    Vec3 p{std::cos(angle) * 380, 0, std::sin(angle) * 380};
    if (c.locate(p).distance < 45) continue;
    Vec3 size{uniform(18, 30), uniform(14, 40), uniform(18, 30)};
    p.y = c.height(p.x, p.z) - 1.0f;
    add_box("building", p + Vec3{0, size.y / 2, 0}, size, -angle, wall);
    race_.add_solid(p, std::min(size.x, size.z) * 0.6f);
    ++placed;
  }
  // Cones: a row on the outside of the fastest bends, past the kerb, and a few at the
  // side of the start straight.
  auto cone = std::make_shared<const Mesh>(make_cone(8));
  std::vector<Vec3> at;
  const auto& samples = c.samples();
  for (size_t i = 0; i < samples.size(); i += 3) {
    const Circuit::Sample& s = samples[i];
    if (!c.kerbed(i) || at.size() >= 40) continue;
    float outside = s.curvature > 0 ? 1.0f : -1.0f;  // a left bend's outside is on the right
    at.push_back(c.point(s.s, outside * (Circuit::kHalfWidth + Circuit::kKerbWidth + 2.0f)));
  }
  for (int i = 0; i < 6; ++i) at.push_back(c.point(30.0f + 10.0f * float(i), -(Circuit::kHalfWidth + 2.5f)));
  for (const Vec3& p : at) {
    race_.add_cone(p);
    ObjectId id = scene_.add_object("cone", cone);
    scene_.object(id).transform.scale = {0.3f, 0.75f, 0.3f};
    scene_.object(id).material = material({1.0f, 0.45f, 0.05f}, Shading::Flat);
    cones_.push_back(id);
  }
  // Trackside camera posts: beside the road every 200 m or so, out on the outside.
  for (float s = 60; s < c.length(); s += 200) {
    Circuit::Sample a = c.at(s);
    float outside = a.curvature > 0 ? 1.0f : -1.0f;
    posts_.push_back(c.point(s, outside * 22.0f) + Vec3{0, 6, 0});
  }

  scene_.lights.push_back(Light::ambient({0.35f, 0.36f, 0.4f}));
  scene_.lights.push_back(Light::directional({0.4f, 0.8f, 0.3f}, {0.85f, 0.82f, 0.75f}));
  scene_.background = {0.55f, 0.72f, 0.92f};
  scene_.camera.near = 0.1f;
  scene_.camera.far = 800.0f;
}

DriveProgram::CarModel DriveProgram::build_car(const std::string& prefix, const DriveOptions* o, Vec3 paint_colour,
                                               bool with_wheels) {
  static const auto studio = std::make_shared<const Texture>(make_environment_map(256));
  const bool ghost = !with_wheels;
  CarModel car;
  car.root = scene_.add_object(prefix + "car", nullptr);
  car.body = scene_.add_object(prefix + "body", nullptr, car.root);
  // The ghost is a wireframe of the built-in body: seen, never in the way.
  auto finish = [&](Material m) {
    if (!ghost) return m;
    return material(paint_colour, Shading::Wireframe);
  };
  if (!o || o->car.empty()) {
    // Body: a wedge (the bonnet slopes down to the nose, at -Z); cabin: a glasshouse
    // narrower at the top.
    auto body = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) {
      Vec3 q{p.x * 1.62f, p.y * 0.55f + 0.62f, p.z * 4.3f};
      if (p.y > 0 && p.z < 0) q.y -= 0.16f;
      if (p.y < 0) q.y += 0.02f;
      return q;
    }));
    Material paint = material(paint_colour, Shading::Phong, 0.7f, 60);
    paint.env_map = studio;
    paint.env_mix = 0.3f;
    ObjectId b = scene_.add_object(prefix + "shell", body, car.body);
    scene_.object(b).material = finish(paint);
    auto cabin = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) {
      Vec3 q{p.x * 1.44f, p.y * 0.5f + 1.14f, p.z * 2.1f + 0.35f};
      if (p.y > 0) q.x *= 0.86f, q.z = p.z * 1.2f + 0.45f;
      return q;
    }));
    Material glass = material({0.06f, 0.08f, 0.12f}, Shading::Phong, 0.95f, 90);
    glass.env_map = studio;
    glass.env_mix = 0.55f;
    ObjectId cab = scene_.add_object(prefix + "windows", cabin, car.body);
    scene_.object(cab).material = finish(glass);
    if (ghost) return car;
    // Lamps (unlit: they glow) and a dark sill along the bottom of the body.
    auto lamp = std::make_shared<const Mesh>(make_cube(1.0f));
    auto add_part = [&](const char* name, Vec3 at, Vec3 size, Vec3 colour, Shading shading) {
      ObjectId id = scene_.add_object(prefix + name, lamp, car.body);
      scene_.object(id).transform.translation = at;
      scene_.object(id).transform.scale = size;
      scene_.object(id).material = material(colour, shading);
    };
    for (float x : {-0.58f, 0.58f}) {
      add_part("headlamp", {x, 0.66f, -2.151f}, {0.36f, 0.14f, 0.02f}, {1.0f, 0.97f, 0.8f}, Shading::Unlit);
      add_part("tail lamp", {x, 0.74f, 2.151f}, {0.4f, 0.12f, 0.02f}, {0.9f, 0.05f, 0.04f}, Shading::Unlit);
    }
    add_part("grille", {0, 0.5f, -2.152f}, {0.7f, 0.12f, 0.02f}, {0.05f, 0.05f, 0.06f}, Shading::Flat);
    add_part("sill", {0, 0.36f, 0}, {1.64f, 0.1f, 4.2f}, {0.08f, 0.08f, 0.09f}, Shading::Flat);
  } else {
    LoadOptions lo;
    Model model = load_model(o->car, lo);
    // Size it as a car: 4.3 m long, its nose forward (-Z), its wheels on the ground.
    Bounds bb{{1e30f, 1e30f, 1e30f}, {-1e30f, -1e30f, -1e30f}};
    size_t tris = 0;
    for (const ModelNode& n : model.nodes) {
      if (!n.mesh || n.mesh->positions.empty()) continue;
      tris += n.mesh->triangle_count();
      Bounds b = n.mesh->bounds();
      bb.min = {std::min(bb.min.x, b.min.x), std::min(bb.min.y, b.min.y), std::min(bb.min.z, b.min.z)};
      bb.max = {std::max(bb.max.x, b.max.x), std::max(bb.max.y, b.max.y), std::max(bb.max.z, b.max.z)};
    }
    if (tris == 0) throw Error(o->car + ": the car model has no triangles");
    Vec3 ext = bb.max - bb.min;
    bool along_x = ext.x > ext.z;
    float length_m = std::max(ext.x, ext.z);
    if (!(length_m > 0)) throw Error(o->car + ": the car model is flat");
    float s = 4.3f / length_m;
    // The paint reflects the studio; dark materials are taken as windows and made glassy.
    for (ModelNode& n : model.nodes) {
      if (!n.mesh) continue;
      if (n.mesh->materials.empty()) n.mesh->materials.emplace_back();
      for (Material& m : n.mesh->materials) {
        m.two_sided = true;
        m.env_map = studio;
        float lum = 0.3f * m.color.x + 0.59f * m.color.y + 0.11f * m.color.z;
        bool window = lum < 0.22f;
        m.shading = Shading::Phong;
        m.specular = window ? 0.9f : 0.5f;
        m.shininess = window ? 90.0f : 48.0f;
        m.env_mix = window ? 0.6f : 0.25f;
      }
    }
    ObjectId fit = scene_.add_object("car model", nullptr, car.body);
    Transform& t = scene_.object(fit).transform;
    t.scale = {s, s, s};
    // 3D Studio models face its front view: +Z once loaded. Turn the nose to -Z.
    t.rotation = {0, kPi + radians(o->car_yaw) + (along_x ? kPi / 2 : 0.0f), 0};
    Vec3 centre = bb.center();
    // Centre it (the rotation is about the model's origin: move the centre there first).
    ObjectId middle = scene_.add_object("car model centre", nullptr, fit);
    scene_.object(middle).transform.translation = {-centre.x, -bb.min.y, -centre.z};
    scene_.object(fit).transform.translation = {0, 0.12f, 0};
    add_to_scene(scene_, model, middle);
  }
  // Wheels: a mount per wheel (the front ones steer), the wheel under it spins.
  static const auto wheel = std::make_shared<const Mesh>(
      make_wheel(14, {0.07f, 0.07f, 0.08f}, {0.13f, 0.13f, 0.14f}, {0.75f, 0.76f, 0.8f}, {0.2f, 0.2f, 0.22f}));
  const float x = kTrack / 2;
  const Vec3 at[4] = {{-x, kWheelRadius, -kWheelBase / 2}, {x, kWheelRadius, -kWheelBase / 2},
                      {-x, kWheelRadius, kWheelBase / 2}, {x, kWheelRadius, kWheelBase / 2}};
  const char* mounts[4] = {"steer_fl", "steer_fr", "mount_rl", "mount_rr"};
  for (int i = 0; i < 4; ++i) {
    ObjectId m = scene_.add_object(prefix + mounts[i], nullptr, car.root);
    scene_.object(m).transform.translation = at[i];
    if (i < 2) car.steer[i] = m;
    car.wheels[i] = scene_.add_object(prefix + kWheelNames[i], wheel, m);
    scene_.object(car.wheels[i]).transform.scale = {0.26f, kWheelRadius, kWheelRadius};
  }
  return car;
}

void DriveProgram::build_dashboard() {
  // In front of the driver (the cockpit camera sits at x = -0.38): a dark panel with
  // the speedometer (0-240 km/h) and the rev counter (0-8,000) whose needles turn.
  ObjectId root = cars_[0].root;
  dashboard_ = scene_.add_object("dashboard", nullptr, root);
  auto box = std::make_shared<const Mesh>(make_cube(1.0f));
  ObjectId panel = scene_.add_object("dash panel", box, dashboard_);
  scene_.object(panel).transform.translation = {-0.1f, 0.84f, -0.8f};
  scene_.object(panel).transform.scale = {1.45f, 0.16f, 0.3f};
  scene_.object(panel).material = material({0.1f, 0.1f, 0.11f}, Shading::Flat);
  auto face = [](float r) {
    Mesh m;
    m.positions = {{-r, -r, 0}, {r, -r, 0}, {r, r, 0}, {-r, r, 0}};
    m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    return m;
  };
  auto needle_mesh = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) {
    return Vec3{(p.x + 0.5f) * 0.062f - 0.008f, p.y * 0.005f, p.z * 0.004f};
  }));
  auto dial = [&](const char* name, float x, std::shared_ptr<const Texture> tex) {
    ObjectId d = scene_.add_object(name, std::make_shared<const Mesh>(face(0.07f)), dashboard_);
    scene_.object(d).transform.translation = {x, 0.96f, -0.66f};
    scene_.object(d).transform.rotation = {-0.35f, 0, 0};  // leaning back, towards the eyes
    scene_.object(d).material = textured(std::move(tex), Shading::Unlit);
    ObjectId pivot = scene_.add_object(std::string(name) + " needle", needle_mesh, d);
    scene_.object(pivot).transform.translation = {0, 0, 0.004f};
    scene_.object(pivot).material = material({1.0f, 0.35f, 0.1f}, Shading::Unlit);
    return pivot;
  };
  speed_needle_ = dial("speedometer", -0.38f - 0.08f, dial_texture(12, 2, 40, 1.0f));
  rev_needle_ = dial("rev counter", -0.38f + 0.08f, dial_texture(8, 1, 1, 7.0f / 8.0f));
}

void DriveProgram::pose_car(const CarModel& m, const CarState& s) {
  Object& root = scene_.object(m.root);
  root.transform.translation = s.position;
  root.transform.rotation = {s.pitch, s.heading, s.roll};
  // The body leans: back under acceleration, out of a turn (springs, not physics).
  scene_.object(m.body).transform.rotation = {std::clamp(s.accel * 0.004f, -0.04f, 0.04f), 0,
                                              std::clamp(-s.lateral * 0.006f, -0.06f, 0.06f)};
  for (int i = 0; i < 2; ++i)
    if (m.steer[i]) scene_.object(m.steer[i]).transform.rotation = {0, s.steer, 0};
  // Rolling forward (-Z) turns the top of the wheel forward: negative about +X.
  for (ObjectId w : m.wheels)
    if (w) scene_.object(w).transform.rotation = {-s.wheel_spin, 0, 0};
}

void DriveProgram::pose_scene() {
  for (size_t i = 0; i < cars_.size(); ++i) pose_car(cars_[i], race_.car(i).state);
  std::optional<Pose> g = race_.ghost();
  Object& ghost = scene_.object(ghost_.root);
  ghost.visible = g.has_value() && !attract_;
  if (g) {
    ghost.transform.translation = g->position;
    ghost.transform.rotation = {g->pitch, g->heading, g->roll};
  }
  for (size_t i = 0; i < cones_.size(); ++i) {
    const Cone& c = race_.cones()[i];
    Transform& t = scene_.object(cones_[i]).transform;
    t.translation = c.position;
    t.rotation = {c.tilt, c.fall_heading, 0};  // over towards where it was pushed
  }
  // The dials: 270 degrees of scale, anticlockwise from lower left.
  auto angle = [](float f) { return (kDialStart - kDialSweep * std::clamp(f, 0.0f, 1.0f)) * kPi / 180.0f; };
  const float speed = std::abs(race_.car(0).state.speed);
  scene_.object(speed_needle_).transform.rotation = {0, 0, angle(speed * 3.6f / 240.0f)};
  scene_.object(rev_needle_).transform.rotation = {0, 0, angle(engine_rpm(speed) / 8000.0f)};
}

void DriveProgram::event(const InputEvent& e, const InputState&) {
  if (e.kind != InputEvent::KeyDown || attract_) return;
  if (e.key == settings_.key(Action::Camera)) {
    camera_ = CameraMode((int(camera_) + 1) % 3);
    swivel_ = pitch_ = roll_ = 0;
  } else if (e.key == settings_.key(Action::HighQuality)) {
    hq_ = !hq_;
  } else if (e.key == settings_.key(Action::ResetCamera)) {
    // The camera as the mode has it: no swivel, pitch or roll, the lens it started with.
    swivel_ = pitch_ = roll_ = 0;
    static constexpr float kLens[3] = {24.0f, 18.0f, 70.0f};
    focal_[int(camera_)] = kLens[int(camera_)];
  } else if (e.key == KeyBackspace) {
    restart();
  }
}

CarControls DriveProgram::player_controls(const InputState& in) const {
  CarControls c;
  c.throttle = in.held(settings_.key(Action::Throttle)) ? 1.0f : 0.0f;
  c.brake = in.held(settings_.key(Action::Brake)) ? 1.0f : 0.0f;
  c.steer = (in.held(settings_.key(Action::Left)) ? 1.0f : 0.0f) - (in.held(settings_.key(Action::Right)) ? 1.0f : 0.0f);
  if (pad_.connected) {
    c.throttle = std::max(c.throttle, std::clamp(pad_.throttle, 0.0f, 1.0f));
    c.brake = std::max(c.brake, std::clamp(pad_.brake, 0.0f, 1.0f));
    if (std::abs(pad_.steer) > 0.08f) c.steer = std::clamp(-pad_.steer, -1.0f, 1.0f);
  }
  return c;
}

void DriveProgram::update(double dt_d, const InputState& in) {
  const float dt = float(dt_d);
  if (!attract_) {
    // The seed's camera controls: focal length, swivel, pitch, roll.
    float& f = focal_[int(camera_)];
    if (in.held('[')) f = std::max(10.0f, f * std::pow(0.5f, dt));
    if (in.held(']')) f = std::min(300.0f, f * std::pow(2.0f, dt));
    if (in.held('q')) swivel_ += dt * 1.5f;
    if (in.held('e')) swivel_ -= dt * 1.5f;
    if (in.held(KeyPageUp)) pitch_ = std::min(pitch_ + dt, 1.2f);
    if (in.held(KeyPageDown)) pitch_ = std::max(pitch_ - dt, -1.2f);
    if (in.held(',')) roll_ += dt;
    if (in.held('.')) roll_ -= dt;
  }
  // The race runs in fixed ticks, as many as the time asked for has room for.
  clock_ += dt_d;
  const long due = long(std::floor(clock_ / Race::kTick + 1e-6));
  while (race_.tick() < due && !finished()) {
    if (options_.replay) controls_ = options_.replay->ticks[size_t(race_.tick())];
    else if (attract_) controls_ = race_.follow_line(race_.car(0));
    else controls_ = player_controls(in);
    race_.step(controls_);
    if (!attract_) recording_.ticks.push_back(controls_);
    pending_crashes_ += race_.crashes_this_tick();
    for (const Race::LapEvent& e : race_.events()) lap_finished(e);
  }
  if (message_time_ > 0) message_time_ -= dt_d;
  pose_scene();
  place_camera(dt);
}

void DriveProgram::lap_finished(const Race::LapEvent& e) {
  if (e.car != 0 || attract_) return;
  message_time_ = 4.0;
  if (!e.counted) {
    message_ = "LAP NOT COUNTED: A CHECKPOINT WAS MISSED";
    return;
  }
  message_ = "LAP " + lap_clock(e.ticks) + (e.best ? "  BEST LAP!" : "");
  if (e.best && race_.best_lap() && !options_.best_lap_file.empty() && !options_.replay) {
    // Kept whole or not at all: written beside and renamed.
    std::error_code ec;
    std::filesystem::path path(options_.best_lap_file);
    std::filesystem::create_directories(path.parent_path(), ec);
    std::string part = options_.best_lap_file + ".part";
    {
      std::ofstream out(part, std::ios::binary);
      out << format_lap(*race_.best_lap(), circuit_->length());
    }
    std::filesystem::rename(part, path, ec);
    if (ec) std::fprintf(stderr, "velocity: cannot keep the best lap in %s: %s\n", path.c_str(), ec.message().c_str());
  }
}

void DriveProgram::place_camera(float dt) {
  Camera& cam = scene_.camera;
  cam.fov_y = Camera::fov_from_focal_length(focal_[int(camera_)]);
  const CarState& s = race_.car(0).state;
  const Vec3 car = s.position;
  switch (camera_) {
    case CameraMode::Chase: {
      // Behind and above, swinging round after the car with a little lag.
      float lag = 1.0f - std::exp(-dt * 4.0f);
      chase_yaw_ += std::remainder(s.heading - chase_yaw_, 2 * kPi) * (dt > 0 ? lag : 1.0f);
      float yaw = chase_yaw_ + swivel_;
      cam.position = car - forward(yaw) * 7.5f + Vec3{0, 2.4f, 0};
      float ground = circuit_->height(cam.position.x, cam.position.z);
      cam.position.y = std::max(cam.position.y, ground + 0.8f);
      cam.roll = 0;
      cam.look_at(car + Vec3{0, 0.9f, 0});
      cam.pitch += pitch_;
      cam.roll = roll_;
      break;
    }
    case CameraMode::Cockpit: {
      // The driver's eyes, on the left of the cabin, looking over the dashboard; the
      // car's pitch and roll are the camera's.
      std::vector<Mat4> world = scene_.world_matrices();
      cam.position = world[cars_[0].root].transform_point({-0.38f, 1.22f, 0.05f});
      cam.yaw = s.heading + swivel_;
      cam.pitch = s.pitch - 0.06f + pitch_;
      cam.roll = s.roll + roll_ + std::clamp(-s.lateral * 0.004f, -0.05f, 0.05f);
      break;
    }
    case CameraMode::Trackside: {
      // The nearest post follows the car.
      Vec3 best = posts_[0];
      for (const Vec3& p : posts_)
        if (length(p - car) < length(best - car)) best = p;
      cam.position = best;
      cam.roll = 0;
      cam.look_at(car + Vec3{0, 0.8f, 0});
      cam.yaw += swivel_;
      cam.pitch += pitch_;
      cam.roll = roll_;
      break;
    }
  }
}

std::vector<HudPanel> DriveProgram::hud() const {
  // Panels flow from the bottom left, a row at a time, each as wide as its text; a panel
  // that does not fit the row starts a row above. The band at the top is the frame-rate
  // overlay's. The text scale shrinks until the widest panel fits the frame.
  const RaceCar& p = race_.car(0);
  static const char* const names[] = {"CHASE", "COCKPIT", "TRACKSIDE"};
  char buf[96];
  std::vector<std::vector<std::string>> content;
  std::snprintf(buf, sizeof buf, "%3.0f KM/H", std::abs(p.state.speed) * 3.6f);
  content.push_back({buf});
  long now = p.lap_start >= 0 ? race_.tick() - p.lap_start : 0;
  std::string lap = "LAP " + std::to_string(p.laps + 1) + "  " + lap_clock(now);
  content.push_back({lap, "BEST " + (p.best_lap ? lap_clock(p.best_lap) : std::string("-:--.--"))});
  if (race_.cars() > 1) {
    // Who is ahead: laps done, then distance along this lap.
    auto progress = [&](const RaceCar& c) { return double(c.laps) * circuit_->length() + c.where.s; };
    int place = 1;
    for (size_t i = 1; i < race_.cars(); ++i) place += progress(race_.car(i)) > progress(p);
    content.push_back({"POSITION " + std::to_string(place) + "/" + std::to_string(race_.cars())});
  }
  std::snprintf(buf, sizeof buf, "%s %.0fMM", names[int(camera_)], focal_[int(camera_)]);
  std::vector<std::string> mode = {buf};
  if (hq_ || settings_.ssaa > 1) mode.push_back(hq_ ? "HQ 3X3" : (std::to_string(settings_.ssaa) + "X SSAA"));
  if (p.state.skidding) mode.push_back("SKID");
  content.push_back(mode);
  if (message_time_ > 0 && !message_.empty()) content.push_back({message_});

  const int top = stats_band_height(height_);
  int scale = std::max(1, height_ / 200);
  auto panel_w = [&](const std::vector<std::string>& lines, int s) {
    int w = 0;
    for (const std::string& l : lines) w = std::max(w, text_width(l, s));
    return w + 6 * s;
  };
  auto widest = [&](int s) {
    int w = 0;
    for (const auto& c : content) w = std::max(w, panel_w(c, s));
    return w;
  };
  while (scale > 1 && widest(scale) > width_) --scale;
  std::vector<HudPanel> panels;
  const int gap = 2 * scale;
  int x = 0, row_bottom = height_, row_h = 0;
  for (const auto& c : content) {
    HudPanel hp;
    hp.scale = scale;
    hp.lines = c;
    for (std::string& l : hp.lines) l = ellipsize(l, width_ - 6 * scale, scale);
    hp.w = std::min(panel_w(hp.lines, scale), width_);
    hp.h = int(hp.lines.size()) * 9 * scale + 4 * scale;
    if (x > 0 && x + hp.w > width_) {  // a new row above
      row_bottom -= row_h + gap;
      x = 0, row_h = 0;
    }
    hp.x = x, hp.y = row_bottom - hp.h;
    if (hp.y < top) break;  // no room left below the overlay band: the rest is not shown
    row_h = std::max(row_h, hp.h);
    x += hp.w + gap;
    panels.push_back(std::move(hp));
  }
  return panels;
}

void DriveProgram::frame(FrameDescription& out) {
  out.scene = scene_;
  out.options.ssaa = hq_ ? 3 : std::clamp(settings_.ssaa, 1, 3);
  out.options.filter = settings_.filter;
  // Nine samples a pixel already average the texels: in the high-quality mode bilinear
  // filtering adds little but costs a fifth of the frame (trilinear, asked for, stays).
  if (hq_ && settings_.filter == Filter::Bilinear) out.options.filter = Filter::Nearest;
  // The dashboard only from the driver's seat; from there the body would hide the road.
  auto hide_under = [&](ObjectId top) {
    for (ObjectId id = 0; id < out.scene.objects().size(); ++id) {
      ObjectId q = id;
      while (q != kNoParent && q != top) q = out.scene.object(q).parent;
      if (q == top) out.scene.object(id).visible = false;
    }
  };
  if (camera_ == CameraMode::Cockpit && !attract_) hide_under(cars_[0].body);
  else hide_under(dashboard_);
  if (attract_) return;
  for (const HudPanel& p : hud()) {
    out.overlay.rect(p.x, p.y, p.w, p.h, {0, 0, 0, 150});
    for (size_t i = 0; i < p.lines.size(); ++i)
      out.overlay.text(p.x + 3 * p.scale, p.y + 3 * p.scale + int(i) * 9 * p.scale, p.lines[i], {255, 255, 255, 255},
                       p.scale);
  }
}

void DriveProgram::sound(Synth& synth) {
  const CarState& s = race_.car(0).state;
  synth.set_engine(true, engine_hz(s.speed), 0.3f + 0.2f * controls_.throttle);
  for (; pending_crashes_ > 0; --pending_crashes_) synth.play(Effect::Crash);
}

ShellText drive_shell_text() {
  ShellText text;
  text.title = "VELOCITY DRIVE";
  text.subtitle = "A RACE ROUND A HILLSIDE CIRCUIT";
  text.start = "DRIVE";
  text.credits =
      "*VELOCITY DRIVE\n\nA RACE ROUND A HILLSIDE CIRCUIT\nIN THE STYLE OF 1990S 3D DRIVING GAMES\n\n\n"
      "*ENGINE\nVELOCITY SOFTWARE RENDERER\nFLAT, GOURAUD AND PHONG SHADING\nTEXTURE AND ENVIRONMENT MAPS\n\n\n"
      "*CONTROLS\nUP  THROTTLE     DOWN  BRAKE\nLEFT / RIGHT  STEER\nC  CAMERA     H  HIGH QUALITY\n"
      "[ ]  FOCAL LENGTH     Q E  SWIVEL\nPGUP PGDN  PITCH     , .  ROLL\nR  CAMERA BACK     P  PAUSE\n"
      "F1  HELP     ESC  MENU\n\n\n"
      "*SOUND\nSYNTHESISED AS YOU LISTEN\n\n\n"
      "*DRIVE SAFELY\n";
  text.bindings = {{Action::Throttle, "THROTTLE"},   {Action::Brake, "BRAKE"},
                   {Action::Left, "STEER LEFT"},     {Action::Right, "STEER RIGHT"},
                   {Action::Camera, "CAMERA"},       {Action::HighQuality, "HIGH QUALITY"},
                   {Action::ResetCamera, "CAMERA BACK"}};
  return text;
}

}  // namespace velocity::realtime
