// User clip planes' state (glClipPlane, GL_CLIP_PLANE0..5): clip_planes.cpp. The
// planes are kept in eye space; the vertex stage gives each vertex its distance to the
// enabled ones, which the renderer's clipper cuts primitives by (PrimitiveBatch).
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "velocity/math.hpp"
#include "velocity/primitives.hpp"

namespace velocity::gl {

constexpr int kMaxClipPlanes = int(kMaxUserClipPlanes);

struct UserClipState {
  Vec4 planes[kMaxClipPlanes];  // eye space, (a, b, c, d): inside where a x + b y + c z + d w >= 0
  bool enabled[kMaxClipPlanes] = {false, false, false, false, false, false};
  // The enabled planes in order, and how many: what each vertex is measured against.
  Vec4 active[kMaxClipPlanes];
  uint32_t count = 0;
};

}  // namespace velocity::gl
