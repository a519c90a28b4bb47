#include "programs/race.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "velocity/error.hpp"

namespace velocity::realtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kGravity = 9.81f;
// The car: engine pull at rest, braking, reversing, air drag, rolling resistance, grip.
constexpr float kEngine = 7.5f, kBrake = 11.0f, kReverse = 3.0f, kReverseTop = 9.0f;
constexpr float kDrag = kEngine / (kTopSpeed * kTopSpeed) * 0.35f, kRolling = 0.25f, kGrip = 0.95f;
constexpr float kSteerRate = 2.2f;  // radians a second at the front wheels
constexpr float kConeRadius = 0.3f;

Vec3 forward(float heading) { return {-std::sin(heading), 0, -std::cos(heading)}; }
Vec3 right_of(float heading) { return {std::cos(heading), 0, -std::sin(heading)}; }

// The next line of `text` (without its newline), advancing `pos`; false at the end.
bool next_line(std::string_view text, size_t& pos, std::string_view& line) {
  if (pos >= text.size()) return false;
  size_t end = text.find('\n', pos);
  if (end == std::string_view::npos) end = text.size();
  line = text.substr(pos, end - pos);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos = end + 1;
  return true;
}

[[noreturn]] void bad(const std::string& name, int line, const std::string& what) {
  throw Error(name + ":" + std::to_string(line) + ": " + what);
}

// Reads exactly `count` finite numbers from a line, nothing after them.
bool read_numbers(std::string_view line, float* out, int count) {
  std::string s(line);
  const char* p = s.c_str();
  for (int i = 0; i < count; ++i) {
    char* end = nullptr;
    float v = std::strtof(p, &end);
    if (end == p || !std::isfinite(v)) return false;
    out[i] = v;
    p = end;
  }
  while (*p == ' ' || *p == '\t') ++p;
  return *p == '\0';
}

// "KEY VALUE" with an integer value in [lo, hi].
long read_keyed(std::string_view line, const char* key, long lo, long hi, const std::string& name, int n) {
  std::string s(line);
  std::string k(key);
  if (s.compare(0, k.size() + 1, k + " ") != 0) bad(name, n, "expected '" + k + " N'");
  char* end = nullptr;
  long v = std::strtol(s.c_str() + k.size() + 1, &end, 10);
  if (end == s.c_str() + k.size() + 1 || *end != '\0' || v < lo || v > hi)
    bad(name, n, "expected '" + k + " N' with N in " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
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
  a -= kGravity * std::sin(car.pitch);  // uphill pulls back
  float nv = v + a * dt;
  // Friction stops the car; it does not drive it backwards (on the level).
  if (c.throttle <= 0 && c.brake <= 0 && nv * v < 0 && std::abs(car.pitch) < 0.02f) nv = 0;
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
  car.wheel_spin += nv / kWheelRadius * dt;
}

bool Cone::fallen() const { return tilt >= kPi / 2 - 1e-3f; }

// --- files ------------------------------------------------------------------------------

std::string format_lap(const Lap& lap, float circuit_length) {
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf, "velocity-lap 1\ncircuit %.3f\nticks %ld\n", double(circuit_length), lap.ticks);
  out += buf;
  for (const Pose& p : lap.poses) {
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g %.9g %.9g\n", double(p.position.x), double(p.position.y),
                  double(p.position.z), double(p.heading), double(p.pitch), double(p.roll));
    out += buf;
  }
  return out;
}

Lap parse_lap(std::string_view text, float circuit_length, const std::string& name) {
  size_t pos = 0;
  std::string_view line;
  int n = 1;
  if (!next_line(text, pos, line) || line != "velocity-lap 1") bad(name, n, "expected 'velocity-lap 1'");
  ++n;
  float length = 0;
  if (!next_line(text, pos, line) || line.substr(0, 8) != "circuit " || !read_numbers(line.substr(8), &length, 1))
    bad(name, n, "expected 'circuit LENGTH'");
  if (std::abs(length - circuit_length) > 0.01f) bad(name, n, "a lap of another circuit");
  ++n;
  if (!next_line(text, pos, line)) bad(name, n, "expected 'ticks N'");
  Lap lap;
  lap.ticks = read_keyed(line, "ticks", 1, kMaxReplayTicks, name, n);
  lap.poses.reserve(std::min(size_t(lap.ticks), text.size() / 12));  // what the text can hold
  while (long(lap.poses.size()) < lap.ticks) {
    ++n;
    float v[6];
    if (!next_line(text, pos, line)) bad(name, n, "the file ends before its " + std::to_string(lap.ticks) + " poses");
    if (!read_numbers(line, v, 6)) bad(name, n, "expected six numbers: x y z heading pitch roll");
    lap.poses.push_back({{v[0], v[1], v[2]}, v[3], v[4], v[5]});
  }
  while (next_line(text, pos, line))
    if (!line.empty()) bad(name, n + 1, "more poses than 'ticks' says");
  return lap;
}

