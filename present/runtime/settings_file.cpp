#include "runtime/settings_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "velocity/error.hpp"

namespace velocity::realtime {

namespace {

constexpr const char* kMagic = "velocity-settings 1";
const char* const kFilters[] = {"nearest", "bilinear", "trilinear"};
const char* const kActions[kActionCount] = {"throttle", "brake",  "left",         "right",       "faster",
                                            "slower",   "camera", "high_quality", "reset_camera"};

}  // namespace

std::string default_settings_file(const std::string& program) {
  std::string base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) base = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home) base = std::string(home) + "/.config";
  else return {};
  return base + "/velocity/" + program + ".conf";
}

Settings parse_settings(std::string_view text, const std::string& name, const Settings& defaults) {
  Settings s = defaults;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0;
  auto fail = [&](const std::string& what) -> void {
    throw Error(name + ":" + std::to_string(number) + ": " + what);
  };
  bool magic = false;
  while (std::getline(in, line)) {
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string key, value, extra;
    if (!(words >> key)) continue;  // blank
    if (!magic) {
      std::string version;
      words >> version;
      if (key + " " + version != kMagic) fail("expected '" + std::string(kMagic) + "' first, found '" + line + "'");
      magic = true;
      continue;
    }
    if (!(words >> value)) fail("'" + key + "' has no value");
    if (key == "key") {
      std::string action = value, key_word;
      if (!(words >> key_word)) fail("expected 'key ACTION KEY'");
      int a = 0;
      while (a < kActionCount && action != kActions[a]) ++a;
      if (a == kActionCount) fail("unknown action '" + action + "' (expected throttle, brake, left, right, faster, "
                                  "slower, camera, high_quality or reset_camera)");
      auto k = parse_key(key_word);
      if (!k) fail("unknown key '" + key_word + "' (a letter, a digit, or a name such as up, space, enter)");
      s.keys[size_t(a)] = *k;
    } else if (key == "screen_mode" || key == "ssaa") {
      char* end = nullptr;
      const long v = std::strtol(value.c_str(), &end, 10);
      const long lo = key == "ssaa" ? 1 : -1, hi = key == "ssaa" ? 3 : 4;
      if (*end || v < lo || v > hi)
        fail(key + " '" + value + "', expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
      (key == "ssaa" ? s.ssaa : s.screen_mode) = int(v);
    } else if (key == "filter") {
      int f = 0;
      while (f < 3 && value != kFilters[f]) ++f;
      if (f == 3) fail("filter '" + value + "', expected nearest, bilinear or trilinear");
      s.filter = Filter(f);
    } else if (key == "volume") {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (*end || !(v >= 0 && v <= 1)) fail("volume '" + value + "', expected a number from 0 to 1");
      s.volume = float(v);
    } else {
      fail("unknown setting '" + key + "' (expected screen_mode, ssaa, filter, volume or key)");
    }
    if (words >> extra) fail("'" + extra + "' after the value");
  }
  if (!magic) fail("empty file, expected '" + std::string(kMagic) + "' first");
  // Two actions on one key would leave one unreachable.
  for (int a = 0; a < kActionCount; ++a)
    for (int b = a + 1; b < kActionCount; ++b)
      if (s.keys[size_t(a)] == s.keys[size_t(b)])
        throw Error(name + ": " + kActions[a] + " and " + kActions[b] + " are both on key '" +
                    key_name(s.keys[size_t(a)]) + "'");
  return s;
}

std::string format_settings(const Settings& s) {
  std::string out = std::string(kMagic) + "\n";
  char volume[32];
  std::snprintf(volume, sizeof volume, "%.2f", double(s.volume));
  out += "screen_mode " + std::to_string(s.screen_mode) + "\n";
  out += "ssaa " + std::to_string(s.ssaa) + "\n";
  out += std::string("filter ") + kFilters[std::clamp(int(s.filter), 0, 2)] + "\n";
  out += std::string("volume ") + volume + "\n";
  for (int a = 0; a < kActionCount; ++a) out += std::string("key ") + kActions[a] + " " + key_name(s.keys[size_t(a)]) + "\n";
  return out;
}

std::optional<Settings> load_settings(const std::string& path, const Settings& defaults) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  if (!fs::is_regular_file(path, ec)) throw Error(path + ": not a settings file (not a regular file)");
  if (fs::file_size(path, ec) > (size_t(1) << 16)) throw Error(path + ": over 64 KiB, not a settings file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read the settings file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_settings(text.str(), path, defaults);
}

void save_settings(const std::string& path, const Settings& settings) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  const std::string part = path + ".tmp";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out << format_settings(settings);
    out.flush();
    if (!out) {
      fs::remove(part, ec);
      throw Error("cannot write the settings file " + path);
    }
  }
  fs::rename(part, path, ec);
  if (ec) {
    fs::remove(part, ec);
    throw Error("cannot write the settings file " + path + ": " + ec.message());
  }
}

}  // namespace velocity::realtime
