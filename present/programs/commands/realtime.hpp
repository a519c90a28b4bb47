// What `velocity view`, `fly` and `drive` share: the window, sound, scripts, recording
// and the statistics line, as command-line options.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "runtime/program.hpp"
#include "runtime/shell.hpp"

namespace velocity::cli {

struct RealtimeArgs {
  std::string command;       // "view", "fly" or "drive" (for messages)
  std::string size;          // "WxH" or "window"; empty: the command's default
  int scale = 0;             // window = frame size x scale (0: fit the screen sensibly)
  bool fullscreen = false;
  long frames = 0;
  std::string record;
  std::string script;
  bool headless = false;
  bool mute = false;
  bool no_overlay = false;
  bool no_vsync = false;
  bool at_origin = false;
  double linger = 0;
  int threads = 0;
  std::string backend = "cpu";  // --backend: cpu, gpu or auto (docs/gpu.md)
  bool no_gl_window = false;    // --no-gl-window: the GPU's frames read back, not drawn in the window
  bool ends_itself = false;  // the program ends on its own (a replay): a run nobody sees may take it
};

// Registers the options above on `cmd`.
void add_realtime_options(CLI::App* cmd, RealtimeArgs& args);
// Runs `program` with a window (or headless), sound and the main loop; prints the
// frame-time statistics at exit. `default_size` when --size is not given.
int run_realtime(realtime::Program& program, const RealtimeArgs& args, const std::string& default_size, bool sound);
// The options screen's choices kept in $XDG_CONFIG_HOME/velocity/COMMAND.conf
// (runtime/settings_file.hpp). A scripted run (or a replay: `replaying`) starts from the
// defaults and keeps nothing, so that a script does the same on every machine.
void keep_settings(realtime::Shell& shell, const RealtimeArgs& args, bool replaying = false);

}  // namespace velocity::cli
