#include "programs/drive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "programs/shapes.hpp"
#include "runtime/synth.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/texture.hpp"

namespace velocity::realtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kGravity = 9.81f;
// The car: engine pull at rest, braking, reversing, air drag, rolling resistance, grip.
constexpr float kEngine = 7.5f, kBrake = 11.0f, kReverse = 3.0f, kReverseTop = 9.0f;
constexpr float kDrag = kEngine / (kTopSpeed * kTopSpeed) * 0.35f, kRolling = 0.25f, kGrip = 0.95f;
constexpr float kSteerRate = 2.2f;  // radians a second at the front wheels
constexpr float kCarRadius = 2.0f;  // for bumping into things
// The track: two 200 m straights joined by half circles of radius 70 m, 12 m wide.
constexpr float kStraight = 200.0f, kBend = 70.0f, kRoadWidth = 12.0f, kGround = 900.0f;

Vec3 forward(float heading) { return {-std::sin(heading), 0, -std::cos(heading)}; }

// A point on the track's centre line, `s` metres from the start (the car's grid spot,
// heading along -Z on the right-hand straight).
Vec3 track_point(float s) {
  const float arc = kPi * kBend, lap = 2 * kStraight + 2 * arc;
  s = std::fmod(std::fmod(s, lap) + lap, lap);
  const float h = kStraight / 2;
  if (s < kStraight) return {kBend, 0, h - s};
  s -= kStraight;
  if (s < arc) {
    float t = s / kBend;
    return {kBend * std::cos(t), 0, -h - kBend * std::sin(t)};
  }
  s -= arc;
  if (s < kStraight) return {-kBend, 0, -h + s};
  float t = (s - kStraight) / kBend;
  return {-kBend * std::cos(t), 0, h + kBend * std::sin(t)};
}

float track_length() { return 2 * kStraight + 2 * kPi * kBend; }

// Generated textures (nothing to ship): grass, asphalt with white edges and a dashed
// centre line, and a wall of windows.
uint8_t to8(float v) { return uint8_t(std::lrint(std::clamp(v, 0.0f, 1.0f) * 255)); }

std::shared_ptr<const Texture> grass_texture() {
  Image img(256, 256);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      float blotch = 0.5f + 0.25f * std::sin(float(x) * 0.0491f * 2) * std::cos(float(y) * 0.0491f * 3);
      float n = u(rng) * 0.08f;
      uint8_t* p = img.pixel(x, y);
      p[0] = to8(0.22f + 0.1f * blotch + n), p[1] = to8(0.42f + 0.14f * blotch + n), p[2] = to8(0.16f + n * 0.5f);
      p[3] = 255;
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
      uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = to8(g);
      p[3] = 255;
    }
  return std::make_shared<const Texture>(img);
}

