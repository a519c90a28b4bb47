// `velocity drive`: the driving simulation (after seed 000's). A car whose four wheels are child
// objects (spinning with the speed; the front two steer), on a race track over textured
// grass with trees, buildings and cones; chase, cockpit and trackside cameras with the
// seed's camera controls (position, roll, pitch, swivel, focal length); an
// environment-mapped body with glassy windows; simple car physics (throttle, brake,
// steering with limited grip, on the ground, bouncing off the scenery). H switches the
// high-quality mode (3 x 3 super-sampling, seed 000's second mode).
#pragma once

#include <string>
#include <vector>

#include "runtime/shell.hpp"

namespace velocity::realtime {

struct DriveOptions {
  std::string car;         // a model file for the body (ASC, ...); empty: the built-in car
  float car_yaw = 0;       // degrees to turn the model further (files are taken to face +Z, as 3D Studio's do)
  bool high_quality = false;
};

// The car's state and its physics, apart from any drawing (tests check it directly).
struct CarState {
  Vec3 position;
  float heading = 0;      // radians, 0 = driving towards -Z, positive turns left
  float speed = 0;        // metres a second along the heading (negative: reversing)
  float steer = 0;        // front wheel angle, radians, positive = left
  float wheel_spin = 0;   // radians the wheels have turned
  float accel = 0;        // last step's acceleration (m/s^2)
  float lateral = 0;      // last step's lateral acceleration (m/s^2)
  bool skidding = false;  // the turn asked for more grip than the tyres have
};

struct CarControls {
  float throttle = 0, brake = 0, steer = 0;  // 0..1, 0..1, -1 (right)..1 (left)
};

// One physics step. Constants in SI units; see drive.cpp for the model.
void step_car(CarState& car, const CarControls& controls, float dt);

inline constexpr float kWheelBase = 2.6f, kWheelRadius = 0.34f, kMaxSteer = 0.55f, kTopSpeed = 62.0f;

class DriveProgram : public Game {
 public:
  enum class CameraMode { Chase, Cockpit, Trackside };

  explicit DriveProgram(DriveOptions options = {});  // throws velocity::Error for a bad car file
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  void sound(Synth& synth) override;
  bool finished() const override { return false; }
  std::string title() const override { return "Velocity - drive"; }
  void set_attract(bool on) override { attract_ = on; }
  void restart() override;

  const CarState& car() const { return car_; }
  const Scene& scene() const { return scene_; }
  CameraMode camera_mode() const { return camera_; }
  float focal_mm() const { return focal_[int(camera_)]; }
  bool high_quality() const { return hq_; }
  int collisions() const { return collisions_; }
  // The engine note's pitch for a speed (Hz): rises with speed.
  static float engine_hz(float speed);
  // Names of the wheel objects (front left, front right, rear left, rear right).
  static constexpr const char* kWheelNames[4] = {"wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"};

 private:
  void build_track();
  void build_car(const DriveOptions& o);
  void pose_car();
  void place_camera(float dt);
  CarControls autopilot() const;

  Scene scene_;
  CarState car_;
  CarControls controls_;
  ObjectId car_root_ = 0, body_ = 0;
  ObjectId steer_[2] = {0, 0};
  ObjectId wheels_[4] = {0, 0, 0, 0};
  std::vector<Vec3> centre_line_;  // the track's middle, every few metres
  struct Solid {
    Vec3 centre;
    float radius;
  };
  std::vector<Solid> solids_;
  std::vector<Vec3> posts_;  // trackside camera positions
  CameraMode camera_ = CameraMode::Chase;
  float focal_[3] = {24.0f, 18.0f, 70.0f};
  float swivel_ = 0, pitch_ = 0, roll_ = 0;
  float chase_yaw_ = 0;
  bool hq_ = false, attract_ = false;
  int collisions_ = 0, pending_crashes_ = 0;
};

// The title screen, menu and credits around the game (plain words: no seed numbers).
ShellText drive_shell_text();

}  // namespace velocity::realtime
