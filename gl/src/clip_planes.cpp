// User clip planes (GL 1.5 section 2.12): glClipPlane takes a plane in object space and
// keeps it in eye space (times the inverse of the modelview matrix then current);
// glEnable(GL_CLIP_PLANEi) makes the vertex stage measure every vertex against it, and
// the renderer's clipper keeps what is on its non-negative side.
#include "context.hpp"

namespace velocity::gl {

void Context::clip_plane(GLenum plane, const double* eq) {
  if (in_begin_error()) return;
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) return error(GL_INVALID_ENUM);
  // (a b c d) M^-1, a row vector times the inverse; a singular modelview keeps the
  // plane as given (Mesa's inverse falls back to the identity too).
  Mat4 inv;
  if (!invert(transform_.modelview.back(), inv)) inv = Mat4{};
  const float p[4] = {float(eq[0]), float(eq[1]), float(eq[2]), float(eq[3])};
  float e[4];
  for (int c = 0; c < 4; ++c) e[c] = p[0] * inv.m[0][c] + p[1] * inv.m[1][c] + p[2] * inv.m[2][c] + p[3] * inv.m[3][c];
  user_clip.planes[plane - GL_CLIP_PLANE0] = {e[0], e[1], e[2], e[3]};
  update_clip_planes();
}

bool Context::get_clip_plane(GLenum plane, double* eq) {
  if (in_begin_error()) return true;
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) return false;
  const Vec4& p = user_clip.planes[plane - GL_CLIP_PLANE0];
  eq[0] = p.x, eq[1] = p.y, eq[2] = p.z, eq[3] = p.w;
  return true;
}

bool Context::enable_clip_plane(GLenum cap, bool on) {
  if (cap < GL_CLIP_PLANE0 || cap >= GL_CLIP_PLANE0 + kMaxClipPlanes) return false;
  user_clip.enabled[cap - GL_CLIP_PLANE0] = on;
  update_clip_planes();
  return true;
}

void Context::update_clip_planes() {
  uint32_t n = 0;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    if (user_clip.enabled[i]) user_clip.active[n++] = user_clip.planes[i];
  // A batch carries its count of distances per vertex: a new count opens a new batch.
  // (A new plane does not: each vertex's distances are taken as it is drawn.)
  if (n != user_clip.count) changed();
  user_clip.count = n;
}

bool Context::outside_clip_planes(const Vec4& eye) const {
  for (uint32_t k = 0; k < user_clip.count; ++k) {
    const Vec4& p = user_clip.active[k];
    if (!(p.x * eye.x + p.y * eye.y + p.z * eye.z + p.w * eye.w >= 0)) return true;
  }
  return false;
}

}  // namespace velocity::gl
