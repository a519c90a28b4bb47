// Tests of the real-time programs without a window: scripts, the 2D layer, the loop,
// the flythrough's path, the car's wheels and physics, the menus, the synthesiser. (The
// viewer's model policy is the library's: tests/unit/test_view_setup.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include "programs/drive.hpp"
#include "programs/fly.hpp"
#include "programs/viewer.hpp"
#include "runtime/canvas.hpp"
#include "runtime/loop.hpp"
#include "runtime/script.hpp"
#include "gltf_animated.hpp"
#include "scripted.hpp"
#include "runtime/shell.hpp"
#include "runtime/synth.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"

using namespace velocity;
using namespace velocity::realtime;

namespace {

using velocity::realtime::test::run_scripted;

}  // namespace

TEST(Script, ParsesEveryAction) {
  Script s = parse_script(
      "# a comment\n"
      "0.5 down up\n"
      "1   press Space   # trailing comment\n"
      "0.2 move 10 20\n"
      "2 click 5 6 right\r\n"
      "3 wheel -2\n"
      "4 drop /tmp/some file.asc\n"
      "5 mousedown middle 1 2\n"
      "6 quit\n");
  ASSERT_EQ(s.events.size(), 10u);
  EXPECT_EQ(s.events[0].event.kind, InputEvent::MouseMove);  // sorted by time
  EXPECT_EQ(s.events[1].event.key, KeyUp);
  EXPECT_EQ(s.events[2].event.key, KeySpace);
  EXPECT_EQ(s.events[3].event.kind, InputEvent::KeyUp);
  EXPECT_NEAR(s.events[3].time, 1.05, 1e-9);
  EXPECT_EQ(s.events[4].event.button, MouseButton::Right);
  EXPECT_EQ(s.events[7].event.path, "/tmp/some file.asc");
  EXPECT_EQ(s.events.back().event.kind, InputEvent::Quit);

  ScriptPlayer p(s);
  std::vector<InputEvent> due;
  p.due(0.5, due);
  EXPECT_EQ(due.size(), 2u);
  p.due(100, due);
  EXPECT_TRUE(p.finished());
}

TEST(Script, ErrorsNameTheLine) {
  auto fails = [](const char* text, const char* expect) {
    try {
      parse_script(text, "s.txt");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  };
  fails("\n1 down nosuchkey\n", "s.txt:2: unknown key 'nosuchkey'");
  fails("x down up\n", "s.txt:1: expected a time");
  fails("-1 down up\n", "expected a time");
  fails("nan down up\n", "expected a time");
  fails("1 jump\n", "unknown action 'jump'");
  fails("1 move 1\n", "expected 'TIME move X Y'");
  fails("1 click 1 2 thumb\n", "expected a mouse button");
  fails("1\n", "expected TIME ACTION");
}

TEST(Keys, NamesRoundTrip) {
  for (int k : {int(KeyLeft), int(KeyF11), int(KeyEscape), int('a'), int('+'), int(KeyPageDown)})
    EXPECT_EQ(parse_key(key_name(Key(k))), Key(k)) << key_name(Key(k));
  EXPECT_FALSE(parse_key("f13"));
  EXPECT_FALSE(parse_key(""));
}

TEST(Canvas, TextAndRectsStayInside) {
  Image img(40, 20, 0xff000000u);
  Canvas c{img.pixels.data(), 40, 20, 40 * 4};
  fill_rect(c, -10, -10, 15, 15, {255, 0, 0, 255});  // clipped to [0,5) x [0,5)
  EXPECT_EQ(img.pixel(4, 4)[0], 255);
  EXPECT_EQ(img.pixel(5, 5)[0], 0);
  draw_text(c, 8, 6, "A1", {0, 255, 0, 255});
  int lit = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) lit += img.pixel(x, y)[1] == 255;
  EXPECT_GT(lit, 10);
  EXPECT_GT(text_width("A1"), 6);
  EXPECT_EQ(text_width("AB\nABCD"), text_width("ABCD"));
  draw_text(c, 35, 15, "WWWWWWWWWWWWW\nWWWWW", {0, 0, 255, 255}, 3);  // runs off: must not write outside
  fade(c, 1.0f);
  EXPECT_EQ(img.pixel(4, 4)[0], 0);
}

TEST(Loop, PercentilesAndRecording) {
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 0.5), 3);
  EXPECT_EQ(percentile({5, 1, 3, 2, 4}, 0.99), 5);
  EXPECT_EQ(percentile({}, 0.5), 0);

  ViewerProgram viewer({});
  LoopOptions o;
  o.width = 64, o.height = 48, o.frames = 4, o.threads = 2, o.quiet = true;
  o.record_dir = (std::filesystem::temp_directory_path() / "velocity_rt_loop_test").string();
  std::filesystem::remove_all(o.record_dir);
  LoopResult r = run_loop(viewer, nullptr, o);
  EXPECT_EQ(r.frames, 4);
  EXPECT_EQ(r.frame_ms.size(), 3u);
  EXPECT_EQ(r.render_ms.size(), 4u);
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(std::filesystem::exists(o.record_dir + "/frame_0000" + std::to_string(i) + ".png"));
  EXPECT_NE(summarize(r).find("median_ms="), std::string::npos);
  std::filesystem::remove_all(o.record_dir);
}

// The camera's forward direction, read from its view matrix (third row, negated).
static Vec3 view_forward(const Camera& c) {
  Mat4 v = c.view();
  return normalize(Vec3{-v.m[2][0], -v.m[2][1], -v.m[2][2]});
}

