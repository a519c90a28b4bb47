// GLUT's pop-up menus: glutCreateMenu and the calls that fill, change and attach them.
// A menu attached to a mouse button opens at the pointer when the button is pressed;
// moving over an entry highlights it (a sub-menu entry opens its menu beside it), and
// releasing the button on an entry calls the menu's callback with the entry's value,
// with that menu current (glutGetMenu), as GLUT does. Released where it was pressed,
// the menu stays open until the next click: on an entry, it is chosen; elsewhere, the
// menu closes. While a menu is in use the program's mouse callbacks see none of it.
// The open menus are drawn over a copy of the frame when it is shown (glut.cpp).
#include <GL/glut.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "menu.hpp"

namespace velocity::glut {

namespace {

using velocity::realtime::InputEvent;
using velocity::realtime::MouseButton;

struct Entry {
  std::string label;
  int value = 0;
  int submenu = 0;  // a menu's id: this entry opens it
};

struct Menu {
  void (*callback)(int) = nullptr;  // nullptr: destroyed
  std::vector<Entry> entries;
};

// An open menu on the screen.
struct Popup {
  int menu;
  int x, y, w, h;
  int hover = -1;  // the entry under the pointer
};

constexpr int kItemHeight = 18, kPadding = 8, kArrowRoom = 14;

struct Menus {
  std::vector<Menu> menus;  // id - 1
  int current = 0;
  int attached[3] = {0, 0, 0};  // per GLUT button (left, middle, right)
  std::vector<Popup> open;      // the root first, then each sub-menu opened from it
  int button = -1;              // the button that opened them
  int press_x = 0, press_y = 0;
  bool moved = false;   // since the press: a release then chooses
  bool eat_up[3] = {false, false, false};  // a press the menu took: its release too
  bool changed = false;
};

Menus& state() {
  static Menus* m = new Menus;  // never destroyed: callbacks may run at exit
  return *m;
}

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "velocity-glut: %s\n", message.c_str());
  std::exit(1);
}

Menu* find(int id) {
  Menus& s = state();
  if (id < 1 || size_t(id) > s.menus.size() || !s.menus[size_t(id) - 1].callback) return nullptr;
  return &s.menus[size_t(id) - 1];
}

Menu& current(const char* function) {
  Menu* m = find(state().current);
  if (!m) fail(std::string(function) + " called with no current menu (glutCreateMenu or glutSetMenu first)");
  return *m;
}

// Entry `item` (1-based, as GLUT counts) of the current menu.
Entry& item_of(const char* function, int item) {
  Menu& m = current(function);
  if (item < 1 || size_t(item) > m.entries.size())
    fail(std::string(function) + ": item " + std::to_string(item) + " does not exist (the menu has " +
         std::to_string(m.entries.size()) + ")");
  return m.entries[size_t(item) - 1];
}

int glut_button(MouseButton b) {
  return b == MouseButton::Middle ? GLUT_MIDDLE_BUTTON : b == MouseButton::Right ? GLUT_RIGHT_BUTTON : GLUT_LEFT_BUTTON;
}

// A popup for `menu` with its top left at (x, y), moved inside the window.
Popup place(int menu, int x, int y, int w, int h) {
  const Menu& m = *find(menu);
  int width = 0;
  for (const Entry& e : m.entries) width = std::max(width, menu_text_width(e.label.c_str()) + (e.submenu ? kArrowRoom : 0));
  Popup p{menu, x, y, width + 2 * kPadding, int(m.entries.size()) * kItemHeight + 2};
  p.x = std::max(0, std::min(p.x, w - p.w)), p.y = std::max(0, std::min(p.y, h - p.h));
  return p;
}

// The popup (deepest first) and entry under (x, y): false when none.
bool hit(int x, int y, size_t& popup, int& entry) {
  const Menus& s = state();
  for (size_t k = s.open.size(); k-- > 0;) {
    const Popup& p = s.open[k];
    if (x < p.x || x >= p.x + p.w || y < p.y + 1 || y >= p.y + p.h - 1) continue;
    popup = k, entry = (y - p.y - 1) / kItemHeight;
    return true;
  }
  return false;
}

