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
#include "runtime/script.hpp"
#include "velocity/backend.hpp"
#include "velocity/renderer.hpp"

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

  // The windowed GPU path (docs/gpu.md, "In a window"). The window's OpenGL context,
  // when it was made with one, for the GPU backend to draw in; null otherwise. While it
  // is in use, frames are drawn into its back buffer and shown by swap(), not present().
  virtual GlContextProvider* gl_context() { return nullptr; }
  // Why the window has no GL context although one was asked for ("" otherwise).
  virtual std::string gl_missing() const { return ""; }
  // Gives the GL context up (the GPU backend cannot draw in it: `why`); frames come
  // through present() from then on.
  virtual void drop_gl_context(const std::string& why) { (void)why; }
  // Shows the GL context's back buffer (waits for vertical sync when asked for).
  virtual void swap() {}
  // Whether the window was uncovered since the last call: the GL path shows its last
  // frame again (present() does that by itself).
  virtual bool take_exposed() { return false; }
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
  // What draws (docs/gpu.md): with gpu (or auto choosing it) and a presenter that has a
  // GL context, the GPU backend draws in the window's context and the frame is never
  // read back for display; otherwise it renders offscreen (EGL) and the frame is read
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
  // Which path presented: "cpu", "gpu, windowed (SDL GL context)" or "gpu, offscreen
  // EGL + read-back (why not windowed)".
  std::string present_path;
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