std::string format_replay(const Replay& r) {
  std::string out = "velocity-replay 1\nticks " + std::to_string(r.ticks.size()) + "\n";
  char buf[160];
  for (size_t i = 0; i < r.ticks.size();) {
    size_t j = i;
    while (j < r.ticks.size() && r.ticks[j] == r.ticks[i]) ++j;
    const CarControls& c = r.ticks[i];
    std::snprintf(buf, sizeof buf, "%zu %.9g %.9g %.9g\n", j - i, double(c.throttle), double(c.brake), double(c.steer));
    out += buf;
    i = j;
  }
  return out;
}

Replay parse_replay(std::string_view text, const std::string& name) {
  size_t pos = 0;
  std::string_view line;
  int n = 1;
  if (!next_line(text, pos, line) || line != "velocity-replay 1") bad(name, n, "expected 'velocity-replay 1'");
  ++n;
  if (!next_line(text, pos, line)) bad(name, n, "expected 'ticks N'");
  const long ticks = read_keyed(line, "ticks", 0, kMaxReplayTicks, name, n);
  Replay r;
  while (next_line(text, pos, line)) {
    ++n;
    if (line.empty()) continue;
    float v[4];
    if (!read_numbers(line, v, 4) || v[0] < 1 || v[0] != std::floor(v[0]))
      bad(name, n, "expected 'COUNT THROTTLE BRAKE STEER' with COUNT a whole number from 1");
    if (v[1] < 0 || v[1] > 1 || v[2] < 0 || v[2] > 1 || v[3] < -1 || v[3] > 1)
      bad(name, n, "throttle and brake must be 0..1 and steer -1..1");
    if (double(r.ticks.size()) + double(v[0]) > double(ticks)) bad(name, n, "more ticks than 'ticks' says");
    r.ticks.insert(r.ticks.end(), size_t(v[0]), CarControls{v[1], v[2], v[3]});
  }
  if (long(r.ticks.size()) != ticks)
    bad(name, n, "the file holds " + std::to_string(r.ticks.size()) + " ticks, not " + std::to_string(ticks));
  return r;
}

// --- the race --------------------------------------------------------------------------

Race::Race(const Circuit& circuit, int opponents) : circuit_(circuit) {
  cars_.resize(size_t(1 + std::max(0, opponents)));
  for (size_t i = 1; i < cars_.size(); ++i) cars_[i].ai = true;
  reset();
}

void Race::add_cone(Vec3 at) {
  Cone c;
  c.position = {at.x, circuit_.height(at.x, at.z), at.z};
  cones_.push_back(c);
  cones_start_.push_back(c);
}

void Race::place(size_t i, float s, float lateral) {
  RaceCar& car = cars_[i];
  car.state = {};
  Vec3 t = circuit_.tangent(s);
  car.state.heading = std::atan2(-t.x, -t.z);
  car.state.position = circuit_.point(s, lateral);
  car.where = circuit_.locate(car.state.position);
  ground(car);
}

void Race::reset() {
  // The grid: the player behind, on the right; opponents ahead, alternating sides.
  const float L = circuit_.length();
  for (size_t i = 0; i < cars_.size(); ++i) {
    RaceCar fresh;
    fresh.ai = cars_[i].ai;
    fresh.best_lap = cars_[i].best_lap;
    cars_[i] = fresh;
    place(i, L - 14.0f + 8.0f * float(i), i % 2 == 0 ? 2.6f : -2.6f);
  }
  cones_ = cones_start_;
  current_ = {};
  events_.clear();
  tick_ = 0;
  crashes_ = 0;
}

Pose Race::pose(size_t i) const {
  const CarState& s = cars_[i].state;
  return {s.position, s.heading, s.pitch, s.roll};
}

void Race::set_best_lap(Lap lap) {
  cars_[0].best_lap = lap.ticks;
  best_ = std::move(lap);
}

std::optional<Pose> Race::ghost() const {
  const RaceCar& p = cars_[0];
  if (!best_ || p.lap_start < 0) return std::nullopt;
  long j = tick_ - p.lap_start;
  if (j < 0 || j >= long(best_->poses.size())) return std::nullopt;
  return best_->poses[size_t(j)];
}

