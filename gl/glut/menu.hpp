// GLUT's pop-up menus (menu.cpp), as glut.cpp's window uses them: the mouse events a
// menu takes, and the open menus drawn over a copy of the frame before it is shown.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/input.hpp"

namespace velocity::glut {

// A mouse event in the window (w x h): true when a menu took it (an attached button
// pressed, a menu open), so that the program's mouse callbacks do not see it. May call
// a menu's callback.
bool menu_event(const velocity::realtime::InputEvent& e, int w, int h);
// Whether a menu is open now, and whether what is drawn of menus changed since the
// last time this was asked.
bool menu_open();
bool menu_changed();
// glutGet(GLUT_MENU_NUM_ITEMS): the current menu's entries.
int menu_items();
// The open menus drawn into `rgba` (w x h, top row first).
void menu_overlay(std::vector<uint8_t>& rgba, int w, int h);

// Menu labels in GLUT's Helvetica 12 (fonts.cpp; without the fonts, none): the width
// of `text`, and `text` drawn with its baseline at row `baseline`, clipped to w x h.
int menu_text_width(const char* text);
void menu_text(std::vector<uint8_t>& rgba, int w, int h, int x, int baseline, const char* text, const uint8_t rgb[3]);

}  // namespace velocity::glut
