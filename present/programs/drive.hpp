// `velocity drive`: the driving game (grown from seed 000's driving simulation). A closed
// circuit over hills (programs/circuit.hpp) with kerbs in the bends, trees, buildings, a
// grandstand, a start gantry and cones; the race (programs/race.hpp): lap times through
// checkpoint gates, the best lap kept on disk and driven by a ghost car, an opponent on
// the racing line, cars that bump and cones that fall. The car's four wheels are child
// objects (spinning with the speed; the front two steer), and the car follows the ground
// (pitch and roll from the wheels' heights). Chase, cockpit (with a dashboard the engine
// draws: speedometer and rev counter) and trackside cameras with the seed's camera
// controls (focal length, swivel, pitch, roll; R puts them back). H switches the high
// quality mode (3 x 3 super-sampling).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "programs/circuit.hpp"
#include "programs/race.hpp"
#include "runtime/shell.hpp"

namespace velocity::realtime {

struct DriveOptions {
  std::string car;         // a model file for the body (ASC, ...); empty: the built-in car
  float car_yaw = 0;       // degrees to turn the model further (files are taken to face +Z, as 3D Studio's do)
  bool high_quality = false;
  int opponents = 1;
  std::string best_lap_file;  // where the best lap is read from and kept; empty: not kept
  std::optional<Replay> replay;  // play this race back (the keys are ignored)
};

// A rectangle of the heads-up display with its lines of text, in frame pixels.
struct HudPanel {
  int x = 0, y = 0, w = 0, h = 0, scale = 1;
  std::vector<std::string> lines;
};

class DriveProgram : public Game {
 public:
  enum class CameraMode { Chase, Cockpit, Trackside };

  explicit DriveProgram(DriveOptions options = {});  // throws velocity::Error for a bad car file
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  void sound(Synth& synth) override;
  bool finished() const override;
  std::string title() const override { return "Velocity - drive"; }
  void set_attract(bool on) override { attract_ = on; }
  void restart() override;
  std::string help() const override;
  void set_gamepad(const GamepadState& pad) override { pad_ = pad; }
  void set_settings(const Settings& s) override { settings_ = s; }

  const Race& race() const { return race_; }
  Race& race() { return race_; }
  const Circuit& circuit() const { return *circuit_; }
  const CarState& car() const { return race_.car(0).state; }
  const Scene& scene() const { return scene_; }
  CameraMode camera_mode() const { return camera_; }
  float focal_mm() const { return focal_[int(camera_)]; }
  bool high_quality() const { return hq_; }
  int collisions() const { return race_.car(0).collisions; }
  float swivel() const { return swivel_; }
  float camera_pitch() const { return pitch_; }
  float camera_roll() const { return roll_; }
  // The race so far as a replay (every tick's controls since the start or restart).
  const Replay& recording() const { return recording_; }
  // The heads-up display's panels for the frame size (resize first); none overlap.
  std::vector<HudPanel> hud() const;
  // The engine note's pitch for a speed (Hz): rises with speed.
  static float engine_hz(float speed);
  // The rev counter's reading (revolutions a minute) at a speed: five gears.
  static float engine_rpm(float speed);
  // Names of the wheel objects (front left, front right, rear left, rear right).
  static constexpr const char* kWheelNames[4] = {"wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"};

 private:
  struct CarModel {
    ObjectId root = 0, body = 0;
    ObjectId steer[2] = {0, 0};
    ObjectId wheels[4] = {0, 0, 0, 0};
  };
  void build_world();
  void build_ground();
  CarModel build_car(const std::string& prefix, const DriveOptions* model, Vec3 paint, bool wheels);
  void build_dashboard();
  void pose_car(const CarModel& model, const CarState& state);
  void pose_scene();
  void place_camera(float dt);
  CarControls player_controls(const InputState& in) const;
  void lap_finished(const Race::LapEvent& e);

  std::shared_ptr<const Circuit> circuit_;
  Race race_;
  Scene scene_;
  DriveOptions options_;
  CarControls controls_;
  std::vector<CarModel> cars_;  // the player's, then the opponents'
  CarModel ghost_;
  std::vector<ObjectId> cones_;
  ObjectId dashboard_ = 0, speed_needle_ = 0, rev_needle_ = 0;
  std::vector<Vec3> posts_;  // trackside camera positions
  CameraMode camera_ = CameraMode::Chase;
  float focal_[3] = {24.0f, 18.0f, 70.0f};
  float swivel_ = 0, pitch_ = 0, roll_ = 0;
  float chase_yaw_ = 0;
  bool hq_ = false, attract_ = false;
  double clock_ = 0;  // seconds of race time asked for; ticks run to catch up
  Replay recording_;
  std::string message_;  // shown for a while after a lap
  double message_time_ = 0;
  int pending_crashes_ = 0;
  GamepadState pad_;
  Settings settings_;
};

// The title screen, menu and credits around the game (plain words: no seed numbers).
ShellText drive_shell_text();
// Where the best lap is kept: $XDG_DATA_HOME/velocity/drive/best_lap.txt, else
// $HOME/.local/share/velocity/drive/best_lap.txt; empty when neither is set.
std::string default_best_lap_file();

}  // namespace velocity::realtime
