// GL 1.3's GL_COMBINE texture environment (ARB_texture_env_combine and _dot3): the
// glTexEnv parameters of GL 1.5 section 3.8.13, kept per texture unit as the
// renderer's TexCombine (TextureState::combine, multitexture.cpp's TextureUnitState);
// and the queries of the texture environment and parameters, glGetTexEnv and
// glGetTexParameter, with their C entry points.
#include <GL/gl.h>

#include "api_entry.hpp"
#include "context.hpp"

namespace velocity::gl {
namespace {

// GL_COMBINE_RGB's and GL_COMBINE_ALPHA's values, in CombineOp's order.
constexpr GLenum kCombineOps[] = {GL_REPLACE,  GL_MODULATE, GL_ADD,      GL_ADD_SIGNED,
                                  GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
constexpr GLenum kSources[] = {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS};  // CombineSource's
constexpr GLenum kOperands[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};

// The index of `e` in `names`, or -1.
template <size_t N>
int index_of(const GLenum (&names)[N], GLenum e) {
  for (size_t i = 0; i < N; ++i)
    if (names[i] == e) return int(i);
  return -1;
}

}  // namespace

bool Context::tex_env_combine(GLenum pname, const float* v) {
  TexCombine& k = texture_.combine;
  const GLenum e = to_enum(v[0]);
  switch (pname) {
    case GL_COMBINE_RGB:
    case GL_COMBINE_ALPHA: {
      const int op = index_of(kCombineOps, e);
      // The dot products make RGB (and alpha with DOT3_RGBA): not an alpha function.
      if (op < 0 || (pname == GL_COMBINE_ALPHA && op >= int(CombineOp::Dot3Rgb))) break;
      (pname == GL_COMBINE_RGB ? k.rgb : k.alpha) = CombineOp(op);
      return changed(), true;
    }
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB:
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA: {
      const int s = index_of(kSources, e);
      if (s < 0) break;
      const bool rgb = pname <= GL_SOURCE2_RGB;
      (rgb ? k.source_rgb : k.source_alpha)[pname - (rgb ? GL_SOURCE0_RGB : GL_SOURCE0_ALPHA)] = CombineSource(s);
      return changed(), true;
    }
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA: {
      const int o = index_of(kOperands, e);
      const bool rgb = pname <= GL_OPERAND2_RGB;
      if (o < 0 || (!rgb && o < int(CombineOperand::SrcAlpha))) break;  // alpha: the alpha two
      (rgb ? k.operand_rgb : k.operand_alpha)[pname - (rgb ? GL_OPERAND0_RGB : GL_OPERAND0_ALPHA)] = CombineOperand(o);
      return changed(), true;
    }
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE:
      if (v[0] != 1 && v[0] != 2 && v[0] != 4) return error(GL_INVALID_VALUE), true;
      (pname == GL_RGB_SCALE ? k.rgb_scale : k.alpha_scale) = v[0];
      return changed(), true;
    default: return false;
  }
  return error(GL_INVALID_ENUM), true;  // a known parameter with a value it does not take
}

int Context::get_tex_env(GLenum target, GLenum pname, float* out, bool* normalized) {
  *normalized = false;
  if (in_begin_error()) return 0;
  if (target == GL_TEXTURE_FILTER_CONTROL) {
    if (pname != GL_TEXTURE_LOD_BIAS) return error(GL_INVALID_ENUM), 0;
    out[0] = texture_.lod_bias;
    return 1;
  }
  if (target != GL_TEXTURE_ENV) return error(GL_INVALID_ENUM), 0;
  const TexCombine& k = texture_.combine;
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: out[0] = float(texture_.env_mode); return 1;
    case GL_TEXTURE_ENV_COLOR: {
      const Vec4& c = texture_.env_color;
      out[0] = c.x, out[1] = c.y, out[2] = c.z, out[3] = c.w;
      *normalized = true;
      return 4;
    }
    case GL_COMBINE_RGB: out[0] = float(kCombineOps[int(k.rgb)]); return 1;
    case GL_COMBINE_ALPHA: out[0] = float(kCombineOps[int(k.alpha)]); return 1;
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB:
      out[0] = float(kSources[int(k.source_rgb[pname - GL_SOURCE0_RGB])]);
      return 1;
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA:
      out[0] = float(kSources[int(k.source_alpha[pname - GL_SOURCE0_ALPHA])]);
      return 1;
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
      out[0] = float(kOperands[int(k.operand_rgb[pname - GL_OPERAND0_RGB])]);
      return 1;
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
      out[0] = float(kOperands[int(k.operand_alpha[pname - GL_OPERAND0_ALPHA])]);
      return 1;
    case GL_RGB_SCALE: out[0] = k.rgb_scale; return 1;
    case GL_ALPHA_SCALE: out[0] = k.alpha_scale; return 1;
    default: return error(GL_INVALID_ENUM), 0;
  }
}

int Context::get_tex_parameter(GLenum target, GLenum pname, float* out, bool* normalized) {
  *normalized = false;
  if (in_begin_error()) return 0;
  const TextureObject* tp = target_texture(target);  // (GL_INVALID_ENUM but for 1-D, 2-D, 3-D)
  if (!tp) return 0;
  const TextureObject& t = *tp;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: out[0] = float(t.min_filter); return 1;
    case GL_TEXTURE_MAG_FILTER: out[0] = float(t.mag_filter); return 1;
    case GL_TEXTURE_WRAP_S: out[0] = float(t.wrap_s); return 1;
    case GL_TEXTURE_WRAP_T: out[0] = float(t.wrap_t); return 1;
    case GL_TEXTURE_WRAP_R: out[0] = float(t.wrap_r); return 1;
    case GL_TEXTURE_BORDER_COLOR:
      out[0] = t.border.x, out[1] = t.border.y, out[2] = t.border.z, out[3] = t.border.w;
      *normalized = true;
      return 4;
    // pGL has no glPrioritizeTextures and keeps every texture in memory: each has GL's
    // initial priority, 1, and is resident.
    case GL_TEXTURE_PRIORITY: out[0] = 1, *normalized = true; return 1;
    case GL_TEXTURE_RESIDENT: out[0] = 1; return 1;
    case GL_TEXTURE_MIN_LOD: out[0] = t.min_lod; return 1;
    case GL_TEXTURE_MAX_LOD: out[0] = t.max_lod; return 1;
    case GL_TEXTURE_LOD_BIAS: out[0] = t.lod_bias; return 1;
    case GL_TEXTURE_BASE_LEVEL: out[0] = float(t.base_level); return 1;
    case GL_TEXTURE_MAX_LEVEL: out[0] = float(t.max_level); return 1;
    case GL_GENERATE_MIPMAP: out[0] = t.generate_mipmap ? 1.0f : 0.0f; return 1;
    default: return error(GL_INVALID_ENUM), 0;
  }
}

}  // namespace velocity::gl

