#include "programs/fly.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "programs/shapes.hpp"
#include "runtime/synth.hpp"
#include "velocity/load.hpp"

namespace velocity::realtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

Material flat(Vec3 color) {
  Material m;
  m.color = color;
  m.shading = Shading::Flat;
  return m;
}

// The forward direction of a camera turned by yaw, then pitch (looking down its -Z).
Vec3 forward(float yaw, float pitch) {
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

float wrap(float v) {
  const float half = FlyProgram::kWorld / 2;
  if (v > half) v -= FlyProgram::kWorld;
  if (v < -half) v += FlyProgram::kWorld;
  return v;
}

}  // namespace

FlyProgram::FlyProgram(FlyOptions options) {
  build_world(options);
  restart();
}

void FlyProgram::restart() {
  pos_ = {0, 40, 0};
  yaw_ = 0, pitch_ = 0, speed_ = kStartSpeed;
  place_camera();
}

void FlyProgram::build_world(const FlyOptions& o) {
  std::mt19937 rng(o.seed);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };

  // The ground: a checkerboard of flat tiles, by face colour.
  const int cells = 20;
  auto ground = std::make_shared<Mesh>(make_plane_grid(kWorld * 1.4f, cells));
  for (size_t t = 0; t < ground->triangles.size(); ++t) {
    size_t cell = t / 2;
    bool dark = ((cell % cells) + (cell / cells)) % 2;
    ground->face_colors.push_back(dark ? Vec3{0.10f, 0.22f, 0.14f} : Vec3{0.16f, 0.34f, 0.2f});
  }
  ground->materials.push_back(flat({1, 1, 1}));  // the face colours show through
  ground->materials.back().two_sided = true;
  scene_.add_object("ground", ground);

  // The shapes: the given models (each normalised to radius 1), else the built-ins.
  std::vector<std::shared_ptr<const Mesh>> shapes;
  for (const std::string& path : o.models) {
    try {
      Model model = load_model(path);
      for (const ModelNode& n : model.nodes)
        if (n.mesh && n.mesh->triangle_count() > 0) {
          Mesh m = *n.mesh;
          normalize_to_unit_sphere(m);
          shapes.push_back(std::make_shared<const Mesh>(std::move(m)));
          break;
        }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "velocity: skipping %s\n", e.what());
    }
  }
  const bool own_colours = !shapes.empty();
  if (shapes.empty()) {
    shapes.push_back(std::make_shared<const Mesh>(make_cube(1.2f)));
    shapes.push_back(std::make_shared<const Mesh>(make_pyramid()));
    shapes.push_back(std::make_shared<const Mesh>(make_torus(0.7f, 0.3f, 16, 8)));
  }
  const Vec3 palette[] = {{0.9f, 0.3f, 0.25f}, {0.25f, 0.55f, 0.95f}, {0.95f, 0.8f, 0.2f},
                          {0.6f, 0.3f, 0.85f}, {0.3f, 0.85f, 0.6f},  {0.95f, 0.55f, 0.2f}};

  // Objects on a jittered grid, so they never overlap; every fifth is a station with
  // two moons orbiting it (children of a spinning hub).
  const int n = std::clamp(o.objects, 1, 2000);
  const int side = int(std::ceil(std::sqrt(float(n))));
  const float cell = kWorld / float(side);
  for (int i = 0; i < n; ++i) {
    float size = uniform(9.0f, 24.0f);
    Vec3 at{(float(i % side) + 0.5f) * cell - kWorld / 2 + uniform(-0.2f, 0.2f) * cell, uniform(size + 8, 110.0f),
            (float(i / side) + 0.5f) * cell - kWorld / 2 + uniform(-0.2f, 0.2f) * cell};
    if (std::abs(at.x) < cell && std::abs(at.z) < cell) continue;  // keep the start clear
    auto shape = shapes[size_t(i) % shapes.size()];
    ObjectId id = scene_.add_object("object", shape);
    Object& obj = scene_.object(id);
    obj.transform.translation = at;
    obj.transform.scale = {size, size, size};
    obj.transform.rotation = {uniform(0, kPi), uniform(0, kPi), 0};
    if (!own_colours) obj.material = flat(palette[size_t(i) % std::size(palette)]);
    if (i % 5 == 0) {
      // A station: a hub that spins, and two moons on it.
      ObjectId hub = scene_.add_object("hub", nullptr);
      scene_.object(hub).transform.translation = at;
      spinners_.push_back(hub);
      spin_rates_.push_back(uniform(0.3f, 0.8f));
      for (int k = 0; k < 2; ++k) {
        ObjectId moon = scene_.add_object("moon", shapes[size_t(i + k + 1) % shapes.size()], hub);
        float r = size * 2.2f;
        scene_.object(moon).transform.translation = {k ? r : -r, 0, 0};
        scene_.object(moon).transform.scale = {size * 0.35f, size * 0.35f, size * 0.35f};
        if (!own_colours) scene_.object(moon).material = flat(palette[size_t(i + k + 2) % std::size(palette)]);
        solids_.push_back({moon, size * 0.35f * 1.05f});
      }
    }
    spinners_.push_back(id);
    spin_rates_.push_back(uniform(-0.6f, 0.6f));
    solids_.push_back({id, size * 1.05f});
  }

  // Light: a little ambient and a point light high over the world.
  scene_.lights.push_back(Light::ambient({0.28f, 0.28f, 0.3f}));
  scene_.lights.push_back(Light::point({-300, 600, 200}, {1.0f, 0.97f, 0.9f}));
  scene_.background = {0.05f, 0.06f, 0.16f};
  scene_.camera.fov_y = radians(60);
  scene_.camera.near = 1.0f;
  scene_.camera.far = 900.0f;
}

