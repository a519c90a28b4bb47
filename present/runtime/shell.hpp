// The screens around a game, as seed 001 has them: a title screen, a menu whose buttons
// light up under the mouse and answer clicks and keys, credits, and a fade to black and
// back between any two screens. The game runs on its own (attract mode) behind the
// title, menu and credits. Esc in the game returns to the menu; Esc in the menu quits.
#pragma once

#include <string>
#include <vector>

#include "runtime/program.hpp"
#include "runtime/synth.hpp"

namespace velocity::realtime {

// A program that can also play itself behind the menus.
class Game : public Program {
 public:
  virtual void set_attract(bool on) = 0;
  // Back to the start (a new flight, the car on the grid).
  virtual void restart() = 0;
};

struct ShellText {
  std::string title = "VELOCITY";
  std::string subtitle;
  std::string start = "START";
  std::string credits;  // lines separated by '\n'
};

class Shell : public Program {
 public:
  enum class Screen { Title, Menu, Credits, Game };
  enum Button { ButtonStart, ButtonCredits, ButtonQuit, ButtonCount };

  // `skip_menus` starts in the game (scripts and recordings of the game itself).
  Shell(Game& game, ShellText text, bool skip_menus = false);
  void resize(int width, int height) override;
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  void sound(Synth& synth) override;
  bool finished() const override { return quit_; }
  std::string title() const override { return game_.title(); }

  Screen screen() const { return screen_; }
  // The button under the mouse (or chosen with the arrow keys), -1 for none.
  int highlighted() const { return hot_; }
  // Where a button is drawn, in frame pixels.
  struct Rect {
    int x, y, w, h;
    bool contains(int px, int py) const { return px >= x && px < x + w && py >= y && py < y + h; }
  };
  Rect button_rect(int button) const;
  // 0 = the screen fully shown, 1 = black (mid-fade).
  float fade() const { return fade_; }

 private:
  void go(Screen next);
  void activate(int button);

  Game& game_;
  ShellText text_;
  Screen screen_ = Screen::Title;
  Screen next_ = Screen::Title;
  bool fading_out_ = false, quit_ = false, quit_after_fade_ = false;
  float fade_ = 1.0f;  // starts black and fades in
  int hot_ = -1;
  double time_ = 0, credits_time_ = 0;
  std::vector<Effect> effects_;
};

}  // namespace velocity::realtime
