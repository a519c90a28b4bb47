// `velocity fly`: the flythrough (after seed 001's). A world of flat-shaded objects (built-in cubes,
// pyramids and tori, or PLG models) in an object hierarchy (stations with moons that
// orbit them), lit by an ambient and a point light. Left and right turn, up dives, down
// climbs, A or Ctrl flies faster, Z or Shift slower. Each object's bounding sphere
// rejects it from the frame when it is out of view and keeps the viewer from flying
// through it. The world wraps around at its edges.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/shell.hpp"

namespace velocity::realtime {

struct FlyOptions {
  std::vector<std::string> models;  // PLG (or any) files; empty: cubes, pyramids, tori
  int objects = 90;
  unsigned seed = 1;
};

class FlyProgram : public Game {
 public:
  explicit FlyProgram(FlyOptions options = {});
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  void sound(Synth& synth) override;
  bool finished() const override { return false; }
  std::string title() const override { return "Velocity - flythrough"; }
  void set_attract(bool on) override { attract_ = on; }
  void restart() override;
  std::string help() const override;
  void set_gamepad(const GamepadState& pad) override { pad_ = pad; }
  void set_settings(const Settings& s) override { settings_ = s; }

  // Flight state, for tests.
  Vec3 position() const { return pos_; }
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  float speed() const { return speed_; }
  const Camera& camera() const { return scene_.camera; }
  int collisions() const { return collisions_; }
  // Objects rejected by their bounding sphere in the last frame(), of all with a mesh.
  size_t rejected() const { return rejected_; }
  size_t solid_objects() const { return solids_.size(); }
  // Object i's bounding sphere now (world space), and the viewer's distance from the
  // nearest object's surface after the last update.
  Sphere solid(size_t i) const;
  float clearance() const { return clearance_; }
  // Puts the viewer somewhere (tests).
  void place(Vec3 position, float yaw, float pitch);

  static constexpr float kWorld = 1000.0f;    // the world is kWorld across, wrapping
  static constexpr float kTurnRate = 1.2f;    // radians a second
  static constexpr float kPitchRate = 0.8f;
  static constexpr float kAccel = 60.0f;      // units a second, a second
  static constexpr float kMinSpeed = 0.0f, kMaxSpeed = 240.0f, kStartSpeed = 40.0f;
  static constexpr float kMinAltitude = 4.0f;
  static constexpr float kViewerRadius = 3.0f;

 private:
  struct Solid {
    ObjectId id;
    float radius;  // world units, bounding sphere about the object's origin
  };
  void build_world(const FlyOptions& o);
  void place_camera();

  Scene scene_;
  std::vector<Solid> solids_;
  std::vector<ObjectId> spinners_;  // objects that turn on their own
  std::vector<float> spin_rates_;
  Vec3 pos_;
  float yaw_ = 0, pitch_ = 0, speed_ = kStartSpeed;
  bool attract_ = false;
  double time_ = 0;
  int collisions_ = 0, pending_crashes_ = 0;
  size_t rejected_ = 0;
  float clearance_ = 1e30f;
  GamepadState pad_;
  Settings settings_;
};

// The title screen, menu and credits around the flight (plain words: no seed numbers).
ShellText fly_shell_text();

}  // namespace velocity::realtime