Sphere FlyProgram::solid(size_t i) const {
  const Solid& s = solids_.at(i);
  return {scene_.world_matrices()[s.id].transform_point({0, 0, 0}), s.radius};
}

void FlyProgram::place(Vec3 position, float yaw, float pitch) {
  pos_ = position, yaw_ = yaw, pitch_ = pitch;
  place_camera();
}

void FlyProgram::event(const InputEvent&, const InputState&) {}

void FlyProgram::place_camera() {
  Camera& c = scene_.camera;
  c.position = pos_;
  c.yaw = yaw_;
  c.pitch = pitch_;
  c.roll = 0;
}

void FlyProgram::update(double dt_d, const InputState& in) {
  const float dt = float(dt_d);
  time_ += dt_d;
  float turn = 0, climb = 0, accel = 0;
  if (attract_) {
    turn = 0.25f;  // a lazy circle behind the menus
    climb = pos_.y < 50 ? 0.3f : pos_.y > 70 ? -0.3f : 0.0f;
    speed_ = kStartSpeed;
  } else {
    auto held = [&](Action a) { return in.held(settings_.key(a)); };
    if (held(Action::Left)) turn += 1;
    if (held(Action::Right)) turn -= 1;
    if (held(Action::Throttle)) climb -= 1;  // dive
    if (held(Action::Brake)) climb += 1;
    if (in.held(KeyCtrl) || held(Action::Faster)) accel += 1;
    if (in.held(KeyShift) || held(Action::Slower)) accel -= 1;
    // A game controller: the left stick steers and dives or climbs, the triggers
    // change speed.
    if (pad_.connected) {
      if (std::abs(pad_.steer) > 0.08f) turn = std::clamp(-pad_.steer, -1.0f, 1.0f);
      if (std::abs(pad_.pitch) > 0.08f) climb = std::clamp(pad_.pitch, -1.0f, 1.0f);
      accel += pad_.throttle - pad_.brake;
    }
  }
  yaw_ += turn * kTurnRate * dt;
  if (attract_) pitch_ = climb * 0.2f;
  else pitch_ = std::clamp(pitch_ + climb * kPitchRate * dt, -1.2f, 1.2f);
  speed_ = std::clamp(speed_ + accel * kAccel * dt, kMinSpeed, kMaxSpeed);
  pos_ = pos_ + forward(yaw_, pitch_) * (speed_ * dt);
  if (pos_.y < kMinAltitude) {
    pos_.y = kMinAltitude;
    pitch_ = std::max(pitch_, 0.0f);
  }
  pos_.y = std::min(pos_.y, 400.0f);
  pos_.x = wrap(pos_.x), pos_.z = wrap(pos_.z);

  // Turn the spinners.
  for (size_t i = 0; i < spinners_.size(); ++i)
    scene_.object(spinners_[i]).transform.rotation.y += spin_rates_[i] * dt;

  // Collisions: the viewer's sphere against each object's bounding sphere. The viewer
  // is pushed back out to the surface and loses most of its speed.
  std::vector<Mat4> world = scene_.world_matrices();
  for (const Solid& s : solids_) {
    Vec3 c = world[s.id].transform_point({0, 0, 0});
    Vec3 d = pos_ - c;
    float dist = length(d), min_dist = s.radius + kViewerRadius;
    if (dist < min_dist) {
      Vec3 n = dist > 1e-4f ? d * (1.0f / dist) : Vec3{0, 1, 0};
      pos_ = c + n * min_dist;
      speed_ *= 0.25f;
      ++collisions_;
      ++pending_crashes_;
    }
  }
  clearance_ = 1e30f;
  for (const Solid& s : solids_)
    clearance_ = std::min(clearance_, length(pos_ - world[s.id].transform_point({0, 0, 0})) - s.radius);
  place_camera();
}

