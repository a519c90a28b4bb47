// `velocity fly`: the flythrough (programs/fly.hpp) behind its title screen and menu.
#include <algorithm>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "programs/commands/realtime.hpp"
#include "programs/fly.hpp"
#include "velocity/error.hpp"

namespace velocity::cli {

std::function<int()> add_fly_command(CLI::App& app) {
  struct Args {
    RealtimeArgs realtime;
    std::vector<std::string> models;
    std::string plg_dir;
    int objects = 90;
    unsigned seed = 1;
    bool skip_menu = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("fly", "Fly through a world of polygon shapes: arrows turn, dive and climb; A/Z faster/slower; Esc menu");
  cmd->add_option("--models", args->models, "Model files to fill the world with (PLG, ASC, OBJ, ...)");
  cmd->add_option("--plg", args->plg_dir, "Fill the world with every .plg file in this folder (e.g. ../shared/data/models/plg)");
  cmd->add_option("--objects", args->objects, "How many objects (1..2000)")->capture_default_str();
  cmd->add_option("--seed", args->seed, "World layout seed")->capture_default_str();
  cmd->add_flag("--skip-menu", args->skip_menu, "Start flying at once (no title screen or menu)");
  add_realtime_options(cmd, args->realtime);
  return [args] {
    realtime::FlyOptions o;
    o.models = args->models;
    if (!args->plg_dir.empty()) {
      std::error_code ec;
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(args->plg_dir, ec)) {
        std::string ext = entry.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (entry.is_regular_file() && ext == ".plg") found.push_back(entry.path().string());
      }
      if (ec) throw Error("--plg: cannot read folder " + args->plg_dir + ": " + ec.message());
      std::sort(found.begin(), found.end());
      o.models.insert(o.models.end(), found.begin(), found.end());
    }
    if (args->objects < 1 || args->objects > 2000) throw Error("--objects must be 1..2000");
    o.objects = args->objects;
    o.seed = args->seed;
    realtime::FlyProgram fly(o);
    realtime::Shell shell(fly, realtime::fly_shell_text(), args->skip_menu);
    keep_settings(shell, args->realtime);
    return run_realtime(shell, args->realtime, "640x480", true);
  };
}

}  // namespace velocity::cli
