// `velocity drive`: the driving simulation (programs/drive.hpp) behind a title screen and
// menu.
#include <memory>

#include "commands.hpp"
#include "programs/commands/realtime.hpp"
#include "programs/drive.hpp"

namespace velocity::cli {

std::function<int()> add_drive_command(CLI::App& app) {
  struct Args {
    RealtimeArgs realtime;
    std::string car;
    float car_yaw = 0;
    bool hq = false, skip_menu = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("drive", "Drive a car on a race track: arrows drive, C camera, H high quality, Esc menu");
  cmd->add_option("--car", args->car, "Car body model (e.g. ../shared/data/models/asc/car01.asc); default: the built-in car");
  cmd->add_option("--car-yaw", args->car_yaw, "Turn the car model by this many degrees (its nose must point forward)");
  cmd->add_flag("--hq", args->hq, "High quality: 3x3 super-sampling (H toggles)");
  cmd->add_flag("--skip-menu", args->skip_menu, "Start driving at once (no title screen or menu)");
  add_realtime_options(cmd, args->realtime);
  return [args] {
    realtime::DriveOptions o;
    o.car = args->car;
    o.car_yaw = args->car_yaw;
    o.high_quality = args->hq;
    realtime::DriveProgram drive(o);
    realtime::Shell shell(drive, realtime::drive_shell_text(), args->skip_menu);
    return run_realtime(shell, args->realtime, "800x600", true);
  };
}

}  // namespace velocity::cli
