#include "velocity/log.hpp"

#include <cstdio>
#include <utility>

namespace velocity {

namespace {
WarningHandler& handler() {
  static WarningHandler h = [](std::string_view m) {
    std::fprintf(stderr, "velocity: warning: %.*s\n", int(m.size()), m.data());
  };
  return h;
}
}  // namespace

WarningHandler set_warning_handler(WarningHandler h) { return std::exchange(handler(), std::move(h)); }

void warn(std::string_view message) {
  if (handler()) handler()(message);
}

}  // namespace velocity
