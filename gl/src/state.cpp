// Display lists, glGet and glReadPixels.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

// --- display lists --------------------------------------------------------------

GLuint Context::gen_lists(GLsizei range) {
  if (in_begin_error()) return 0;
  if (range < 0) return error(GL_INVALID_VALUE), 0;
  if (range == 0) return 0;
  if (lists_.size() + size_t(range) > (size_t(1) << 20)) return error(GL_OUT_OF_MEMORY), 0;
  // The first run of `range` unused names after the largest one in use.
  const GLuint first = lists_.empty() ? 1 : lists_.rbegin()->first + 1;
  if (first == 0 || uint64_t(first) + uint64_t(range) > 0xffffffffull) return error(GL_OUT_OF_MEMORY), 0;
  for (GLsizei i = 0; i < range; ++i) lists_[first + GLuint(i)];
  return first;
}

void Context::new_list(GLuint list, GLenum mode) {
  if (in_begin_error()) return;
  if (list == 0) return error(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return error(GL_INVALID_ENUM);
  if (compiling_) return error(GL_INVALID_OPERATION);
  compiling_ = list;
  compile_mode_ = mode;
  compiling_commands_.clear();
  list_overflow_ = false;
}

void Context::end_list() {
  if (in_begin_error()) return;
  if (!compiling_) return error(GL_INVALID_OPERATION);
  if (list_overflow_) {
    error(GL_OUT_OF_MEMORY);
    compiling_commands_.clear();
  }
  if (lists_.size() < (size_t(1) << 20) || lists_.count(compiling_)) lists_[compiling_] = std::move(compiling_commands_);
  compiling_commands_ = {};
  compiling_ = 0;
}

void Context::record(ListCommand cmd) {
  if (list_overflow_) return;
  if (compiling_commands_.size() >= kMaxListCommands) {
    list_overflow_ = true;
    return;
  }
  compiling_commands_.push_back(std::move(cmd));
}

void Context::call_list(GLuint list) { execute_list(list, 0); }

void Context::execute_list(GLuint list, int) {
  if (list_depth_ >= kMaxListNesting) return;  // GL: deeper calls are ignored
  auto it = lists_.find(list);
  if (it == lists_.end()) return;
  if (list_depth_ == 0) list_budget_ = kMaxListCallCommands;
  ++list_depth_;
  // The commands of a list cannot change lists (glNewList, glDeleteLists are never
  // compiled), so the vector stays put while it runs.
  for (const ListCommand& c : it->second) {
    if (list_budget_ == 0) break;
    if (--list_budget_ == 0) error(GL_OUT_OF_MEMORY);
    c(*this);
  }
  --list_depth_;
}

void Context::delete_lists(GLuint list, GLsizei range) {
  if (in_begin_error()) return;
  if (range < 0) return error(GL_INVALID_VALUE);
  if (list_depth_ > 0) return;
  for (GLsizei i = 0; i < range; ++i) {
    const uint64_t id = uint64_t(list) + uint64_t(i);
    if (id > 0xffffffffull) break;
    lists_.erase(GLuint(id));
  }
}

// --- glGet ----------------------------------------------------------------------

bool Context::get(GLenum pname, std::vector<double>& out, int& kind) {
  kind = 0;
  out.clear();
  auto v4 = [&](Vec4 c) { out = {c.x, c.y, c.z, c.w}; };
  auto matrix_out = [&](const M4& m) { out.assign(m.m, m.m + 16); };
  bool known = false;
  const bool enabled = is_enabled(pname, &known);
  if (known) return out = {enabled ? 1.0 : 0.0}, true;
  switch (pname) {
    case GL_MATRIX_MODE: out = {double(matrix_mode_)}; return true;
    case GL_MODELVIEW_MATRIX: matrix_out(modelview_.back()); return true;
    case GL_PROJECTION_MATRIX: matrix_out(projection_.back()); return true;
    case GL_TEXTURE_MATRIX: matrix_out(texture_matrix_.back()); return true;
    case GL_MODELVIEW_STACK_DEPTH: out = {double(modelview_.size())}; return true;
    case GL_PROJECTION_STACK_DEPTH: out = {double(projection_.size())}; return true;
    case GL_TEXTURE_STACK_DEPTH: out = {double(texture_matrix_.size())}; return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out = {double(kMaxModelviewDepth)}; return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out = {double(kMaxProjectionDepth)}; return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: out = {double(kMaxTextureDepth)}; return true;
    case GL_MAX_LIGHTS: out = {double(kMaxLights)}; return true;
    case GL_MAX_TEXTURE_SIZE: out = {double(kMaxTextureSize)}; return true;
    case GL_MAX_LIST_NESTING: out = {double(kMaxListNesting)}; return true;
    case GL_MAX_VIEWPORT_DIMS: out = {double(kMaxViewport), double(kMaxViewport)}; return true;
    case GL_VIEWPORT: out = {double(vp_x_), double(vp_y_), double(vp_w_), double(vp_h_)}; return true;
    case GL_DEPTH_RANGE: out = {depth_near_, depth_far_}; return true;
    case GL_SCISSOR_BOX: out = {double(sc_x_), double(sc_y_), double(sc_w_), double(sc_h_)}; return true;
    case GL_COLOR_CLEAR_VALUE: v4(clear_color_), kind = 1; return true;
    case GL_DEPTH_CLEAR_VALUE: out = {clear_depth_}, kind = 1; return true;
    case GL_DEPTH_FUNC: out = {double(depth_func_)}; return true;
    case GL_DEPTH_WRITEMASK: out = {depth_write_ ? 1.0 : 0.0}; return true;
    case GL_COLOR_WRITEMASK: out = {double(mask_[0]), double(mask_[1]), double(mask_[2]), double(mask_[3])}; return true;
    case GL_BLEND_SRC: out = {double(blend_src_)}; return true;
    case GL_BLEND_DST: out = {double(blend_dst_)}; return true;
    case GL_ALPHA_TEST_FUNC: out = {double(alpha_func_)}; return true;
    case GL_ALPHA_TEST_REF: out = {alpha_ref_}, kind = 1; return true;
    case GL_FOG_MODE: out = {double(fog_mode_)}; return true;
    case GL_FOG_DENSITY: out = {fog_density_}; return true;
    case GL_FOG_START: out = {fog_start_}; return true;
    case GL_FOG_END: out = {fog_end_}; return true;
    case GL_FOG_COLOR: v4(fog_color_), kind = 1; return true;
    case GL_CULL_FACE_MODE: out = {double(cull_mode_)}; return true;
    case GL_FRONT_FACE: out = {double(front_face_)}; return true;
    case GL_POLYGON_MODE: out = {double(polygon_mode_[0]), double(polygon_mode_[1])}; return true;
    case GL_POLYGON_OFFSET_FACTOR: out = {offset_factor_}; return true;
    case GL_POLYGON_OFFSET_UNITS: out = {offset_units_}; return true;
    case GL_POINT_SIZE: out = {point_size_}; return true;
    case GL_LINE_WIDTH: out = {line_width_}; return true;
    case GL_SHADE_MODEL: out = {double(shade_model_)}; return true;
    case GL_LIGHT_MODEL_AMBIENT: v4(model_ambient_), kind = 1; return true;
    case GL_LIGHT_MODEL_TWO_SIDE: out = {two_side_ ? 1.0 : 0.0}; return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: out = {local_viewer_ ? 1.0 : 0.0}; return true;
    case GL_COLOR_MATERIAL_FACE: out = {double(color_material_face_)}; return true;
    case GL_COLOR_MATERIAL_PARAMETER: out = {double(color_material_mode_)}; return true;
    case GL_CURRENT_COLOR: v4(color_), kind = 1; return true;
    case GL_CURRENT_NORMAL: out = {normal_.x, normal_.y, normal_.z}; return true;
    case GL_CURRENT_TEXTURE_COORDS: v4(texcoord_); return true;
    case GL_TEXTURE_BINDING_2D: out = {double(bound_)}; return true;
    case GL_LIST_BASE: out = {double(list_base)}; return true;
    case GL_LIST_INDEX: out = {double(compiling_)}; return true;
    case GL_LIST_MODE: out = {compiling_ ? double(compile_mode_) : 0.0}; return true;
    case GL_UNPACK_ALIGNMENT: out = {double(unpack_alignment)}; return true;
    case GL_PACK_ALIGNMENT: out = {double(pack_alignment)}; return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: out = {8}; return true;
    case GL_ALPHA_BITS: out = {format_ == GL_RGB || format_ == 0x4 ? 0.0 : 8.0}; return true;
    case GL_DEPTH_BITS: out = {depth_bits_ > 0 ? 24.0 : 0.0}; return true;
    case GL_PERSPECTIVE_CORRECTION_HINT: case GL_POINT_SMOOTH_HINT: case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT: case GL_FOG_HINT:
      out = {double(hints_[pname - GL_PERSPECTIVE_CORRECTION_HINT])};
      return true;
    case GL_VERTEX_ARRAY_SIZE: out = {double(vertex_array.size)}; return true;
    case GL_VERTEX_ARRAY_TYPE: out = {double(vertex_array.type)}; return true;
    case GL_VERTEX_ARRAY_STRIDE: out = {double(vertex_array.stride)}; return true;
    case GL_NORMAL_ARRAY_TYPE: out = {double(normal_array.type)}; return true;
    case GL_NORMAL_ARRAY_STRIDE: out = {double(normal_array.stride)}; return true;
    case GL_COLOR_ARRAY_SIZE: out = {double(color_array.size)}; return true;
    case GL_COLOR_ARRAY_TYPE: out = {double(color_array.type)}; return true;
    case GL_COLOR_ARRAY_STRIDE: out = {double(color_array.stride)}; return true;
    case GL_TEXTURE_COORD_ARRAY_SIZE: out = {double(texcoord_array.size)}; return true;
    case GL_TEXTURE_COORD_ARRAY_TYPE: out = {double(texcoord_array.type)}; return true;
    case GL_TEXTURE_COORD_ARRAY_STRIDE: out = {double(texcoord_array.stride)}; return true;
    default: return false;
  }
}

// --- glReadPixels ---------------------------------------------------------------

void Context::read_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  int comps;
  switch (format) {
    case GL_RGBA: case GL_BGRA: comps = 4; break;
    case GL_RGB: case GL_BGR: comps = 3; break;
    case GL_ALPHA: case GL_LUMINANCE: case 0x1903: /* GL_RED */ case 0x1904: /* GL_GREEN */
    case 0x1905: /* GL_BLUE */ case GL_DEPTH_COMPONENT:
      comps = 1;
      break;
    default: return error(GL_INVALID_ENUM);
  }
  size_t tsize;
  switch (type) {
    case GL_UNSIGNED_BYTE: tsize = 1; break;
    case GL_FLOAT: case GL_UNSIGNED_INT: tsize = 4; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (in_begin_error()) return;
  if (!renderer_ || !pixels || w == 0 || h == 0) return;
  run_frame();
  const bool depth = format == GL_DEPTH_COMPONENT;
  if (depth && depth_bits_ <= 0) return error(GL_INVALID_OPERATION);
  std::vector<float> zbuf;
  if (depth) zbuf = renderer_->window_depth();
  const size_t align = size_t(std::max(pack_alignment, 1));
  const size_t row_bytes = (size_t(w) * comps * tsize + align - 1) / align * align;
  uint8_t* out = static_cast<uint8_t*>(pixels);
  for (GLsizei j = 0; j < h; ++j) {
    const int64_t wy = int64_t(y) + j;
    if (wy < 0 || wy >= height_) continue;
    const size_t row = size_t(wy);  // the framebuffer is bottom row first
    for (GLsizei i = 0; i < w; ++i) {
      const int64_t wx = int64_t(x) + i;
      if (wx < 0 || wx >= width_) continue;
      const size_t at = row * size_t(width_) + size_t(wx);
      float c[4];
      if (depth) {
        c[0] = zbuf[at];
      } else {
        const uint8_t* p = colour_rows() + at * 4;
        const float r = p[0] / 255.0f, g = p[1] / 255.0f, b = p[2] / 255.0f;
        const float a = format_ == GL_RGB || format_ == 0x4 ? 1.0f : p[3] / 255.0f;
        switch (format) {
          case GL_RGBA: c[0] = r, c[1] = g, c[2] = b, c[3] = a; break;
          case GL_BGRA: c[0] = b, c[1] = g, c[2] = r, c[3] = a; break;
          case GL_RGB: c[0] = r, c[1] = g, c[2] = b; break;
          case GL_BGR: c[0] = b, c[1] = g, c[2] = r; break;
          case GL_ALPHA: c[0] = a; break;
          case GL_LUMINANCE: c[0] = std::min(1.0f, r + g + b); break;
          case 0x1903: c[0] = r; break;
          case 0x1904: c[0] = g; break;
          default: c[0] = b; break;
        }
      }
      uint8_t* dst = out + size_t(j) * row_bytes + size_t(i) * comps * tsize;
      for (int k = 0; k < comps; ++k) {
        if (type == GL_UNSIGNED_BYTE) {
          dst[k] = uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
        } else if (type == GL_FLOAT) {
          std::memcpy(dst + 4 * k, &c[k], 4);
        } else {
          const uint32_t u = uint32_t(std::llround(double(std::clamp(c[k], 0.0f, 1.0f)) * 4294967295.0));
          std::memcpy(dst + 4 * k, &u, 4);
        }
      }
    }
  }
}

}  // namespace velocity::gl