TEST(Fly, ScriptedFlightFollowsTheExpectedPath) {
  FlyOptions fo;
  fo.objects = 4;  // far apart: nothing in the way
  FlyProgram fly(fo);
  Vec3 start = fly.position();
  ASSERT_FLOAT_EQ(fly.speed(), FlyProgram::kStartSpeed);
  // 1 s straight, then Left held for 1 s (a left turn at kTurnRate), then 1 s straight.
  std::vector<Vec3> path;
  run_scripted(fly, "1 down left\n2 up left\n", 3.0, [&](int) { path.push_back(fly.position()); });
  const float v = FlyProgram::kStartSpeed, w = FlyProgram::kTurnRate;
  // path[n] is after step n; steps 1..59 fly straight, 60..119 turn (Left is down from
  // t = 1 s, applied before step 60), 120..179 fly straight.
  // After 59 steps: straight ahead, where the camera looked at the start (-Z).
  Vec3 p1 = path[59];
  EXPECT_NEAR(p1.x, start.x, 1e-3);
  EXPECT_NEAR(p1.z, start.z - v * 59.0f / 60.0f, 0.05f);
  EXPECT_NEAR(p1.y, start.y, 1e-3);
  // After the turn: on the circle of radius v / w that bends left (towards -X).
  const float r = v / w;
  Vec3 centre = p1 + Vec3{-r, 0, 0};
  Vec3 p2 = path[119];
  EXPECT_NEAR(length(p2 - centre), r, 0.6f);
  EXPECT_NEAR(fly.yaw(), w * 1.0f, 0.03f);
  float angle = std::atan2(-(p2.z - centre.z), p2.x - centre.x);  // swept from +X towards -Z
  EXPECT_NEAR(angle, w * 1.0f, 0.03f);
  // Then straight on along the camera's (view matrix's) forward direction.
  Vec3 f = view_forward(fly.camera());
  Vec3 p3 = path[179];
  Vec3 expect = p2 + f * v;
  EXPECT_NEAR(length(p3 - expect), 0.0f, 0.05f);
  EXPECT_NEAR(f.x, -std::sin(w), 0.03f);  // heading left of -Z by the turn
}

TEST(Fly, DiveClimbSpeedAndBoundingSpheres) {
  FlyProgram fly;
  run_scripted(fly, "0 down down\n0.5 up down\n0.5 down a\n1.5 up a\n", 1.5);
  EXPECT_GT(fly.pitch(), 0.3f);  // climbed
  EXPECT_NEAR(fly.speed(), FlyProgram::kStartSpeed + FlyProgram::kAccel * 1.0f, 1.5f);
  run_scripted(fly, "0 down up\n1.2 up up\n0 down z\n3 up z\n", 3.0);
  EXPECT_LT(fly.pitch(), 0.0f);  // dived
  EXPECT_GE(fly.position().y, FlyProgram::kMinAltitude);
  EXPECT_FLOAT_EQ(fly.speed(), FlyProgram::kMinSpeed);
  // Objects out of view are rejected by their bounding spheres, the rest kept.
  fly.resize(320, 200);
  FrameDescription f;
  fly.frame(f);
  EXPECT_GT(fly.rejected(), 0u);
  EXPECT_LT(fly.rejected(), fly.solid_objects());
  size_t hidden = 0;
  for (const Object& o : f.scene.objects()) hidden += !o.visible;
  EXPECT_EQ(hidden, fly.rejected());
}

TEST(Fly, CannotFlyThroughObjects) {
  FlyProgram fly;
  // Aim straight at an object 150 units away and fly at it, faster and faster.
  Sphere target = fly.solid(0);
  Vec3 from = target.center + Vec3{0, 0, 150};
  fly.place(from, 0, 0);  // looking down -Z, at it
  float closest = 1e30f;
  run_scripted(fly, "0 down a\n", 6.0, [&](int) { closest = std::min(closest, fly.clearance()); });
  EXPECT_GE(fly.collisions(), 1);
  EXPECT_GE(closest, FlyProgram::kViewerRadius - 1e-3f);
  EXPECT_LT(closest, FlyProgram::kViewerRadius + 1.0f);  // it did get there
}

TEST(Drive, ScriptedDriveSteersTheFrontWheelsAndSpinsAllFour) {
  DriveProgram drive;
  const Scene& scene = drive.scene();
  auto id = [&](const char* name) { return *scene.find(name); };
  float travelled = 0;
  Vec3 last = drive.car().position;
  float steer_at_turn = 0;
  run_scripted(drive, "0 down up\n2 down left\n2.5 up left\n", 3.0, [&](int n) {
    travelled += length(drive.car().position - last);
    last = drive.car().position;
    if (n == 150) steer_at_turn = scene.object(id("steer_fl")).transform.rotation.y;
  });
  // Front wheels turned left (positive about Y) while Left was held, rear ones never.
  EXPECT_GT(steer_at_turn, 0.2f);
  EXPECT_FLOAT_EQ(scene.object(id("steer_fr")).transform.rotation.y, scene.object(id("steer_fl")).transform.rotation.y);
  EXPECT_EQ(scene.object(id("mount_rl")).transform.rotation.y, 0.0f);
  EXPECT_EQ(scene.object(id("mount_rr")).transform.rotation.y, 0.0f);
  // All four spun together by the distance rolled over the wheel radius (an
  // independent sum of the car's steps).
  float spin = -scene.object(id("wheel_fl")).transform.rotation.x;
  EXPECT_NEAR(spin, travelled / kWheelRadius, 0.02f * spin);
  for (const char* w : DriveProgram::kWheelNames) EXPECT_FLOAT_EQ(scene.object(id(w)).transform.rotation.x, -spin) << w;
  // The wheels are children of the car: they move with it.
  std::vector<Mat4> world = scene.world_matrices();
  Vec3 wheel = world[id("wheel_rl")].transform_point({0, 0, 0});
  EXPECT_LT(length(wheel - drive.car().position), 2.0f);
  EXPECT_GT(drive.car().speed, 10.0f);
  EXPECT_GT(drive.car().heading, 0.05f);  // turned left
  // On the ground: the road's surface under the car.
  EXPECT_NEAR(drive.car().position.y, drive.circuit().height(drive.car().position.x, drive.car().position.z), 0.05f);
}

