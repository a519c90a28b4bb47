#include "runtime/input.hpp"

#include <cctype>

namespace velocity::realtime {

namespace {

struct Named {
  const char* name;
  Key key;
};
constexpr Named kNames[] = {
    {"enter", KeyEnter},   {"return", KeyEnter}, {"esc", KeyEscape},       {"escape", KeyEscape},
    {"space", KeySpace},   {"tab", KeyTab},      {"backspace", KeyBackspace}, {"left", KeyLeft},
    {"right", KeyRight},   {"up", KeyUp},        {"down", KeyDown},         {"ctrl", KeyCtrl},
    {"shift", KeyShift},   {"pageup", KeyPageUp}, {"pagedown", KeyPageDown},
};

}  // namespace

std::optional<Key> parse_key(std::string_view name) {
  std::string s;
  for (char c : name) s += char(std::tolower(static_cast<unsigned char>(c)));
  if (s.empty()) return std::nullopt;
  for (const Named& n : kNames)
    if (s == n.name) return n.key;
  if (s.size() >= 2 && s[0] == 'f' && std::isdigit(static_cast<unsigned char>(s[1]))) {
    int n = 0;
    for (size_t i = 1; i < s.size(); ++i) {
      if (!std::isdigit(static_cast<unsigned char>(s[i])) || n > 12) return std::nullopt;
      n = n * 10 + (s[i] - '0');
    }
    if (n >= 1 && n <= 12) return Key(KeyF1 + n - 1);
    return std::nullopt;
  }
  if (s.size() == 1 && s[0] > 32 && s[0] < 127) return Key(s[0]);
  return std::nullopt;
}

std::string key_name(Key key) {
  for (const Named& n : kNames)
    if (n.key == key) return n.name;
  if (key >= KeyF1 && key <= KeyF12) return "f" + std::to_string(key - KeyF1 + 1);
  if (key > 32 && key < 127) return std::string(1, char(key));
  return "?";
}

void InputState::apply(const InputEvent& e) {
  switch (e.kind) {
    case InputEvent::KeyDown:
    case InputEvent::KeyUp:
      if (e.key > KeyNone && e.key < KeyCount) keys_[size_t(e.key)] = e.kind == InputEvent::KeyDown;
      break;
    case InputEvent::MouseDown:
    case InputEvent::MouseUp:
      buttons_[size_t(e.button)] = e.kind == InputEvent::MouseDown;
      mx_ = e.x, my_ = e.y;
      break;
    case InputEvent::MouseMove: mx_ = e.x, my_ = e.y; break;
    default: break;
  }
}

std::string key_label(Key key) {
  std::string s = key_name(key);
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace velocity::realtime
