// Texture coordinate generation's state (glTexGen, GL_TEXTURE_GEN_S..Q): tex_gen.cpp.
// Each of s, t, r and q has a mode, an object plane and an eye plane (kept in eye
// space, as GL 1.5 section 2.11.4 has glTexGen transform it by the inverse modelview).
#pragma once

#include <GL/gl.h>

#include "velocity/math.hpp"

namespace velocity::gl {

struct TexGenCoord {
  bool enabled = false;
  GLenum mode = GL_EYE_LINEAR;
  Vec4 object_plane, eye_plane;
};

struct TexGenState {
  // s, t, r, q. GL's initial planes: s (1 0 0 0), t (0 1 0 0), r and q zero.
  TexGenCoord coords[4] = {{false, GL_EYE_LINEAR, {1, 0, 0, 0}, {1, 0, 0, 0}},
                           {false, GL_EYE_LINEAR, {0, 1, 0, 0}, {0, 1, 0, 0}},
                           {false, GL_EYE_LINEAR, {0, 0, 0, 0}, {0, 0, 0, 0}},
                           {false, GL_EYE_LINEAR, {0, 0, 0, 0}, {0, 0, 0, 0}}};
  bool any() const { return coords[0].enabled || coords[1].enabled || coords[2].enabled || coords[3].enabled; }
};

}  // namespace velocity::gl
