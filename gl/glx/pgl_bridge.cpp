// The two things the GLX side sets in pGL's current context. Kept apart from glx.cpp:
// Xlib's macros (None, Always, Success, ...) collide with the engine's names.
#include "pgl_bridge.h"

#include "../src/context.hpp"

void velocity_glx_set_double_buffered(bool double_buffered) {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->double_buffered = double_buffered;
}

void velocity_glx_gl_error(unsigned error) {
  if (velocity::gl::Context* gl = velocity::gl::current()) gl->error(error);
}
