// What the GLX side asks of pGL's current context. Kept apart from glx.cpp:
// Xlib's macros (None, Always, Success, ...) collide with the engine's names.
#include "pgl_bridge.h"

#include "../src/context.hpp"

void velocity_glx_set_double_buffered(bool double_buffered) {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->set_double_buffered(double_buffered);
}

void velocity_glx_set_samples_side(int k) {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->set_samples_side(k);
}

void velocity_glx_gl_error(unsigned error) {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->error(error);
}

void velocity_glx_swap_buffers() {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->swap_buffers();
}

bool velocity_glx_front(unsigned char* bgra, int width, int height) {
  velocity::gl::Context* gl = velocity::gl::current();
  if (!gl || !gl->window_draws_front() || gl->window_width() != width || gl->window_height() != height) return false;
  const unsigned char* rows = gl->front_rows();
  if (!rows) return false;
  // RGBA bottom row first to the XImage's BGRA top row first.
  for (int y = 0; y < height; ++y) {
    const unsigned char* src = rows + size_t(height - 1 - y) * size_t(width) * 4;
    unsigned char* dst = bgra + size_t(y) * size_t(width) * 4;
    for (int x = 0; x < width; ++x)
      dst[4 * x] = src[4 * x + 2], dst[4 * x + 1] = src[4 * x + 1], dst[4 * x + 2] = src[4 * x], dst[4 * x + 3] = src[4 * x + 3];
  }
  return true;
}
