#include "runtime/shell.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace velocity::realtime {

namespace {

constexpr float kFadeSeconds = 0.35f;
const char* const kButtonLabels[] = {nullptr, "CREDITS", "QUIT"};

// Function keys belong to the window (fullscreen, screen mode, overlay), not the screens.
bool is_window_key(Key k) { return k >= KeyF1 && k <= KeyF12; }

int ui_scale(int height) { return std::max(1, height / 200); }

}  // namespace

Shell::Shell(Game& game, ShellText text, bool skip_menus) : game_(game), text_(std::move(text)) {
  if (skip_menus) {
    screen_ = next_ = Screen::Game;
    fade_ = 0;
  }
  game_.set_attract(screen_ != Screen::Game);
}

void Shell::resize(int width, int height) {
  Program::resize(width, height);
  game_.resize(width, height);
}

Shell::Rect Shell::button_rect(int button) const {
  int s = ui_scale(height_);
  int w = 90 * s, h = 16 * s;
  int x = (width_ - w) / 2;
  int y = height_ / 2 - 14 * s + button * (h + 6 * s);
  return {x, y, w, h};
}

void Shell::go(Screen next) {
  if (fading_out_) return;
  next_ = next;
  fading_out_ = true;
}

void Shell::activate(int button) {
  effects_.push_back(Effect::Click);
  switch (button) {
    case ButtonStart: go(Screen::Game); break;
    case ButtonCredits: go(Screen::Credits); break;
    case ButtonQuit:
      quit_after_fade_ = true;
      go(Screen::Menu);
      break;
    default: break;
  }
}

void Shell::event(const InputEvent& e, const InputState& input) {
  if (fading_out_) return;  // the screen is on its way out
  switch (screen_) {
    case Screen::Title:
      if ((e.kind == InputEvent::KeyDown && e.key == KeyEscape)) quit_ = true;
      else if ((e.kind == InputEvent::KeyDown && !is_window_key(e.key)) || e.kind == InputEvent::MouseDown) {
        effects_.push_back(Effect::Click);
        go(Screen::Menu);
      }
      break;
    case Screen::Menu:
      if (e.kind == InputEvent::MouseMove || e.kind == InputEvent::MouseDown || e.kind == InputEvent::MouseUp) {
        int over = -1;
        for (int b = 0; b < ButtonCount; ++b)
          if (button_rect(b).contains(e.x, e.y)) over = b;
        if (e.kind == InputEvent::MouseMove) {
          if (over != hot_ && over >= 0) effects_.push_back(Effect::Click);
          hot_ = over;
        }
        if (e.kind == InputEvent::MouseUp && e.button == MouseButton::Left && over >= 0) activate(over);
      } else if (e.kind == InputEvent::KeyDown) {
        if (e.key == KeyUp) hot_ = hot_ <= 0 ? ButtonCount - 1 : hot_ - 1;
        else if (e.key == KeyDown || e.key == KeyTab) hot_ = (hot_ + 1) % ButtonCount;
        else if ((e.key == KeyEnter || e.key == KeySpace) && hot_ >= 0) activate(hot_);
        else if (e.key == KeyEnter || e.key == KeySpace) activate(ButtonStart);
        else if (e.key == KeyEscape) activate(ButtonQuit);
        else if (e.key == 'c') activate(ButtonCredits);
        else if (e.key == 'q') activate(ButtonQuit);
      }
      break;
    case Screen::Credits:
      if ((e.kind == InputEvent::KeyDown && !is_window_key(e.key)) ||
          e.kind == InputEvent::MouseDown) {
        effects_.push_back(Effect::Click);
        go(Screen::Menu);
      }
      break;
    case Screen::Game:
      if (e.kind == InputEvent::KeyDown && e.key == KeyEscape) {
        go(Screen::Menu);
        return;
      }
      game_.event(e, input);
      break;
  }
}