std::shared_ptr<const Texture> windows_texture() {
  Image img(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      bool window = (x % 16) >= 4 && (x % 16) < 12 && (y % 16) >= 4 && (y % 16) < 12;
      bool lit = window && ((x / 16 + y / 16 * 3) % 4 == 0);
      uint8_t* p = img.pixel(x, y);
      Vec3 c = lit ? Vec3{0.95f, 0.85f, 0.5f} : window ? Vec3{0.25f, 0.35f, 0.5f} : Vec3{0.75f, 0.72f, 0.68f};
      p[0] = to8(c.x), p[1] = to8(c.y), p[2] = to8(c.z), p[3] = 255;
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

}  // namespace

void step_car(CarState& car, const CarControls& c, float dt) {
  const float v = car.speed;
  float a = 0;
  if (c.throttle > 0) a += v >= 0 ? c.throttle * kEngine * std::max(0.0f, 1.0f - v / kTopSpeed) : c.throttle * kBrake;
  if (c.brake > 0) {
    if (v > 0.3f) a -= c.brake * kBrake;
    else a -= c.brake * kReverse * std::max(0.0f, 1.0f + v / kReverseTop);
  }
  a -= kDrag * v * std::abs(v);
  if (std::abs(v) > 0.05f) a -= kRolling * (v > 0 ? 1.0f : -1.0f);
  float nv = v + a * dt;
  // Friction stops the car; it does not drive it backwards.
  if (c.throttle <= 0 && c.brake <= 0 && nv * v < 0) nv = 0;
  if (c.throttle > 0 && v < 0 && nv > 0) nv = 0;
  if (c.brake > 0 && v > 0.3f && nv < 0) nv = 0;
  car.speed = nv;
  car.accel = a;

  // Steering: less lock at speed (as drivers do), turned at a limited rate.
  float target = std::clamp(c.steer, -1.0f, 1.0f) * kMaxSteer / (1.0f + std::abs(nv) / 15.0f);
  float ds = std::clamp(target - car.steer, -kSteerRate * dt, kSteerRate * dt);
  car.steer += ds;

  // A bicycle model: the yaw rate the wheels ask for, limited by what the tyres can
  // hold (lateral acceleration v * yaw rate <= grip * g); beyond it the car runs wide.
  float yaw_rate = nv * std::tan(car.steer) / kWheelBase;
  float lateral = std::abs(nv * yaw_rate), limit = kGrip * kGravity;
  car.skidding = lateral > limit;
  if (car.skidding) yaw_rate *= limit / lateral;
  car.lateral = nv * yaw_rate;
  car.heading += yaw_rate * dt;
  car.position = car.position + forward(car.heading) * (nv * dt);
  car.position.y = 0;  // the ground is level: the car stays on it
  car.wheel_spin += nv / kWheelRadius * dt;
}

float DriveProgram::engine_hz(float speed) { return 55.0f + 6.5f * std::abs(speed); }

DriveProgram::DriveProgram(DriveOptions o) : hq_(o.high_quality) {
  build_track();
  build_car(o);
  restart();
}

void DriveProgram::restart() {
  car_ = {};
  car_.position = track_point(0);
  car_.heading = 0;
  chase_yaw_ = car_.heading;
  controls_ = {};
  pose_car();
  place_camera(0);
}

void DriveProgram::build_track() {
  // Ground: grass, 10 m a texture repeat.
  auto ground = std::make_shared<Mesh>(make_plane_grid(kGround, 12));
  for (Vec2& uv : ground->uvs) uv = {uv.x * kGround / 10, uv.y * kGround / 10};
  Material grass = material({1, 1, 1}, Shading::Gouraud);
  grass.texture = grass_texture();
  ground->materials.push_back(grass);
  scene_.add_object("ground", ground);

  // Road: a strip along the centre line, u across, v along (12 m a repeat).
  auto road = std::make_shared<Mesh>();
  const float lap = track_length();
  const int n = 240;
  for (int i = 0; i <= n; ++i) {
    float s = lap * float(i) / float(n);
    Vec3 p = track_point(s), q = track_point(s + 0.5f);
    Vec3 t = normalize(q - p), side{-t.z, 0, t.x};  // to the right of the direction of travel
    if (i < n) centre_line_.push_back(p);
    Vec3 l = p - side * (kRoadWidth / 2), r = p + side * (kRoadWidth / 2);
    l.y = r.y = 0.04f;
    road->positions.insert(road->positions.end(), {l, r});
    road->uvs.insert(road->uvs.end(), {{0, s / 12}, {1, s / 12}});
    road->normals.insert(road->normals.end(), {{0, 1, 0}, {0, 1, 0}});
    if (i > 0) {
      uint32_t a = uint32_t(2 * i - 2);
      road->triangles.push_back({{a, a + 2, a + 1}});
      road->triangles.push_back({{a + 1, a + 2, a + 3}});
    }
  }
  // Wind the strip upwards whichever way the loop above went.
  for (Triangle& tri : road->triangles) {
    Vec3 a = road->positions[tri.v[0]], b = road->positions[tri.v[1]], c = road->positions[tri.v[2]];
    if (cross(b - a, c - a).y < 0) std::swap(tri.v[1], tri.v[2]);
  }
  Material asphalt = material({1, 1, 1}, Shading::Gouraud);
  asphalt.texture = road_texture();
  road->materials.push_back(asphalt);
  scene_.add_object("road", road);

  // Scenery, away from the road.
  std::mt19937 rng(3);
  auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
  auto clear_of_road = [&](Vec3 p, float margin) {
    for (const Vec3& c : centre_line_)
      if (length(p - c) < kRoadWidth / 2 + margin) return false;
    return true;
  };
  auto foliage = std::make_shared<const Mesh>(make_cone(10));
  auto trunk = std::make_shared<const Mesh>(make_wheel(8, {0.35f, 0.22f, 0.1f}, {0.3f, 0.2f, 0.1f}, {0.3f, 0.2f, 0.1f},
                                                       {0.3f, 0.2f, 0.1f}));
  for (int placed = 0, tries = 0; placed < 70 && tries < 2000; ++tries) {
    Vec3 p{uniform(-260, 260), 0, uniform(-300, 300)};
    if (!clear_of_road(p, 6)) continue;
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
    solids_.push_back({p, 0.6f});
    ++placed;
  }
  // Buildings around the outside, with lit windows.
  auto box = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) { return p; }));
  Material wall = material({1, 1, 1}, Shading::Flat);
  wall.texture = windows_texture();
  for (int i = 0; i < 10; ++i) {
    float angle = float(i) / 10 * 2 * kPi + 0.2f;
    Vec3 p{std::cos(angle) * 230, 0, std::sin(angle) * 330};
    Vec3 size{uniform(18, 34), uniform(14, 40), uniform(18, 34)};
    ObjectId b = scene_.add_object("building", box);
    scene_.object(b).transform.translation = p + Vec3{0, size.y / 2, 0};
    scene_.object(b).transform.scale = size;
    scene_.object(b).transform.rotation = {0, -angle, 0};
    scene_.object(b).material = wall;
    solids_.push_back({p, std::min(size.x, size.z) * 0.6f});
  }
  // Cones on the inside of the straights and a start gantry post either side.
  auto cone = std::make_shared<const Mesh>(make_cone(8));
  for (int i = 0; i < 16; ++i) {
    float z = -kStraight / 2 + 12.5f * float(i) + 6;
    for (float x : {kBend - kRoadWidth / 2 - 1.5f, -kBend + kRoadWidth / 2 + 1.5f}) {
      ObjectId c = scene_.add_object("cone", cone);
      scene_.object(c).transform.translation = {x, 0, z};
      scene_.object(c).transform.scale = {0.35f, 0.8f, 0.35f};
      scene_.object(c).material = material({1.0f, 0.45f, 0.05f}, Shading::Flat);
      solids_.push_back({{x, 0, z}, 0.35f});
    }
  }
  // Trackside camera posts: the outside of each bend and the middle of each straight.
  posts_ = {{kBend + 25, 7, 0}, {-kBend - 25, 7, 0}, {0, 9, -kStraight / 2 - kBend - 30},
            {0, 9, kStraight / 2 + kBend + 30}};

  scene_.lights.push_back(Light::ambient({0.35f, 0.36f, 0.4f}));
  scene_.lights.push_back(Light::directional({0.4f, 0.8f, 0.3f}, {0.85f, 0.82f, 0.75f}));
  scene_.background = {0.55f, 0.72f, 0.92f};
  scene_.camera.near = 0.25f;
  scene_.camera.far = 700.0f;
}

