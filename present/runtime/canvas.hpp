// 2D drawing on a rendered frame: filled rectangles, text in the engine's own bitmap
// font, and fades. Menus, credits and the frame-rate overlay are drawn with these.
//
// A DrawList records the 2D layer as data, so that a program describes a frame's
// overlay on the main thread and the render thread draws it after the 3D pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace velocity::realtime {

struct Rgba {
  uint8_t r = 255, g = 255, b = 255, a = 255;
};

// A view of RGBA8 pixels, top row first, `stride` bytes apart. Drawing clips to it.
struct Canvas {
  uint8_t* pixels = nullptr;
  int width = 0, height = 0;
  size_t stride = 0;
  // A layer to be blended over a frame later (the GPU's windowed path): starts
  // transparent (all zero), holds premultiplied colour, and its alpha records how much
  // of what lies under it shows through (255 - alpha of 255), so that composing it with
  // "one, one minus source alpha" gives what drawing on the frame itself gives.
  bool layer = false;
};

// Blends `color` (its alpha) over the rectangle [x, x + w) x [y, y + h), clipped.
void fill_rect(Canvas& c, int x, int y, int w, int h, Rgba color);
// Darkens the whole canvas towards black: amount 0 leaves it, 1 makes it black.
void fade(Canvas& c, float amount);

// The bitmap font (stb_easy_font's glyph strokes, rasterised here as pixel blocks):
// about 6 x 8 pixels a character at scale 1; `scale` multiplies that whole pixels.
// '\n' starts a new line. Returns the width in pixels of the widest line.
int text_width(const std::string& text, int scale = 1);
int text_height(const std::string& text, int scale = 1);
void draw_text(Canvas& c, int x, int y, const std::string& text, Rgba color, int scale = 1);
// `text` cut to at most `max_width` pixels, ending in "..." when cut (one line).
std::string ellipsize(const std::string& text, int max_width, int scale = 1);
// `text` with line breaks so that no line is wider than `max_width` pixels: at spaces,
// and where a word alone is too wide, after a '/' or anywhere in it. Keeps its '\n's.
std::string wrap_text(const std::string& text, int max_width, int scale = 1);
// draw_text with a one-pixel (times scale) dark shadow, readable on any background.
void draw_text_shadow(Canvas& c, int x, int y, const std::string& text, Rgba color, int scale = 1);

struct DrawOp {
  enum Kind { Rect, Text, TextShadow, Fade } kind = Rect;
  int x = 0, y = 0, w = 0, h = 0, scale = 1;
  Rgba color;
  float amount = 0;  // Fade
  std::string text;
};

class DrawList {
 public:
  void rect(int x, int y, int w, int h, Rgba color) { ops_.push_back({DrawOp::Rect, x, y, w, h, 1, color, 0, {}}); }
  void text(int x, int y, std::string s, Rgba color, int scale = 1, bool shadow = true) {
    ops_.push_back({shadow ? DrawOp::TextShadow : DrawOp::Text, x, y, 0, 0, scale, color, 0, std::move(s)});
  }
  // Text centred horizontally on `cx`.
  void text_centered(int cx, int y, std::string s, Rgba color, int scale = 1) {
    int w = text_width(s, scale);
    text(cx - w / 2, y, std::move(s), color, scale);
  }
  void fade(float amount) {
    if (amount > 0) ops_.push_back({DrawOp::Fade, 0, 0, 0, 0, 1, {}, amount, {}});
  }
  void clear() { ops_.clear(); }
  const std::vector<DrawOp>& ops() const { return ops_; }
  // Draws every op in order.
  void draw(Canvas& c) const;

 private:
  std::vector<DrawOp> ops_;
};

}  // namespace velocity::realtime
