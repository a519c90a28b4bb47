// Fuzz target: the real-time programs' script reader (present/runtime/script.cpp). The input
// is the script's text. Property: it parses or throws velocity::Error; what parses is
// in time order, with finite non-negative times, and plays back completely.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "runtime/script.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  realtime::Script script;
  try {
    script = realtime::parse_script(text, "fuzz.txt");
  } catch (const Error&) {
    return 0;
  }
  if (script.events.size() > realtime::kMaxScriptEvents) std::abort();
  double last = 0;
  for (const realtime::TimedEvent& e : script.events) {
    if (!std::isfinite(e.time) || e.time < 0 || e.time < last) std::abort();
    last = e.time;
  }
  realtime::ScriptPlayer player(script);
  std::vector<realtime::InputEvent> events;
  player.due(2e6, events);
  if (events.size() != script.events.size() || !player.finished()) std::abort();
  return 0;
}