void Shell::update(double dt, const InputState& input) {
  time_ += dt;
  if (screen_ == Screen::Credits) credits_time_ += dt;
  // Fade: out to black, switch screens, back in.
  const float step = float(dt) / kFadeSeconds;
  if (fading_out_) {
    fade_ = std::min(1.0f, fade_ + step);
    if (fade_ >= 1.0f) {
      fading_out_ = false;
      if (quit_after_fade_) {
        quit_ = true;
        return;
      }
      if (next_ == Screen::Game && screen_ != Screen::Game) game_.restart();
      screen_ = next_;
      credits_time_ = 0;
      game_.set_attract(screen_ != Screen::Game);
      if (screen_ == Screen::Game) effects_.push_back(Effect::Whoosh);
    }
  } else {
    fade_ = std::max(0.0f, fade_ - step);
  }
  static const InputState kNoInput;
  game_.update(dt, screen_ == Screen::Game ? input : kNoInput);
}

void Shell::sound(Synth& synth) {
  synth.set_music(screen_ != Screen::Game);
  for (Effect e : effects_) synth.play(e);
  effects_.clear();
  game_.sound(synth);
}

void Shell::frame(FrameDescription& out) {
  game_.frame(out);
  DrawList& d = out.overlay;
  const int s = ui_scale(height_);
  if (screen_ != Screen::Game) {
    d.clear();  // the game's own display stays out of the menus
    d.rect(0, 0, width_, height_, {0, 0, 20, 110});
  }
  switch (screen_) {
    case Screen::Title: {
      // The title pulses gently; "press any key" blinks.
      int big = std::max(1, std::min(4 * s, width_ * 9 / 10 / std::max(1, text_width(text_.title))));
      float pulse = 0.5f + 0.5f * float(std::sin(time_ * 2.0));
      Rgba gold{255, uint8_t(190 + 50 * pulse), 60, 255};
      d.text_centered(width_ / 2, height_ / 3 - 10 * s, text_.title, gold, big);
      d.text_centered(width_ / 2, height_ / 3 + 26 * s, text_.subtitle, {200, 220, 255, 255}, s);
      if (std::fmod(time_, 1.2) < 0.8) d.text_centered(width_ / 2, height_ * 3 / 4, "PRESS ANY KEY", {255, 255, 255, 255}, s);
      break;
    }
    case Screen::Menu: {
      int big = std::max(1, std::min(3 * s, width_ * 8 / 10 / std::max(1, text_width(text_.title))));
      d.text_centered(width_ / 2, height_ / 2 - 50 * s, text_.title, {255, 210, 80, 255}, big);
      for (int b = 0; b < ButtonCount; ++b) {
        Rect r = button_rect(b);
        bool hot = b == hot_;
        d.rect(r.x - s, r.y - s, r.w + 2 * s, r.h + 2 * s, hot ? Rgba{255, 220, 90, 255} : Rgba{90, 110, 150, 255});
        d.rect(r.x, r.y, r.w, r.h, hot ? Rgba{200, 70, 30, 255} : Rgba{20, 30, 60, 230});
        std::string label = b == ButtonStart ? text_.start : kButtonLabels[b];
        d.text_centered(r.x + r.w / 2, r.y + (r.h - 7 * s) / 2, label, hot ? Rgba{255, 255, 255, 255} : Rgba{180, 200, 230, 255}, s);
      }
      d.text_centered(width_ / 2, height_ - 14 * s, "MOUSE OR ARROWS AND ENTER", {150, 160, 190, 255}, s);
      break;
    }
    case Screen::Credits: {
      // The credits roll up from the bottom, and round again.
      int line_h = 14 * s;
      std::vector<std::string> lines;
      std::stringstream ss(text_.credits);
      for (std::string l; std::getline(ss, l);) lines.push_back(l);
      int total = int(lines.size()) * line_h + height_;
      int offset = int(credits_time_ * 30.0 * s) % std::max(total, 1);
      for (size_t i = 0; i < lines.size(); ++i) {
        int y = height_ - offset + int(i) * line_h;
        if (y < -line_h || y > height_) continue;
        bool heading = !lines[i].empty() && lines[i][0] == '*';
        std::string t = heading ? lines[i].substr(1) : lines[i];
        d.text_centered(width_ / 2, y, t, heading ? Rgba{255, 210, 80, 255} : Rgba{220, 230, 255, 255}, heading ? 2 * s : s);
      }
      break;
    }
    case Screen::Game: break;
  }
  d.fade(fade_);
}

}  // namespace velocity::realtime
