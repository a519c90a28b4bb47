// Raster state: glEnable/glDisable, the per-fragment tests and operations (scissor,
// alpha test, depth, blend, masks, fog), glClear, and rasterization (culling, polygon
// mode and offset, point size, line width).
#include <algorithm>

#include "context.hpp"

namespace velocity::gl {

namespace {
bool is_blend_factor(GLenum f, bool /*source*/) {
  switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR:
      return true;
    case GL_SRC_ALPHA_SATURATE: return true;  // also as a destination factor (Mesa, GL 3.3)
    case GL_CONSTANT_COLOR: case GL_ONE_MINUS_CONSTANT_COLOR: case GL_CONSTANT_ALPHA:
    case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;  // GL 1.4's constant colour (glBlendColor, blend.cpp)
    default: return false;
  }
}

bool is_compare(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }
}  // namespace

void Context::enable(GLenum cap, bool on) {
  if (in_begin_error()) return;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return void(lighting_.lights[cap - GL_LIGHT0].enabled = on);
  if (enable_evaluator(cap, on)) return;  // (evaluators.cpp)
  if (enable_color_sum(cap, on)) return;  // (color_sum.cpp)
  if (enable_clip_plane(cap, on)) return;  // (clip_planes.cpp)
  if (enable_tex_gen(cap, on)) return;     // (tex_gen.cpp)
  switch (cap) {
    case GL_DEPTH_TEST: raster_.depth_test = on; break;
    case GL_CULL_FACE: raster_.cull = on; return;
    case GL_LIGHTING: lighting_.enabled = on; return;
    case GL_NORMALIZE: transform_.normalize = on; return;
    case GL_RESCALE_NORMAL: transform_.rescale_normal = on; return;
    case GL_COLOR_MATERIAL:
      lighting_.color_material = on;
      if (on) apply_color_material();
      return;
    case GL_TEXTURE_2D: texture_.enabled = on; break;
    case GL_TEXTURE_1D: texture_.enabled_1d = on; break;
    case GL_TEXTURE_3D: texture_.enabled_3d = on; break;
    case GL_BLEND: raster_.blend = on; break;
    case GL_COLOR_LOGIC_OP: raster_.logic_op = on; break;
    case GL_LINE_STIPPLE: raster_.line_stipple = on; return;
    case GL_POLYGON_STIPPLE: raster_.polygon_stipple = on; break;
    case GL_ALPHA_TEST: raster_.alpha_test = on; break;
    case GL_FOG: raster_.fog = on; break;
    case GL_SCISSOR_TEST: raster_.scissor_test = on; break;
    case GL_STENCIL_TEST: stencil_.test = on; break;
    // The vertex arrays' client state through glEnable, as Mesa's compatibility
    // profile (and old programs) allow.
    case GL_VERTEX_ARRAY: case GL_NORMAL_ARRAY: case GL_COLOR_ARRAY: case GL_TEXTURE_COORD_ARRAY:
    case GL_EDGE_FLAG_ARRAY:
      return client_state(cap, on);
    case GL_POLYGON_OFFSET_FILL: raster_.offset_fill = on; return;
    case GL_POLYGON_OFFSET_LINE: raster_.offset_line = on; return;
    case GL_POLYGON_OFFSET_POINT: raster_.offset_point = on; return;
    // Accepted and without effect on what is drawn here (aliased points and lines,
    // colour dithering of an 8-bit framebuffer):
    case GL_DITHER: return;
    default: return error(GL_INVALID_ENUM);
  }
  changed();
}

void Context::scissor(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  raster_.scissor = within_reach(x, y, w, h);
  changed();
}

void Context::clear(GLbitfield mask) {
  if (in_begin_error()) return;
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT))
    return error(GL_INVALID_VALUE);
  if (framebuffer_incomplete() || !renderer_) return;
  if (mask & GL_ACCUM_BUFFER_BIT) clear_accum_buffer();  // (the context's own: accum.cpp)
  submit_pending();
  const RasterState& r = raster_;
  const bool color = (mask & GL_COLOR_BUFFER_BIT) && drawn_ != 0, depth = (mask & GL_DEPTH_BUFFER_BIT) && depth_bits_ > 0;
  const bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && stencil_bits_ > 0;
  const bool all_channels = (r.color_mask_bits() & channel_mask_) == 0xf;
  const bool all_stencil = (stencil_.write_mask & 0xff) == 0xff;
  if (!in_frame_ && !r.scissor_test && (!color || all_channels) && (!depth || r.depth_write) && (!stencil || all_stencil) &&
      (color || depth || stencil)) {
    start_clear_ = true;  // the frame begins with it (ensure_frame)
    if (color) {
      start_clear_color_ = true;
      start_color_ = {unit(r.clear_color.x), unit(r.clear_color.y), unit(r.clear_color.z), unit(r.clear_color.w)};
    }
    if (depth) start_clear_depth_ = true, start_depth_ = r.clear_depth;
    if (stencil) start_clear_stencil_ = true, start_stencil_ = stencil_clear_value();
    return;
  }
  ensure_frame();
  ClearRequest q;
  q.color = color;
  q.depth = depth;
  q.color_value = {unit(r.clear_color.x), unit(r.clear_color.y), unit(r.clear_color.z), unit(r.clear_color.w)};
  q.depth_value = r.clear_depth;
  q.color_mask = raster_.color_mask_bits() & channel_mask_;
  q.depth_write = r.depth_write;
  q.stencil = stencil;
  q.stencil_value = stencil_clear_value();
  q.stencil_mask = uint8_t(stencil_.write_mask);
  q.scissor = r.scissor_test;
  if (r.scissor_test) sample_scissor(r.scissor, q.x0, q.y0, q.x1, q.y1);  // (multisample.cpp)
  if (q.color || q.depth || q.stencil) renderer_->clear(q);
  if (mirror_ && (q.color || q.depth || q.stencil)) mirror_->clear(q);  // GL_FRONT_AND_BACK (buffers.cpp)
}