TEST(Drive, PhysicsLimits) {
  CarState car;
  CarControls full{1, 0, 0};
  for (int i = 0; i < 120 * 120; ++i) step_car(car, full, 1.0f / 120);
  EXPECT_GT(car.speed, 40.0f);
  EXPECT_LT(car.speed, kTopSpeed);
  // Full lock at speed: the tyres hold at most their grip.
  CarControls turn{1, 0, 1};
  for (int i = 0; i < 240; ++i) {
    step_car(car, turn, 1.0f / 120);
    EXPECT_LE(std::abs(car.lateral), 0.95f * 9.81f + 1e-3f);
  }
  EXPECT_TRUE(car.skidding);
  // Braking stops the car and does not throw it into reverse.
  CarControls brake{0, 1, 0};
  int steps = 0;
  while (car.speed > 0.3f && steps < 120 * 20) step_car(car, brake, 1.0f / 120), ++steps;
  EXPECT_LT(steps, 120 * 8);
  EXPECT_GE(car.speed, -0.5f);
  // The engine note rises with speed.
  EXPECT_LT(DriveProgram::engine_hz(5), DriveProgram::engine_hz(30));
}

TEST(Drive, CamerasAndHighQuality) {
  DriveProgram drive;
  drive.resize(320, 240);
  run_scripted(drive, "0 press c\n0.5 down ]\n1 up ]\n1.2 press h\n", 1.5);
  EXPECT_EQ(drive.camera_mode(), DriveProgram::CameraMode::Cockpit);
  EXPECT_GT(drive.focal_mm(), 18.0f * 1.3f);  // ] lengthens the lens
  EXPECT_TRUE(drive.high_quality());
  FrameDescription f;
  drive.frame(f);
  EXPECT_EQ(f.options.ssaa, 3);
  EXPECT_FALSE(f.scene.object(*f.scene.find("body")).visible);  // the cockpit sees out
}

TEST(Menu, ReactsToMouseMoveAndClick) {
  FlyOptions fo;
  fo.objects = 10;
  FlyProgram fly(fo);
  Shell shell(fly, {"TITLE", "SUB", "FLY", "*CREDITS\nNAME", {}});
  shell.resize(640, 400);
  EXPECT_EQ(shell.screen(), Shell::Screen::Title);
  run_scripted(shell, "0.5 press space\n", 1.5);
  ASSERT_EQ(shell.screen(), Shell::Screen::Menu);
  EXPECT_EQ(shell.highlighted(), -1);

  // Move over the credits button: it lights up, in the frame too.
  Shell::Rect r = shell.button_rect(Shell::ButtonCredits);
  int cx = r.x + r.w / 2, cy = r.y + r.h / 2;
  InputState in;
  InputEvent move{InputEvent::MouseMove, KeyNone, MouseButton::Left, cx, cy, 0, {}};
  in.apply(move);
  shell.event(move, in);
  EXPECT_EQ(shell.highlighted(), Shell::ButtonCredits);
  FrameDescription f;
  shell.frame(f);
  Image img(640, 400, 0xff000000u);
  Canvas c{img.pixels.data(), 640, 400, 640 * 4};
  f.overlay.draw(c);
  const uint8_t* px = img.pixel(r.x + 3, r.y + 3);  // inside the button, off its label
  EXPECT_EQ(px[0], 200);
  EXPECT_EQ(px[1], 70);
  const uint8_t* other = img.pixel(shell.button_rect(Shell::ButtonStart).x + 3, shell.button_rect(Shell::ButtonStart).y + 3);
  EXPECT_NE(other[0], 200);

  // Click it: a fade to the credits.
  run_scripted(shell, "0 click " + std::to_string(cx) + " " + std::to_string(cy) + "\n", 0.2);
  EXPECT_GT(shell.fade(), 0.0f);
  run_scripted(shell, "", 0.5);
  EXPECT_EQ(shell.screen(), Shell::Screen::Credits);
  // Any key back to the menu; Enter on the highlighted START flies; Esc back; Quit.
  run_scripted(shell, "0 press x\n", 1.0);
  EXPECT_EQ(shell.screen(), Shell::Screen::Menu);
  // (From CREDITS, the fourth button: down to QUIT, then up four to the first.)
  run_scripted(shell, "0 press down\n0.1 press up\n0.15 press up\n0.2 press up\n0.25 press up\n0.3 press enter\n", 1.2);
  EXPECT_EQ(shell.screen(), Shell::Screen::Game);
  run_scripted(shell, "0 press esc\n", 1.0);
  EXPECT_EQ(shell.screen(), Shell::Screen::Menu);
  Shell::Rect q = shell.button_rect(Shell::ButtonQuit);
  run_scripted(shell, "0 click " + std::to_string(q.x + 2) + " " + std::to_string(q.y + 2) + "\n", 1.0);
  EXPECT_TRUE(shell.finished());
}

// The frequency of a tone by counting upward zero crossings (independent of the synth).
static double zero_crossing_hz(const std::vector<int16_t>& s, int rate) {
  int first = -1, last = -1, count = 0;
  for (size_t i = 1; i < s.size(); ++i)
    if (s[i - 1] < 0 && s[i] >= 0) {
      if (first < 0) first = int(i);
      last = int(i);
      ++count;
    }
  return count > 1 ? (count - 1) * double(rate) / double(last - first) : 0.0;
}

TEST(Synth, EngineNoteHasTheRequestedPitch) {
  for (float hz : {80.0f, 220.0f, 400.0f}) {
    Synth synth(44100);
    synth.set_engine(true, hz, 0.8f);
    std::vector<int16_t> buf(44100);
    synth.render(buf.data(), buf.size());
    std::vector<int16_t> tail(buf.begin() + 22050, buf.end());  // after the glide
    EXPECT_NEAR(zero_crossing_hz(tail, 44100), hz, hz * 0.01) << hz;
  }
  Synth quiet;
  std::vector<int16_t> buf(4410);
  quiet.render(buf.data(), buf.size());
  for (int16_t v : buf) ASSERT_EQ(v, 0);
  quiet.set_music(true);
  quiet.play(Effect::Click);
  quiet.render(buf.data(), buf.size());
  EXPECT_NE(*std::max_element(buf.begin(), buf.end()), 0);
}

