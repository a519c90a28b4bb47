// Runs a real-time program at the fixed step with a script's input events, as the main
// loop does (runtime/loop.hpp), but without a window or a clock: for the program tests.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "runtime/input.hpp"
#include "runtime/loop.hpp"
#include "runtime/script.hpp"

namespace velocity::realtime::test {

// Runs `program` for `seconds` at the fixed step, feeding the script's events, and
// calls `each` after every step.
template <typename F>
void run_scripted(Program& program, const std::string& script, double seconds, F&& each) {
  ScriptPlayer player(parse_script(script));
  InputState input;
  std::vector<InputEvent> events;
  const int steps = int(std::lround(seconds / kFixedStep));
  for (int n = 0; n <= steps; ++n) {
    events.clear();
    player.due(n * kFixedStep, events);
    for (const InputEvent& e : events) {
      input.apply(e);
      program.event(e, input);
    }
    program.update(n ? kFixedStep : 0.0, input);
    each(n);
  }
}

inline void run_scripted(Program& program, const std::string& script, double seconds) {
  run_scripted(program, script, seconds, [](int) {});
}

}  // namespace velocity::realtime::test
