// glPushAttrib / glPopAttrib and glPushClientAttrib / glPopClientAttrib: the groups of
// state GL 1.5's tables 6.5-6.35 name, saved and restored group by group. A group
// restores exactly its own fields (GL_ENABLE_BIT the enables, GL_DEPTH_BUFFER_BIT the
// depth test, function, mask and clear value, ...), whatever else the frame saved.
#include <algorithm>
#include <iterator>

#include "context.hpp"

namespace velocity::gl {

void Context::push_attrib(GLbitfield mask) {
  if (in_begin_error()) return;
  if (attrib_stack_.size() >= size_t(kMaxAttribDepth)) return error(GL_STACK_OVERFLOW);
  AttribFrame f;
  f.mask = mask;
  save_units(f);  // (multitexture.cpp: unit 0 live from here)
  f.raster = raster_;
  f.lighting = lighting_;
  f.stencil = stencil_;
  f.accum_clear = accum_clear_;
  f.viewport = transform_.viewport;
  f.depth_near = transform_.depth_near, f.depth_far = transform_.depth_far;
  f.matrix_mode = transform_.matrix_mode;
  f.normalize = transform_.normalize, f.rescale_normal = transform_.rescale_normal;
  f.texture_enabled = texture_.enabled, f.texture_bound = texture_.bound;
  f.texture_enabled_1d = texture_.enabled_1d, f.texture_bound_1d = texture_.bound_1d;
  f.texture_enabled_3d = texture_.enabled_3d, f.texture_bound_3d = texture_.bound_3d;
  f.env_mode = texture_.env_mode, f.env_color = texture_.env_color;
  f.combine = texture_.combine;
  f.color = color_, f.texcoord = texcoord_, f.normal = normal_, f.edge_flag = edge_flag_;
  f.list_base = lists_.base;
  f.raster_pos = pixels.raster;
  f.zoom_x = pixels.zoom_x, f.zoom_y = pixels.zoom_y;
  f.user_clip = user_clip;
  f.tex_gen = tex_gen_;
  f.draw_buffer = draw_buffer_, f.read_buffer = read_buffer_;
  f.transfer = pixels.transfer;
  save_color_sum(f);  // (color_sum.cpp)
  if (mask & (GL_EVAL_BIT | GL_ENABLE_BIT)) f.eval = eval_;
  attrib_stack_.push_back(std::move(f));
  make_live(active_unit_);
}

void Context::pop_attrib() {
  if (in_begin_error()) return;
  if (attrib_stack_.empty()) return error(GL_STACK_UNDERFLOW);
  const AttribFrame f = std::move(attrib_stack_.back());
  attrib_stack_.pop_back();
  make_live(0);  // (multitexture.cpp: the frame's fields are unit 0's)
  const GLbitfield m = f.mask;
  RasterState& r = raster_;
  const RasterState& s = f.raster;
  if (m & GL_CURRENT_BIT) {
    color_ = f.color, texcoord_ = f.texcoord, normal_ = f.normal, edge_flag_ = f.edge_flag;
    pixels.raster = f.raster_pos;
  }
  if (m & GL_PIXEL_MODE_BIT) {
    // (glPixelMap's tables are in no group: the current ones stay.)
    const auto maps = pixels.transfer.maps;
    pixels.zoom_x = f.zoom_x, pixels.zoom_y = f.zoom_y, pixels.transfer = f.transfer, read_buffer(f.read_buffer);
    pixels.transfer.maps = maps;
  }
  if (m & GL_POINT_BIT) r.point_size = s.point_size;
  if (m & GL_LINE_BIT) {
    r.line_width = s.line_width;
    r.line_stipple = s.line_stipple, r.stipple_factor = s.stipple_factor, r.stipple_pattern = s.stipple_pattern;
  }
  if (m & GL_POLYGON_BIT) {
    r.cull = s.cull, r.cull_mode = s.cull_mode, r.front_face = s.front_face;
    r.polygon_mode[0] = s.polygon_mode[0], r.polygon_mode[1] = s.polygon_mode[1];
    r.offset_fill = s.offset_fill, r.offset_line = s.offset_line, r.offset_point = s.offset_point;
    r.offset_factor = s.offset_factor, r.offset_units = s.offset_units;
    r.polygon_stipple = s.polygon_stipple;
  }
  if (m & GL_POLYGON_STIPPLE_BIT) r.stipple = s.stipple;
  if (m & GL_LIGHTING_BIT) lighting_ = f.lighting;
  if (m & GL_FOG_BIT) {
    r.fog = s.fog, r.fog_mode = s.fog_mode, r.fog_start = s.fog_start, r.fog_end = s.fog_end;
    r.fog_density = s.fog_density, r.fog_color = s.fog_color;
  }
  if (m & GL_DEPTH_BUFFER_BIT) r.depth_test = s.depth_test, r.depth_func = s.depth_func, r.clear_depth = s.clear_depth, r.depth_write = s.depth_write;
  if (m & GL_STENCIL_BUFFER_BIT) stencil_ = f.stencil;
  if (m & GL_ACCUM_BUFFER_BIT) accum_clear_ = f.accum_clear;
  if (m & GL_VIEWPORT_BIT) {
    transform_.viewport = f.viewport;
    transform_.depth_near = f.depth_near, transform_.depth_far = f.depth_far;
  }
  if (m & GL_TRANSFORM_BIT) {
    transform_.matrix_mode = f.matrix_mode;
    transform_.normalize = f.normalize, transform_.rescale_normal = f.rescale_normal;
    for (int i = 0; i < kMaxClipPlanes; ++i) user_clip.planes[i] = f.user_clip.planes[i];
    for (int i = 0; i < kMaxClipPlanes; ++i) user_clip.enabled[i] = f.user_clip.enabled[i];
  }
  if (m & GL_ENABLE_BIT) {
    r.alpha_test = s.alpha_test, r.blend = s.blend, r.logic_op = s.logic_op, r.cull = s.cull, r.depth_test = s.depth_test, r.fog = s.fog;
    r.offset_fill = s.offset_fill, r.offset_line = s.offset_line, r.offset_point = s.offset_point;
    r.scissor_test = s.scissor_test, r.line_stipple = s.line_stipple, r.polygon_stipple = s.polygon_stipple;
    lighting_.enabled = f.lighting.enabled, lighting_.color_material = f.lighting.color_material;
    for (int i = 0; i < kMaxLights; ++i) lighting_.lights[i].enabled = f.lighting.lights[i].enabled;
    transform_.normalize = f.normalize, transform_.rescale_normal = f.rescale_normal;
    stencil_.test = f.stencil.test;
    texture_.enabled = f.texture_enabled;
    texture_.enabled_1d = f.texture_enabled_1d;
    texture_.enabled_3d = f.texture_enabled_3d;
    for (int i = 0; i < kMaxClipPlanes; ++i) user_clip.enabled[i] = f.user_clip.enabled[i];
    for (int i = 0; i < 4; ++i) tex_gen_.coords[i].enabled = f.tex_gen.coords[i].enabled;
  }
  if (m & GL_COLOR_BUFFER_BIT) {
    r.alpha_test = s.alpha_test, r.alpha_func = s.alpha_func, r.alpha_ref = s.alpha_ref;
    r.blend = s.blend, r.blend_src = s.blend_src, r.blend_dst = s.blend_dst;
    r.blend_src_alpha = s.blend_src_alpha, r.blend_dst_alpha = s.blend_dst_alpha;
    r.blend_equation = s.blend_equation, r.blend_color = s.blend_color;
    r.logic_op = s.logic_op, r.logic_op_mode = s.logic_op_mode;
    for (int i = 0; i < 4; ++i) r.color_mask[i] = s.color_mask[i];
    r.clear_color = s.clear_color;
    draw_buffer(f.draw_buffer);
  }
  if (m & GL_HINT_BIT)
    for (int i = 0; i < 5; ++i) r.hints[i] = s.hints[i];
  if (m & GL_SCISSOR_BIT) r.scissor_test = s.scissor_test, r.scissor = s.scissor;
  if (m & GL_TEXTURE_BIT) {
    texture_.enabled = f.texture_enabled;
    // The binding comes back if its texture still exists (a deleted one binds 0).
    texture_.bound = f.texture_bound == 0 || texture_.objects.count(f.texture_bound) ? f.texture_bound : 0;
    texture_.enabled_1d = f.texture_enabled_1d;
    texture_.bound_1d = f.texture_bound_1d == 0 || texture_.objects.count(f.texture_bound_1d) ? f.texture_bound_1d : 0;
    texture_.enabled_3d = f.texture_enabled_3d;
    texture_.bound_3d = f.texture_bound_3d == 0 || texture_.objects.count(f.texture_bound_3d) ? f.texture_bound_3d : 0;
    texture_.env_mode = f.env_mode, texture_.env_color = f.env_color;
    texture_.combine = f.combine;
    tex_gen_ = f.tex_gen;
  }
  if (m & GL_LIST_BIT) lists_.base = f.list_base;
  restore_color_sum(f);  // (color_sum.cpp)
  restore_units(f);
  make_live(active_unit_);
  if (m & (GL_EVAL_BIT | GL_ENABLE_BIT)) {
    // Both groups hold the maps' enables and GL_AUTO_NORMAL; GL_EVAL_BIT the grids too
    // (the maps themselves are in no group).
    std::copy(std::begin(f.eval.enabled), std::end(f.eval.enabled), eval_.enabled);
    std::copy(std::begin(f.eval.enabled2), std::end(f.eval.enabled2), eval_.enabled2);
    eval_.auto_normal = f.eval.auto_normal;
    if (m & GL_EVAL_BIT) eval_.grid1 = f.eval.grid1, eval_.grid2u = f.eval.grid2u, eval_.grid2v = f.eval.grid2v;
  }
  update_clip_planes();
  transform_.derived_dirty = true;
  if (lighting_.color_material) apply_color_material();
  changed();
}

void Context::push_client_attrib(GLbitfield mask) {
  if (in_begin_error()) return;
  if (client_attrib_stack_.size() >= size_t(kMaxAttribDepth)) return error(GL_STACK_OVERFLOW);
  ClientAttribFrame f;
  f.mask = mask;
  f.unpack_alignment = unpack_alignment, f.pack_alignment = pack_alignment;
  f.unpack = pixels.unpack, f.pack = pixels.pack;
  save_client_units(f);  // (multitexture.cpp: unit 0's array live from here)
  f.arrays = arrays;
  client_attrib_stack_.push_back(f);
  make_client_live(client_unit_);
}

void Context::pop_client_attrib() {
  if (in_begin_error()) return;
  if (client_attrib_stack_.empty()) return error(GL_STACK_UNDERFLOW);
  const ClientAttribFrame f = client_attrib_stack_.back();
  client_attrib_stack_.pop_back();
  if (f.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    unpack_alignment = f.unpack_alignment, pack_alignment = f.pack_alignment;
    pixels.unpack = f.unpack, pixels.pack = f.pack;
  }
  make_client_live(0);
  if (f.mask & GL_CLIENT_VERTEX_ARRAY_BIT) arrays = f.arrays;
  restore_client_units(f);
  make_client_live(client_unit_);
}

int Context::attrib_depth() const { return int(attrib_stack_.size()); }
int Context::client_attrib_depth() const { return int(client_attrib_stack_.size()); }

}  // namespace velocity::gl