TEST(Viewer, OrbitZoomAndModes) {
  ViewerProgram v({});
  v.resize(320, 240);
  float yaw = v.yaw(), d = v.distance();
  run_scripted(v, "0 mousedown left 100 100\n0.1 move 180 100\n0.2 mouseup left 180 100\n0.3 wheel 2\n"
                  "0.4 press w\n0.5 press p\n0.6 press a\n0.7 press t\n", 1.0);
  EXPECT_NEAR(v.yaw(), yaw - 80.0f / 240.0f * std::numbers::pi_v<float>, 1e-4);
  EXPECT_NEAR(v.distance(), d * 0.88f * 0.88f, 1e-3 * d);
  EXPECT_EQ(v.render_options().depth_mode, DepthMode::Painter);
  EXPECT_EQ(v.render_options().ssaa, 2);
  EXPECT_TRUE(v.render_options().affine);
  FrameDescription f;
  v.frame(f);
  EXPECT_EQ(f.options.shading, Shading::Wireframe);
  // A dropped file that cannot be read leaves the scene and says why.
  run_scripted(v, "0 drop /nonexistent/model.asc\n", 0.1);
  EXPECT_NE(v.message().find("nonexistent"), std::string::npos);
}

// Issue 21: R after rotating, panning, zooming and spinning returns to the opening view
// (on the demo scene it jumped to a distant one).
TEST(Viewer, ResetReturnsToTheOpeningView) {
  for (std::string model : {std::string(), std::string(VELOCITY_TEST_MODEL)}) {
    SCOPED_TRACE(model.empty() ? "demo scene" : model);
    ViewerOptions o;
    o.model = model;
    ViewerProgram v(o);
    v.resize(320, 240);
    run_scripted(v, "", 0);
    const Vec3 start = v.scene().camera.position;
    const float yaw = v.yaw(), pitch = v.pitch(), d = v.distance();
    run_scripted(v, "0 mousedown left 100 100\n0.1 move 180 140\n0.2 mouseup left 180 140\n"
                    "0.3 mousedown right 100 100\n0.4 move 150 60\n0.5 mouseup right 150 60\n"
                    "0.6 wheel -3\n0.7 press space\n1.5 press r\n", 1.6);
    EXPECT_NEAR(v.yaw(), yaw, 1e-5);
    EXPECT_NEAR(v.pitch(), pitch, 1e-5);
    EXPECT_NEAR(v.distance(), d, 1e-5 * d);
    const Vec3 end = v.scene().camera.position;
    EXPECT_LT(length(end - start), 1e-4f * d) << "the camera is not where it started";
  }
}

// Issue 21: the "SSAA 2X2" message's last glyph came out cut (stb_easy_font ran out of
// room for the quads of 'X'). Every glyph of a string is drawn whole: the string lights
// as many pixels as its characters do one by one.
TEST(Canvas, EveryGlyphIsDrawnWhole) {
  auto lit = [](const std::string& text) {
    std::vector<uint8_t> px(400 * 20 * 4, 0);
    Canvas c{px.data(), 400, 20, 400 * 4};
    draw_text(c, 0, 2, text, {255, 255, 255, 255});
    int n = 0;
    for (size_t i = 0; i < px.size(); i += 4) n += px[i] == 255;
    return n;
  };
  for (std::string s : {"SSAA 2X2", "SSAA 3X3", "XXXXXXXXXXXX", "8888%%%%@@@@", "MW#&$"}) {
    int sum = 0;
    for (char ch : s) sum += lit(std::string(1, ch));
    EXPECT_EQ(lit(s), sum) << s;
  }
}

namespace {

// Every text and rectangle of a frame's 2D layer inside the frame; all its text, joined.
std::string expect_overlay_inside(const FrameDescription& f, int width, int height) {
  std::string all;
  for (const DrawOp& op : f.overlay.ops()) {
    if (op.kind == DrawOp::Fade) continue;
    int w = op.kind == DrawOp::Rect ? op.w : text_width(op.text, op.scale);
    int h = op.kind == DrawOp::Rect ? op.h : text_height(op.text, op.scale);
    EXPECT_GE(op.x, 0) << op.text;
    EXPECT_GE(op.y, 0) << op.text;
    EXPECT_LE(op.x + w, width) << "'" << op.text << "' runs off the right edge at " << width << "x" << height;
    EXPECT_LE(op.y + h, height) << op.text;
    all += op.text + "\n";
  }
  return all;
}

}  // namespace

// Issue 21: the status bar ran off the right edge at 800x600 ("H:"), and a dropped bad
// file's error was cut at both edges. At every screen mode, with a long file name and a
// long error, the 2D layer stays inside the frame and still says everything.
TEST(Viewer, StatusBarAndMessagesStayInside) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "velocity_viewer_overlay";
  fs::create_directories(dir);
  fs::path long_name = dir / (std::string(90, 'w') + "_a_model_with_a_very_long_name.obj");
  fs::copy_file(VELOCITY_TEST_MODEL, long_name, fs::copy_options::overwrite_existing);
  const std::string bad = "/nonexistent/folder/with/a/rather/long/path/to/somewhere/" + std::string(60, 'x') + ".obj";
  for (auto [w, h] : {std::pair{320, 200}, {320, 240}, {640, 480}, {800, 600}, {1280, 720}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    ViewerProgram v({});
    v.resize(w, h);
    run_scripted(v, "0 press h\n", 0.2);
    FrameDescription f;
    v.frame(f);
    std::string text = expect_overlay_inside(f, w, h);
    EXPECT_NE(text.find("H: HELP"), std::string::npos) << text;
    EXPECT_NE(text.find("QUIT"), std::string::npos) << text;

    run_scripted(v, "0 press h\n0 drop " + bad + "\n", 0.2);
    FrameDescription g;
    v.frame(g);
    text = expect_overlay_inside(g, w, h);
    EXPECT_NE(text.find("nonexistent"), std::string::npos) << text;

    run_scripted(v, "0 drop " + long_name.string() + "\n", 0.2);
    FrameDescription k;
    v.frame(k);
    text = expect_overlay_inside(k, w, h);
    EXPECT_NE(text.find("WWWW"), std::string::npos) << text;
    EXPECT_NE(text.find("H: HELP"), std::string::npos) << text;
  }
  fs::remove_all(dir);
}

