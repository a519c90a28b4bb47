// pGL's vertex stage for a run of vertices under the usual lighting — directional
// lights without spots, no local viewer, one side, a fixed material: the clip-space
// position and the lit, clamped colour of N vertices at a time (SIMD, the instruction
// set chosen at run time). The same floats as the scalar path (light_gl, then each
// component clamped to [0, 1]), operation for operation: gl_vertices.cpp is compiled
// without contracting a * b + c into one rounding.
#pragma once

#include <cstddef>

#include "shading/lighting.hpp"
#include "velocity/math.hpp"

namespace velocity::shading {

struct GlVertexRun {
  const Vec4* position = nullptr;  // object space
  const Vec3* normal = nullptr;    // object space, as glNormal gave it
  size_t count = 0;
  Mat4 mvp, normal_matrix;         // normal_matrix: the modelview's inverse transpose
  bool normalize = false;          // GL_NORMALIZE or GL_RESCALE_NORMAL
  const GlLight* lights = nullptr;  // directional, no spot (as light_gl reads them)
  int light_count = 0;
  Vec3 model_ambient;
  GlMaterial material;
  Vec4* clip = nullptr;   // out: count positions
  Vec4* color = nullptr;  // out: count colours
};

void gl_vertices(const GlVertexRun& run);

}  // namespace velocity::shading
