// GL 1.4's blending beyond glBlendFunc (raster_state.cpp): separate alpha factors
// (glBlendFuncSeparate), the equation (glBlendEquation: add, subtract, reverse
// subtract, min, max) and the constant colour (glBlendColor) the CONSTANT factors read.
// The renderer blends with them (PixelState's blend_*). Also GL 1.1's logic op
// (glLogicOp, GL_COLOR_LOGIC_OP), which takes blending's place when enabled.
#include "context.hpp"

namespace velocity::gl {

namespace {
bool is_factor(GLenum f) {
  switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR: case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA: case GL_SRC_ALPHA_SATURATE: case GL_CONSTANT_COLOR:
    case GL_ONE_MINUS_CONSTANT_COLOR: case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;
    default: return false;
  }
}
}  // namespace

void Context::blend_func_separate(GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha) {
  if (in_begin_error()) return;
  if (!is_factor(src_rgb) || !is_factor(dst_rgb) || !is_factor(src_alpha) || !is_factor(dst_alpha))
    return error(GL_INVALID_ENUM);
  RasterState& r = raster_;
  r.blend_src = src_rgb, r.blend_dst = dst_rgb, r.blend_src_alpha = src_alpha, r.blend_dst_alpha = dst_alpha;
  changed();
}

void Context::blend_equation(GLenum mode) {
  if (in_begin_error()) return;
  switch (mode) {
    case GL_FUNC_ADD: case GL_FUNC_SUBTRACT: case GL_FUNC_REVERSE_SUBTRACT: case GL_MIN: case GL_MAX: break;
    default: return error(GL_INVALID_ENUM);
  }
  raster_.blend_equation = mode;
  changed();
}

void Context::blend_color(Vec4 c) {
  if (in_begin_error()) return;
  raster_.blend_color = {unit(c.x), unit(c.y), unit(c.z), unit(c.w)};  // clamped, as GL 1.4's
  changed();
}

void Context::logic_op(GLenum op) {
  if (in_begin_error()) return;
  if (op < GL_CLEAR || op > GL_SET) return error(GL_INVALID_ENUM);
  raster_.logic_op_mode = op;
  changed();
}

bool Context::get_blend(GLenum pname, std::vector<double>& out, int& kind) const {
  const RasterState& r = raster_;
  switch (pname) {
    case GL_BLEND_SRC: case GL_BLEND_SRC_RGB: out = {double(r.blend_src)}; return true;
    case GL_BLEND_DST: case GL_BLEND_DST_RGB: out = {double(r.blend_dst)}; return true;
    case GL_BLEND_SRC_ALPHA: out = {double(r.blend_src_alpha)}; return true;
    case GL_BLEND_DST_ALPHA: out = {double(r.blend_dst_alpha)}; return true;
    case GL_BLEND_EQUATION: out = {double(r.blend_equation)}; return true;
    case GL_LOGIC_OP_MODE: out = {double(r.logic_op_mode)}; return true;
    case GL_BLEND_COLOR: out = {r.blend_color.x, r.blend_color.y, r.blend_color.z, r.blend_color.w}, kind = 1; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