void DriveProgram::build_car(const DriveOptions& o) {
  auto studio = std::make_shared<const Texture>(make_environment_map(256));
  car_root_ = scene_.add_object("car", nullptr);
  body_ = scene_.add_object("body", nullptr, car_root_);
  if (o.car.empty()) {
    // Body: a wedge (the bonnet slopes down to the nose, at -Z); cabin: a glasshouse
    // narrower at the top.
    auto body = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) {
      Vec3 q{p.x * 1.62f, p.y * 0.55f + 0.62f, p.z * 4.3f};
      if (p.y > 0 && p.z < 0) q.y -= 0.16f;
      if (p.y < 0) q.y += 0.02f;
      return q;
    }));
    Material paint = material({0.78f, 0.06f, 0.05f}, Shading::Phong, 0.7f, 60);
    paint.env_map = studio;
    paint.env_mix = 0.3f;
    ObjectId b = scene_.add_object("shell", body, body_);
    scene_.object(b).material = paint;
    auto cabin = std::make_shared<const Mesh>(make_shaped_box([](Vec3 p) {
      Vec3 q{p.x * 1.44f, p.y * 0.5f + 1.14f, p.z * 2.1f + 0.35f};
      if (p.y > 0) q.x *= 0.86f, q.z = p.z * 1.2f + 0.45f;
      return q;
    }));
    Material glass = material({0.06f, 0.08f, 0.12f}, Shading::Phong, 0.95f, 90);
    glass.env_map = studio;
    glass.env_mix = 0.55f;
    ObjectId c = scene_.add_object("windows", cabin, body_);
    scene_.object(c).material = glass;
    // Lamps (unlit: they glow) and a dark sill along the bottom of the body.
    auto lamp = std::make_shared<const Mesh>(make_cube(1.0f));
    auto add_part = [&](const char* name, Vec3 at, Vec3 size, Vec3 colour, Shading shading) {
      ObjectId id = scene_.add_object(name, lamp, body_);
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
    Model model = load_model(o.car, lo);
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
    if (tris == 0) throw Error(o.car + ": the car model has no triangles");
    Vec3 ext = bb.max - bb.min;
    bool along_x = ext.x > ext.z;
    float length_m = std::max(ext.x, ext.z);
    if (!(length_m > 0)) throw Error(o.car + ": the car model is flat");
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
    ObjectId fit = scene_.add_object("car model", nullptr, body_);
    Transform& t = scene_.object(fit).transform;
    t.scale = {s, s, s};
    // 3D Studio models face its front view: +Z once loaded. Turn the nose to -Z.
    t.rotation = {0, kPi + radians(o.car_yaw) + (along_x ? kPi / 2 : 0.0f), 0};
    Vec3 c = bb.center();
    // Centre it (the rotation is about the model's origin: move the centre there first).
    ObjectId centre = scene_.add_object("car model centre", nullptr, fit);
    scene_.object(centre).transform.translation = {-c.x, -bb.min.y, -c.z};
    scene_.object(fit).transform.translation = {0, 0.12f, 0};
    add_to_scene(scene_, model, centre);
  }
  // Wheels: a mount per wheel (the front ones steer), the wheel under it spins.
  auto wheel = std::make_shared<const Mesh>(
      make_wheel(14, {0.07f, 0.07f, 0.08f}, {0.13f, 0.13f, 0.14f}, {0.75f, 0.76f, 0.8f}, {0.2f, 0.2f, 0.22f}));
  const Vec3 at[4] = {{-0.86f, kWheelRadius, -kWheelBase / 2}, {0.86f, kWheelRadius, -kWheelBase / 2},
                      {-0.86f, kWheelRadius, kWheelBase / 2}, {0.86f, kWheelRadius, kWheelBase / 2}};
  const char* mounts[4] = {"steer_fl", "steer_fr", "mount_rl", "mount_rr"};
  for (int i = 0; i < 4; ++i) {
    ObjectId m = scene_.add_object(mounts[i], nullptr, car_root_);
    scene_.object(m).transform.translation = at[i];
    if (i < 2) steer_[i] = m;
    wheels_[i] = scene_.add_object(kWheelNames[i], wheel, m);
    scene_.object(wheels_[i]).transform.scale = {0.26f, kWheelRadius, kWheelRadius};
  }
}

