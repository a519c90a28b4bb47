// Warnings: things the library handled but a person should hear about (a mesh with NaN
// vertices that were dropped, say). By default they go to stderr, prefixed "velocity:
// warning:"; a program may route them elsewhere or silence them.
#pragma once

#include <functional>
#include <string_view>

namespace velocity {

using WarningHandler = std::function<void(std::string_view message)>;

// Replaces the handler (an empty function silences warnings); returns the old one.
// Not thread-safe with respect to concurrent warnings: set it at start-up.
WarningHandler set_warning_handler(WarningHandler handler);

// Sends `message` to the current handler.
void warn(std::string_view message);

}  // namespace velocity