TEST(Canvas, WrapAndEllipsize) {
  EXPECT_EQ(wrap_text("ONE TWO THREE", 1000), "ONE TWO THREE");
  std::string w = wrap_text("ONE TWO THREE FOUR", text_width("ONE TWO"));
  EXPECT_EQ(w, "ONE TWO\nTHREE\nFOUR");
  std::string p = wrap_text("/a/very/long/path/name", text_width("/a/very/"));
  EXPECT_EQ(p.substr(0, p.find('\n')), "/a/very/");
  for (size_t a = 0, b; a <= p.size(); a = b + 1) {
    b = std::min(p.find('\n', a), p.size());
    EXPECT_LE(text_width(p.substr(a, b - a)), text_width("/a/very/"));
  }
  EXPECT_EQ(ellipsize("SHORT", 1000), "SHORT");
  std::string e = ellipsize("A RATHER LONG NAME", text_width("A RATHER"));
  EXPECT_LE(text_width(e), text_width("A RATHER"));
  EXPECT_EQ(e.substr(e.size() - 3), "...");
}

// Issue 21: "seed 000", "seed 001" and "OWN" meant nothing to a user. The menus and
// credits say what the programs are in plain words, and the viewer's status bar names
// each mode (the command line's help: rt_help_plain_words).
TEST(Words, NoSeedNumbersAndEveryModeNamed) {
  for (const ShellText& t : {drive_shell_text(), fly_shell_text()}) {
    for (const std::string& s : {t.title, t.subtitle, t.start, t.credits}) {
      EXPECT_EQ(s.find("SEED"), std::string::npos) << s;
      EXPECT_EQ(s.find("seed"), std::string::npos) << s;
    }
    EXPECT_FALSE(t.credits.empty());
  }
  ViewerProgram v({});
  v.resize(800, 600);
  run_scripted(v, "", 0);
  FrameDescription f;
  v.frame(f);
  std::string text = expect_overlay_inside(f, 800, 600);
  EXPECT_EQ(text.find("OWN"), std::string::npos) << text;
  for (const char* named : {"SHADING: AS THE MODEL SAYS", "DEPTH BUFFER", "SSAA 1X1", "PERSPECTIVE TEXTURES", "TRIANGLES"})
    EXPECT_NE(text.find(named), std::string::npos) << named << " not in " << text;
}

// Issue 21: screenshots always included the overlay. F12 (or C) writes the model alone,
// Shift+F12 the frame as the window shows it (status bar and frame rate too).
TEST(Viewer, ScreenshotsWithAndWithoutTheOverlay) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "velocity_viewer_shots";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ViewerOptions vo;
  vo.screenshot_prefix = (dir / "shot").string();
  ViewerProgram viewer(vo);
  LoopOptions o;
  o.width = 320, o.height = 240, o.frames = 20, o.threads = 2, o.quiet = true;
  o.record_dir = (dir / "frames").string();
  o.script = parse_script("0.05 press f12\n0.1 down shift\n0.15 press f12\n0.25 up shift\n");
  run_loop(viewer, nullptr, o);
  Image clean = read_image((dir / "shot-000.png").string());
  Image shown = read_image((dir / "shot-001.png").string());
  ASSERT_EQ(clean.width, 320);
  ASSERT_EQ(shown.width, 320);
  // Shift+F12 is exactly a frame the window showed.
  bool recorded = false;
  for (int i = 0; i < 20 && !recorded; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    recorded = read_image((dir / "frames" / name).string()).pixels == shown.pixels;
  }
  EXPECT_TRUE(recorded);
  // F12: the same scene, without the status bar (bottom rows) or the frame rate (top left).
  auto rows_equal = [&](int y0, int y1) {  // rows [y0, y1); y1 may be the height
    const size_t row = size_t(clean.width) * 4;
    return std::equal(clean.pixels.begin() + y0 * row, clean.pixels.begin() + y1 * row, shown.pixels.begin() + y0 * row);
  };
  EXPECT_TRUE(rows_equal(30, 180));
  EXPECT_FALSE(rows_equal(230, 240)) << "the status bar is in the F12 screenshot";
  EXPECT_FALSE(rows_equal(0, 10)) << "the frame rate is in the F12 screenshot";
  fs::remove_all(dir);
}

namespace {

// A window that is not there: counts the frames shown, hands out `events` at the given
// polls, and closes itself at poll `quit_at`.
struct FakeWindow : Presenter {
  int polls = 0, presents = 0, quit_at = 40;
  std::vector<std::pair<int, InputEvent>> events;
  void poll(std::vector<InputEvent>& out) override {
    ++polls;
    for (auto& [at, e] : events)
      if (at == polls) out.push_back(e);
    if (polls >= quit_at) {
      InputEvent quit;
      quit.kind = InputEvent::Quit;
      out.push_back(quit);
    }
  }
  void present(const uint8_t*, int, int) override { ++presents; }
  void set_title(const std::string&) override {}
  void toggle_fullscreen() override {}
  std::pair<int, int> window_size() const override { return {64, 48}; }
};

}  // namespace

