// glPixelTransfer (GL 1.5 section 3.6.3): the scale and bias of each colour component
// and of depth, the index shift and offset, and GL_MAP_COLOR / GL_MAP_STENCIL. They
// apply where client pixels are unpacked — glDrawPixels (pixel_unpack.cpp),
// glTexImage2D and glTexSubImage2D (pixels.cpp) — before the clamp to [0, 1]; the
// tables glPixelMap gives (GL's default: one entry, 0) are looked up there with
// GL_MAP_COLOR (R_TO_R .. A_TO_A) and GL_MAP_STENCIL (S_TO_S). The I_TO_* and I_TO_I
// tables are kept and read back; no colour-index image uses them (no GL_COLOR_INDEX).
#include <algorithm>
#include <cmath>
#include <memory>

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

namespace {
// The table of a GL_PIXEL_MAP_* name, or -1.
int map_index(GLenum map) { return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A ? int(map - GL_PIXEL_MAP_I_TO_I) : -1; }
bool is_index_map(int m) { return m <= 1; }  // I_TO_I, S_TO_S: indices, not colours
}  // namespace

// Colour tables keep their values clamped to [0, 1], index tables theirs (in int's
// range), as Mesa stores them; NaN reads 0.
void Context::pixel_map(GLenum map, const std::vector<float>& values) {
  if (in_begin_error()) return;
  const int m = map_index(map);
  if (m < 0) return error(GL_INVALID_ENUM);
  const size_t n = values.size();
  if (n < 1 || n > size_t(kMaxPixelMap)) return error(GL_INVALID_VALUE);
  // The tables looked up by an index (I_TO_*, S_TO_S) have a power-of-two size.
  if (map <= GL_PIXEL_MAP_I_TO_A && (n & (n - 1)) != 0) return error(GL_INVALID_VALUE);
  auto maps = std::make_shared<PixelMaps>(*pixels.transfer.maps);
  std::vector<float>& t = maps->table[m];
  t.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float v = std::isnan(values[i]) ? 0.0f : values[i];
    t[i] = is_index_map(m) ? std::clamp(v, -2147483648.0f, 2147483520.0f) : std::clamp(v, 0.0f, 1.0f);
  }
  pixels.transfer.maps = std::move(maps);
}

// glGetPixelMap: the table as floats; *colour says whether its values are colours.
bool Context::get_pixel_map(GLenum map, std::vector<float>& out, bool* colour) {
  if (in_begin_error()) return false;
  const int m = map_index(map);
  if (m < 0) return error(GL_INVALID_ENUM), false;
  out = pixels.transfer.maps->table[m];
  *colour = !is_index_map(m);
  return true;
}

bool Context::get_pixel_transfer(GLenum pname, std::vector<double>& out) const {
  const PixelTransfer& t = pixels.transfer;
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE)
    return out = {double(t.maps->table[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size())}, true;
  switch (pname) {
    case GL_MAX_PIXEL_MAP_TABLE: out = {double(kMaxPixelMap)}; return true;
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
