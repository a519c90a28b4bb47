// Input as the programs see it: keys, mouse and dropped files, independent of SDL.
// The SDL presenter and the script player both produce these events.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace velocity::realtime {

// Keys: lowercase ASCII letters, digits and punctuation stand for themselves; the others
// are named below (values above 127).
enum Key : int {
  KeyNone = 0,
  KeyEnter = 13,
  KeyEscape = 27,
  KeySpace = 32,
  KeyTab = 9,
  KeyBackspace = 8,
  KeyLeft = 256,
  KeyRight,
  KeyUp,
  KeyDown,
  KeyCtrl,
  KeyShift,
  KeyPageUp,
  KeyPageDown,
  KeyF1,  // KeyF1 + n - 1 is Fn, n = 1..12
  KeyF2,
  KeyF3,
  KeyF11 = KeyF1 + 10,
  KeyF12,
  KeyCount
};

// "left", "esc", "f11", "a", "+" ... to a Key (case-insensitive); nullopt if unknown.
std::optional<Key> parse_key(std::string_view name);
std::string key_name(Key key);
// The key as the screens show it: "UP", "W", "PAGEUP".
std::string key_label(Key key);

enum class MouseButton { Left = 1, Middle = 2, Right = 3 };

struct InputEvent {
  enum Kind { KeyDown, KeyUp, MouseMove, MouseDown, MouseUp, Wheel, Drop, Quit, Resize } kind = KeyDown;
  Key key = KeyNone;
  MouseButton button = MouseButton::Left;
  int x = 0, y = 0;   // mouse position in frame pixels; Resize: the new window size
  float wheel = 0;    // Wheel: positive away from the user (zoom in)
  std::string path;   // Drop
};

// A game controller's sticks and triggers (SDL's GameController layout); its buttons
// arrive as key events (the d-pad as arrows, A as Enter, B and Back as Esc, Start as P).
struct GamepadState {
  bool connected = false;
  float steer = 0;     // left stick across: -1 left .. 1 right
  float pitch = 0;     // left stick up and down: -1 up .. 1 down
  float throttle = 0;  // right trigger 0..1
  float brake = 0;     // left trigger 0..1
};

// What is held down now, kept up to date from the events.
class InputState {
 public:
  void apply(const InputEvent& e);
  bool held(int k) const { return k > KeyNone && k < KeyCount && keys_[size_t(k)]; }
  bool button(MouseButton b) const { return buttons_[size_t(b)]; }
  int mouse_x() const { return mx_; }
  int mouse_y() const { return my_; }

 private:
  std::array<bool, KeyCount> keys_{};
  std::array<bool, 4> buttons_{};
  int mx_ = -1, my_ = -1;
};

}  // namespace velocity::realtime