void DriveProgram::pose_car() {
  Object& root = scene_.object(car_root_);
  root.transform.translation = car_.position;
  root.transform.rotation = {0, car_.heading, 0};
  // The body leans: back under acceleration, out of a turn (springs, not physics).
  Object& body = scene_.object(body_);
  body.transform.rotation = {std::clamp(car_.accel * 0.004f, -0.04f, 0.04f), 0,
                             std::clamp(-car_.lateral * 0.006f, -0.06f, 0.06f)};
  for (int i = 0; i < 2; ++i) scene_.object(steer_[i]).transform.rotation = {0, car_.steer, 0};
  // Rolling forward (-Z) turns the top of the wheel forward: negative about +X.
  for (ObjectId w : wheels_) scene_.object(w).transform.rotation = {-car_.wheel_spin, 0, 0};
}

CarControls DriveProgram::autopilot() const {
  // Aim at the centre line 25 m ahead of the nearest point; hold about 22 m/s.
  size_t nearest = 0;
  float best = 1e30f;
  for (size_t i = 0; i < centre_line_.size(); ++i) {
    float d = length(centre_line_[i] - car_.position);
    if (d < best) best = d, nearest = i;
  }
  Vec3 aim = centre_line_[(nearest + 7) % centre_line_.size()] - car_.position;
  float want = std::atan2(-aim.x, -aim.z);
  float diff = std::remainder(want - car_.heading, 2 * kPi);
  CarControls c;
  c.steer = std::clamp(diff * 2.0f, -1.0f, 1.0f);
  c.throttle = car_.speed < 22 ? 1.0f : 0.0f;
  return c;
}