namespace {

using velocity::gl::Context;

// glGet*iv's conversions: enums and counts as they are, colours (and the priority)
// from [0, 1] to [0, 2^31 - 1], other reals rounded to the nearest integer.
void to_ints(const float* v, int n, bool normalized, GLint* out) {
  for (int i = 0; i < n; ++i)
    out[i] = normalized ? GLint(double(v[i]) * 2147483647.0) : GLint(v[i] >= 0 ? double(v[i]) + 0.5 : double(v[i]) - 0.5);
}

}  // namespace

void glGetTexEnvfv(GLenum target, GLenum pname, GLfloat* params) {
  NOW(float v[4]; bool norm; const int n = c.get_tex_env(target, pname, v, &norm);
      if (params) for (int i = 0; i < n; ++i) params[i] = v[i]);
}
void glGetTexEnviv(GLenum target, GLenum pname, GLint* params) {
  NOW(float v[4]; bool norm; const int n = c.get_tex_env(target, pname, v, &norm); if (params) to_ints(v, n, norm, params));
}
void glGetTexParameterfv(GLenum target, GLenum pname, GLfloat* params) {
  NOW(float v[4]; bool norm; const int n = c.get_tex_parameter(target, pname, v, &norm);
      if (params) for (int i = 0; i < n; ++i) params[i] = v[i]);
}
void glGetTexParameteriv(GLenum target, GLenum pname, GLint* params) {
  NOW(float v[4]; bool norm; const int n = c.get_tex_parameter(target, pname, v, &norm);
      if (params) to_ints(v, n, norm, params));
}
