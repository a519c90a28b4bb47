// The driving game (issue 21): the circuit, the car on the ground, laps through
// checkpoints, the ghost of the best lap, the opponent, collisions, cones, replays, the
// shell around it (pause, resume, restart, options, help, gamepad) and the HUD.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "programs/drive.hpp"
#include "programs/fly.hpp"
#include "runtime/loop.hpp"
#include "runtime/script.hpp"
#include "scripted.hpp"
#include "runtime/settings_file.hpp"
#include "runtime/shell.hpp"
#include "velocity/error.hpp"

using namespace velocity;
using namespace velocity::realtime;

namespace {

using test::run_scripted;

DriveOptions no_disk() {
  DriveOptions o;
  o.best_lap_file.clear();
  return o;
}

// A person's lap as a script: the racing-line follower's wishes turned into the arrow
// keys held or let go (no half measures), written down as the key presses. Times fall
// between frames, so the script plays back frame for frame.
std::string keyboard_lap_script(double seconds) {
  DriveProgram d(no_disk());
  InputState in;
  std::string script;
  const char* names[4] = {"up", "down", "left", "right"};
  const Key keys[4] = {KeyUp, KeyDown, KeyLeft, KeyRight};
  bool held[4] = {};
  const int steps = int(std::lround(seconds / kFixedStep));
  for (int n = 0; n <= steps; ++n) {
    CarControls c = d.race().follow_line(d.race().car(0));
    bool want[4] = {c.throttle > 0.3f, c.brake > 0.3f, c.steer > 0.2f, c.steer < -0.2f};
    for (int k = 0; k < 4; ++k) {
      if (want[k] == held[k]) continue;
      held[k] = want[k];
      char line[64];
      std::snprintf(line, sizeof line, "%.6f %s %s\n", n == 0 ? 0.0 : (n - 0.5) * kFixedStep, want[k] ? "down" : "up",
                    names[k]);
      script += line;
      InputEvent e;
      e.kind = want[k] ? InputEvent::KeyDown : InputEvent::KeyUp;
      e.key = keys[k];
      in.apply(e);
    }
    d.update(n ? kFixedStep : 0.0, in);
  }
  return script;
}

// The racing-line follower driving the player's car in a bare race for `ticks`.
template <typename F>
void drive_line(Race& race, long ticks, F&& each) {
  for (long i = 0; i < ticks; ++i) {
    race.step(race.follow_line(race.car(0)));
    each();
  }
}

std::string temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("velocity_drive_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace

TEST(Circuit, ClosedHillyBankedAndNeverRunsIntoItself) {
  Circuit c;
  EXPECT_GT(c.length(), 1200.0f);
  EXPECT_LT(c.length(), 2500.0f);
  EXPECT_GT(c.closest_approach(), 60.0f);  // room for verges, trees and run-off between stretches
  float lo = 1e9f, hi = -1e9f, bank = 0, left = 0, right = 0;
  for (const Circuit::Sample& s : c.samples()) {
    lo = std::min(lo, s.centre.y), hi = std::max(hi, s.centre.y);
    bank = std::max(bank, std::abs(s.bank));
    left = std::max(left, s.curvature), right = std::min(right, s.curvature);
  }
  EXPECT_GT(hi - lo, 4.0f);   // elevation
  EXPECT_GT(bank, 0.05f);     // banking in the bends
  EXPECT_GT(left, 1 / 80.0f);  // bends both ways
  EXPECT_LT(right, -1 / 80.0f);
  // The line closes on itself.
  EXPECT_LT(length(c.point(0) - c.point(c.length())), 1e-3f);
  // A left bend's outside (its right) is the higher side.
  for (const Circuit::Sample& s : c.samples())
    if (s.curvature > 1 / 60.0f) {
      EXPECT_GT(c.point(s.s, 5).y, c.point(s.s, -5).y) << s.s;
    }
  // The ground at a point on the road is the road's surface; locate finds it back.
  for (float s = 3; s < c.length(); s += 97) {
    Vec3 p = c.point(s, 2.5f);
    TrackPosition t;
    EXPECT_NEAR(c.height(p.x, p.z, nullptr, &t), p.y, 0.02f) << s;
    EXPECT_NEAR(t.lateral, 2.5f, 0.05f) << s;
    EXPECT_NEAR(std::remainder(t.s - s, c.length()), 0.0f, 0.1f) << s;
  }
}

TEST(Circuit, GroundHeightIsTheDrawnTriangles) {
  // Away from the road, the height is the grid's triangles: at each vertex the vertex,
  // on a cell's diagonal the average of its two ends, inside a triangle linear.
  Circuit c;
  const float cell = Circuit::kGroundCell, half = Circuit::kGroundHalf;
  int checked = 0;
  for (int iz = 3; iz < c.ground_cells() - 3; iz += 7)
    for (int ix = 3; ix < c.ground_cells() - 3; ix += 7) {
      float x = -half + float(ix) * cell, z = -half + float(iz) * cell;
      EXPECT_FLOAT_EQ(c.ground_height(x, z), c.ground_vertex(ix, iz));
      float mid = (c.ground_vertex(ix, iz) + c.ground_vertex(ix + 1, iz + 1)) / 2;
      EXPECT_NEAR(c.ground_height(x + cell / 2, z + cell / 2), mid, 1e-3f);
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

TEST(Race, TheCarSitsOnTheGroundWithPitchAndRollFromIt) {
  Circuit c;
  Race race(c, 0);
  // Find the steepest stretch and the most banked one; put the car there.
  float steep_s = 0, grade = 0, banked_s = 0, bank = 0;
  for (const Circuit::Sample& s : c.samples()) {
    float g = (c.point(s.s + 2).y - c.point(s.s - 2).y) / 4;
    if (std::abs(g) > std::abs(grade)) grade = g, steep_s = s.s;
    if (std::abs(s.bank) > std::abs(bank)) bank = s.bank, banked_s = s.s;
  }
  ASSERT_GT(std::abs(grade), 0.02f);
  race.place(0, steep_s, 0);
  race.step({});
  const CarState& car = race.car(0).state;
  EXPECT_NEAR(std::tan(car.pitch), grade, 0.01f);  // nose up on a climb
  // Every wheel on the surface: the car's height is the four contact heights' mean.
  EXPECT_NEAR(car.position.y, c.point(race.car(0).where.s, race.car(0).where.lateral).y, 0.03f);
  race.place(0, banked_s, 0);
  race.step({});
  EXPECT_NEAR(std::tan(race.car(0).state.roll), bank, 0.01f);  // right side up where the road rises to the right
  EXPECT_NE(race.car(0).state.roll, 0.0f);
}

TEST(Race, TheOpponentFinishesALapWithoutLeavingTheTrack) {
  Circuit c;
  Race race(c, 1);
  float widest = 0;
  bool counted = false;
  for (long i = 0; i < long(120 * 80) && !counted; ++i) {
    race.step({});  // the player waits on the grid, behind
    widest = std::max(widest, std::abs(race.car(1).where.lateral));
    for (const Race::LapEvent& e : race.events()) counted |= e.car == 1 && e.counted;
  }
  EXPECT_TRUE(counted);
  EXPECT_EQ(race.car(1).laps, 1);
  // Its wheels never left the tarmac (half the car's width inside the edge).
  EXPECT_LT(widest, Circuit::kHalfWidth - kTrack / 2);
  EXPECT_EQ(race.car(1).collisions, 0);
}

TEST(Race, AScriptedLapTakesTheSameTimeEveryRun) {
  const std::string script = keyboard_lap_script(80);
  ASSERT_GT(std::count(script.begin(), script.end(), '\n'), 20);
  long lap[2] = {0, 0};
  Vec3 end[2];
  for (int run = 0; run < 2; ++run) {
    DriveProgram d(no_disk());
    run_scripted(d, script, 80);
    ASSERT_GE(d.race().car(0).laps, 1) << "run " << run;
    lap[run] = d.race().car(0).last_lap;
    end[run] = d.car().position;
  }
  const double t0 = double(lap[0]) * Race::kTick, t1 = double(lap[1]) * Race::kTick;
  EXPECT_GT(t0, 40.0);
  EXPECT_LT(std::abs(t1 - t0) / t0, 0.02);
  EXPECT_EQ(lap[0], lap[1]);  // in fact exactly: fixed ticks
  EXPECT_EQ(end[0], end[1]);
}

TEST(Race, TheGhostReplaysTheBestLapExactly) {
  Circuit c;
  Race race(c, 0);
  // The player's poses lap by lap, kept here independently of the race's own record.
  std::vector<std::vector<Pose>> laps(1);
  size_t best = 0;  // the fastest finished lap so far, by this test's count
  long compared = 0, expected = 0;
  drive_line(race, 120 * 200, [&] {
    const RaceCar& p = race.car(0);
    if (p.lap_start < 0) return;
    if (size_t(p.laps) + 1 > laps.size()) {  // a lap just finished
      size_t done = laps.size() - 1;
      if (done == 0 || laps[done].size() < laps[best].size()) best = done;
      laps.emplace_back();
    }
    laps.back().push_back(race.pose(0));
    if (p.laps >= 1 && p.laps <= 2) {
      long j = race.tick() - p.lap_start;
      std::optional<Pose> g = race.ghost();
      if (j < long(laps[best].size())) {
        ASSERT_TRUE(g.has_value()) << j;
        ASSERT_EQ(*g, laps[best][size_t(j)]) << "lap " << p.laps + 1 << " tick " << j;
        ++compared;
      } else {
        EXPECT_FALSE(g.has_value());  // past the end of the best lap
      }
    }
  });
  ASSERT_GE(race.car(0).laps, 3);
  ASSERT_TRUE(race.best_lap().has_value());
  // Laps 2 and 3 were each compared with the best before them for as long as both ran.
  expected = std::min<long>(long(laps[0].size()), long(laps[1].size())) +
             std::min<long>(long(laps[laps[1].size() < laps[0].size() ? 1 : 0].size()), long(laps[2].size()));
  EXPECT_EQ(compared, expected);
  EXPECT_GT(compared, 120 * 80);
  long fastest = std::min({long(laps[0].size()), long(laps[1].size()), long(laps[2].size())});
  EXPECT_EQ(race.best_lap()->ticks, fastest);
}

TEST(Race, ALapThatMissesACheckpointDoesNotCount) {
  Circuit c;
  Race race(c, 0);
  // Start the lap, then cut across to just past the fifth gate (as a shortcut over the
  // grass would), and drive on to the line.
  drive_line(race, 120 * 3, [] {});
  ASSERT_GE(race.car(0).lap_start, 0);
  race.place(0, c.checkpoint(5) + 5, 0);
  bool closed = false, counted = true;
  for (long i = 0; i < 120 * 60 && !closed; ++i) {
    race.step(race.follow_line(race.car(0)));
    for (const Race::LapEvent& e : race.events()) closed = true, counted = e.counted;
  }
  EXPECT_TRUE(closed);
  EXPECT_FALSE(counted);
  EXPECT_EQ(race.car(0).laps, 0);
  EXPECT_EQ(race.car(0).best_lap, 0);
  // Off the road a gate does not count either: beside the line, on the grass.
  Race off(c, 0);
  off.place(0, c.checkpoint(3) - 20, Circuit::kHalfWidth + 8);
  off.car(0).lap_start = 0;
  for (int i = 0; i < 120 * 3; ++i) off.step({1, 0, 0});
  EXPECT_FALSE(off.car(0).passed[3]);
}

TEST(Race, ConesFallOverWhenHitAndDoNotStopTheCar) {
  DriveProgram d(no_disk());
  Race& race = d.race();
  const Circuit& c = d.circuit();
  // The cones beside the start straight: aim the car at one from 25 m.
  size_t target = 0;
  float best = 1e30f;
  Vec3 want = c.point(50, -(Circuit::kHalfWidth + 2.5f));
  for (size_t i = 0; i < race.cones().size(); ++i)
    if (float dd = length(race.cones()[i].position - want); dd < best) best = dd, target = i;
  ASSERT_LT(best, 0.5f);
  const Vec3 cone = race.cones()[target].position;
  // Across the row, from the road out over the grass (the next cone is 10 m on).
  Vec3 t = c.tangent(50), dir = normalize(Vec3{t.z, 0, -t.x});
  RaceCar& car = race.car(0);
  car.state.position = cone - dir * 25.0f;
  car.state.heading = std::atan2(-dir.x, -dir.z);
  car.state.speed = 20;
  car.where = c.locate(car.state.position);
  float speed_before = 0;
  for (int i = 0; i < 120 * 1.6; ++i) {
    if (length(car.state.position - cone) > 4) speed_before = car.state.speed;
    race.step({0.5f, 0, 0});
  }
  const Cone& hit = race.cones()[target];
  EXPECT_TRUE(hit.fallen());
  EXPECT_GT(length(hit.position - cone), 1.0f);  // shoved along
  EXPECT_GT(car.state.speed, 0.9f * speed_before);  // a cone is not a wall
  EXPECT_EQ(car.collisions, 0);
  // The other cones stand.
  int standing = 0;
  for (const Cone& k : race.cones()) standing += !k.fallen();
  EXPECT_EQ(standing, int(race.cones().size()) - 1);
  // The scene shows it on its side.
  d.update(0, InputState{});
  FrameDescription f;
  d.frame(f);
  int on_side = 0;
  for (const Object& o : f.scene.objects())
    if (o.name == "cone" && std::abs(o.transform.rotation.x) > 1.5f) ++on_side;
  EXPECT_EQ(on_side, 1);
}

TEST(Race, CarsArePushedApartAndDoNotStick) {
  Circuit c;
  Race race(c, 1);
  // The opponent stopped 8 m ahead on the straight; the player arrives at 25 m/s.
  race.place(1, 60, 0);
  race.place(0, 52, 0);
  race.car(0).state.speed = 25;
  float worst_overlap = 0, gap_after = 0;
  int contacts = 0;
  for (int i = 0; i < 120 * 3; ++i) {
    race.step({});
    const CarState &a = race.car(0).state, &b = race.car(1).state;
    Vec3 d = a.position - b.position;
    float centres = std::sqrt(d.x * d.x + d.z * d.z);
    // Nose to tail the two circles nearest each other are 2 * offset closer than the centres.
    float overlap = 2 * Race::kCarCircle - (centres - 2 * Race::kCarCircleOffset);
    worst_overlap = std::max(worst_overlap, overlap);
    contacts += overlap > -0.05f;
    gap_after = centres;
  }
  EXPECT_GE(race.car(0).collisions, 1);
  EXPECT_LT(worst_overlap, 0.05f);  // never inside each other after a tick
  EXPECT_GT(race.car(1).state.speed, 5.0f);  // the bump pushed it along (and it drives on)
  EXPECT_LT(contacts, 60);                    // half a second at most in contact: no sticking
  EXPECT_GT(gap_after, 2 * Race::kCarCircle + 2 * Race::kCarCircleOffset);
}

TEST(Replay, FormatsParsesAndRefusesBadFiles) {
  Replay r;
  r.ticks = {{1, 0, 0}, {1, 0, 0}, {0.25f, 0, -0.3333333f}, {0, 1, 1}};
  Replay back = parse_replay(format_replay(r));
  ASSERT_EQ(back.ticks.size(), r.ticks.size());
  for (size_t i = 0; i < r.ticks.size(); ++i) EXPECT_EQ(back.ticks[i], r.ticks[i]) << i;
  auto refuses = [](const std::string& text, const std::string& message) {
    try {
      parse_replay(text, "race.replay");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refuses("", "race.replay:1: expected 'velocity-replay 1'");
  refuses("velocity-replay 1\nticks -1\n", "race.replay:2: expected 'ticks N'");
  refuses("velocity-replay 1\nticks 2\n1 0 0 0\n1 2 0 0\n", "race.replay:4: throttle and brake must be 0..1");
  refuses("velocity-replay 1\nticks 2\n1 0 0\n", "race.replay:3: expected 'COUNT THROTTLE BRAKE STEER'");
  refuses("velocity-replay 1\nticks 2\n3 0 0 0\n", "race.replay:3: more ticks than 'ticks' says");
  refuses("velocity-replay 1\nticks 3\n2 0 0 0\n", "holds 2 ticks, not 3");
  refuses("velocity-replay 1\nticks 99999999999\n", "race.replay:2");
  EXPECT_THROW(parse_lap("velocity-lap 1\ncircuit 1\nticks 1\n0 0 0 0 0 0\n", 1567.0f), Error);  // another circuit
}

TEST(Replay, PlaysTheRaceBackExactly) {
  const std::string script = keyboard_lap_script(25);
  std::vector<std::vector<Vec3>> seen(2);
  Replay recorded;
  for (int run = 0; run < 2; ++run) {
    DriveOptions o = no_disk();
    if (run == 1) o.replay = parse_replay(format_replay(recorded));  // through the file format
    DriveProgram d(o);
    run_scripted(d, run == 0 ? script : "", 25, [&](int) {
      seen[size_t(run)].push_back(d.race().car(0).state.position);
      seen[size_t(run)].push_back(d.race().car(1).state.position);
    });
    if (run == 0) recorded = d.recording();
    if (run == 1) {
      EXPECT_TRUE(d.finished());
    }
  }
  ASSERT_EQ(recorded.ticks.size(), size_t(25 * 120));
  ASSERT_EQ(seen[0].size(), seen[1].size());
  for (size_t i = 0; i < seen[0].size(); ++i) ASSERT_EQ(seen[0][i], seen[1][i]) << i;
  EXPECT_GT(length(seen[0].back() - seen[0][0]), 100.0f);  // it did go somewhere
}

TEST(Drive, TheBestLapIsKeptOnDiskAndItsGhostComesBack) {
  const std::string dir = temp_dir("best");
  DriveOptions o = no_disk();
  o.best_lap_file = dir + "/velocity/drive/best_lap.txt";
  long best = 0;
  {
    DriveProgram d(o);
    run_scripted(d, keyboard_lap_script(80), 80);
    ASSERT_GE(d.race().car(0).laps, 1);
    best = d.race().car(0).best_lap;
  }
  ASSERT_TRUE(std::filesystem::exists(o.best_lap_file));
  EXPECT_FALSE(std::filesystem::exists(o.best_lap_file + ".part"));
  DriveProgram again(o);
  ASSERT_TRUE(again.race().best_lap().has_value());
  EXPECT_EQ(again.race().best_lap()->ticks, best);
  EXPECT_EQ(again.race().car(0).best_lap, best);
  // Once the lap starts the ghost is out there, and drawn.
  run_scripted(again, "0 down up\n", 3);
  ASSERT_TRUE(again.race().ghost().has_value());
  FrameDescription f;
  again.frame(f);
  EXPECT_TRUE(f.scene.object(*f.scene.find("ghost car")).visible);
  // XDG's data folder is where it goes by default.
  ::setenv("XDG_DATA_HOME", dir.c_str(), 1);
  EXPECT_EQ(default_best_lap_file(), o.best_lap_file);
  std::filesystem::remove_all(dir);
}

TEST(Drive, RPutsTheCameraBack) {
  DriveProgram d(no_disk());
  run_scripted(d, "0 down q\n0.5 up q\n0.5 down pageup\n0.8 up pageup\n0.8 down ,\n1 up ,\n1 down ]\n1.4 up ]\n", 1.5);
  EXPECT_NE(d.swivel(), 0.0f);
  EXPECT_NE(d.camera_pitch(), 0.0f);
  EXPECT_NE(d.camera_roll(), 0.0f);
  EXPECT_GT(d.focal_mm(), 24.0f);
  run_scripted(d, "0 press r\n", 0.1);
  EXPECT_EQ(d.swivel(), 0.0f);
  EXPECT_EQ(d.camera_pitch(), 0.0f);
  EXPECT_EQ(d.camera_roll(), 0.0f);
  EXPECT_EQ(d.focal_mm(), 24.0f);
}

TEST(Drive, TheHudNeverOverlapsAtAnySize) {
  DriveOptions o = no_disk();
  o.high_quality = true;
  DriveProgram d(o);
  run_scripted(d, "0 down up\n2 down left\n", 4);  // speed, a skid, the lap message
  const int sizes[][2] = {{160, 120}, {320, 200}, {320, 240}, {400, 700}, {640, 480},
                          {800, 600}, {1024, 300}, {1280, 720}, {1920, 1080}, {3840, 2160}};
  for (auto [w, h] : sizes) {
    d.resize(w, h);
    std::vector<HudPanel> panels = d.hud();
    if (w >= 320) {
      EXPECT_GE(panels.size(), 4u) << w << "x" << h;  // speed, lap, position, camera
    }
    for (size_t i = 0; i < panels.size(); ++i) {
      const HudPanel& a = panels[i];
      EXPECT_GE(a.x, 0);
      EXPECT_LE(a.x + a.w, w) << w << "x" << h;
      EXPECT_LE(a.y + a.h, h);
      EXPECT_GE(a.y, stats_band_height(h)) << "under the frame-rate overlay at " << w << "x" << h;
      for (const std::string& line : a.lines) EXPECT_LE(text_width(line, a.scale) + 6 * a.scale, a.w) << line;
      for (size_t j = i + 1; j < panels.size(); ++j) {
        const HudPanel& b = panels[j];
        bool apart = a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
        EXPECT_TRUE(apart) << a.lines[0] << " and " << b.lines[0] << " at " << w << "x" << h;
      }
    }
    // Every piece of text the frame draws lies in a panel.
    FrameDescription f;
    d.frame(f);
    for (const DrawOp& op : f.overlay.ops()) {
      if (op.kind == DrawOp::Rect) continue;
      int tw = text_width(op.text, op.scale), th = text_height(op.text, op.scale);
      bool inside = false;
      for (const HudPanel& p : panels)
        inside |= op.x >= p.x && op.y >= p.y && op.x + tw <= p.x + p.w && op.y + th <= p.y + p.h;
      EXPECT_TRUE(inside) << op.text << " at " << w << "x" << h;
    }
  }
}

TEST(Shell, EscPausesTheRaceAndDriveResumesIt) {
  DriveProgram d(no_disk());
  Shell shell(d, drive_shell_text());
  shell.resize(640, 480);
  run_scripted(shell, "0.5 press space\n1 press enter\n", 2);  // title, menu, DRIVE
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  run_scripted(shell, "0 down up\n", 3);
  const Vec3 at_esc = d.car().position;
  const long ticks = d.race().tick();
  ASSERT_GT(d.car().speed, 5.0f);
  run_scripted(shell, "0 press esc\n", 2);
  ASSERT_EQ(shell.screen(), Shell::Screen::Menu);
  EXPECT_TRUE(shell.in_progress());
  // Behind the menu the race waits (a fade's worth of driving at most).
  const long waited = d.race().tick();
  EXPECT_LT(waited - ticks, 60);
  run_scripted(shell, "0 press enter\n", 1);  // the first button: RESUME
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  EXPECT_GE(d.race().tick(), waited);  // not back on the grid
  EXPECT_GT(length(d.car().position - at_esc), 0.0f);
  EXPECT_GT(d.race().tick(), 120 * 3);
  // P pauses: nothing moves; P again goes on.
  run_scripted(shell, "0 press p\n", 1);
  EXPECT_TRUE(shell.paused());
  const long paused_at = d.race().tick();
  run_scripted(shell, "0 down up\n", 1);
  EXPECT_EQ(d.race().tick(), paused_at);
  FrameDescription f;
  shell.frame(f);
  bool says = false;
  for (const DrawOp& op : f.overlay.ops()) says |= op.text == "PAUSED";
  EXPECT_TRUE(says);
  run_scripted(shell, "0 press p\n", 1);
  EXPECT_GT(d.race().tick(), paused_at);
  // RESTART puts the car back on the grid.
  run_scripted(shell, "0 press esc\n1 press down\n1.05 press down\n1.1 press enter\n", 2.5);
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  EXPECT_LT(d.race().tick(), 150);
  EXPECT_EQ(d.race().car(0).laps, 0);
}

TEST(Shell, F1ShowsHelpAndHStaysHighQuality) {
  DriveProgram d(no_disk());
  Shell shell(d, drive_shell_text(), true);
  shell.resize(320, 200);
  run_scripted(shell, "0 press f1\n", 0.5);
  ASSERT_TRUE(shell.help_shown());
  const long ticks = d.race().tick();
  run_scripted(shell, "0 down up\n0.5 up up\n", 1);
  EXPECT_EQ(d.race().tick(), ticks);  // the game waits under the help
  FrameDescription f;
  shell.frame(f);
  std::string all;
  for (const DrawOp& op : f.overlay.ops()) {
    all += op.text;
    if (op.kind != DrawOp::Rect) {
      EXPECT_LE(op.x + text_width(op.text, op.scale), 320) << op.text;  // the help fits the frame
      EXPECT_LE(op.y + text_height(op.text, op.scale), 200) << op.text;
    }
  }
  EXPECT_NE(all.find("THROTTLE"), std::string::npos);
  EXPECT_NE(all.find("CHECKPOINT"), std::string::npos);
  run_scripted(shell, "0 press f1\n0.2 press h\n", 0.5);
  EXPECT_FALSE(shell.help_shown());
  EXPECT_TRUE(d.high_quality());
}

TEST(Shell, TheOptionsScreenChangesQualitySoundAndKeys) {
  DriveProgram d(no_disk());
  Shell shell(d, drive_shell_text());
  shell.resize(320, 200);
  // Title, menu, OPTIONS; super-sampling up to 2x2; texture filter to trilinear; volume
  // down; THROTTLE onto W.
  run_scripted(shell,
               "0.3 press space\n0.8 press o\n1.6 press down\n1.7 press right\n1.8 press down\n1.9 press right\n"
               "2.0 press down\n2.1 press left\n2.2 press down\n2.3 press enter\n2.4 press w\n",
               2.6);
  ASSERT_EQ(shell.screen(), Shell::Screen::Options);
  EXPECT_EQ(shell.settings().ssaa, 2);
  EXPECT_EQ(shell.settings().filter, Filter::Trilinear);
  EXPECT_NEAR(shell.settings().volume, 0.7f, 1e-6f);
  EXPECT_EQ(shell.settings().key(Action::Throttle), Key('w'));
  EXPECT_EQ(shell.option_text(4), "THROTTLE: W");
  // Every row fits the frame.
  for (int r = 0; r < shell.option_rows(); ++r) {
    Shell::Rect rc = shell.option_rect(r);
    EXPECT_LE(rc.x + rc.w, 320);
    EXPECT_LE(rc.y + rc.h, 200 - 10);
  }
  // Back, DRIVE, and W drives; the frames are 2x2 super-sampled, trilinear.
  run_scripted(shell, "0 press esc\n0.8 press enter\n1.6 down w\n", 4);
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  EXPECT_GT(d.car().speed, 10.0f);
  FrameDescription f;
  shell.frame(f);
  EXPECT_EQ(f.options.ssaa, 2);
  EXPECT_EQ(f.options.filter, Filter::Trilinear);
  // The screen mode row asks the loop for 320x200, as F2 would.
  Shell again(d, drive_shell_text());
  Script s = parse_script("0.3 press space\n0.8 press o\n1.6 press right\n2.2 press esc\n");
  LoopOptions lo;
  lo.width = 640, lo.height = 480, lo.frames = 150, lo.script = s, lo.quiet = true;
  LoopResult r = run_loop(again, nullptr, lo);
  EXPECT_EQ(r.width, 320);
  EXPECT_EQ(r.height, 200);
  // ... and back to the size it started with.
  Shell third(d, drive_shell_text());
  lo.script = parse_script("0.3 press space\n0.8 press o\n1.6 press right\n1.8 press left\n2.2 press esc\n");
  r = run_loop(third, nullptr, lo);
  EXPECT_EQ(r.width, 640);
  EXPECT_EQ(r.height, 480);
}

TEST(Shell, AGamepadDrivesAndSteers) {
  DriveProgram d(no_disk());
  Shell shell(d, drive_shell_text(), true);
  GamepadState pad;
  pad.connected = true;
  pad.throttle = 1;
  pad.steer = -1;  // stick to the left
  shell.set_gamepad(pad);
  const float heading = d.car().heading;
  run_scripted(shell, "", 3);
  EXPECT_GT(d.car().speed, 10.0f);
  EXPECT_GT(d.car().heading, heading + 0.2f);  // turned left
}

TEST(Shell, TheFlythroughResumesFromTheMenuToo) {
  FlyOptions fo;
  fo.objects = 10;
  FlyProgram fly(fo);
  Shell shell(fly, fly_shell_text());
  shell.resize(320, 200);
  run_scripted(shell, "0.3 press space\n0.8 press enter\n", 1.5);
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  run_scripted(shell, "0 down a\n", 2);
  const Vec3 flown = fly.position();
  run_scripted(shell, "0 press esc\n", 1);
  ASSERT_EQ(shell.screen(), Shell::Screen::Menu);
  const Vec3 waiting = fly.position();
  run_scripted(shell, "", 1);
  EXPECT_EQ(fly.position(), waiting);  // the flight waits behind the menu
  run_scripted(shell, "0 press enter\n", 0.5);  // RESUME
  ASSERT_EQ(shell.screen(), Shell::Screen::Game);
  EXPECT_LT(length(fly.position() - flown), 200.0f);  // not a new flight
  EXPECT_GT(length(fly.position() - FlyProgram().position()), 50.0f);
  // P pauses the flight; F1 shows its help.
  run_scripted(shell, "0 press p\n", 0.5);
  const Vec3 paused = fly.position();
  run_scripted(shell, "", 0.5);
  EXPECT_EQ(fly.position(), paused);
  run_scripted(shell, "0 press p\n0.1 press f1\n", 0.3);
  EXPECT_TRUE(shell.help_shown());
  EXPECT_NE(fly.help().find("DIVE"), std::string::npos);
}

TEST(Drive, TheCockpitDashboardReadsSpeedAndRevs) {
  DriveProgram d(no_disk());
  d.resize(640, 400);
  run_scripted(d, "0 press c\n0.1 down up\n", 4);
  ASSERT_EQ(d.camera_mode(), DriveProgram::CameraMode::Cockpit);
  FrameDescription f;
  d.frame(f);
  const Scene& s = f.scene;
  // Seen from the driver's seat: the dials, not the body.
  EXPECT_TRUE(s.object(*s.find("speedometer")).visible);
  EXPECT_TRUE(s.object(*s.find("rev counter")).visible);
  EXPECT_FALSE(s.object(*s.find("shell")).visible);
  // The speedometer's scale: 0 km/h at 225 degrees, 240 km/h at -45, anticlockwise from +x.
  const float kmh = d.car().speed * 3.6f;
  ASSERT_GT(kmh, 60.0f);
  const float pi = 3.14159265f;
  EXPECT_NEAR(s.object(*s.find("speedometer needle")).transform.rotation.z, (225.0f - 270.0f * kmh / 240.0f) * pi / 180,
              1e-3f);
  const float rpm = DriveProgram::engine_rpm(d.car().speed);
  EXPECT_GE(rpm, 3000.0f);
  EXPECT_LE(rpm, 7000.0f);
  EXPECT_NEAR(s.object(*s.find("rev counter needle")).transform.rotation.z, (225.0f - 270.0f * rpm / 8000.0f) * pi / 180,
              1e-3f);
  // The revs rise through a gear and drop at the change.
  EXPECT_LT(DriveProgram::engine_rpm(5), DriveProgram::engine_rpm(11));
  EXPECT_GT(DriveProgram::engine_rpm(11.9f), DriveProgram::engine_rpm(12.1f));
  // From the chase camera the dashboard is not drawn.
  run_scripted(d, "0 press c\n0.1 press c\n", 0.2);
  FrameDescription g;
  d.frame(g);
  EXPECT_FALSE(g.scene.object(*g.scene.find("speedometer")).visible);
}

TEST(Shell, AGamepadFliesTheFlythrough) {
  FlyOptions fo;
  fo.objects = 10;
  FlyProgram fly(fo);
  Shell shell(fly, fly_shell_text(), true);
  GamepadState pad;
  pad.connected = true;
  pad.steer = 1;     // stick right: turn right
  pad.pitch = 1;     // stick back: climb
  pad.throttle = 1;  // faster
  shell.set_gamepad(pad);
  const float yaw = fly.yaw(), speed = fly.speed();
  run_scripted(shell, "", 1);
  EXPECT_LT(fly.yaw(), yaw - 0.5f);
  EXPECT_GT(fly.pitch(), 0.1f);
  EXPECT_GT(fly.speed(), speed + 20);
}

// Issue 21: the options are kept on disk. Changing them on the options screen writes the
// file whole (no PATH.tmp left behind); a new shell (the next run) starts with them; the
// file reads back exactly what was written.
TEST(Settings, TheOptionsAreKeptOnDiskAndComeBack) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("velocity_settings_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string path = (dir / "velocity" / "drive.conf").string();  // the folder is made
  {
    DriveProgram d(no_disk());
    Shell shell(d, drive_shell_text());
    shell.keep_settings_in(path);  // no file yet: the defaults
    EXPECT_EQ(shell.settings().ssaa, 1);
    shell.resize(320, 200);
    run_scripted(shell,
                 "0.3 press space\n0.8 press o\n1.6 press down\n1.7 press right\n1.8 press down\n1.9 press right\n"
                 "2.0 press down\n2.1 press left\n2.2 press down\n2.3 press enter\n2.4 press w\n",
                 2.6);
    ASSERT_EQ(shell.settings().key(Action::Throttle), Key('w'));
  }
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  DriveProgram d(no_disk());
  Shell next(d, drive_shell_text());
  next.keep_settings_in(path);
  EXPECT_EQ(next.settings().ssaa, 2);
  EXPECT_EQ(next.settings().filter, Filter::Trilinear);
  EXPECT_NEAR(next.settings().volume, 0.7f, 1e-6f);
  EXPECT_EQ(next.settings().key(Action::Throttle), Key('w'));
  EXPECT_EQ(next.settings().key(Action::Brake), KeyDown);
  // Written and read back: the same settings, the same text.
  const std::string text = format_settings(next.settings());
  EXPECT_EQ(format_settings(parse_settings(text, "x")), text);
  fs::remove_all(dir);
}

// A bad settings file is refused with one line naming the file, the line and what was
// expected; the file is left as it was.
TEST(Settings, ABadFileIsRefusedWithItsLine) {
  auto error = [](const std::string& text) {
    try {
      parse_settings(text, "drive.conf");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error("velocity-settings 1\nssaa 7\n"), "drive.conf:2: ssaa '7', expected a whole number from 1 to 3");
  EXPECT_EQ(error("velocity-settings 1\n# a comment\nfilter smooth\n"),
            "drive.conf:3: filter 'smooth', expected nearest, bilinear or trilinear");
  EXPECT_EQ(error("velocity-settings 1\nvolume 1.5\n"), "drive.conf:2: volume '1.5', expected a number from 0 to 1");
  EXPECT_EQ(error("velocity-settings 1\nkey jump space\n").substr(0, 36), "drive.conf:2: unknown action 'jump' ");
  EXPECT_EQ(error("velocity-settings 1\nkey throttle nokey\n").substr(0, 33), "drive.conf:2: unknown key 'nokey'");
  EXPECT_EQ(error("velocity-settings 1\nkey throttle down\n"), "drive.conf: throttle and brake are both on key 'down'");
  EXPECT_EQ(error("ssaa 2\n"), "drive.conf:1: expected 'velocity-settings 1' first, found 'ssaa 2'");
  EXPECT_EQ(error(""), "drive.conf:0: empty file, expected 'velocity-settings 1' first");
  EXPECT_EQ(error("velocity-settings 1\nssaa 2 3\n"), "drive.conf:2: '3' after the value");
  EXPECT_EQ(error("velocity-settings 1\nfog on\n").substr(0, 36), "drive.conf:2: unknown setting 'fog' ");
  // Missing lines keep the defaults.
  Settings s = parse_settings("velocity-settings 1\nssaa 3\n", "x");
  EXPECT_EQ(s.ssaa, 3);
  EXPECT_EQ(s.filter, Settings{}.filter);
}