CarControls Race::follow_line(const RaceCar& car) const {
  // Pure pursuit: aim at the racing line a speed-dependent distance ahead and steer the
  // arc that reaches it; take the speed the line allows a few metres on.
  const CarState& st = car.state;
  const float v = std::max(st.speed, 0.0f);
  const float look = 7.0f + 0.45f * v;
  const Circuit::Sample ahead = circuit_.at(car.where.s + look);
  Vec3 aim = ahead.centre + ahead.right * ahead.line - st.position;
  float dist = std::sqrt(aim.x * aim.x + aim.z * aim.z);
  float alpha = std::remainder(std::atan2(-aim.x, -aim.z) - st.heading, 2 * kPi);
  float curvature = 2.0f * std::sin(alpha) / std::max(dist, 1.0f);
  float wheel = std::atan(curvature * kWheelBase);
  float lock = kMaxSteer / (1.0f + v / 15.0f);
  CarControls c;
  c.steer = std::clamp(wheel / lock, -1.0f, 1.0f);
  float target = circuit_.at(car.where.s + 3.0f + 0.2f * v).top_speed;
  c.throttle = std::clamp((target - v) * 0.6f, 0.0f, 1.0f);
  c.brake = std::clamp((v - target) * 0.6f - 0.2f, 0.0f, 1.0f);
  return c;
}

void Race::ground(RaceCar& car) {
  // The four wheels on the surface: height the average, pitch and roll from the slopes.
  CarState& s = car.state;
  const Vec3 f = forward(s.heading) * (kWheelBase / 2), r = right_of(s.heading) * (kTrack / 2);
  auto h = [&](Vec3 p) { return circuit_.height(p.x, p.z, &car.where); };
  const Vec3 p = s.position;
  float fl = h(p + f - r), fr = h(p + f + r), rl = h(p - f - r), rr = h(p - f + r);
  s.position.y = (fl + fr + rl + rr) / 4;
  s.pitch = std::atan2((fl + fr - rl - rr) / 2, kWheelBase);
  s.roll = std::atan2((fr + rr - fl - rl) / 2, kTrack);
  car.where = circuit_.locate(s.position, &car.where);
}

void Race::collide_scenery(RaceCar& car) {
  // Pushed out of trees, buildings and the edge of the world, keeping the speed along
  // them (it slides; it never sticks), losing most of the speed into them.
  CarState& s = car.state;
  auto respond = [&](Vec3 n, float depth) {
    s.position = s.position + n * depth;
    Vec3 v = forward(s.heading) * s.speed;
    float into = dot(v, n);
    if (into < 0) {
      v = v - n * (into * 1.3f);
      if (into < -2.0f) ++car.collisions, ++crashes_;
    }
    s.speed = dot(v, forward(s.heading));
  };
  for (int end = -1; end <= 1; end += 2) {
    for (const Solid& o : solids_) {
      Vec3 c = s.position + forward(s.heading) * (kCarCircleOffset * float(end));
      Vec3 d{c.x - o.centre.x, 0, c.z - o.centre.z};
      float dist = length(d), min = o.radius + kCarCircle;
      if (dist < min) respond(dist > 1e-4f ? d * (1.0f / dist) : Vec3{1, 0, 0}, min - dist);
    }
  }
  const float edge = Circuit::kGroundHalf - 15;
  if (s.position.x > edge) respond({-1, 0, 0}, s.position.x - edge);
  if (s.position.x < -edge) respond({1, 0, 0}, -edge - s.position.x);
  if (s.position.z > edge) respond({0, 0, -1}, s.position.z - edge);
  if (s.position.z < -edge) respond({0, 0, 1}, -edge - s.position.z);
}

void Race::collide_cars() {
  // Two circles a car; overlapping cars are pushed apart by half the overlap each and
  // trade the speed they close at (a soft bounce), so they never stay locked together.
  for (size_t a = 0; a < cars_.size(); ++a)
    for (size_t b = a + 1; b < cars_.size(); ++b)
      for (int ea = -1; ea <= 1; ea += 2)
        for (int eb = -1; eb <= 1; eb += 2) {
          CarState &A = cars_[a].state, &B = cars_[b].state;
          Vec3 ca = A.position + forward(A.heading) * (kCarCircleOffset * float(ea));
          Vec3 cb = B.position + forward(B.heading) * (kCarCircleOffset * float(eb));
          Vec3 d{ca.x - cb.x, 0, ca.z - cb.z};
          float dist = length(d), min = 2 * kCarCircle;
          if (dist >= min) continue;
          Vec3 n = dist > 1e-4f ? d * (1.0f / dist) : right_of(A.heading);
          float push = (min - dist) / 2;
          A.position = A.position + n * push;
          B.position = B.position - n * push;
          Vec3 va = forward(A.heading) * A.speed, vb = forward(B.heading) * B.speed;
          float closing = dot(va - vb, n);
          if (closing < 0) {
            float j = -closing * (1 + 0.3f) / 2;
            va = va + n * j, vb = vb - n * j;
            A.speed = dot(va, forward(A.heading));
            B.speed = dot(vb, forward(B.heading));
            if (closing < -2.0f) ++cars_[a].collisions, ++cars_[b].collisions, ++crashes_;
          }
        }
}

