// The command-line program's subcommands: each part of the program registers its own.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "velocity/renderer.hpp"

namespace velocity::cli {

// Parses "WxH" into width and height (1..16384 each); throws CLI::ValidationError.
void parse_size(const std::string& text, int& width, int& height);

// --color, --tone-map, --exposure, --shadows and --shadow-map-size
// (apps/velocity/appearance.cpp), and how they set the RenderOptions (throws
// velocity::Error naming the flag on a bad value).
struct AppearanceArgs {
  std::string color = "auto", tone_map = "none";
  float exposure = 1.0f;
  bool shadows = false;
  int shadow_map_size = 2048;
};
void add_appearance_options(CLI::App* cmd, AppearanceArgs& a);
void apply_appearance(const AppearanceArgs& a, RenderOptions& o);

// Each registers its subcommand on `app` and returns a function that runs it (exit code).
std::function<int()> add_render_command(CLI::App& app);
std::function<int()> add_bench_command(CLI::App& app);
std::function<int()> add_info_command(CLI::App& app);
std::function<int()> add_batch_command(CLI::App& app);
// Real time: a window, input and sound. Defined by the real-time part
// (present/programs/commands), registered when it is built (VELOCITY_HAVE_REALTIME:
// apps/velocity/CMakeLists.txt).
std::function<int()> add_view_command(CLI::App& app);
std::function<int()> add_fly_command(CLI::App& app);
std::function<int()> add_drive_command(CLI::App& app);

}  // namespace velocity::cli
