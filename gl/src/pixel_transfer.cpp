// glPixelTransfer (GL 1.5 section 3.6.3): the scale and bias of each colour component
// and of depth, the index shift and offset, and GL_MAP_COLOR / GL_MAP_STENCIL. They
// apply where client pixels are unpacked — glDrawPixels (pixel_unpack.cpp),
// glTexImage2D and glTexSubImage2D (pixels.cpp) — before the clamp to [0, 1]. glPixelMap
// does not exist, so the maps are GL's defaults (one entry, 0): a map turned on maps
// every value to 0, as Mesa does with the same maps.
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

void Context::pixel_transfer(GLenum pname, double value) {
  if (in_begin_error()) return;
  PixelTransfer& t = pixels.transfer;
  const float v = std::isfinite(value) ? float(value) : 0.0f;
  // An index shift or offset as GL rounds an integer parameter given as a float.
  const GLint i = std::isfinite(value) ? GLint(std::clamp(std::round(value), -2147483648.0, 2147483647.0)) : 0;
  switch (pname) {
    case GL_RED_SCALE: t.scale[0] = v; break;
    case GL_GREEN_SCALE: t.scale[1] = v; break;
    case GL_BLUE_SCALE: t.scale[2] = v; break;
    case GL_ALPHA_SCALE: t.scale[3] = v; break;
    case GL_RED_BIAS: t.bias[0] = v; break;
    case GL_GREEN_BIAS: t.bias[1] = v; break;
    case GL_BLUE_BIAS: t.bias[2] = v; break;
    case GL_ALPHA_BIAS: t.bias[3] = v; break;
    case GL_DEPTH_SCALE: t.depth_scale = v; break;
    case GL_DEPTH_BIAS: t.depth_bias = v; break;
    case GL_MAP_COLOR: t.map_color = value != 0; break;
    case GL_MAP_STENCIL: t.map_stencil = value != 0; break;
    case GL_INDEX_SHIFT: t.index_shift = i; break;
    case GL_INDEX_OFFSET: t.index_offset = i; break;
    default: return error(GL_INVALID_ENUM);
  }
}

bool Context::get_pixel_transfer(GLenum pname, std::vector<double>& out) const {
  const PixelTransfer& t = pixels.transfer;
  switch (pname) {
    case GL_RED_SCALE: case GL_GREEN_SCALE: out = {t.scale[pname == GL_RED_SCALE ? 0 : 1]}; return true;
    case GL_BLUE_SCALE: out = {t.scale[2]}; return true;
    case GL_ALPHA_SCALE: out = {t.scale[3]}; return true;
    case GL_RED_BIAS: out = {t.bias[0]}; return true;
    case GL_GREEN_BIAS: out = {t.bias[1]}; return true;
    case GL_BLUE_BIAS: out = {t.bias[2]}; return true;
    case GL_ALPHA_BIAS: out = {t.bias[3]}; return true;
    case GL_DEPTH_SCALE: out = {t.depth_scale}; return true;
    case GL_DEPTH_BIAS: out = {t.depth_bias}; return true;
    case GL_MAP_COLOR: out = {t.map_color ? 1.0 : 0.0}; return true;
    case GL_MAP_STENCIL: out = {t.map_stencil ? 1.0 : 0.0}; return true;
    case GL_INDEX_SHIFT: out = {double(t.index_shift)}; return true;
    case GL_INDEX_OFFSET: out = {double(t.index_offset)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