void close_all() {
  Menus& s = state();
  s.open.clear(), s.button = -1, s.changed = true;
}

// The pointer at (x, y): highlight, and open or close sub-menus to match.
void hover(int x, int y, int w, int h) {
  Menus& s = state();
  size_t k;
  int e;
  if (!hit(x, y, k, e)) {
    if (!s.open.empty() && s.open.back().hover != -1) s.open.back().hover = -1, s.changed = true;
    return;
  }
  if (s.open.size() > k + 1 && s.open[k].hover == e) return;  // its sub-menu is open already
  if (s.open[k].hover != e || s.open.size() != k + 1) s.changed = true;
  s.open.resize(k + 1);
  s.open[k].hover = e;
  const Entry& entry = find(s.open[k].menu)->entries[size_t(e)];
  if (entry.submenu && find(entry.submenu)) {
    const Popup& p = s.open[k];
    s.open.push_back(place(entry.submenu, p.x + p.w - 2, p.y + e * kItemHeight, w, h));
  }
}

// Chooses the entry under (x, y), if it is one (not a sub-menu): true when chosen.
bool choose(int x, int y) {
  Menus& s = state();
  size_t k;
  int e;
  if (!hit(x, y, k, e)) return false;
  const int id = s.open[k].menu;
  const Entry entry = find(id)->entries[size_t(e)];
  if (entry.submenu) return false;
  close_all();
  // The callback runs with its menu current (and may change the menus).
  const int before = s.current;
  s.current = id;
  find(id)->callback(entry.value);
  if (find(before)) s.current = before;
  return true;
}

}  // namespace

bool menu_event(const InputEvent& e, int w, int h) {
  Menus& s = state();
  switch (e.kind) {
    case InputEvent::MouseDown: {
      const int b = glut_button(e.button);
      if (s.open.empty()) {
        if (!find(s.attached[b])) return false;
        s.open.push_back(place(s.attached[b], e.x, e.y, w, h));
        s.button = b, s.press_x = e.x, s.press_y = e.y, s.moved = false, s.changed = true;
        return true;
      }
      // A click while the menu stays open: an entry is chosen, elsewhere it closes.
      s.eat_up[b] = true;
      if (!choose(e.x, e.y)) {
        size_t k;
        int entry;
        if (!hit(e.x, e.y, k, entry)) close_all();
      }
      return true;
    }
    case InputEvent::MouseMove:
      if (s.open.empty()) return false;
      if (std::abs(e.x - s.press_x) > 2 || std::abs(e.y - s.press_y) > 2) s.moved = true;
      hover(e.x, e.y, w, h);
      return true;
    case InputEvent::MouseUp: {
      if (s.open.empty()) return std::exchange(s.eat_up[glut_button(e.button)], false);
      if (glut_button(e.button) != s.button) return true;
      if (!s.moved && std::abs(e.x - s.press_x) <= 2 && std::abs(e.y - s.press_y) <= 2) return true;  // stays open
      if (!choose(e.x, e.y)) {
        size_t k;
        int entry;
        if (!hit(e.x, e.y, k, entry)) close_all();
      }
      return true;
    }
    default: return false;
  }
}

bool menu_open() { return !state().open.empty(); }

int menu_items() {
  const Menu* m = find(state().current);
  return m ? int(m->entries.size()) : 0;
}

#ifndef VELOCITY_GLUT_FONTS
// Built without GLUT's fonts (no freeglut3-dev): entries without labels.
int menu_text_width(const char* text) { return 7 * int(std::string(text).size()); }
void menu_text(std::vector<uint8_t>&, int, int, int, int, const char*, const uint8_t*) {}
#endif

bool menu_changed() {
  const bool changed = state().changed;
  state().changed = false;
  return changed;
}