void Context::clear_depth(double d) {
  if (in_begin_error()) return;
  raster_.clear_depth = unit(d);
}

void Context::depth_func(GLenum f) {
  if (in_begin_error()) return;
  if (!is_compare(f)) return error(GL_INVALID_ENUM);
  raster_.depth_func = f;
  changed();
}

void Context::depth_mask(bool on) {
  if (in_begin_error()) return;
  raster_.depth_write = on;
  changed();
}

void Context::color_mask(bool r, bool g, bool b, bool a) {
  if (in_begin_error()) return;
  raster_.color_mask[0] = r, raster_.color_mask[1] = g, raster_.color_mask[2] = b, raster_.color_mask[3] = a;
  changed();
}

void Context::blend_func(GLenum s, GLenum d) {
  if (in_begin_error()) return;
  if (!is_blend_factor(s, true) || !is_blend_factor(d, false)) return error(GL_INVALID_ENUM);
  raster_.blend_src = raster_.blend_src_alpha = s, raster_.blend_dst = raster_.blend_dst_alpha = d;
  changed();
}

void Context::alpha_func(GLenum f, float ref) {
  if (in_begin_error()) return;
  if (!is_compare(f)) return error(GL_INVALID_ENUM);
  raster_.alpha_func = f, raster_.alpha_ref = unit(ref);
  changed();
}

void Context::fog(GLenum pname, const float* v) {
  if (in_begin_error()) return;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum m = to_enum(v[0]);
      if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) return error(GL_INVALID_ENUM);
      raster_.fog_mode = m;
      break;
    }
    case GL_FOG_DENSITY:
      if (v[0] < 0) return error(GL_INVALID_VALUE);
      raster_.fog_density = v[0];
      break;
    case GL_FOG_START: raster_.fog_start = v[0]; break;
    case GL_FOG_END: raster_.fog_end = v[0]; break;
    case GL_FOG_COLOR: raster_.fog_color = {unit(v[0]), unit(v[1]), unit(v[2]), unit(v[3])}; break;
    case GL_FOG_INDEX: break;
    default:
      if (fog_coord_source(pname, v[0])) break;  // (color_sum.cpp)
      return error(GL_INVALID_ENUM);
  }
  changed();
}

void Context::hint(GLenum target, GLenum mode) {
  if (in_begin_error()) return;
  if (target < GL_PERSPECTIVE_CORRECTION_HINT || target > GL_FOG_HINT) return error(GL_INVALID_ENUM);
  if (mode != GL_DONT_CARE && mode != GL_FASTEST && mode != GL_NICEST) return error(GL_INVALID_ENUM);
  // Hints allow any quality: Velocity always interpolates perspective-correct and fogs
  // per pixel.
  raster_.hints[target - GL_PERSPECTIVE_CORRECTION_HINT] = mode;
}

void Context::cull_face(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_FRONT && m != GL_BACK && m != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  raster_.cull_mode = m;
}

void Context::front_face(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_CW && m != GL_CCW) return error(GL_INVALID_ENUM);
  raster_.front_face = m;
}

void Context::polygon_mode(GLenum face, GLenum mode) {
  if (in_begin_error()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return error(GL_INVALID_ENUM);
  if (face != GL_BACK) raster_.polygon_mode[0] = mode;
  if (face != GL_FRONT) raster_.polygon_mode[1] = mode;
}

void Context::polygon_offset(float factor, float units) {
  if (in_begin_error()) return;
  raster_.offset_factor = factor, raster_.offset_units = units;
  changed();
}

void Context::point_size(float s) {
  if (in_begin_error()) return;
  if (!(s > 0)) return error(GL_INVALID_VALUE);
  s = std::min(s, kMaxPointLineSize);
  if (s != raster_.point_size) changed();  // the open batch keeps the size it was drawn with
  raster_.point_size = s;
}

void Context::line_width(float w) {
  if (in_begin_error()) return;
  if (!(w > 0)) return error(GL_INVALID_VALUE);
  w = std::min(w, kMaxPointLineSize);
  if (w != raster_.line_width) changed();  // (as glPointSize)
  raster_.line_width = w;
}

}  // namespace velocity::gl