// Issue 21: the viewer redrew when nothing changed (28 % of a core, idle). In a window,
// a frame with no input and nothing moving is not drawn; spinning draws every frame.
TEST(Loop, IdleViewerDrawsNothing) {
  LoopOptions o;
  o.width = 64, o.height = 48, o.threads = 1, o.quiet = true;
  {
    ViewerProgram viewer({});
    FakeWindow window;
    LoopResult r = run_loop(viewer, &window, o);
    EXPECT_EQ(window.polls, 40);
    EXPECT_LE(r.frames, 2);
    EXPECT_GE(window.presents, 1);  // the first frame is shown
  }
  {
    ViewerProgram viewer({});
    FakeWindow window;
    InputEvent space;
    space.kind = InputEvent::KeyDown;
    space.key = KeySpace;
    window.events = {{5, space}};
    LoopResult r = run_loop(viewer, &window, o);
    EXPECT_GE(r.frames, 35);  // spinning: every frame drawn
  }
}

// Issue 21: a light you can move. Shift+left-drag turns the key light about the vertical
// (and up or down); the camera stays; a plain drag still orbits the camera.
TEST(Viewer, ShiftDragMovesTheLight) {
  ViewerProgram v({});
  v.resize(320, 240);
  run_scripted(v, "", 0);
  const Vec3 light = v.light_direction();
  const float yaw = v.yaw(), pitch = v.pitch();
  ASSERT_GT(length(light), 0.5f);
  run_scripted(v, "0 down shift\n0.05 mousedown left 100 100\n0.1 move 160 100\n0.2 mouseup left 160 100\n"
                  "0.3 up shift\n", 0.4);
  const Vec3 moved = v.light_direction();
  EXPECT_NEAR(v.yaw(), yaw, 1e-6);
  EXPECT_NEAR(v.pitch(), pitch, 1e-6);
  EXPECT_NEAR(std::atan2(moved.x, moved.z) - std::atan2(light.x, light.z), 60.0f / 240.0f * std::numbers::pi_v<float>,
              1e-4);
  EXPECT_NEAR(moved.y, light.y, 1e-4);  // a horizontal drag keeps its height
  FrameDescription f;
  v.frame(f);
  bool found = false;
  for (const Light& l : f.scene.lights)
    found |= l.type == LightType::Directional && length(normalize(l.direction) - moved) < 1e-5f;
  EXPECT_TRUE(found) << "the frame is not lit from the moved light";
}

// Issue 21: a grid toggle. G puts a grid on the floor, under the model's lowest point,
// and it shows in the rendered frame; G again takes it away.
TEST(Viewer, GridOnTheFloor) {
  ViewerOptions o;
  o.model = VELOCITY_TEST_MODEL;
  ViewerProgram v(o);
  v.resize(160, 120);
  auto render = [&](FrameDescription& f) {
    v.frame(f);
    Renderer r(160, 120);
    r.options = f.options;
    r.render(f.scene);
    std::vector<uint8_t> px(160 * 120 * 4);
    r.read_color(px.data(), 160 * 4, 4);
    return px;
  };
  run_scripted(v, "", 0);
  FrameDescription plain;
  std::vector<uint8_t> without = render(plain);
  EXPECT_FALSE(plain.scene.find("viewer grid"));
  run_scripted(v, "0 press g\n", 0.1);
  EXPECT_TRUE(v.grid_shown());
  FrameDescription gridded;
  std::vector<uint8_t> with = render(gridded);
  auto id = gridded.scene.find("viewer grid");
  ASSERT_TRUE(id);
  float low = 1e30f;
  std::vector<Mat4> world = plain.scene.world_matrices();
  for (size_t i = 0; i < plain.scene.objects().size(); ++i)
    if (plain.scene.objects()[i].mesh)
      for (const Vec3& p : plain.scene.objects()[i].mesh->positions) low = std::min(low, world[i].transform_point(p).y);
  const float grid_y = gridded.scene.object(*id).transform.translation.y;
  EXPECT_NEAR(grid_y, low, 0.01f * plain.scene.bounds().radius);
  EXPECT_NE(with, without) << "the grid does not show";
  run_scripted(v, "0 press g\n", 0.1);
  FrameDescription again;
  EXPECT_EQ(render(again), without);
}

// Issue 21: an axes toggle. X draws the world's axes at its origin (red X, green Y,
// blue Z), and they show in the rendered frame.
TEST(Viewer, AxesAtTheOrigin) {
  ViewerOptions o;
  o.model = VELOCITY_TEST_MODEL;
  ViewerProgram v(o);
  v.resize(160, 120);
  run_scripted(v, "0 press x\n", 0.1);
  ASSERT_TRUE(v.axes_shown());
  FrameDescription f;
  v.frame(f);
  int axis = 0;
  for (const char* name : {"viewer axis x", "viewer axis y", "viewer axis z"}) {
    auto id = f.scene.find(name);
    ASSERT_TRUE(id) << name;
    Bounds b = f.scene.object(*id).mesh->bounds();
    // Long along its own axis from the origin, thin across.
    EXPECT_NEAR((&b.min.x)[axis], 0.0f, 1e-5f) << name;
    EXPECT_GT((&b.max.x)[axis], 10 * (&b.max.x)[(axis + 1) % 3]) << name;
    ++axis;
  }
  Renderer r(160, 120);
  r.options = f.options;
  r.render(f.scene);
  std::vector<uint8_t> px(160 * 120 * 4);
  r.read_color(px.data(), 160 * 4, 4);
  int red = 0, green = 0, blue = 0;
  for (size_t i = 0; i < px.size(); i += 4) {
    red += px[i] > 180 && px[i + 1] < 80 && px[i + 2] < 80;
    green += px[i + 1] > 180 && px[i] < 100 && px[i + 2] < 100;
    blue += px[i + 2] > 200 && px[i] < 100 && px[i + 1] < 140;
  }
  EXPECT_GT(red, 5);
  EXPECT_GT(green, 5);
  EXPECT_GT(blue, 5);
}

