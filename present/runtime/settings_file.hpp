// The options screen's choices kept on disk, one file a program:
// $XDG_CONFIG_HOME/velocity/PROGRAM.conf (else ~/.config/velocity/PROGRAM.conf).
//
//   velocity-settings 1
//   screen_mode -1          -1 (as started) .. 4 (the window's size)
//   ssaa 2                  1..3
//   filter bilinear         nearest, bilinear or trilinear
//   volume 0.8              0..1
//   key throttle up         one line an action: its name, then a key (runtime/input.hpp)
//
// Lines may come in any order and any may be missing (the default stays); '#' starts a
// comment. A file is written whole, beside its name and then renamed over it, so a crash
// or a full disk leaves the old file or the new one, never half of one.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "runtime/shell.hpp"

namespace velocity::realtime {

// Where PROGRAM's settings live; "" when neither XDG_CONFIG_HOME nor HOME is set.
std::string default_settings_file(const std::string& program);

// The settings a file's text says, starting from `defaults`. Throws velocity::Error
// "NAME:LINE: ..." with what was expected, for the first bad line.
Settings parse_settings(std::string_view text, const std::string& name, const Settings& defaults = {});
std::string format_settings(const Settings& settings);

// Reads `path`: nullopt when there is no such file; throws velocity::Error for a file
// that cannot be read or is not a settings file (the message names it and the line).
std::optional<Settings> load_settings(const std::string& path, const Settings& defaults = {});
// Writes `path` whole (PATH.tmp, then renamed), creating its folder. Throws
// velocity::Error naming the file when it cannot.
void save_settings(const std::string& path, const Settings& settings);

}  // namespace velocity::realtime
