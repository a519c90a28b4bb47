#include "runtime/shell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "runtime/settings_file.hpp"
#include "velocity/error.hpp"

namespace velocity::realtime {

namespace {

constexpr float kFadeSeconds = 0.35f;
const char* const kButtonLabels[] = {nullptr, "RESTART", "OPTIONS", "CREDITS", "QUIT"};
const char* const kModeNames[] = {"AS STARTED", "320X200", "320X240", "640X480", "800X600", "THE WINDOW'S SIZE"};
const char* const kFilterNames[] = {"NEAREST", "BILINEAR", "TRILINEAR"};
constexpr int kSettingRows = 4;  // screen mode, super-sampling, texture filter, volume

// Function keys belong to the window (fullscreen, screen mode, overlay), not the screens.
bool is_window_key(Key k) { return k >= KeyF1 && k <= KeyF12; }

int ui_scale(int height) { return std::max(1, height / 200); }

}  // namespace

Shell::Shell(Game& game, ShellText text, bool skip_menus) : game_(game), text_(std::move(text)) {
  if (skip_menus) {
    screen_ = next_ = Screen::Game;
    fade_ = 0;
    in_progress_ = true;
  }
  game_.set_attract(screen_ != Screen::Game);
  game_.set_settings(settings_);
}

void Shell::keep_settings_in(const std::string& path) {
  if (auto loaded = load_settings(path, settings_)) {
    settings_ = *loaded;
    game_.set_settings(settings_);
  }
  settings_file_ = path;
}

void Shell::settings_changed() {
  game_.set_settings(settings_);
  if (settings_file_.empty()) return;
  try {
    save_settings(settings_file_, settings_);
  } catch (const Error& e) {  // the game goes on; the options stay as chosen for this run
    std::fprintf(stderr, "velocity: %s\n", e.what());
  }
}

void Shell::resize(int width, int height) {
  Program::resize(width, height);
  game_.resize(width, height);
}

Shell::Rect Shell::button_rect(int button) const {
  int s = ui_scale(height_);
  int w = 90 * s, h = 14 * s;
  int x = (width_ - w) / 2;
  int y = height_ / 2 - 34 * s + button * (h + 4 * s);
  return {x, y, w, h};
}

int Shell::option_rows() const { return kSettingRows + int(text_.bindings.size()) + 1; }

Shell::Rect Shell::option_rect(int row) const {
  int s = ui_scale(height_);
  int h = 10 * s, w = std::min(width_ - 8 * s, 170 * s);
  return {(width_ - w) / 2, 28 * s + row * (h + 2 * s), w, h};
}

std::string Shell::option_text(int row) const {
  switch (row) {
    case 0: return std::string("SCREEN MODE: ") + kModeNames[settings_.screen_mode + 1];
    case 1: return "SUPER-SAMPLING: " + std::to_string(settings_.ssaa) + "X" + std::to_string(settings_.ssaa);
    case 2: return std::string("TEXTURE FILTER: ") + kFilterNames[int(settings_.filter)];
    case 3: return "SOUND VOLUME: " + std::to_string(int(std::lround(settings_.volume * 100))) + "%";
    default: break;
  }
  int b = row - kSettingRows;
  if (b < int(text_.bindings.size())) {
    const auto& [action, label] = text_.bindings[size_t(b)];
    return label + ": " + (binding_ && row == row_ ? std::string("PRESS A KEY") : key_label(settings_.key(action)));
  }
  return "BACK";
}

void Shell::change_option(int row, int step) {
  switch (row) {
    case 0: settings_.screen_mode = (settings_.screen_mode + 1 + step + 6) % 6 - 1; break;
    case 1: settings_.ssaa = (settings_.ssaa - 1 + step + 3) % 3 + 1; break;
    case 2: settings_.filter = Filter((int(settings_.filter) + step + 3) % 3); break;
    case 3: settings_.volume = std::clamp(std::round(settings_.volume * 10 + float(step)) / 10, 0.0f, 1.0f); break;
    default:
      if (row - kSettingRows < int(text_.bindings.size())) binding_ = true;  // the next key is the new one
      else go(Screen::Menu);
      return;
  }
  effects_.push_back(Effect::Click);
  settings_changed();
}

void Shell::options_event(const InputEvent& e) {
  if (binding_) {
    if (e.kind != InputEvent::KeyDown || is_window_key(e.key)) return;
    if (e.key != KeyEscape) {
      Action a = text_.bindings[size_t(row_ - kSettingRows)].first;
      // A key does one thing: whatever had it takes this action's old key.
      for (Key& k : settings_.keys)
        if (k == e.key) k = settings_.key(a);
      settings_.keys[size_t(a)] = e.key;
      settings_changed();
      effects_.push_back(Effect::Click);
    }
    binding_ = false;
    return;
  }
  const int rows = option_rows();
  if (e.kind == InputEvent::KeyDown) {
    if (e.key == KeyUp) row_ = (row_ + rows - 1) % rows;
    else if (e.key == KeyDown || e.key == KeyTab) row_ = (row_ + 1) % rows;
    else if (e.key == KeyLeft) change_option(row_, -1);
    else if (e.key == KeyRight || e.key == KeyEnter || e.key == KeySpace) change_option(row_, 1);
    else if (e.key == KeyEscape) go(Screen::Menu);
  } else if (e.kind == InputEvent::MouseMove || e.kind == InputEvent::MouseUp) {
    for (int r = 0; r < rows; ++r)
      if (option_rect(r).contains(e.x, e.y)) {
        row_ = r;
        if (e.kind == InputEvent::MouseUp) change_option(r, e.button == MouseButton::Right ? -1 : 1);
      }
  }
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
    case ButtonRestart:
      restart_next_ = true;
      go(Screen::Game);
      break;
    case ButtonOptions:
      row_ = 0;
      go(Screen::Options);
      break;
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
  const bool key = e.kind == InputEvent::KeyDown;
  switch (screen_) {
    case Screen::Title:
      if (key && e.key == KeyEscape) quit_ = true;
      else if ((key && !is_window_key(e.key)) || e.kind == InputEvent::MouseDown) {
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
      } else if (key) {
        if (e.key == KeyUp) hot_ = hot_ <= 0 ? ButtonCount - 1 : hot_ - 1;
        else if (e.key == KeyDown || e.key == KeyTab) hot_ = (hot_ + 1) % ButtonCount;
        else if ((e.key == KeyEnter || e.key == KeySpace) && hot_ >= 0) activate(hot_);
        else if (e.key == KeyEnter || e.key == KeySpace) activate(ButtonStart);
        else if (e.key == KeyEscape) activate(ButtonQuit);
        else if (e.key == 'c') activate(ButtonCredits);
        else if (e.key == 'o') activate(ButtonOptions);
        else if (e.key == 'q') activate(ButtonQuit);
      }
      break;
    case Screen::Credits:
      if ((key && !is_window_key(e.key)) || e.kind == InputEvent::MouseDown) {
        effects_.push_back(Effect::Click);
        go(Screen::Menu);
      }
      break;
    case Screen::Options: options_event(e); break;
    case Screen::Game:
      if (key && e.key == KeyF12) {
        shot_ = true;
        return;
      }
      // F1 help and P pause stop the game; Esc goes to the menu (the game waits there).
      if (key && e.key == KeyF1) {
        help_ = !help_;
        return;
      }
      if (key && e.key == KeyEscape) {
        if (help_) help_ = false;
        else go(Screen::Menu);
        return;
      }
      if (key && e.key == 'p') {
        paused_ = !paused_;
        effects_.push_back(Effect::Click);
        return;
      }
      if (paused_ || help_) return;
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
      if (next_ == Screen::Game && (restart_next_ || !in_progress_)) game_.restart();
      if (next_ == Screen::Game) in_progress_ = true, paused_ = help_ = false;
      restart_next_ = false;
      screen_ = next_;
      credits_time_ = 0;
      game_.set_attract(screen_ != Screen::Game && !in_progress_);
      if (screen_ == Screen::Game) effects_.push_back(Effect::Whoosh);
    }
  } else {
    fade_ = std::max(0.0f, fade_ - step);
  }
  static const InputState kNoInput;
  // A game in progress waits behind the menus, and while paused; before one starts the
  // game plays itself behind them.
  if (screen_ == Screen::Game) {
    if (!paused_ && !help_) game_.update(dt, input);
  } else if (!in_progress_) {
    game_.update(dt, kNoInput);
  }
}

