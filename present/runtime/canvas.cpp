#include "runtime/canvas.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>

namespace velocity::realtime {

void fill_rect(Canvas& c, int x, int y, int w, int h, Rgba color) {
  int x0 = std::max(x, 0), y0 = std::max(y, 0);
  int x1 = std::min(x + w, c.width), y1 = std::min(y + h, c.height);
  if (x0 >= x1 || y0 >= y1 || color.a == 0) return;
  const unsigned a = color.a, ia = 255 - a;
  for (int j = y0; j < y1; ++j) {
    uint8_t* p = c.pixels + size_t(j) * c.stride + size_t(x0) * 4;
    for (int i = x0; i < x1; ++i, p += 4) {
      // (v * 255 + 127) / 255 rounding, exact for a = 255.
      p[0] = uint8_t((color.r * a + p[0] * ia + 127) / 255);
      p[1] = uint8_t((color.g * a + p[1] * ia + 127) / 255);
      p[2] = uint8_t((color.b * a + p[2] * ia + 127) / 255);
      p[3] = c.layer ? uint8_t((255 * a + p[3] * ia + 127) / 255) : 255;
    }
  }
}

void fade(Canvas& c, float amount) {
  amount = std::clamp(amount, 0.0f, 1.0f);
  if (amount <= 0) return;
  const unsigned keep = unsigned((1.0f - amount) * 256.0f + 0.5f);
  for (int j = 0; j < c.height; ++j) {
    uint8_t* p = c.pixels + size_t(j) * c.stride;
    for (int i = 0; i < c.width * 4; i += 4) {
      p[i] = uint8_t((p[i] * keep) >> 8);
      p[i + 1] = uint8_t((p[i + 1] * keep) >> 8);
      p[i + 2] = uint8_t((p[i + 2] * keep) >> 8);
      // A layer: black at 1 - keep over what it holds, so the frame under it darkens too.
      if (c.layer) p[i + 3] = uint8_t(255 - (((255 - p[i + 3]) * keep) >> 8));
    }
  }
}

namespace {

// stb_easy_font returns axis-aligned quads, 4 vertices of 16 bytes (x, y, z floats and
// an RGBA colour) each. Calls `f(x0, y0, x1, y1)` for every quad of `text` at (0, 0).
template <typename F>
void for_each_quad(const std::string& text, F&& f) {
  // 64 bytes a quad; 'X' takes 11 quads and other glyphs more than 5, so guess generously
  // and, when the buffer filled up (stb_easy_font stops writing quietly and the last
  // glyphs would come out cut), try again with twice the room. A line at a time.
  std::vector<char> buffer;
  size_t start = 0;
  int line = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string s = text.substr(start, end - start);
    int quads = 0;
    for (size_t size = s.size() * 16 * 64 + 64;; size *= 2) {
      buffer.resize(size);
      quads = stb_easy_font_print(0, float(line * 10), s.data(), nullptr, buffer.data(), int(buffer.size()));
      if (size_t(quads) * 64 + 64 <= size) break;
    }
    for (int q = 0; q < quads; ++q) {
      const float* v0 = reinterpret_cast<const float*>(buffer.data() + q * 64);
      const float* v2 = reinterpret_cast<const float*>(buffer.data() + q * 64 + 32);
      f(int(v0[0]), int(v0[1]), int(v2[0]), int(v2[1]));
    }
    start = end + 1;
    ++line;
  }
}

}  // namespace

int text_width(const std::string& text, int scale) {
  int w = 0;
  for_each_quad(text, [&](int, int, int x1, int) { w = std::max(w, x1); });
  return w * scale;
}

int text_height(const std::string& text, int scale) {
  int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
  return (lines * 10 - 3) * scale;
}

void draw_text(Canvas& c, int x, int y, const std::string& text, Rgba color, int scale) {
  for_each_quad(text, [&](int x0, int y0, int x1, int y1) {
    fill_rect(c, x + x0 * scale, y + y0 * scale, (x1 - x0) * scale, (y1 - y0) * scale, color);
  });
}

std::string ellipsize(const std::string& text, int max_width, int scale) {
  if (text_width(text, scale) <= max_width) return text;
  std::string s = text;
  while (!s.empty() && text_width(s + "...", scale) > max_width) s.pop_back();
  return s.empty() ? std::string() : s + "...";
}

std::string wrap_text(const std::string& text, int max_width, int scale) {
  std::string out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string rest = text.substr(start, end - start), line;
    while (text_width(rest, scale) > max_width && rest.size() > 1) {
      // The longest start of `rest` that fits, ended at a space, else after a '/',
      // else anywhere (at least one character a line).
      size_t fit = 1;
      while (fit < rest.size() && text_width(rest.substr(0, fit + 1), scale) <= max_width) ++fit;
      size_t cut = rest.rfind(' ', fit);
      if (cut == std::string::npos || cut == 0) {
        cut = rest.rfind('/', fit - 1);
        cut = cut == std::string::npos || cut == 0 ? fit : cut + 1;
      }
      out += rest.substr(0, cut) + "\n";
      rest = rest.substr(cut);
      rest.erase(0, rest.find_first_not_of(' ') == std::string::npos ? rest.size() : rest.find_first_not_of(' '));
    }
    out += rest;
    if (end < text.size()) out += "\n";
    start = end + 1;
  }
  return out;
}

void draw_text_shadow(Canvas& c, int x, int y, const std::string& text, Rgba color, int scale) {
  draw_text(c, x + scale, y + scale, text, {0, 0, 0, uint8_t(color.a * 3 / 4)}, scale);
  draw_text(c, x, y, text, color, scale);
}

void DrawList::draw(Canvas& c) const {
  for (const DrawOp& op : ops_) {
    switch (op.kind) {
      case DrawOp::Rect: fill_rect(c, op.x, op.y, op.w, op.h, op.color); break;
      case DrawOp::Text: draw_text(c, op.x, op.y, op.text, op.color, op.scale); break;
      case DrawOp::TextShadow: draw_text_shadow(c, op.x, op.y, op.text, op.color, op.scale); break;
      case DrawOp::Fade: realtime::fade(c, op.amount); break;
    }
  }
}

}  // namespace velocity::realtime
