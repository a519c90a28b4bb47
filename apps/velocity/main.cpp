// velocity: render a model or the built-in demo scene, benchmark, inspect a file.
//
//   velocity                      render the demo scene to velocity.png
//   velocity render MODEL ...     render a model file or a generated model
//   velocity bench ...            the reference scene convention, timed
//   velocity info FILE            what a model file holds
//   velocity batch JOB ...        many models x many views to a folder (the Python job runner)
//   velocity view [FILE]          look at a model in a window (present/programs)
//   velocity fly                  a flythrough among polygon shapes
//   velocity drive                a driving simulation on a race track
#include <cstdio>

#include "commands.hpp"
#include "velocity/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Velocity: a software 3D renderer. With no command, renders the demo scene to velocity.png."};
  app.require_subcommand(0, 1);
  app.set_help_all_flag("--help-all", "Show the help of every command");
  auto render = velocity::cli::add_render_command(app);
  auto bench = velocity::cli::add_bench_command(app);
  auto info = velocity::cli::add_info_command(app);
  auto batch = velocity::cli::add_batch_command(app);
#ifdef VELOCITY_HAVE_REALTIME
  auto view = velocity::cli::add_view_command(app);
  auto fly = velocity::cli::add_fly_command(app);
  auto drive = velocity::cli::add_drive_command(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (app.got_subcommand("bench")) return bench();
    if (app.got_subcommand("info")) return info();
    if (app.got_subcommand("batch")) return batch();
#ifdef VELOCITY_HAVE_REALTIME
    if (app.got_subcommand("view")) return view();
    if (app.got_subcommand("fly")) return fly();
    if (app.got_subcommand("drive")) return drive();
#endif
    return render();  // `render`, or no command at all: the demo scene
  } catch (const velocity::Error& e) {
    std::fprintf(stderr, "velocity: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "velocity: %s\n", e.what());
    return 1;
  }
}
