#include "programs/commands/realtime.hpp"

#include <SDL.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "runtime/loop.hpp"
#include "runtime/settings_file.hpp"
#include "runtime/synth.hpp"
#include "sdl/presenter.hpp"
#include "velocity/error.hpp"

namespace velocity::cli {

void add_realtime_options(CLI::App* cmd, RealtimeArgs& a) {
  a.command = cmd->get_name();
  cmd->add_option("--size", a.size,
                  "Frame size WxH (the classic modes: 320x200, 320x240, 640x480, 800x600) or 'window' (the window's size)");
  cmd->add_option("--scale", a.scale, "Window size as a multiple of the frame size (default: fits the screen)");
  cmd->add_flag("--fullscreen", a.fullscreen, "Start fullscreen (F11 or Alt+Enter toggles)");
  cmd->add_option("--frames", a.frames, "Stop after this many frames");
  cmd->add_option("--record", a.record,
                  a.command == "drive" ? "Write every frame to DIR/frame_NNNNN.png (fixed 1/60 s step); a name ending in "
                                         ".replay records the race instead, for --replay"
                                       : "Write every frame to DIR/frame_NNNNN.png (fixed 1/60 s step)");
  cmd->add_option("--script", a.script, "Timed key presses and mouse events (see present/runtime/script.hpp)");
  cmd->add_flag("--headless", a.headless, "No window; needs --frames N or --script FILE to end the run");
  cmd->add_flag("--mute", a.mute, "No sound");
  cmd->add_flag("--no-overlay", a.no_overlay, "Hide the frame-rate overlay (F3 toggles)");
  cmd->add_flag("--no-vsync", a.no_vsync, "Present without waiting for vertical sync (may tear)");
  cmd->add_flag("--window-at-origin", a.at_origin, "Put the window at the screen's top-left corner");
  cmd->add_option("--linger", a.linger, "After the last frame, keep the window open this many seconds");
  cmd->add_option("--threads", a.threads, "Threads rasterizing tiles (0: every core)");
  cmd->add_option("--backend", a.backend,
                  "What draws: cpu, gpu (OpenGL 3.3: in the window's own GL context, or through EGL with the frame "
                  "read back when there is no window or it has no GL context) or auto (a hardware GPU, else cpu)")
      ->capture_default_str();
  cmd->add_flag("--no-gl-window", a.no_gl_window,
                "With --backend gpu: draw offscreen through EGL and show the frame read back, not in the window's "
                "OpenGL context");
}

void keep_settings(realtime::Shell& shell, const RealtimeArgs& a, bool replaying) {
  if (!a.script.empty() || replaying) return;
  if (std::string path = realtime::default_settings_file(a.command); !path.empty()) shell.keep_settings_in(path);
}

int run_realtime(realtime::Program& program, const RealtimeArgs& a, const std::string& default_size, bool sound) {
  realtime::LoopOptions lo;
  std::string size = a.size.empty() ? default_size : a.size;
  if (size == "window") {
    lo.follow_window = true;
    lo.width = 800, lo.height = 600;
  } else {
    parse_size(size, lo.width, lo.height);
  }
  if (a.frames < 0) throw Error("--frames must be 0 or more");
  if (a.scale < 0 || a.scale > 16) throw Error("--scale must be 1..16");
  if (a.linger < 0 || a.linger > 3600) throw Error("--linger must be 0..3600 seconds");
  // Something must end a run nobody sees: --frames, or a script (it ends when played out).
  const bool bounded = a.frames > 0 || !a.script.empty() || a.ends_itself;
  if (a.headless && !bounded)
    throw Error("--headless runs until something ends it: give --frames N, or --script FILE (the run ends when "
                "the script has played out)");
  lo.frames = a.frames;
  lo.record_dir = a.record;
  if (!a.script.empty()) lo.script = realtime::load_script(a.script);
  lo.overlay = !a.no_overlay;
  lo.linger = a.linger;
  lo.threads = a.threads;
  const std::optional<BackendChoice> backend = parse_backend(a.backend);
  if (!backend) throw Error("--backend: expected cpu|gpu|auto, got '" + a.backend + "'");
  lo.backend = *backend;

  // Ctrl+C and SIGTERM finish the frame in progress and the recording, then end.
  realtime::install_stop_signals();
  std::unique_ptr<present::SdlPresenter> window;
  if (!a.headless) {
    present::WindowOptions w;
    w.title = program.title();
    // Small modes get a bigger window (the seed's 320x200 is a postage stamp today).
    int scale = a.scale ? a.scale : std::max(1, 800 / std::max(lo.width, 1));
    w.width = lo.width * scale, w.height = lo.height * scale;
    w.fullscreen = a.fullscreen;
    w.vsync = !a.no_vsync;
    w.at_origin = a.at_origin;
    // The GPU draws in the window's own OpenGL context (the loop falls back to reading
    // its frames back when that context cannot be made or used).
    w.opengl = lo.backend != BackendChoice::Cpu && !a.no_gl_window;
    try {
      window = std::make_unique<present::SdlPresenter>(w);
    } catch (const Error& e) {
      if (!bounded)
        throw Error(std::string(e.what()) + "; without a display, run: velocity " + a.command +
                    " --headless --frames N");
      std::fprintf(stderr, "velocity: %s; running headless\n", e.what());
    }
    // SDL_VIDEODRIVER=dummy (tests): nobody sees the window, so something must end the run.
    if (window && window->invisible() && !bounded)
      throw Error("the " + window->driver().substr(0, window->driver().find('/')) +
                  " video driver shows nothing: give --frames N (or --script FILE) to end the run, " +
                  "or unset SDL_VIDEODRIVER to open a window");
  }
  lo.end_with_script = a.frames <= 0 && (!window || window->invisible());
  realtime::Synth synth;
  std::unique_ptr<present::SdlAudio> audio;
  if (sound && !a.mute) audio = std::make_unique<present::SdlAudio>(synth);
  lo.synth = &synth;
  lo.pace_to_clock = audio && audio->active();
  realtime::run_loop(program, window.get(), lo);
  audio.reset();
  window.reset();
  SDL_Quit();
  if (int sig = realtime::stop_signal()) return 128 + sig;  // as a shell reports a signal
  return 0;
}

}  // namespace velocity::cli
