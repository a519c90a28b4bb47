// GLUT's bitmap and stroke fonts as freeglut 3 draws them: a bitmap character is one
// glBitmap at the raster position (with the unpack state GLUT needs, put back after),
// advancing it by the character's width; a stroke character is line strips in model
// space, then a glTranslate by its advance. The glyphs are freeglut's own, read from
// Debian's libglut when Velocity is built (font_tables.c writes glut_font_tables.inc).
#include <GL/glut.h>

#include <cstdio>

#include "menu.hpp"

namespace {

// A bitmap font: each character's face is its width, then `height` rows (bottom row
// first) of (width + 7) / 8 bytes, most significant bit first.
struct BitmapFont {
  int height;
  float xorig, yorig;
  const unsigned char* data;
  const unsigned* offsets;  // per character (256), into data
};

struct StrokeStrip {
  unsigned first;  // into the font's vertices (x, y pairs)
  int count;
};
struct StrokeChar {
  float advance;  // -1: the font has no such character
  unsigned first_strip;
  int strips;
};
struct StrokeFont {
  int quantity;
  float height;
  const float* vertices;
  const StrokeStrip* strips;
  const StrokeChar* chars;
};

#include "glut_font_tables.inc"

}  // namespace

extern "C" {
// The fonts' handles: programs pass these variables' addresses (GLUT_BITMAP_9_BY_15 is
// &glutBitmap9By15), as freeglut's header has them on X11.
void *glutStrokeRoman, *glutStrokeMonoRoman, *glutBitmap9By15, *glutBitmap8By13, *glutBitmapTimesRoman10,
    *glutBitmapTimesRoman24, *glutBitmapHelvetica10, *glutBitmapHelvetica12, *glutBitmapHelvetica18;
}

namespace {

const BitmapFont* bitmap_font(void* id, const char* caller) {
  if (id == GLUT_BITMAP_8_BY_13) return &kFixed8x13;
  if (id == GLUT_BITMAP_9_BY_15) return &kFixed9x15;
  if (id == GLUT_BITMAP_HELVETICA_10) return &kHelvetica10;
  if (id == GLUT_BITMAP_HELVETICA_12) return &kHelvetica12;
  if (id == GLUT_BITMAP_HELVETICA_18) return &kHelvetica18;
  if (id == GLUT_BITMAP_TIMES_ROMAN_10) return &kTimesRoman10;
  if (id == GLUT_BITMAP_TIMES_ROMAN_24) return &kTimesRoman24;
  std::fprintf(stderr, "%s: %p is not a GLUT bitmap font (a stroke font, or no font)\n", caller, id);
  return nullptr;
}

const StrokeFont* stroke_font(void* id, const char* caller) {
  if (id == GLUT_STROKE_ROMAN) return &kRoman;
  if (id == GLUT_STROKE_MONO_ROMAN) return &kMonoRoman;
  std::fprintf(stderr, "%s: %p is not a GLUT stroke font (a bitmap font, or no font)\n", caller, id);
  return nullptr;
}

const unsigned char* face(const BitmapFont& f, unsigned char c) { return f.data + f.offsets[c]; }

// GLUT's unpack state for its glyphs while it draws them, and the program's put back.
class GlyphUnpack {
 public:
  GlyphUnpack() {
    for (int i = 0; i < 6; ++i) glGetIntegerv(kNames[i], &saved_[i]);
    static const GLint glyph[6] = {GL_FALSE, GL_FALSE, 0, 0, 0, 1};
    for (int i = 0; i < 6; ++i) glPixelStorei(kNames[i], glyph[i]);
  }
  ~GlyphUnpack() {
    for (int i = 0; i < 6; ++i) glPixelStorei(kNames[i], saved_[i]);
  }
  GlyphUnpack(const GlyphUnpack&) = delete;
  GlyphUnpack& operator=(const GlyphUnpack&) = delete;

 private:
  static constexpr GLenum kNames[6] = {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH,
                                       GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT};
  GLint saved_[6] = {0, 0, 0, 0, 0, 4};
};

void draw_bitmap_char(const BitmapFont& f, unsigned char c) {
  const unsigned char* g = face(f, c);
  glBitmap(g[0], f.height, f.xorig, f.yorig, float(g[0]), 0, g + 1);
}

void draw_stroke_char(const StrokeFont& f, const StrokeChar& ch) {
  for (int s = 0; s < ch.strips; ++s) {
    const StrokeStrip& strip = f.strips[ch.first_strip + unsigned(s)];
    glBegin(GL_LINE_STRIP);
    for (int v = 0; v < strip.count; ++v) {
      const float* xy = f.vertices + 2 * (strip.first + unsigned(v));
      glVertex2f(xy[0], xy[1]);
    }
    glEnd();
  }
}

// The font's character c, or null where it has none (freeglut draws nothing there).
const StrokeChar* stroke_char(const StrokeFont& f, int c) {
  if (c < 0 || c >= f.quantity || f.chars[c].advance < 0) return nullptr;
  return &f.chars[c];
}

}  // namespace

