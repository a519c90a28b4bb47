// The screens around a game, as seed 001 has them: a title screen, a menu whose buttons
// light up under the mouse and answer clicks and keys, credits, and a fade to black and
// back between any two screens. The game runs on its own (attract mode) behind the
// title, menu and credits. Esc in the game returns to the menu; Esc in the menu quits.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/program.hpp"
#include "runtime/synth.hpp"
#include "velocity/texture.hpp"

namespace velocity::realtime {

// What a game's controls do, each bound to a key on the options screen.
enum class Action { Throttle, Brake, Left, Right, Faster, Slower, Camera, HighQuality, ResetCamera, Count };
inline constexpr int kActionCount = int(Action::Count);

// The options screen's choices, which the games and the main loop follow.
struct Settings {
  int screen_mode = -1;  // index into the loop's screen modes (-1: as started)
  int ssaa = 1;          // 1..3 super-sampling (the games' H still switches 3x3 on and off)
  Filter filter = Filter::Bilinear;
  float volume = 0.8f;  // 0..1
  std::array<Key, kActionCount> keys = {KeyUp, KeyDown, KeyLeft, KeyRight, Key('a'), Key('z'),
                                        Key('c'), Key('h'), Key('r')};
  Key key(Action a) const { return keys[size_t(a)]; }
};

// A program that can also play itself behind the menus.
class Game : public Program {
 public:
  virtual void set_attract(bool on) = 0;
  // Back to the start (a new flight, the car on the grid).
  virtual void restart() = 0;
  // The in-game help (F1): lines separated by '\n'.
  virtual std::string help() const = 0;
  virtual void set_settings(const Settings&) {}
};

struct ShellText {
  std::string title = "VELOCITY";
  std::string subtitle;
  std::string start = "START";
  std::string credits;  // lines separated by '\n'
  // The controls the options screen lets the player rebind, with this game's words.
  std::vector<std::pair<Action, std::string>> bindings;
};

class Shell : public Program {
 public:
  enum class Screen { Title, Menu, Credits, Options, Game };
  enum Button { ButtonStart, ButtonRestart, ButtonOptions, ButtonCredits, ButtonQuit, ButtonCount };

  // `skip_menus` starts in the game (scripts and recordings of the game itself).
  Shell(Game& game, ShellText text, bool skip_menus = false);
  void resize(int width, int height) override;
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  void sound(Synth& synth) override;
  bool finished() const override { return quit_ || (screen_ == Screen::Game && game_.finished()); }
  std::string title() const override { return game_.title(); }
  void set_gamepad(const GamepadState& pad) override { game_.set_gamepad(pad); }
  int screen_mode() const override { return settings_.screen_mode; }

  // Keeps the options in `path` (runtime/settings_file.hpp): read now, if it exists, and
  // written whole each time an option changes. Throws velocity::Error for a bad file.
  void keep_settings_in(const std::string& path);

  Screen screen() const { return screen_; }
  // A game was started and not finished: the menu's first button resumes it.
  bool in_progress() const { return in_progress_; }
  bool paused() const { return paused_; }
  bool help_shown() const { return help_; }
  const Settings& settings() const { return settings_; }
  // The button under the mouse (or chosen with the arrow keys), -1 for none.
  int highlighted() const { return hot_; }
  // Where a button is drawn, in frame pixels.
  struct Rect {
    int x, y, w, h;
    bool contains(int px, int py) const { return px >= x && px < x + w && py >= y && py < y + h; }
  };
  Rect button_rect(int button) const;
  // The options screen: its rows, the one chosen, and where each is drawn.
  int option_rows() const;
  int option_row() const { return row_; }
  Rect option_rect(int row) const;
  std::string option_text(int row) const;
  bool waiting_for_key() const { return binding_; }
  // 0 = the screen fully shown, 1 = black (mid-fade).
  float fade() const { return fade_; }

 private:
  void go(Screen next);
  void activate(int button);
  void options_event(const InputEvent& e);
  void change_option(int row, int step);
  void settings_changed();  // to the game, and to the settings file

  Game& game_;
  ShellText text_;
  Settings settings_;
  std::string settings_file_;
  Screen screen_ = Screen::Title;
  Screen next_ = Screen::Title;
  bool fading_out_ = false, quit_ = false, quit_after_fade_ = false;
  bool in_progress_ = false, restart_next_ = false, paused_ = false, help_ = false;
  bool binding_ = false;
  bool shot_ = false;  // F12 asked for a screenshot of the next frame
  int shots_ = 0;
  float fade_ = 1.0f;  // starts black and fades in
  int hot_ = -1, row_ = 0;
  double time_ = 0, credits_time_ = 0;
  std::vector<Effect> effects_;
};

}  // namespace velocity::realtime
