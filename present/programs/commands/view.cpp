// `velocity view [FILE]`: the orbit viewer (programs/viewer.hpp) in a window.
#include <memory>

#include "commands.hpp"
#include "programs/commands/realtime.hpp"
#include "programs/viewer.hpp"

namespace velocity::cli {

std::function<int()> add_view_command(CLI::App& app) {
  struct Args {
    RealtimeArgs realtime;
    std::string model;
    bool cull = false, swap_yz = true;
    int ssaa = 1;
    std::string shot = "velocity-shot";
    AppearanceArgs appearance;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("view", "Look at a model in a window: drag rotates, wheel zooms, right-drag pans, H for help");
  cmd->add_option("model", args->model, "Model file (.asc, .plg, .obj, .gltf, .glb, .3ds, .ply, .stl); none: the demo scene");
  cmd->add_flag("--cull", args->cull, "Cull back faces (default: drawn, lit from both sides)");
  cmd->add_flag("!--no-swap-yz", args->swap_yz, "Keep 3D Studio's Z-up coordinates (ASC files)");
  cmd->add_option("--ssaa", args->ssaa, "Super-sampling factor 1..3 to start with (A cycles)")
      ->check(CLI::Range(1, 3))
      ->capture_default_str();
  cmd->add_option("--screenshot-prefix", args->shot, "Screenshots (C or F12) go to PREFIX-NNN.png")->capture_default_str();
  add_appearance_options(cmd, args->appearance);
  add_realtime_options(cmd, args->realtime);
  return [args] {
    RenderOptions colour;
    apply_appearance(args->appearance, colour);
    realtime::ViewerOptions o;
    o.model = args->model;
    o.load.swap_yz = args->swap_yz;
    o.cull_back_faces = args->cull;
    o.ssaa = args->ssaa;
    o.shadows = colour.shadows;  // to start with (O toggles)
    o.shadow_map_size = colour.shadow_map_size;
    o.screenshot_prefix = args->shot;
    o.color = colour.color, o.tone_map = colour.tone_map, o.exposure = colour.exposure;
    realtime::ViewerProgram viewer(o);
    return run_realtime(viewer, args->realtime, "800x600", false);
  };
}

}  // namespace velocity::cli