// Issue 21: a point cloud (a PLY file with vertices and no faces) opens in the viewer,
// the status bar counts points, and ] / [ make the points bigger and smaller in pixels:
// the rendered frame lights about size² pixels a point.
TEST(Viewer, PointCloudsWithAPointSizeKey) {
  namespace fs = std::filesystem;
  const fs::path path = fs::temp_directory_path() / ("velocity_viewer_cloud_" + std::to_string(::getpid()) + ".ply");
  {
    std::ofstream f(path);
    // Five points well apart (an asymmetric cross), so their squares never overlap.
    f << "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
         "end_header\n0 0 0\n1 0 0\n-1 0 0\n0 1.5 0\n0 -0.7 0.3\n";
  }
  ViewerOptions o;
  o.model = path.string();
  ViewerProgram v(o);
  fs::remove(path);
  v.resize(200, 150);
  EXPECT_EQ(v.points(), 5u);
  auto lit = [&] {
    FrameDescription f;
    v.frame(f);
    Renderer r(200, 150);
    r.options = f.options;
    r.render(f.scene);
    std::vector<uint8_t> px(200 * 150 * 4);
    r.read_color(px.data(), 200 * 4, 4);
    const Vec3 bg = f.scene.background;
    int n = 0;
    for (size_t i = 0; i < px.size(); i += 4) n += std::abs(px[i] - int(std::lround(bg.x * 255))) > 40;
    return n;
  };
  run_scripted(v, "0 wheel -4\n", 0);  // back a little: the framing puts points at the edge
  EXPECT_EQ(v.render_options().point_size, 1.0f);
  const int one = lit();
  EXPECT_EQ(one, 5) << "one pixel a point";
  run_scripted(v, "0 press ]\n0.1 press ]\n0.2 press ]\n", 0.3);
  EXPECT_EQ(v.render_options().point_size, 4.0f);
  EXPECT_EQ(lit(), 5 * 16) << "4x4 pixels a point";
  FrameDescription f;
  v.frame(f);
  std::string bar;
  for (const DrawOp& op : f.overlay.ops()) bar += op.text + "|";
  EXPECT_NE(bar.find("5 POINTS"), std::string::npos) << bar;
  EXPECT_NE(bar.find("POINTS 4 PX"), std::string::npos) << bar;
  run_scripted(v, "0 press [\n", 0.1);
  EXPECT_EQ(v.render_options().point_size, 3.0f);
  for (int i = 0; i < 20; ++i) run_scripted(v, "0 press [\n", 0.02);
  EXPECT_EQ(v.render_options().point_size, 1.0f) << "never below one pixel";
}

// Issue 21: a glTF file's animation plays in the viewer. One second in, the animated
// node is at the pose interpolated between the keys (translation and slerped rotation
// halfway, the STEP scale past its step), numerically and in pixels: the frame equals
// the one of a still file with the node placed at that pose by hand. K pauses; J and L
// step back and on.
// N chooses the next animation: the one before goes back to its rest pose, the new one
// plays from its start, and the status bar names it.
TEST(Viewer, NextAnimationKeyChoosesAmongTheFilesAnimations) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("velocity_viewer_anims_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "two.gltf") << velocity::test::animated_box_gltf(true, {0, 0, 0}, {0, 0, 0, 1}, {1, 1, 1}, true);
  ViewerOptions o;
  o.model = (dir / "two.gltf").string();
  ViewerProgram v(o);
  v.resize(640, 480);
  ASSERT_EQ(v.animations().size(), 2u);
  EXPECT_EQ(v.animation(), 0u);
  // "move" plays half a second, then N, K (pause) and four steps of a tenth: 0.4 s into "lift".
  run_scripted(v, "0.5 press n\n0.5 press k\n0.6 press l\n0.7 press l\n0.8 press l\n0.9 press l\n", 1.0);
  EXPECT_EQ(v.animation(), 1u);
  EXPECT_FALSE(v.playing());
  EXPECT_NEAR(v.animation_time(), 0.4, 1e-6);
  FrameDescription f;
  v.frame(f);
  // "mover" at rest again (no translation, turn or scale of its own) under "base", lifted
  // a quarter of the way from (0, 1, 0) to (0, 3, -1).
  const Mat4 world = f.scene.world_matrices()[*f.scene.find("mover")];
  const Mat4 expected = translate({0, 1.5f, -0.25f});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(world.m[i][j], expected.m[i][j], 1e-5f) << i << "," << j;
  std::string bar;
  for (const DrawOp& op : f.overlay.ops()) bar += op.text + "|";
  EXPECT_NE(bar.find("ANIMATION 2/2 LIFT 0.40/1.60 S PAUSED"), std::string::npos) << bar;
  // And round again to the first, from its start.
  run_scripted(v, "0 press n\n", 0.0);
  EXPECT_EQ(v.animation(), 0u);
  fs::remove_all(dir);
}

