// The accumulation buffer: glAccum, glClearAccum, glClear's GL_ACCUM_BUFFER_BIT.
//
// It is the context's own: RGBA per pixel in signed 16-bit fixed point (1 is 32767), as
// Mesa's (OSMesa's accumulation bits give a GL_RGBA16_SNORM buffer), with Mesa's
// arithmetic: each product cut toward zero to a step, the clear value converted as
// FLOAT_TO_SHORT does. A result past [-1, 1] (undefined in GL) is clamped where Mesa's
// wraps. glAccum reads the colour buffer after running the frame; GL_RETURN's colours
// go through the pipeline as window rectangles with only the scissor test and the
// colour mask applied (GL 1.5 section 4.2.4).
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
constexpr float kAccumOne = 32767.0f;

// A sum or product, cut toward zero, kept in a 16-bit component.
int16_t accum_value(double v) {
  if (!(v == v)) return 0;  // (NaN)
  return int16_t(std::clamp(std::trunc(v), -32768.0, 32767.0));
}
}  // namespace

// The pixels glAccum and glClear touch: the framebuffer, or the scissor box in it.
Box Context::accum_region() const {
  if (!raster_.scissor_test) return {0, 0, width_, height_};
  const Box& s = raster_.scissor;
  const int x0 = std::clamp(s.x, 0, width_), y0 = std::clamp(s.y, 0, height_);
  const int x1 = int(std::clamp<int64_t>(int64_t(s.x) + s.width, x0, width_));
  const int y1 = int(std::clamp<int64_t>(int64_t(s.y) + s.height, y0, height_));
  return {x0, y0, x1 - x0, y1 - y0};
}

void Context::clear_accum(float r, float g, float b, float a) {
  if (in_begin_error()) return;
  accum_clear_ = {std::clamp(r, -1.0f, 1.0f), std::clamp(g, -1.0f, 1.0f), std::clamp(b, -1.0f, 1.0f), std::clamp(a, -1.0f, 1.0f)};
}

// The buffer, allocated when first used (a context that never uses it costs nothing).
bool Context::accum_buffer_ready() {
  if (accum_bits_ <= 0 || !renderer_) return false;
  const size_t n = size_t(width_) * size_t(height_) * 4;
  if (accum_.size() != n) accum_.assign(n, 0);
  return true;
}

void Context::clear_accum_buffer() {
  if (!accum_buffer_ready()) return;
  const Box r = accum_region();
  // (Mesa's FLOAT_TO_SHORT: (65535 c - 1) / 2.)
  int16_t v[4];
  const float c[4] = {accum_clear_.x, accum_clear_.y, accum_clear_.z, accum_clear_.w};
  for (int k = 0; k < 4; ++k) v[k] = accum_value((double(c[k]) * 65535.0 - 1.0) / 2.0);
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) std::copy(v, v + 4, &accum_[(size_t(y) * size_t(width_) + size_t(x)) * 4]);
}

void Context::accum(GLenum op, float value) {
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD) return error(GL_INVALID_ENUM);
  if (in_begin_error()) return;
  if (accum_bits_ <= 0) return error(GL_INVALID_OPERATION);
  // (Selection and feedback draw nothing: Mesa leaves both buffers alone then.)
  if (selecting() || feeding_back() || !accum_buffer_ready()) return;
  const Box r = accum_region();
  if (r.width <= 0 || r.height <= 0) return;
  if (op == GL_RETURN) return accum_return(r, value);
  if (op == GL_ACCUM || op == GL_LOAD) run_frame();
  const bool has_alpha = !(format_ == GL_RGB || format_ == 0x4 /* OSMESA_BGR */);
  const float scale = value * kAccumOne;
  const int16_t step = accum_value(double(scale));
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const size_t at = size_t(y) * size_t(width_) + size_t(x);
      int16_t* a = &accum_[at * 4];
      const uint8_t* p = colour_rows() + at * 4;
      for (int k = 0; k < 4; ++k) {
        const float c = k == 3 && !has_alpha ? 1.0f : p[k] / 255.0f;
        switch (op) {
          case GL_ADD: a[k] = accum_value(double(a[k]) + step); break;
          case GL_MULT: a[k] = accum_value(double(float(a[k]) * value)); break;
          case GL_LOAD: a[k] = accum_value(double(c * scale)); break;
          default: a[k] = accum_value(double(a[k]) + std::trunc(double(c * scale))); break;  // GL_ACCUM
        }
      }
    }
}

// GL_RETURN: value times the buffer, clamped to [0, 1], to the colour buffer; runs of
// equal colours in a row go as one rectangle.
void Context::accum_return(const Box& r, float value) {
  std::vector<WindowRect> rects;
  const float scale = value / kAccumOne;
  auto colour = [&](size_t at) {
    const int16_t* a = &accum_[at * 4];
    auto c = [&](int k) { return std::clamp(float(a[k]) * scale, 0.0f, 1.0f); };
    return Vec4{c(0), c(1), c(2), c(3)};
  };
  for (int y = r.y; y < r.y + r.height; ++y) {
    const size_t row = size_t(y) * size_t(width_);
    for (int x = r.x; x < r.x + r.width;) {
      const Vec4 c = colour(row + size_t(x));
      int e = x + 1;
      while (e < r.x + r.width) {
        const Vec4 n = colour(row + size_t(e));
        if (n.x != c.x || n.y != c.y || n.z != c.z || n.w != c.w) break;
        ++e;
      }
      rects.push_back({float(x), float(y), float(e), float(y + 1), 0.0f, c});
      x = e;
    }
  }
  // The rectangles' fragments skip every per-fragment operation but the scissor test
  // and the colour mask (pixel_state reads accum_returning_).
  accum_returning_ = true;
  changed();
  draw_window_rects(rects);
  submit_pending();
  accum_returning_ = false;
  changed();
}

}  // namespace velocity::gl
