// Texture coordinate generation (GL 1.5 section 2.11.4): glTexGen gives s, t, r and q
// each a mode and planes; glEnable(GL_TEXTURE_GEN_S..Q) makes the vertex stage replace
// that coordinate of the current one with the generated value, before the texture
// matrix. Modes: object linear (the plane times the object-space vertex), eye linear
// (the eye plane, kept in eye space, times the eye-space vertex), sphere map (the
// reflection of the eye vector about the normal, as GL's formula maps it to [0, 1]),
// and GL 1.3's normal map and reflection map (the normal's or the reflection's
// component).
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
int coord_index(GLenum coord) { return coord >= GL_S && coord <= GL_Q ? int(coord - GL_S) : -1; }

// The modes coordinate `i` (0 s .. 3 q) may take: sphere map only s and t, the two
// cube-map modes s, t and r.
bool valid_mode(int i, GLenum mode) {
  switch (mode) {
    case GL_OBJECT_LINEAR: case GL_EYE_LINEAR: return true;
    case GL_SPHERE_MAP: return i < 2;
    case GL_NORMAL_MAP: case GL_REFLECTION_MAP: return i < 3;
    default: return false;
  }
}

float plane_dot(const Vec4& p, const Vec4& v) { return p.x * v.x + p.y * v.y + p.z * v.z + p.w * v.w; }
}  // namespace

void Context::tex_gen(GLenum coord, GLenum pname, const double* params) {
  if (in_begin_error()) return;
  const int i = coord_index(coord);
  if (i < 0) return error(GL_INVALID_ENUM);
  TexGenCoord& g = tex_gen_.coords[i];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      // A mode given as a float names the enum only when it is one exactly.
      const double m = params[0];
      if (!(m >= 0 && m <= 65535) || m != std::floor(m) || !valid_mode(i, GLenum(m))) return error(GL_INVALID_ENUM);
      g.mode = GLenum(m);
      return;
    }
    case GL_OBJECT_PLANE:
      g.object_plane = {float(params[0]), float(params[1]), float(params[2]), float(params[3])};
      return;
    case GL_EYE_PLANE: {
      // (p1 p2 p3 p4) M^-1 with the modelview now current; a singular modelview keeps
      // the plane as given (as glClipPlane does).
      Mat4 inv;
      if (!invert(transform_.modelview.back(), inv)) inv = Mat4{};
      float e[4];
      for (int c = 0; c < 4; ++c)
        e[c] = float(params[0] * inv.m[0][c] + params[1] * inv.m[1][c] + params[2] * inv.m[2][c] + params[3] * inv.m[3][c]);
      g.eye_plane = {e[0], e[1], e[2], e[3]};
      return;
    }
    default: return error(GL_INVALID_ENUM);
  }
}

bool Context::get_tex_gen(GLenum coord, GLenum pname, double* out, int* count) {
  const int i = coord_index(coord);
  if (i < 0) return false;
  const TexGenCoord& g = tex_gen_.coords[i];
  const auto put = [&](const Vec4& p) { out[0] = p.x, out[1] = p.y, out[2] = p.z, out[3] = p.w, *count = 4; };
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: out[0] = double(g.mode), *count = 1; return true;
    case GL_OBJECT_PLANE: put(g.object_plane); return true;
    case GL_EYE_PLANE: put(g.eye_plane); return true;
    default: return false;
  }
}

bool Context::enable_tex_gen(GLenum cap, bool on) {
  if (cap < GL_TEXTURE_GEN_S || cap > GL_TEXTURE_GEN_Q) return false;
  tex_gen_.coords[cap - GL_TEXTURE_GEN_S].enabled = on;
  return true;
}

bool Context::tex_gen_needs_eye() const { return tex_gen_needs_eye(tex_gen_); }

bool Context::tex_gen_needs_eye(const TexGenState& state) {
  for (const TexGenCoord& g : state.coords)
    if (g.enabled && g.mode != GL_OBJECT_LINEAR) return true;
  return false;
}

// `state` and `current`: a texture unit's (multitexture.cpp keeps the other unit's).
Vec4 Context::generate_texcoord(const TexGenState& state, const Vec4& current, const Vec4& object, const Vec4& eye) const {
  float out[4] = {current.x, current.y, current.z, current.w};
  // The eye-space normal and the reflection, only when a mode needs them.
  bool have_normal = false;
  Vec3 n, r;
  for (int i = 0; i < 4; ++i) {
    const TexGenCoord& g = state.coords[i];
    if (!g.enabled) continue;
    if (g.mode == GL_OBJECT_LINEAR) {
      out[i] = plane_dot(g.object_plane, object);
      continue;
    }
    if (g.mode == GL_EYE_LINEAR) {
      out[i] = plane_dot(g.eye_plane, eye);
      continue;
    }
    if (!have_normal) {
      n = transform_.normal_matrix.transform_vector(normal_);
      if (transform_.normalize || transform_.rescale_normal) n = normalize(n);
      const Vec3 u = normalize(eye.xyz());
      r = u - n * (2 * dot(n, u));
      have_normal = true;
    }
    const float nv[3] = {n.x, n.y, n.z}, rv[3] = {r.x, r.y, r.z};
    if (g.mode == GL_NORMAL_MAP) out[i] = nv[i];
    else if (g.mode == GL_REFLECTION_MAP) out[i] = rv[i];
    else {  // GL_SPHERE_MAP: r / m + 1/2, m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2)
      const float m2 = r.x * r.x + r.y * r.y + (r.z + 1) * (r.z + 1);
      const float inv_m = m2 > 0 ? 0.5f / std::sqrt(m2) : 0;
      out[i] = rv[i] * inv_m + 0.5f;
    }
  }
  return {out[0], out[1], out[2], out[3]};
}

}  // namespace velocity::gl