extern "C" {

void glutBitmapCharacter(void* font, int character) {
  const BitmapFont* f = bitmap_font(font, "glutBitmapCharacter");
  if (!f || character < 1 || character > 255) return;
  GlyphUnpack unpack;
  draw_bitmap_char(*f, static_cast<unsigned char>(character));
}

// A newline moves the raster position back to where the line began and down a line.
void glutBitmapString(void* font, const unsigned char* string) {
  const BitmapFont* f = bitmap_font(font, "glutBitmapString");
  if (!f || !string || !*string) return;
  GlyphUnpack unpack;
  float x = 0;
  for (const unsigned char* p = string; *p; ++p) {
    if (*p == '\n') {
      glBitmap(0, 0, 0, 0, -x, -float(f->height), nullptr);
      x = 0;
    } else {
      draw_bitmap_char(*f, *p);
      x += float(face(*f, *p)[0]);
    }
  }
}

int glutBitmapWidth(void* font, int character) {
  const BitmapFont* f = bitmap_font(font, "glutBitmapWidth");
  if (!f || character < 1 || character > 255) return 0;
  return face(*f, static_cast<unsigned char>(character))[0];
}

// The widest line's width.
int glutBitmapLength(void* font, const unsigned char* string) {
  const BitmapFont* f = bitmap_font(font, "glutBitmapLength");
  if (!f || !string) return 0;
  int longest = 0, line = 0;
  for (const unsigned char* p = string; *p; ++p) {
    if (*p == '\n') {
      longest = line > longest ? line : longest;
      line = 0;
    } else {
      line += face(*f, *p)[0];
    }
  }
  return line > longest ? line : longest;
}

int glutBitmapHeight(void* font) {
  const BitmapFont* f = bitmap_font(font, "glutBitmapHeight");
  return f ? f->height : 0;
}

void glutStrokeCharacter(void* font, int character) {
  const StrokeFont* f = stroke_font(font, "glutStrokeCharacter");
  if (!f) return;
  const StrokeChar* ch = stroke_char(*f, character);
  if (!ch) return;
  draw_stroke_char(*f, *ch);
  glTranslatef(ch->advance, 0, 0);
}

void glutStrokeString(void* font, const unsigned char* string) {
  const StrokeFont* f = stroke_font(font, "glutStrokeString");
  if (!f || !string) return;
  float length = 0;
  for (const unsigned char* p = string; *p; ++p) {
    if (*p == '\n' && *p < f->quantity) {
      glTranslatef(-length, -f->height, 0);
      length = 0;
    } else if (const StrokeChar* ch = stroke_char(*f, *p)) {
      draw_stroke_char(*f, *ch);
      length += ch->advance;
      glTranslatef(ch->advance, 0, 0);
    }
  }
}

GLfloat glutStrokeWidthf(void* font, int character) {
  const StrokeFont* f = stroke_font(font, "glutStrokeWidth");
  const StrokeChar* ch = f ? stroke_char(*f, character) : nullptr;
  return ch ? ch->advance : 0;
}

int glutStrokeWidth(void* font, int character) { return int(glutStrokeWidthf(font, character) + 0.5f); }

GLfloat glutStrokeLengthf(void* font, const unsigned char* string) {
  const StrokeFont* f = stroke_font(font, "glutStrokeLength");
  if (!f || !string) return 0;
  float longest = 0, line = 0;
  for (const unsigned char* p = string; *p; ++p) {
    if (*p == '\n') {
      longest = line > longest ? line : longest;
      line = 0;
    } else if (const StrokeChar* ch = stroke_char(*f, *p)) {
      line += ch->advance;
    }
  }
  return line > longest ? line : longest;
}

int glutStrokeLength(void* font, const unsigned char* string) { return int(glutStrokeLengthf(font, string) + 0.5f); }

GLfloat glutStrokeHeight(void* font) {
  const StrokeFont* f = stroke_font(font, "glutStrokeHeight");
  return f ? f->height : 0;
}

}  // extern "C"

namespace velocity::glut {

int menu_text_width(const char* text) {
  int w = 0;
  for (const unsigned char* c = reinterpret_cast<const unsigned char*>(text); *c; ++c) w += face(kHelvetica12, *c)[0];
  return w;
}

// The glyphs' bits straight into the frame: rows bottom first, most significant bit
// first, the origin (xorig, yorig) on the baseline as glBitmap places it.
void menu_text(std::vector<uint8_t>& rgba, int w, int h, int x, int baseline, const char* text, const uint8_t rgb[3]) {
  const BitmapFont& f = kHelvetica12;
  for (const unsigned char* c = reinterpret_cast<const unsigned char*>(text); *c; ++c) {
    const unsigned char* g = face(f, *c);
    const int gw = g[0], stride = (gw + 7) / 8;
    for (int r = 0; r < f.height; ++r) {
      const int py = baseline + int(f.yorig) - r;
      for (int b = 0; b < gw; ++b) {
        const int px = x - int(f.xorig) + b;
        if (px < 0 || py < 0 || px >= w || py >= h || !(g[1 + r * stride + b / 8] & (0x80 >> (b % 8)))) continue;
        uint8_t* p = &rgba[(size_t(py) * size_t(w) + size_t(px)) * 4];
        p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2];
      }
    }
    x += gw;
  }
}

}  // namespace velocity::glut