void DriveProgram::event(const InputEvent& e, const InputState&) {
  if (e.kind != InputEvent::KeyDown) return;
  switch (int(e.key)) {
    case 'c': camera_ = CameraMode((int(camera_) + 1) % 3), swivel_ = pitch_ = roll_ = 0; break;
    case 'h': hq_ = !hq_; break;
    case 'r': restart(); break;
    default: break;
  }
}

void DriveProgram::update(double dt_d, const InputState& in) {
  float dt = float(dt_d);
  if (attract_) {
    controls_ = autopilot();
  } else {
    controls_.throttle = in.held(KeyUp) ? 1.0f : 0.0f;
    controls_.brake = in.held(KeyDown) ? 1.0f : 0.0f;
    controls_.steer = (in.held(KeyLeft) ? 1.0f : 0.0f) - (in.held(KeyRight) ? 1.0f : 0.0f);
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
  // Physics in steps of at most 1/120 s.
  int steps = std::max(1, int(std::ceil(dt * 120.0f)));
  for (int i = 0; i < steps; ++i) {
    step_car(car_, controls_, dt / float(steps));
    // Bump into the scenery and the edge of the world.
    for (const Solid& s : solids_) {
      Vec3 d = car_.position - s.centre;
      d.y = 0;
      float dist = length(d), min = s.radius + kCarRadius;
      if (dist < min) {
        car_.position = s.centre + (dist > 1e-4f ? d * (1.0f / dist) : Vec3{1, 0, 0}) * min;
        car_.position.y = 0;
        if (std::abs(car_.speed) > 2.0f) ++pending_crashes_, ++collisions_;
        car_.speed *= -0.3f;
      }
    }
    const float edge = kGround / 2 - 20;
    if (std::abs(car_.position.x) > edge || std::abs(car_.position.z) > edge) {
      car_.position.x = std::clamp(car_.position.x, -edge, edge);
      car_.position.z = std::clamp(car_.position.z, -edge, edge);
      if (std::abs(car_.speed) > 2.0f) ++pending_crashes_, ++collisions_;
      car_.speed *= -0.3f;
    }
  }
  pose_car();
  place_camera(dt);
}

void DriveProgram::place_camera(float dt) {
  Camera& cam = scene_.camera;
  cam.fov_y = Camera::fov_from_focal_length(focal_[int(camera_)]);
  const Vec3 car = car_.position;
  switch (camera_) {
    case CameraMode::Chase: {
      // Behind and above, swinging round after the car with a little lag.
      float lag = 1.0f - std::exp(-dt * 4.0f);
      chase_yaw_ += std::remainder(car_.heading - chase_yaw_, 2 * kPi) * (dt > 0 ? lag : 1.0f);
      float yaw = chase_yaw_ + swivel_;
      cam.position = car - forward(yaw) * 7.5f + Vec3{0, 2.4f, 0};
      cam.roll = 0;
      cam.look_at(car + Vec3{0, 0.9f, 0});
      cam.pitch += pitch_;
      cam.roll = roll_;
      break;
    }
    case CameraMode::Cockpit: {
      // The driver's eyes, on the left of the cabin, looking over the bonnet.
      Vec3 right{std::cos(car_.heading), 0, -std::sin(car_.heading)};
      cam.position = car + right * -0.38f + forward(car_.heading) * 0.1f + Vec3{0, 1.28f, 0};
      cam.yaw = car_.heading + swivel_;
      cam.pitch = -0.06f + pitch_;
      cam.roll = roll_ + std::clamp(-car_.lateral * 0.004f, -0.05f, 0.05f);
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

void DriveProgram::frame(FrameDescription& out) {
  out.scene = scene_;
  out.options.ssaa = hq_ ? 3 : 1;
  if (camera_ == CameraMode::Cockpit) {
    // From inside, the shell would hide the road: leave the body out, keep the wheels.
    out.scene.object(body_).visible = false;
    for (ObjectId id = 0; id < out.scene.objects().size(); ++id) {
      ObjectId p = out.scene.object(id).parent;
      while (p != kNoParent && p != body_) p = out.scene.object(p).parent;
      if (p == body_) out.scene.object(id).visible = false;
    }
  }
  if (attract_) return;
  const int s = std::max(1, height_ / 200);
  static const char* const names[] = {"CHASE", "COCKPIT", "TRACKSIDE"};
  char hud[200];
  std::snprintf(hud, sizeof hud, "%3.0f KM/H  %s %.0fMM  %s%s", std::abs(car_.speed) * 3.6f, names[int(camera_)],
                focal_[int(camera_)], hq_ ? "HQ 3X3  " : "", car_.skidding ? "SKID" : "");
  int bar = int(float(width_ / 3) * std::min(std::abs(car_.speed) / kTopSpeed, 1.0f));
  out.overlay.rect(0, height_ - 12 * s, width_, 12 * s, {0, 0, 0, 140});
  out.overlay.rect(width_ - width_ / 3 - 4 * s, height_ - 9 * s, bar, 6 * s, {255, 140, 40, 230});
  out.overlay.text(3 * s, height_ - 10 * s, hud, {255, 255, 255, 255}, s);
}

void DriveProgram::sound(Synth& synth) {
  synth.set_engine(true, engine_hz(car_.speed), 0.3f + 0.2f * controls_.throttle);
  for (; pending_crashes_ > 0; --pending_crashes_) synth.play(Effect::Crash);
}

ShellText drive_shell_text() {
  ShellText text;
  text.title = "VELOCITY DRIVE";
  text.subtitle = "A DRIVING SIMULATION";
  text.start = "DRIVE";
  text.credits =
      "*VELOCITY DRIVE\n\nA CAR ON A RACE TRACK\nIN THE STYLE OF 1990S 3D DRIVING GAMES\n\n\n"
      "*ENGINE\nVELOCITY SOFTWARE RENDERER\nFLAT, GOURAUD AND PHONG SHADING\nTEXTURE AND ENVIRONMENT MAPS\n\n\n"
      "*CONTROLS\nUP  THROTTLE     DOWN  BRAKE\nLEFT / RIGHT  STEER\nC  CAMERA     H  HIGH QUALITY\n"
      "[ ]  FOCAL LENGTH     Q E  SWIVEL\nPGUP PGDN  PITCH     , .  ROLL\nR  BACK TO THE GRID     ESC  MENU\n\n\n"
      "*SOUND\nSYNTHESISED AS YOU LISTEN\n\n\n"
      "*DRIVE SAFELY\n";
  return text;
}

}  // namespace velocity::realtime