void Race::collide_cones(RaceCar& car) {
  // A cone is light: the car shoves it along and it goes over; the car hardly slows.
  CarState& s = car.state;
  for (Cone& cone : cones_) {
    for (int end = -1; end <= 1; end += 2) {
      Vec3 c = s.position + forward(s.heading) * (kCarCircleOffset * float(end));
      Vec3 d{cone.position.x - c.x, 0, cone.position.z - c.z};
      float dist = length(d), min = kCarCircle + kConeRadius;
      if (dist >= min) continue;
      Vec3 n = dist > 1e-4f ? d * (1.0f / dist) : forward(s.heading);
      cone.position = cone.position + n * (min - dist);
      Vec3 v = forward(s.heading) * s.speed;
      float along = dot(v, n);
      if (along > 0) {
        cone.velocity = n * (along * 1.4f) + v * 0.2f;
        cone.velocity.y = 0;
        if (cone.tilt_rate == 0) cone.tilt_rate = 3.0f + 0.25f * along;
        cone.fall_heading = std::atan2(cone.velocity.x, cone.velocity.z);
        s.speed *= 0.985f;
      }
    }
  }
}

void Race::move_cones() {
  const float dt = float(kTick);
  for (Cone& c : cones_) {
    if (c.tilt_rate > 0 && !c.fallen()) {
      c.tilt = std::min(kPi / 2, c.tilt + c.tilt_rate * dt);
      c.tilt_rate += 12.0f * dt;  // gravity takes over once it leans
    }
    float v = length(c.velocity);
    if (v > 0) {
      c.position = c.position + c.velocity * dt;
      float slow = std::max(0.0f, v - 5.0f * dt);  // sliding on the ground
      c.velocity = c.velocity * (slow / v);
      c.position.y = circuit_.height(c.position.x, c.position.z);
    }
  }
}

void Race::gates(size_t index, float before) {
  // A gate counts when the car crosses it forwards on the road. The line closes a lap
  // that counts only if every other gate was passed since it was last crossed.
  RaceCar& car = cars_[index];
  const float L = circuit_.length();
  const float moved = std::remainder(car.where.s - before, L);
  if (moved <= 0 || !circuit_.on_road(car.where)) return;
  for (int k = 0; k < Circuit::kCheckpoints; ++k) {
    float off = std::fmod(circuit_.checkpoint(k) - before + 2 * L, L);
    if (off >= moved) continue;
    if (k > 0) {
      if (car.lap_start >= 0) car.passed[size_t(k)] = true;
      continue;
    }
    if (car.lap_start >= 0) {
      LapEvent e;
      e.car = index;
      e.ticks = tick_ - car.lap_start;
      e.counted = std::all_of(car.passed.begin() + 1, car.passed.end(), [](bool b) { return b; });
      if (e.counted) {
        ++car.laps;
        car.last_lap = e.ticks;
        if (car.best_lap == 0 || e.ticks < car.best_lap) {
          car.best_lap = e.ticks;
          e.best = index == 0;
          if (index == 0) {
            current_.ticks = e.ticks;
            best_ = std::move(current_);
          }
        }
      }
      events_.push_back(e);
    }
    car.lap_start = tick_;
    car.passed = {};
    if (index == 0) current_ = {};
  }
}

void Race::step(const CarControls& player) {
  events_.clear();
  crashes_ = 0;
  const float dt = float(kTick);
  std::vector<float> before(cars_.size());
  for (size_t i = 0; i < cars_.size(); ++i) {
    RaceCar& car = cars_[i];
    before[i] = car.where.s;
    car.controls = car.ai ? follow_line(car) : player;
    step_car(car.state, car.controls, dt);
  }
  collide_cars();
  for (RaceCar& car : cars_) {
    collide_scenery(car);
    collide_cones(car);
    ground(car);
  }
  move_cones();
  ++tick_;
  for (size_t i = 0; i < cars_.size(); ++i) gates(i, before[i]);
  if (cars_[0].lap_start >= 0) current_.poses.push_back(pose(0));
}

}  // namespace velocity::realtime