void Shell::sound(Synth& synth) {
  synth.set_volume(settings_.volume);
  synth.set_music(screen_ != Screen::Game);
  for (Effect e : effects_) synth.play(e);
  effects_.clear();
  const bool waiting = screen_ == Screen::Game ? paused_ || help_ : in_progress_;
  if (waiting) synth.set_engine(false, 60);
  else game_.sound(synth);
}

void Shell::frame(FrameDescription& out) {
  game_.frame(out);
  if (shot_) {
    // F12: the frame as shown, to the first free velocity_NNN.png here.
    shot_ = false;
    char name[32];
    do std::snprintf(name, sizeof name, "velocity_%03d.png", ++shots_);
    while (std::filesystem::exists(name) && shots_ < 999);
    out.screenshot = name;
  }
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
      d.text_centered(width_ / 2, height_ / 2 - 62 * s, text_.title, {255, 210, 80, 255}, big);
      for (int b = 0; b < ButtonCount; ++b) {
        Rect r = button_rect(b);
        bool hot = b == hot_;
        d.rect(r.x - s, r.y - s, r.w + 2 * s, r.h + 2 * s, hot ? Rgba{255, 220, 90, 255} : Rgba{90, 110, 150, 255});
        d.rect(r.x, r.y, r.w, r.h, hot ? Rgba{200, 70, 30, 255} : Rgba{20, 30, 60, 230});
        std::string label = b == ButtonStart ? (in_progress_ ? "RESUME" : text_.start) : kButtonLabels[b];
        d.text_centered(r.x + r.w / 2, r.y + (r.h - 7 * s) / 2, label, hot ? Rgba{255, 255, 255, 255} : Rgba{180, 200, 230, 255}, s);
      }
      d.text_centered(width_ / 2, height_ - 12 * s, "MOUSE OR ARROWS AND ENTER   F1 HELP IN GAME", {150, 160, 190, 255}, s);
      break;
    }
    case Screen::Options: {
      d.text_centered(width_ / 2, 8 * s, "OPTIONS", {255, 210, 80, 255}, 2 * s);
      for (int r = 0; r < option_rows(); ++r) {
        Rect rc = option_rect(r);
        bool hot = r == row_;
        d.rect(rc.x, rc.y, rc.w, rc.h, hot ? Rgba{200, 70, 30, 255} : Rgba{20, 30, 60, 200});
        std::string t = ellipsize(option_text(r), rc.w - 4 * s, s);
        d.text_centered(rc.x + rc.w / 2, rc.y + (rc.h - 7 * s) / 2, t, {255, 255, 255, 255}, s);
      }
      std::string hint = binding_ ? "PRESS THE NEW KEY, ESC KEEPS THE OLD ONE" : "UP DOWN CHOOSE, LEFT RIGHT CHANGE, ESC BACK";
      d.text_centered(width_ / 2, height_ - 10 * s, ellipsize(hint, width_, s), {150, 160, 190, 255}, s);
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
    case Screen::Game:
      if (help_) {
        // The help over a dimmed game, as large as fits.
        std::string text = game_.help() + "\n\nF1 OR ESC CLOSES THIS";
        int hs = s;
        while (hs > 1 && (text_width(text, hs) > width_ - 8 * hs || text_height(text, hs) > height_ - 8 * hs)) --hs;
        text = wrap_text(text, width_ - 8 * hs, hs);
        d.rect(0, 0, width_, height_, {0, 0, 20, 190});
        d.text(4 * hs, 4 * hs, text, {230, 240, 255, 255}, hs);
      } else if (paused_) {
        d.rect(0, 0, width_, height_, {0, 0, 20, 120});
        d.text_centered(width_ / 2, height_ / 2 - 10 * s, "PAUSED", {255, 210, 80, 255}, 2 * s);
        d.text_centered(width_ / 2, height_ / 2 + 12 * s, ellipsize("P RESUMES   ESC MENU   F1 HELP", width_, s),
                        {220, 230, 255, 255}, s);
      }
      break;
  }
  d.fade(fade_);
}

}  // namespace velocity::realtime