void menu_overlay(std::vector<uint8_t>& rgba, int w, int h) {
  const Menus& s = state();
  auto fill = [&](int x0, int y0, int x1, int y1, const uint8_t c[3]) {
    for (int y = std::max(y0, 0); y < std::min(y1, h); ++y)
      for (int x = std::max(x0, 0); x < std::min(x1, w); ++x) {
        uint8_t* p = &rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
        p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
      }
  };
  static const uint8_t border[3] = {40, 40, 40}, face[3] = {224, 224, 224}, lit[3] = {60, 90, 170},
                       text[3] = {0, 0, 0}, lit_text[3] = {255, 255, 255};
  for (const Popup& p : s.open) {
    const Menu* m = find(p.menu);
    if (!m) continue;
    fill(p.x, p.y, p.x + p.w, p.y + p.h, border);
    fill(p.x + 1, p.y + 1, p.x + p.w - 1, p.y + p.h - 1, face);
    for (size_t i = 0; i < m->entries.size(); ++i) {
      const int top = p.y + 1 + int(i) * kItemHeight;
      const bool on = int(i) == p.hover;
      if (on) fill(p.x + 1, top, p.x + p.w - 1, top + kItemHeight, lit);
      const Entry& e = m->entries[i];
      menu_text(rgba, w, h, p.x + kPadding, top + 13, e.label.c_str(), on ? lit_text : text);
      if (e.submenu)  // a small triangle pointing right
        for (int r = 0; r < 4; ++r) fill(p.x + p.w - kPadding - 4 + r, top + 5 + r, p.x + p.w - kPadding - 3 + r, top + 13 - r, on ? lit_text : text);
    }
  }
}

}  // namespace velocity::glut

using namespace velocity::glut;

extern "C" {

int glutCreateMenu(void (*callback)(int)) {
  if (!callback) fail("glutCreateMenu: the menu's callback cannot be NULL");
  Menus& s = state();
  s.menus.push_back({callback, {}});
  return s.current = int(s.menus.size());
}

void glutDestroyMenu(int menu) {
  Menu* m = find(menu);
  if (!m) fail("glutDestroyMenu: menu " + std::to_string(menu) + " does not exist");
  Menus& s = state();
  if (std::any_of(s.open.begin(), s.open.end(), [&](const Popup& p) { return p.menu == menu; })) close_all();
  *m = Menu{};
  for (int& a : s.attached)
    if (a == menu) a = 0;
  if (s.current == menu) s.current = 0;
}

int glutGetMenu(void) { return find(state().current) ? state().current : 0; }

void glutSetMenu(int menu) {
  if (!find(menu)) fail("glutSetMenu: menu " + std::to_string(menu) + " does not exist");
  state().current = menu;
}

void glutAddMenuEntry(const char* label, int value) {
  current("glutAddMenuEntry").entries.push_back({label ? label : "", value, 0});
  state().changed = true;
}

void glutAddSubMenu(const char* label, int submenu) {
  if (!find(submenu)) fail("glutAddSubMenu: menu " + std::to_string(submenu) + " does not exist");
  current("glutAddSubMenu").entries.push_back({label ? label : "", 0, submenu});
  state().changed = true;
}

void glutChangeToMenuEntry(int item, const char* label, int value) {
  item_of("glutChangeToMenuEntry", item) = {label ? label : "", value, 0};
  state().changed = true;
}

void glutChangeToSubMenu(int item, const char* label, int submenu) {
  if (!find(submenu)) fail("glutChangeToSubMenu: menu " + std::to_string(submenu) + " does not exist");
  item_of("glutChangeToSubMenu", item) = {label ? label : "", 0, submenu};
  state().changed = true;
}

void glutRemoveMenuItem(int item) {
  item_of("glutRemoveMenuItem", item);
  Menu& m = current("glutRemoveMenuItem");
  m.entries.erase(m.entries.begin() + (item - 1));
  close_all();  // (what is open may show it)
}

void glutAttachMenu(int button) {
  if (button < GLUT_LEFT_BUTTON || button > GLUT_RIGHT_BUTTON) return;
  state().attached[button] = glutGetMenu();
}

void glutDetachMenu(int button) {
  if (button < GLUT_LEFT_BUTTON || button > GLUT_RIGHT_BUTTON) return;
  state().attached[button] = 0;
}

}  // extern "C"
