// `velocity drive`: seed 000's driving simulation (programs/drive.hpp) behind a title screen
// and menu.
#include <memory>

#include "commands.hpp"
#include "programs/commands/realtime.hpp"
#include "programs/drive.hpp"

namespace velocity::cli {

namespace {

const char* const kCredits =
    "*VELOCITY DRIVE\n\nA DRIVING SIMULATION AFTER SEED 000\n\n\n"
    "*ENGINE\nVELOCITY SOFTWARE RENDERER\nFLAT, GOURAUD AND PHONG SHADING\nTEXTURE AND ENVIRONMENT MAPS\n\n\n"
    "*CONTROLS\nUP  THROTTLE     DOWN  BRAKE\nLEFT / RIGHT  STEER\nC  CAMERA     H  HIGH QUALITY\n"
    "[ ]  FOCAL LENGTH     Q E  SWIVEL\nPGUP PGDN  PITCH     , .  ROLL\nR  BACK TO THE GRID     ESC  MENU\n\n\n"
    "*SOUND\nSYNTHESISED AS YOU LISTEN\n\n\n"
    "*DRIVE SAFELY\n";

}  // namespace

std::function<int()> add_drive_command(CLI::App& app) {
  struct Args {
    RealtimeArgs realtime;
    std::string car;
    float car_yaw = 0;
    bool hq = false, skip_menu = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("drive", "Seed 000's driving simulation: arrows drive, C camera, H high quality, Esc menu");
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
    realtime::ShellText text;
    text.title = "VELOCITY DRIVE";
    text.subtitle = "A DRIVING SIMULATION";
    text.start = "DRIVE";
    text.credits = kCredits;
    realtime::Shell shell(drive, text, args->skip_menu);
    return run_realtime(shell, args->realtime, "800x600", true);
  };
}

}  // namespace velocity::cli
