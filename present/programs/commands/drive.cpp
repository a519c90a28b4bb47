// `velocity drive`: the driving game (programs/drive.hpp) behind a title screen and menu.
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "programs/commands/realtime.hpp"
#include "programs/drive.hpp"
#include "velocity/error.hpp"

namespace velocity::cli {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string read_text(const std::string& path, size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path);
  std::string text;
  text.resize(limit + 1);
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  if (text.size() > limit) throw Error(path + ": larger than " + std::to_string(limit) + " bytes");
  return text;
}

// One line a test (or a person) can compare between a race and its replay.
void print_race(const realtime::Race& race) {
  const realtime::RaceCar& p = race.car(0);
  std::printf("race: ticks=%ld laps=%d best_ticks=%ld", race.tick(), p.laps, p.best_lap);
  for (size_t i = 0; i < race.cars(); ++i) {
    const realtime::CarState& s = race.car(i).state;
    std::printf(" car%zu=%.9g,%.9g,%.9g,%.9g", i, double(s.position.x), double(s.position.y), double(s.position.z),
                double(s.heading));
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

std::function<int()> add_drive_command(CLI::App& app) {
  struct Args {
    RealtimeArgs realtime;
    std::string car, best_lap, replay;
    float car_yaw = 0;
    int opponents = 1;
    bool hq = false, skip_menu = false, no_best_lap = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "drive", "Race round a hillside circuit: arrows drive, C camera, H high quality, P pause, F1 help, Esc menu");
  cmd->add_option("--car", args->car, "Car body model (e.g. ../shared/data/models/asc/car01.asc); default: the built-in car");
  cmd->add_option("--car-yaw", args->car_yaw, "Turn the car model by this many degrees (its nose must point forward)");
  cmd->add_flag("--hq", args->hq, "High quality: 3x3 super-sampling (H toggles)");
  cmd->add_flag("--skip-menu", args->skip_menu, "Start driving at once (no title screen or menu)");
  cmd->add_option("--opponents", args->opponents, "Opponent cars on the racing line (0..3)")->capture_default_str();
  cmd->add_option("--best-lap", args->best_lap,
                  "Where the best lap (its ghost) is kept; default: $XDG_DATA_HOME/velocity/drive/best_lap.txt");
  cmd->add_flag("--no-best-lap", args->no_best_lap, "Neither read nor keep a best lap");
  cmd->add_option("--replay", args->replay, "Play back a race recorded with --record FILE.replay (keys ignored)");
  add_realtime_options(cmd, args->realtime);
  // `--record NAME.replay` records the race (the controls, every tick) rather than frames.
  return [args] {
    realtime::DriveOptions o;
    o.car = args->car;
    o.car_yaw = args->car_yaw;
    o.high_quality = args->hq;
    if (args->opponents < 0 || args->opponents > 3) throw Error("--opponents must be 0..3");
    o.opponents = args->opponents;
    o.best_lap_file = args->no_best_lap ? "" : args->best_lap.empty() ? realtime::default_best_lap_file() : args->best_lap;
    RealtimeArgs rt = args->realtime;
    std::string record_race;
    if (ends_with(rt.record, ".replay")) record_race = rt.record, rt.record.clear();
    if (!args->replay.empty()) {
      o.replay = realtime::parse_replay(read_text(args->replay, size_t(64) << 20), args->replay);
      rt.ends_itself = true;  // the run ends with the replay
    }
    realtime::DriveProgram drive(o);
    realtime::Shell shell(drive, realtime::drive_shell_text(), args->skip_menu || o.replay.has_value());
    keep_settings(shell, rt, o.replay.has_value());
    int status = run_realtime(shell, rt, "800x600", true);
    if (!record_race.empty()) {
      std::string part = record_race + ".part";
      {
        std::ofstream out(part, std::ios::binary);
        out << realtime::format_replay(drive.recording());
        if (!out) throw Error("cannot write " + record_race);
      }
      if (std::rename(part.c_str(), record_race.c_str()) != 0) throw Error("cannot write " + record_race);
      std::printf("wrote %s (%zu ticks)\n", record_race.c_str(), drive.recording().ticks.size());
    }
    print_race(drive.race());
    return status;
  };
}

}  // namespace velocity::cli
