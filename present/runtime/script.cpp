#include "runtime/script.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "velocity/error.hpp"

namespace velocity::realtime {

namespace {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

class LineParser {
 public:
  LineParser(const std::string& name, size_t line) : name_(name), line_(line) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ":" + std::to_string(line_) + ": " + what);
  }
  double number(std::string_view w, const char* what, double lo, double hi) const {
    double v = 0;
    auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || p != w.data() + w.size() || !std::isfinite(v) || v < lo || v > hi)
      fail(std::string("expected ") + what + ", got '" + std::string(w) + "'");
    return v;
  }
  int coord(std::string_view w) const { return int(number(w, "a pixel coordinate (-100000..100000)", -1e5, 1e5)); }
  MouseButton button(std::string_view w) const {
    if (w == "left") return MouseButton::Left;
    if (w == "right") return MouseButton::Right;
    if (w == "middle") return MouseButton::Middle;
    fail("expected a mouse button (left, right, middle), got '" + std::string(w) + "'");
  }
  Key key(std::string_view w) const {
    auto k = parse_key(w);
    if (!k) fail("unknown key '" + std::string(w) + "'");
    return *k;
  }

 private:
  const std::string& name_;
  size_t line_;
};

constexpr double kTap = 0.05;  // how long `press` and `click` hold

}  // namespace

Script parse_script(std::string_view text, const std::string& name) {
  if (text.size() > kMaxScriptBytes) throw Error(name + ": script larger than 4 MiB");
  Script script;
  size_t line_no = 0, pos = 0;
  auto add = [&](double t, InputEvent e, const LineParser& p) {
    if (script.events.size() >= kMaxScriptEvents) p.fail("more than 100000 events");
    script.events.push_back({t, std::move(e)});
  };
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    auto w = split_words(line);
    if (w.empty()) continue;
    LineParser p(name, line_no);
    if (w.size() < 2) p.fail("expected TIME ACTION ...");
    double t = p.number(w[0], "a time in seconds (0..1e6)", 0, 1e6);
    std::string_view action = w[1];
    auto need = [&](size_t n, const char* usage) {
      if (w.size() != n) p.fail(std::string("expected '") + usage + "'");
    };
    InputEvent e;
    if (action == "down" || action == "up" || action == "press") {
      need(3, "TIME down|up|press KEY");
      e.key = p.key(w[2]);
      e.kind = action == "up" ? InputEvent::KeyUp : InputEvent::KeyDown;
      add(t, e, p);
      if (action == "press") {
        e.kind = InputEvent::KeyUp;
        add(t + kTap, e, p);
      }
    } else if (action == "move") {
      need(4, "TIME move X Y");
      e.kind = InputEvent::MouseMove;
      e.x = p.coord(w[2]), e.y = p.coord(w[3]);
      add(t, e, p);
    } else if (action == "click") {
      if (w.size() != 4 && w.size() != 5) p.fail("expected 'TIME click X Y [left|right|middle]'");
      e.x = p.coord(w[2]), e.y = p.coord(w[3]);
      e.button = w.size() == 5 ? p.button(w[4]) : MouseButton::Left;
      e.kind = InputEvent::MouseDown;
      add(t, e, p);
      e.kind = InputEvent::MouseUp;
      add(t + kTap, e, p);
    } else if (action == "mousedown" || action == "mouseup") {
      need(5, "TIME mousedown|mouseup BUTTON X Y");
      e.kind = action == "mousedown" ? InputEvent::MouseDown : InputEvent::MouseUp;
      e.button = p.button(w[2]);
      e.x = p.coord(w[3]), e.y = p.coord(w[4]);
      add(t, e, p);
    } else if (action == "wheel") {
      need(3, "TIME wheel AMOUNT");
      e.kind = InputEvent::Wheel;
      e.wheel = float(p.number(w[2], "a wheel amount (-100..100)", -100, 100));
      add(t, e, p);
    } else if (action == "drop") {
      if (w.size() < 3) p.fail("expected 'TIME drop PATH'");
      e.kind = InputEvent::Drop;
      // The path is the rest of the line (it may hold spaces).
      size_t at = size_t(w[2].data() - line.data());
      std::string_view rest = line.substr(at);
      while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
      e.path = std::string(rest);
      add(t, e, p);
    } else if (action == "quit") {
      need(2, "TIME quit");
      e.kind = InputEvent::Quit;
      add(t, e, p);
    } else {
      p.fail("unknown action '" + std::string(action) +
             "' (expected down, up, press, move, click, mousedown, mouseup, wheel, drop, quit)");
    }
  }
  std::stable_sort(script.events.begin(), script.events.end(),
                   [](const TimedEvent& a, const TimedEvent& b) { return a.time < b.time; });
  return script;
}

Script load_script(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open script");
  std::string text;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, size_t(in.gcount()));
    if (text.size() > kMaxScriptBytes) throw Error(path + ": script larger than 4 MiB");
  }
  return parse_script(text, path);
}

void ScriptPlayer::due(double time, std::vector<InputEvent>& out) {
  while (next_ < script_.events.size() && script_.events[next_].time <= time + 1e-9)
    out.push_back(script_.events[next_++].event);
}

}  // namespace velocity::realtime
