// The driving game's race, apart from any drawing: cars on the circuit (the player's and
// opponents that follow the racing line), the ground under their wheels, collisions,
// cones that fall over, lap timing through checkpoint gates, the best lap and its ghost,
// and replays. It advances in fixed ticks of 1/120 s, so the same controls give the same
// race, bit for bit, on every run.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "programs/circuit.hpp"

namespace velocity::realtime {

// The car's state and its physics (tests check them directly).
struct CarState {
  Vec3 position;
  float heading = 0;      // radians, 0 = driving towards -Z, positive turns left
  float pitch = 0;        // nose up, from the ground under the wheels
  float roll = 0;         // right side up
  float speed = 0;        // metres a second along the heading (negative: reversing)
  float steer = 0;        // front wheel angle, radians, positive = left
  float wheel_spin = 0;   // radians the wheels have turned
  float accel = 0;        // last step's acceleration (m/s^2)
  float lateral = 0;      // last step's lateral acceleration (m/s^2)
  bool skidding = false;  // the turn asked for more grip than the tyres have
};

struct CarControls {
  float throttle = 0, brake = 0, steer = 0;  // 0..1, 0..1, -1 (right)..1 (left)
  bool operator==(const CarControls&) const = default;
};

// One physics step. Constants in SI units; see race.cpp for the model. The slope (pitch)
// pulls the car back uphill.
void step_car(CarState& car, const CarControls& controls, float dt);

inline constexpr float kWheelBase = 2.6f, kWheelRadius = 0.34f, kMaxSteer = 0.55f, kTopSpeed = 62.0f;
inline constexpr float kTrack = 1.72f;  // between the left and right wheels

// A car placed as the scene shows it.
struct Pose {
  Vec3 position;
  float heading = 0, pitch = 0, roll = 0;
  bool operator==(const Pose&) const = default;
};

// A recorded lap: the pose after every tick from the moment the line was crossed.
struct Lap {
  long ticks = 0;
  std::vector<Pose> poses;
};

// Best laps on disk: "velocity-lap 1", "circuit LENGTH", "ticks N", then N lines
// "x y z heading pitch roll". parse_lap throws velocity::Error naming the line.
std::string format_lap(const Lap& lap, float circuit_length);
Lap parse_lap(std::string_view text, float circuit_length, const std::string& name = "lap");

// A replay: the player's controls every tick from the race's start. On disk:
// "velocity-replay 1", "ticks N", then lines "COUNT THROTTLE BRAKE STEER" (runs of
// equal controls). parse_replay throws velocity::Error naming the line.
struct Replay {
  std::vector<CarControls> ticks;
};
std::string format_replay(const Replay& replay);
Replay parse_replay(std::string_view text, const std::string& name = "replay");
inline constexpr long kMaxReplayTicks = 120L * 60 * 60 * 4;  // four hours

struct RaceCar {
  CarState state;
  CarControls controls;
  TrackPosition where;
  bool ai = false;
  long lap_start = -1;  // the tick the current lap began; -1 before the first crossing
  std::array<bool, Circuit::kCheckpoints> passed{};
  int laps = 0;
  long last_lap = 0, best_lap = 0;  // ticks; 0: none yet
  int collisions = 0;
};

struct Cone {
  Vec3 position, velocity;
  float tilt = 0, tilt_rate = 0;  // radians from upright, and how fast it is going over
  float fall_heading = 0;         // the direction it falls, as atan2(x, z)
  bool fallen() const;
};

class Race {
 public:
  static constexpr double kTick = 1.0 / 120;
  static constexpr float kCarCircle = 1.0f, kCarCircleOffset = 1.2f;  // two circles a car

  explicit Race(const Circuit& circuit, int opponents = 1);

  // Scenery the cars bump into (pushed out, sliding along it) and cones they knock over.
  void add_solid(Vec3 centre, float radius) { solids_.push_back({centre, radius}); }
  void add_cone(Vec3 at);
  // Back to the grid: cars, laps and cones as at the start; the best lap is kept.
  void reset();
  // One tick with the player's controls.
  void step(const CarControls& player);

  long tick() const { return tick_; }
  const Circuit& circuit() const { return circuit_; }
  const RaceCar& car(size_t i) const { return cars_[i]; }
  RaceCar& car(size_t i) { return cars_[i]; }
  size_t cars() const { return cars_.size(); }
  const std::vector<Cone>& cones() const { return cones_; }
  Pose pose(size_t car) const;
  // Puts a car somewhere (tests, the grid): `lateral` metres right of the line at `s`,
  // facing along the road, at rest.
  void place(size_t car, float s, float lateral);

  // What happened on the last tick: a car crossed the line.
  struct LapEvent {
    size_t car = 0;
    long ticks = 0;
    bool counted = false;  // every checkpoint passed on the road
    bool best = false;     // the player's best so far
  };
  const std::vector<LapEvent>& events() const { return events_; }
  int crashes_this_tick() const { return crashes_; }

  // The player's best lap (its ghost), set from disk or by a faster lap.
  const std::optional<Lap>& best_lap() const { return best_; }
  void set_best_lap(Lap lap);
  // Where the ghost is now: the best lap's pose at the player's time into this lap.
  std::optional<Pose> ghost() const;
  // The player's current lap so far.
  const Lap& current_lap() const { return current_; }

  // The racing-line follower's controls for a car.
  CarControls follow_line(const RaceCar& car) const;

 private:
  struct Solid {
    Vec3 centre;
    float radius;
  };
  void ground(RaceCar& car);
  void collide_scenery(RaceCar& car);
  void collide_cars();
  void collide_cones(RaceCar& car);
  void move_cones();
  void gates(size_t index, float before);

  const Circuit& circuit_;
  std::vector<RaceCar> cars_;
  std::vector<Solid> solids_;
  std::vector<Cone> cones_, cones_start_;
  std::vector<LapEvent> events_;
  std::optional<Lap> best_;
  Lap current_;
  long tick_ = 0;
  int crashes_ = 0;
};

}  // namespace velocity::realtime
