// GL 1.2's separate specular colour and GL 1.4's colour sum and fog coordinates: the
// state (GL_COLOR_SUM, GL_LIGHT_MODEL_COLOR_CONTROL, GL_FOG_COORD_SRC, the current
// secondary colour and fog coordinate, their arrays), its queries and attribute groups.
// The vertex stage (vertex.cpp) gives each vertex a secondary colour while the sum
// applies — lighting's specular part with GL_SEPARATE_SPECULAR_COLOR, else the current
// secondary colour (black when lit) — and the renderer's fixed-function kernel adds it
// after the texture environments (PixelState::color_sum).
#include "context.hpp"

namespace velocity::gl {

bool Context::enable_color_sum(GLenum cap, bool on) {
  if (cap != GL_COLOR_SUM) return false;
  color_sum_.enabled = on;
  changed();
  return true;
}

bool Context::light_model_color_control(GLenum pname, float v) {
  if (pname != GL_LIGHT_MODEL_COLOR_CONTROL) return false;
  const GLenum m = to_enum(v);
  if (m != GL_SINGLE_COLOR && m != GL_SEPARATE_SPECULAR_COLOR) {
    error(GL_INVALID_ENUM);
    return true;
  }
  color_sum_.separate_specular = m == GL_SEPARATE_SPECULAR_COLOR;
  changed();
  return true;
}

bool Context::fog_coord_source(GLenum pname, float v) {
  if (pname != GL_FOG_COORD_SRC) return false;
  const GLenum m = to_enum(v);
  if (m != GL_FOG_COORD && m != GL_FRAGMENT_DEPTH) {
    error(GL_INVALID_ENUM);
    return true;
  }
  color_sum_.fog_coord_src = m;
  return true;
}

bool Context::color_sum_client_state(GLenum cap, bool on) {
  switch (cap) {
    case GL_SECONDARY_COLOR_ARRAY: arrays.secondary_color.enabled = on; return true;
    case GL_FOG_COORD_ARRAY: arrays.fog_coord.enabled = on; return true;
    case GL_INDEX_ARRAY: arrays.index.enabled = on; return true;
    default: return false;
  }
}

bool Context::color_sum_enabled(GLenum cap, bool* known) const {
  *known = true;
  switch (cap) {
    case GL_COLOR_SUM: return color_sum_.enabled;
    case GL_SECONDARY_COLOR_ARRAY: return arrays.secondary_color.enabled;
    case GL_FOG_COORD_ARRAY: return arrays.fog_coord.enabled;
    case GL_INDEX_ARRAY: return arrays.index.enabled;
    default: *known = false; return false;
  }
}

bool Context::get_color_sum(GLenum pname, std::vector<double>& out, int& kind) const {
  switch (pname) {
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      out = {double(color_sum_.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR)};
      return true;
    case GL_CURRENT_SECONDARY_COLOR:
      out = {secondary_.x, secondary_.y, secondary_.z, secondary_.w};
      kind = 1;  // a colour
      return true;
    case GL_FOG_COORD_SRC: out = {double(color_sum_.fog_coord_src)}; return true;
    case GL_CURRENT_FOG_COORD: out = {fog_coord_}; return true;
    case GL_SECONDARY_COLOR_ARRAY_SIZE: out = {double(arrays.secondary_color.size)}; return true;
    case GL_SECONDARY_COLOR_ARRAY_TYPE: out = {double(arrays.secondary_color.type)}; return true;
    case GL_SECONDARY_COLOR_ARRAY_STRIDE: out = {double(arrays.secondary_color.stride)}; return true;
    case GL_FOG_COORD_ARRAY_TYPE: out = {double(arrays.fog_coord.type)}; return true;
    case GL_FOG_COORD_ARRAY_STRIDE: out = {double(arrays.fog_coord.stride)}; return true;
    case GL_INDEX_ARRAY_TYPE: out = {double(arrays.index.type)}; return true;
    case GL_INDEX_ARRAY_STRIDE: out = {double(arrays.index.stride)}; return true;
    default: return false;
  }
}

// GL 1.5's tables 6.5-6.35: the current secondary colour and fog coordinate are in
// GL_CURRENT_BIT, GL_COLOR_SUM in GL_FOG_BIT and GL_ENABLE_BIT, the fog coordinate's
// source in GL_FOG_BIT, the light model's colour control in GL_LIGHTING_BIT.
void Context::save_color_sum(AttribFrame& f) const {
  f.color_sum = color_sum_;
  f.secondary = secondary_, f.fog_coord = fog_coord_;
}

void Context::restore_color_sum(const AttribFrame& f) {
  const GLbitfield m = f.mask;
  if (m & GL_CURRENT_BIT) secondary_ = f.secondary, fog_coord_ = f.fog_coord;
  if (m & (GL_FOG_BIT | GL_ENABLE_BIT)) color_sum_.enabled = f.color_sum.enabled;
  if (m & GL_FOG_BIT) color_sum_.fog_coord_src = f.color_sum.fog_coord_src;
  if (m & GL_LIGHTING_BIT) color_sum_.separate_specular = f.color_sum.separate_specular;
}

}  // namespace velocity::gl
