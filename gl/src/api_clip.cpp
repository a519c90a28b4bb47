// The C entry points of user clip planes (clip_planes.cpp): glClipPlane (compiled into
// display lists), glGetClipPlane. glEnable(GL_CLIP_PLANEi) goes through glEnable.
#include <GL/gl.h>

#include <array>

#include "api_entry.hpp"
#include "context.hpp"

extern "C" {

void glClipPlane(GLenum plane, const GLdouble* equation) {
  if (!equation) return NOW(c.error(GL_INVALID_VALUE));
  const std::array<double, 4> eq = {equation[0], equation[1], equation[2], equation[3]};
  LIST(c.clip_plane(plane, eq.data()));
}

void glGetClipPlane(GLenum plane, GLdouble* equation) {
  NOW(double eq[4]; if (!c.get_clip_plane(plane, eq)) return c.error(GL_INVALID_ENUM);
      if (equation) for (int i = 0; i < 4; ++i) equation[i] = eq[i]);
}

}  // extern "C"
