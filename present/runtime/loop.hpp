// The main loop: events -> update -> describe the frame -> render it on the render
// thread while the previous frame is presented, so that rendering frame N + 1 overlaps
// presenting frame N (which waits for the display's vertical sync).
//
// With a fixed step (set by scripts and recordings) every frame advances the program
// by exactly 1/60 s, so a scripted run gives the same frames on every machine.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/program.hpp"
#include "velocity/renderer.hpp"
#include "runtime/script.hpp"

namespace velocity::realtime {

// Where frames are shown and events come from: the SDL window (present/sdl), or none.
class Presenter {
 public:
  virtual ~Presenter() = default;
  virtual void poll(std::vector<InputEvent>& out) = 0;
  // Shows an RGBA8 frame (top row first, width * 4 bytes a row), scaled to the window
  // keeping its aspect ratio; waits for vertical sync when the display has one.
  virtual void present(const uint8_t* rgba, int width, int height) = 0;
  virtual void set_title(const std::string& title) = 0;
  virtual void toggle_fullscreen() = 0;
  // The window's drawable size in pixels.
  virtual std::pair<int, int> window_size() const = 0;
  // The first game controller's sticks and triggers (none: connected = false).
  virtual GamepadState gamepad() const { return {}; }
};

// The seed's screen modes (F2 cycles them, then "the window's own size").
struct ScreenMode {
  int width, height;
};
inline constexpr ScreenMode kScreenModes[] = {{320, 200}, {320, 240}, {640, 480}, {800, 600}};

struct LoopOptions {
  int width = 800, height = 600;
  bool follow_window = false;  // the frame takes the window's size (any size)
  long frames = 0;             // stop after this many frames (0: when the program ends)
  std::string record_dir;      // write frame N as DIR/frame_NNNNN.png
  std::optional<Script> script;
  bool end_with_script = false;  // stop once the script has played out (runs nobody sees)
  bool fixed_step = false;     // 1/60 s a frame whatever the clock says
  bool pace_to_clock = false;  // with a fixed step, never run ahead of the wall clock (sound on)
  bool overlay = true;         // frame rate and frame time in the corner (F3 toggles)
  double linger = 0;           // after the last frame keep the window up this long (s)
  int threads = 0;             // rasterizer threads (0: every core)
  // What draws (docs/gpu.md): the GPU backend renders offscreen and the frame is read
  // back and presented as the CPU's is.
  BackendChoice backend = BackendChoice::Cpu;
  Synth* synth = nullptr;      // where the program's sound goes, if anywhere
  bool quiet = false;          // no statistics line at exit
};

struct LoopResult {
  long frames = 0;
  std::vector<double> frame_ms;   // wall time from one frame's start to the next
  std::vector<double> render_ms;  // the render thread's time per frame (3D + 2D + read-back)
  int width = 0, height = 0;
};

inline constexpr double kFixedStep = 1.0 / 60.0;

LoopResult run_loop(Program& program, Presenter* presenter, const LoopOptions& options);

// SIGINT and SIGTERM ask run_loop to stop after the frame in progress: the frame being
// rendered is still shown and recorded, the statistics printed. A second signal ends the
// program at once (frames are written to NAME.part and renamed, so no PNG is ever half
// written). Install before SDL starts (SDL then leaves these signals alone).
void install_stop_signals();
// The signal that asked run_loop to stop; 0 when none.
int stop_signal();

// The height of the frame-rate overlay's band at the top of a frame this high (the
// games keep their displays out of it).
int stats_band_height(int frame_height);

// The value below which `fraction` (0..1) of `samples` lie (nearest rank); 0 when empty.
double percentile(std::vector<double> samples, double fraction);
// "frames=N size=WxH median_ms=... p99_ms=... fps=... render_median_ms=... render_p99_ms=..."
std::string summarize(const LoopResult& result);

}  // namespace velocity::realtime