TEST(Viewer, GltfAnimationPlaysPausesAndSteps) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("velocity_viewer_anim_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const float h = std::sin(std::numbers::pi_v<float> / 8);  // 45 degrees about Y: (0, sin 22.5, 0, cos 22.5)
  std::ofstream(dir / "moving.gltf") << velocity::test::animated_box_gltf(true);
  std::ofstream(dir / "posed.gltf") << velocity::test::animated_box_gltf(false, {1, 0, 0}, {0, h, 0, std::cos(std::numbers::pi_v<float> / 8)},
                                                              {2, 2, 2});
  ViewerOptions o;
  o.model = (dir / "moving.gltf").string();
  ViewerProgram v(o);
  v.resize(160, 120);
  ASSERT_EQ(v.animations().size(), 1u);
  // Plays one second (60 steps), then pauses; back off (the box moves out of the opening view).
  run_scripted(v, "1.01 press k\n1.05 wheel -12\n", 1.2);
  EXPECT_FALSE(v.playing());
  EXPECT_NEAR(v.animation_time(), 1.0, 1e-6);
  FrameDescription f;
  v.frame(f);
  const ObjectId id = *f.scene.find("mover");
  const Mat4 expected = translate({0, 1, 0}) * translate({1, 0, 0}) * rotate_y(std::numbers::pi_v<float> / 4) *
                        scale({2, 2, 2});
  const Mat4 world = f.scene.world_matrices()[id];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(world.m[i][j], expected.m[i][j], 1e-5f) << i << "," << j;
  std::string bar;
  for (const DrawOp& op : f.overlay.ops()) bar += op.text + "|";
  EXPECT_NE(bar.find("ANIMATION 1.00/2.00 S"), std::string::npos) << bar;
  EXPECT_NE(bar.find("ANIMATION PAUSED"), std::string::npos) << bar;

  // The same pixels as the still file's, seen by the same camera in the same light.
  auto pixels = [](const Scene& scene, const RenderOptions& options) {
    Renderer r(160, 120);
    r.options = options;
    r.render(scene);
    std::vector<uint8_t> px(160 * 120 * 4);
    r.read_color(px.data(), 160 * 4, 4);
    return px;
  };
  ViewerOptions so = o;
  so.model = (dir / "posed.gltf").string();
  ViewerProgram still(so);
  still.resize(160, 120);
  run_scripted(still, "", 0);
  FrameDescription sf;
  still.frame(sf);
  sf.scene.camera = f.scene.camera;
  sf.scene.lights = f.scene.lights;
  const std::vector<uint8_t> animated = pixels(f.scene, f.options), posed = pixels(sf.scene, sf.options);
  int differ = 0, lit = 0;
  for (size_t i = 0; i < animated.size(); i += 4) {
    differ += std::abs(animated[i] - posed[i]) > 2 || std::abs(animated[i + 1] - posed[i + 1]) > 2;
    lit += animated[i] != animated[0] || animated[i + 1] != animated[1];
  }
  EXPECT_GT(lit, 100) << "the box does not show";
  EXPECT_LE(differ, 2) << "the animated frame is not the posed one";
  // And not the rest pose's: the animation moved it.
  ViewerOptions ro = o;
  ro.model = (dir / "posed.gltf").string();
  std::ofstream(dir / "posed.gltf") << velocity::test::animated_box_gltf(false);
  ViewerProgram rest(ro);
  rest.resize(160, 120);
  FrameDescription rf;
  rest.frame(rf);
  rf.scene.camera = f.scene.camera;
  rf.scene.lights = f.scene.lights;
  EXPECT_NE(pixels(rf.scene, rf.options), animated);

  // Stepping: L a tenth on, J two back; the pose follows (STEP scale back to 1 before 0.8 s).
  run_scripted(v, "0 press l\n", 0.05);
  EXPECT_NEAR(v.animation_time(), 1.1, 1e-6);
  run_scripted(v, "0 press j\n0.01 press j\n0.02 press j\n", 0.05);
  EXPECT_NEAR(v.animation_time(), 0.8, 1e-6);
  run_scripted(v, "0 press j\n", 0.05);
  FrameDescription g;
  v.frame(g);
  const Mat4 at07 = g.scene.world_matrices()[*g.scene.find("mover")];
  EXPECT_NEAR(at07.m[1][1], 1.0f, 1e-5f) << "the STEP scale is 1 before 0.8 s";
  EXPECT_NEAR(at07.m[0][3], 0.7f, 1e-5f) << "translation at 0.7 s";
  // K plays on from there.
  run_scripted(v, "0 press k\n", 0.5);
  EXPECT_TRUE(v.playing());
  EXPECT_NEAR(v.animation_time(), 1.2, 1e-6);
  fs::remove_all(dir);
}

// `view --color/--tone-map/--exposure` reach the frame as `render`'s do, and a glTF
// model is drawn as `render` draws it (scene_from_model, ColorPipeline::Auto): an unlit
// baseColorFactor 0.5 shows 188 (sRGB of linear 0.5); exposure 0.5 in the linear
// pipeline shows sRGB of 0.25, 137; the display pipeline has no exposure.
TEST(Viewer, ColourOptionsAsRenderHasThem) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "velocity_viewer_colour";
  fs::create_directories(dir);
  const fs::path model = dir / "grey.gltf";
  {
    // One quad, x and y in [-1, 1] at z = 0, facing +Z: positions then indices.
    const float pos[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    std::string blob(reinterpret_cast<const char*>(pos), sizeof pos);
    blob.append(reinterpret_cast<const char*>(idx), sizeof idx);
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string uri;
    for (size_t i = 0; i < blob.size(); i += 3) {
      const size_t n = std::min<size_t>(3, blob.size() - i);
      uint32_t v = 0;
      for (size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? uint8_t(blob[i + k]) : 0u);
      for (size_t k = 0; k < 4; ++k) uri += k <= n ? b64[(v >> (18 - 6 * k)) & 63] : '=';
    }
    std::FILE* f = std::fopen(model.string().c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}, "extensions": {"KHR_materials_unlit": {}}}],
      "extensionsUsed": ["KHR_materials_unlit"],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
      "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,%s"}]})",
                 uri.c_str());
    std::fclose(f);
  }
  auto centre = [&](ColorPipeline color, float exposure) {
    ViewerOptions o;
    o.model = model.string();
    o.color = color, o.exposure = exposure;
    ViewerProgram v(o);
    v.resize(64, 48);
    FrameDescription frame;
    v.frame(frame);
    EXPECT_EQ(frame.options.color, color);
    EXPECT_EQ(frame.options.exposure, exposure);
    Renderer r(64, 48);
    r.options = frame.options;
    r.render(frame.scene);
    return int(r.color_image().pixel(32, 24)[0]);
  };
  EXPECT_EQ(centre(ColorPipeline::Auto, 1.0f), 188);
  EXPECT_EQ(centre(ColorPipeline::Auto, 0.5f), 137);
  EXPECT_EQ(centre(ColorPipeline::Display, 0.5f), 188);
  fs::remove_all(dir);
}
