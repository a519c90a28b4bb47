// Fuzz target: the driving game's files (present/programs/race.cpp): replays and best
// laps. The first byte chooses the reader (even: replay, odd: lap), the rest is the
// file's text. Property: it parses or throws velocity::Error; what parses holds what
// its header says, within range, and survives writing and reading back unchanged.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "programs/race.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  if (size < 1) return 0;
  std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const float circuit = 1567.2f;
  try {
    if (data[0] % 2 == 0) {
      realtime::Replay r = realtime::parse_replay(text, "fuzz.replay");
      if (long(r.ticks.size()) > realtime::kMaxReplayTicks) std::abort();
      for (const realtime::CarControls& c : r.ticks)
        if (!(c.throttle >= 0 && c.throttle <= 1 && c.brake >= 0 && c.brake <= 1 && c.steer >= -1 && c.steer <= 1))
          std::abort();
      realtime::Replay back = realtime::parse_replay(realtime::format_replay(r));
      if (back.ticks != r.ticks) std::abort();
    } else {
      realtime::Lap lap = realtime::parse_lap(text, circuit, "fuzz.txt");
      if (long(lap.poses.size()) != lap.ticks) std::abort();
      realtime::Lap back = realtime::parse_lap(realtime::format_lap(lap, circuit), circuit);
      if (back.poses != lap.poses) std::abort();
    }
  } catch (const Error&) {
  }
  return 0;
}