void FlyProgram::frame(FrameDescription& out) {
  out.scene = scene_;
  out.options.depth_mode = DepthMode::ZBuffer;
  out.options.shading = Shading::Flat;  // the seed's look: flat shading
  out.options.ssaa = std::clamp(settings_.ssaa, 1, 3);
  out.options.filter = settings_.filter;

  // Reject objects by their bounding sphere: behind the viewer, beyond the far plane or
  // outside the view cone (the sphere's distance to each side plane).
  const Camera& c = scene_.camera;
  Mat4 view = c.view();
  float aspect = float(width_) / float(std::max(height_, 1));
  float ty = std::tan(c.fov_y / 2), tx = ty * aspect;
  float ny = 1.0f / std::sqrt(1 + ty * ty), nx = 1.0f / std::sqrt(1 + tx * tx);  // plane normal terms
  std::vector<Mat4> world = out.scene.world_matrices();
  rejected_ = 0;
  for (const Solid& s : solids_) {
    Vec3 p = view.transform_point(world[s.id].transform_point({0, 0, 0}));
    float z = -p.z, r = s.radius;
    bool outside = z + r < c.near || z - r > c.far || (std::abs(p.x) - tx * z) * nx > r ||
                   (std::abs(p.y) - ty * z) * ny > r;
    if (outside) {
      out.scene.object(s.id).visible = false;
      ++rejected_;
    }
  }

  if (attract_) return;
  const int s = std::max(1, height_ / 200);
  char hud[160];
  float heading = std::fmod(std::fmod(-yaw_ * 180.0f / kPi, 360.0f) + 360.0f, 360.0f);
  std::snprintf(hud, sizeof hud, "SPEED %3.0f  HEADING %03.0f  ALT %3.0f  SEEN %zu/%zu", speed_, heading,
                pos_.y, solids_.size() - rejected_, solids_.size());
  out.overlay.rect(0, height_ - 11 * s, width_, 11 * s, {0, 0, 0, 140});
  out.overlay.text(3 * s, height_ - 9 * s, hud, {160, 255, 170, 255}, s);
}

void FlyProgram::sound(Synth& synth) {
  // A soft hum whose pitch follows the speed (the seed's engine drone).
  synth.set_engine(!attract_, 70.0f + speed_ * 0.8f, 0.25f);
  for (; pending_crashes_ > 0; --pending_crashes_) synth.play(Effect::Crash);
}

std::string FlyProgram::help() const {
  auto k = [&](Action a) { return key_label(settings_.key(a)); };
  return "FLY\n\n" + k(Action::Left) + " / " + k(Action::Right) + "  TURN\n" + k(Action::Throttle) + "  DIVE     " +
         k(Action::Brake) + "  CLIMB\n" + k(Action::Faster) + " OR CTRL  FASTER\n" + k(Action::Slower) +
         " OR SHIFT  SLOWER\n\nP  PAUSE     ESC  MENU (RESUME, RESTART, OPTIONS)\n\n"
         "FLY AMONG THE STATIONS AND THEIR MOONS.\nYOU CANNOT FLY THROUGH THEM.\n"
         "GAMEPAD: STICK STEERS, TRIGGERS CHANGE SPEED";
}

ShellText fly_shell_text() {
  ShellText text;
  text.title = "VELOCITY FLIGHT";
  text.subtitle = "A POLYGON FLYTHROUGH";
  text.start = "FLY";
  text.credits =
      "*VELOCITY FLIGHT\n\nA FLIGHT AMONG STATIONS AND MOONS\nIN THE STYLE OF 1990S 3D DEMOS\n\n\n"
      "*ENGINE\nVELOCITY SOFTWARE RENDERER\nEVERY PIXEL ON THE CPU\n\n\n"
      "*CONTROLS\nLEFT / RIGHT  TURN\nUP  DIVE     DOWN  CLIMB\nA or CTRL  FASTER\nZ or SHIFT  SLOWER\nP  PAUSE     F1  HELP     ESC  MENU\n\n\n"
      "*MODELS\nCUBES, PYRAMIDS AND TORI\nOR YOUR OWN PLG FILES\n\n\n"
      "*MUSIC AND SOUND\nSYNTHESISED AS YOU LISTEN\n\n\n"
      "*THANK YOU FOR FLYING\n";
  text.bindings = {{Action::Throttle, "DIVE"},    {Action::Brake, "CLIMB"},  {Action::Left, "TURN LEFT"},
                   {Action::Right, "TURN RIGHT"}, {Action::Faster, "FASTER"}, {Action::Slower, "SLOWER"}};
  return text;
}

}  // namespace velocity::realtime
