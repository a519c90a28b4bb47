// Scripts: timed key presses and mouse events for running a program without a person
// (tests, recordings, benchmarks). One event a line, times in seconds from the start:
//
//   # comment                      blank lines and comments are ignored
//   0.5  down up                   key down (see parse_key for names)
//   2.0  up up                     key up
//   1.0  press space               key down, and up 0.05 s later
//   1.0  move 160 100              mouse to (x, y), in frame pixels
//   1.2  click 160 100 [left|right|middle]   button down and up 0.05 s later
//   1.2  mousedown left 160 100    / mouseup left 160 100
//   1.5  wheel -2                  wheel (positive zooms in)
//   3.0  drop path/to/model.asc    a file dropped on the window
//   9.0  quit                      as closing the window
//
// Scripts are untrusted input: parse_script throws velocity::Error naming the line and
// what was expected. Events are kept in time order (stable for equal times).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/input.hpp"

namespace velocity::realtime {

struct TimedEvent {
  double time = 0;
  InputEvent event;
};

struct Script {
  std::vector<TimedEvent> events;
  double duration() const { return events.empty() ? 0.0 : events.back().time; }
};

// At most this many bytes and events (a script is typed by hand or by a test).
inline constexpr size_t kMaxScriptBytes = size_t(4) << 20;
inline constexpr size_t kMaxScriptEvents = 100000;

Script parse_script(std::string_view text, const std::string& name = "script");
Script load_script(const std::string& path);

// Hands out a script's events as time passes.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(Script script) : script_(std::move(script)) {}
  // Appends every event due at or before `time` (seconds) not handed out yet.
  void due(double time, std::vector<InputEvent>& out);
  bool finished() const { return next_ == script_.events.size(); }
  const Script& script() const { return script_; }

 private:
  Script script_;
  size_t next_ = 0;
};

}  // namespace velocity::realtime
