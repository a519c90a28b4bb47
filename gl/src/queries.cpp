// Queries: glGet* (as doubles, converted by each entry point) and glIsEnabled. The
// light and material queries are with their state (lighting.cpp).
#include "context.hpp"
#include "raster/contract.hpp"  // kSubpixelBits

namespace velocity::gl {

bool Context::get(GLenum pname, std::vector<double>& out, int& kind) {
  if (fbo_) prepare_framebuffer();  // (an FBO's bits after its attachments changed: framebuffer_objects.cpp)
  kind = 0;
  out.clear();
  auto v4 = [&](Vec4 c) { out = {c.x, c.y, c.z, c.w}; };
  auto matrix_out = [&](const Mat4& m) {
    out.resize(16);
    store_column_major(m, out.data());
  };
  const TransformState& t = transform_;
  const RasterState& r = raster_;
  bool known = false;
  const bool enabled = is_enabled(pname, &known);
  if (known) return out = {enabled ? 1.0 : 0.0}, true;
  if (get_multitexture(pname, out)) return true;  // (multitexture.cpp: before the units' own)
  if (get_stencil(pname, out)) return true;
  if (get_blend(pname, out, kind)) return true;
  if (get_pixel_ops(pname, out, kind)) return true;  // (draw_pixels.cpp)
  if (get_buffer_binding(pname, out)) return true;   // (buffer_objects.cpp)
  if (get_eval(pname, out)) return true;             // (evaluators.cpp)
  if (get_buffers(pname, out)) return true;          // (buffers.cpp)
  if (get_multisample(pname, out)) return true;      // (multisample.cpp)
  if (get_pixel_transfer(pname, out)) return true;   // (pixel_transfer.cpp)
  if (get_color_sum(pname, out, kind)) return true;  // (color_sum.cpp)
  if (get_framebuffer(pname, out)) return true;      // (framebuffer_objects.cpp)
  switch (pname) {
    case GL_MATRIX_MODE: out = {double(transform_.matrix_mode)}; return true;
    case GL_MODELVIEW_MATRIX: matrix_out(transform_.modelview.back()); return true;
    case GL_PROJECTION_MATRIX: matrix_out(transform_.projection.back()); return true;
    case GL_TEXTURE_MATRIX: matrix_out(transform_.texture.back()); return true;
    case GL_MODELVIEW_STACK_DEPTH: out = {double(transform_.modelview.size())}; return true;
    case GL_PROJECTION_STACK_DEPTH: out = {double(transform_.projection.size())}; return true;
    case GL_TEXTURE_STACK_DEPTH: out = {double(transform_.texture.size())}; return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out = {double(kMaxModelviewDepth)}; return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out = {double(kMaxProjectionDepth)}; return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: out = {double(kMaxTextureDepth)}; return true;
    case GL_MAX_LIGHTS: out = {double(kMaxLights)}; return true;
    case GL_MAX_TEXTURE_SIZE: out = {double(kMaxTextureSize)}; return true;
    case GL_MAX_TEXTURE_LOD_BIAS: out = {double(kMaxLodBias)}; return true;
    case GL_MAX_LIST_NESTING: out = {double(kMaxListNesting)}; return true;
    // glDrawRangeElements' advice: pGL has no preferred size, so a large one.
    case GL_MAX_ELEMENTS_VERTICES: case GL_MAX_ELEMENTS_INDICES: out = {double(1 << 20)}; return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: out = {double(kMaxAttribDepth)}; return true;
    case GL_MAX_NAME_STACK_DEPTH: out = {double(kMaxNameDepth)}; return true;
    case GL_NAME_STACK_DEPTH: out = {double(select_.names.size())}; return true;
    case GL_RENDER_MODE: out = {double(select_.mode)}; return true;
    case GL_SELECTION_BUFFER_SIZE: out = {double(select_.size)}; return true;
    case GL_FEEDBACK_BUFFER_SIZE: out = {double(feedback_.size)}; return true;
    case GL_FEEDBACK_BUFFER_TYPE: out = {double(feedback_.type)}; return true;
    case GL_ATTRIB_STACK_DEPTH: out = {double(attrib_depth())}; return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: out = {double(client_attrib_depth())}; return true;
    case GL_MAX_VIEWPORT_DIMS: out = {double(kMaxViewport), double(kMaxViewport)}; return true;
    case GL_VIEWPORT:
      out = {double(t.viewport.x), double(t.viewport.y), double(t.viewport.width), double(t.viewport.height)};
      return true;
    case GL_DEPTH_RANGE: out = {transform_.depth_near, transform_.depth_far}; return true;
    case GL_SCISSOR_BOX:
      out = {double(r.scissor.x), double(r.scissor.y), double(r.scissor.width), double(r.scissor.height)};
      return true;
    case GL_COLOR_CLEAR_VALUE: v4(raster_.clear_color), kind = 1; return true;
    case GL_DEPTH_CLEAR_VALUE: out = {raster_.clear_depth}, kind = 1; return true;
    case GL_DEPTH_FUNC: out = {double(raster_.depth_func)}; return true;
    case GL_DEPTH_WRITEMASK: out = {raster_.depth_write ? 1.0 : 0.0}; return true;
    case GL_COLOR_WRITEMASK:
      out = {double(r.color_mask[0]), double(r.color_mask[1]), double(r.color_mask[2]), double(r.color_mask[3])};
      return true;
    case GL_ALPHA_TEST_FUNC: out = {double(raster_.alpha_func)}; return true;
    case GL_ALPHA_TEST_REF: out = {raster_.alpha_ref}, kind = 1; return true;
    case GL_FOG_MODE: out = {double(raster_.fog_mode)}; return true;
    case GL_FOG_DENSITY: out = {raster_.fog_density}; return true;
    case GL_FOG_START: out = {raster_.fog_start}; return true;
    case GL_FOG_END: out = {raster_.fog_end}; return true;
    case GL_FOG_COLOR: v4(raster_.fog_color), kind = 1; return true;
    case GL_CULL_FACE_MODE: out = {double(raster_.cull_mode)}; return true;
    case GL_FRONT_FACE: out = {double(raster_.front_face)}; return true;
    case GL_POLYGON_MODE: out = {double(raster_.polygon_mode[0]), double(raster_.polygon_mode[1])}; return true;
    case GL_POLYGON_OFFSET_FACTOR: out = {raster_.offset_factor}; return true;
    case GL_POLYGON_OFFSET_UNITS: out = {raster_.offset_units}; return true;
    case GL_POINT_SIZE: out = {raster_.point_size}; return true;
    case GL_LINE_WIDTH: out = {raster_.line_width}; return true;
    case GL_LINE_STIPPLE_PATTERN: out = {double(raster_.stipple_pattern)}; return true;
    case GL_LINE_STIPPLE_REPEAT: out = {double(raster_.stipple_factor)}; return true;
    case GL_SHADE_MODEL: out = {double(lighting_.shade_model)}; return true;
    case GL_LIGHT_MODEL_AMBIENT: v4(lighting_.model_ambient), kind = 1; return true;
    case GL_LIGHT_MODEL_TWO_SIDE: out = {lighting_.two_side ? 1.0 : 0.0}; return true;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: out = {lighting_.local_viewer ? 1.0 : 0.0}; return true;
    case GL_COLOR_MATERIAL_FACE: out = {double(lighting_.color_material_face)}; return true;
    case GL_COLOR_MATERIAL_PARAMETER: out = {double(lighting_.color_material_mode)}; return true;
    case GL_CURRENT_COLOR: v4(color_), kind = 1; return true;
    case GL_CURRENT_NORMAL: out = {normal_.x, normal_.y, normal_.z}; return true;
    case GL_CURRENT_TEXTURE_COORDS: v4(texcoord_); return true;
    case GL_TEXTURE_BINDING_2D: out = {double(texture_.bound)}; return true;
    case GL_TEXTURE_BINDING_1D: out = {double(texture_.bound_1d)}; return true;
    case GL_TEXTURE_BINDING_3D: out = {double(texture_.bound_3d)}; return true;
    case GL_MAX_3D_TEXTURE_SIZE: out = {double(kMax3DTextureSize)}; return true;
    case GL_LIST_BASE: out = {double(lists_.base)}; return true;
    case GL_LIST_INDEX: out = {double(lists_.compiling)}; return true;
    case GL_LIST_MODE: out = {lists_.compiling ? double(lists_.mode) : 0.0}; return true;
    case GL_UNPACK_ALIGNMENT: out = {double(unpack_alignment)}; return true;
    case GL_PACK_ALIGNMENT: out = {double(pack_alignment)}; return true;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: out = {8}; return true;
    case GL_ALPHA_BITS: out = {format_ == GL_RGB || format_ == 0x4 ? 0.0 : 8.0}; return true;
    case GL_DEPTH_BITS: out = {depth_bits_ > 0 ? 24.0 : 0.0}; return true;
    // The framebuffer: one RGBA colour buffer (OSMesa's, single-buffered: GL_FRONT),
    // a depth buffer, a stencil buffer (stencil.cpp), an accumulation buffer
    // (accum.cpp); no auxiliary buffers, no colour index, no stereo, no multisampling
    // (all 0 until they exist, whatever the context asked for).
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS:
    case GL_ACCUM_ALPHA_BITS: out = {double(accum_bits_)}; return true;
    case GL_ACCUM_CLEAR_VALUE: v4(accum_clear_), kind = 1; return true;
    case GL_AUX_BUFFERS: case GL_INDEX_BITS: case GL_INDEX_MODE: case GL_STEREO:
      out = {0}; return true;
    case GL_RGBA_MODE: out = {1}; return true;
    // The rasterizer's: window coordinates snap to 24.8 fixed point; points and lines
    // are aliased, of a whole number of pixels (the size rounded), 1 to 64 (glPointSize,
    // glLineWidth clamp there). There is no antialiasing: the "smooth" ranges
    // (GL_POINT_SIZE_RANGE, GL_LINE_WIDTH_RANGE) are the sizes that are drawn.
    case GL_SUBPIXEL_BITS: out = {double(raster::kSubpixelBits)}; return true;
    case GL_POINT_SIZE_RANGE: case GL_LINE_WIDTH_RANGE: case GL_ALIASED_POINT_SIZE_RANGE:
    case GL_ALIASED_LINE_WIDTH_RANGE:
      out = {1, double(kMaxPointLineSize)}; return true;
    case GL_POINT_SIZE_GRANULARITY: case GL_LINE_WIDTH_GRANULARITY: out = {1}; return true;
    // No compressed formats. The features pGL lacks have a limit of 0, so a program
    // that asks learns that they are missing (docs/gl.md).
    case GL_MAX_CLIP_PLANES: out = {double(kMaxClipPlanes)}; return true;
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS:
      out = {0}; return true;
    case GL_PERSPECTIVE_CORRECTION_HINT: case GL_POINT_SMOOTH_HINT: case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT: case GL_FOG_HINT:
      out = {double(raster_.hints[pname - GL_PERSPECTIVE_CORRECTION_HINT])};
      return true;
    case GL_EDGE_FLAG: out = {edge_flag() ? 1.0 : 0.0}; return true;
    case GL_EDGE_FLAG_ARRAY_STRIDE: out = {double(arrays.edge_stride)}; return true;
    case GL_VERTEX_ARRAY_SIZE: out = {double(arrays.vertex.size)}; return true;
    case GL_VERTEX_ARRAY_TYPE: out = {double(arrays.vertex.type)}; return true;
    case GL_VERTEX_ARRAY_STRIDE: out = {double(arrays.vertex.stride)}; return true;
    case GL_NORMAL_ARRAY_TYPE: out = {double(arrays.normal.type)}; return true;
    case GL_NORMAL_ARRAY_STRIDE: out = {double(arrays.normal.stride)}; return true;
    case GL_COLOR_ARRAY_SIZE: out = {double(arrays.color.size)}; return true;
    case GL_COLOR_ARRAY_TYPE: out = {double(arrays.color.type)}; return true;
    case GL_COLOR_ARRAY_STRIDE: out = {double(arrays.color.stride)}; return true;
    case GL_TEXTURE_COORD_ARRAY_SIZE: out = {double(arrays.texcoord.size)}; return true;
    case GL_TEXTURE_COORD_ARRAY_TYPE: out = {double(arrays.texcoord.type)}; return true;
    case GL_TEXTURE_COORD_ARRAY_STRIDE: out = {double(arrays.texcoord.stride)}; return true;
    default: return false;
  }
}

bool Context::is_enabled(GLenum cap, bool* known) const {
  *known = true;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return lighting_.lights[cap - GL_LIGHT0].enabled;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + kMaxClipPlanes) return user_clip.enabled[cap - GL_CLIP_PLANE0];
  if (cap >= GL_TEXTURE_GEN_S && cap <= GL_TEXTURE_GEN_Q) return tex_gen_enabled(cap);
  if (const bool on = evaluator_enabled(cap, known); *known) return on;  // (evaluators.cpp)
  if (const bool on = color_sum_enabled(cap, known); *known) return on;  // (color_sum.cpp)
  *known = true;
  switch (cap) {
    case GL_DEPTH_TEST: return raster_.depth_test;
    case GL_CULL_FACE: return raster_.cull;
    case GL_LIGHTING: return lighting_.enabled;
    case GL_NORMALIZE: return transform_.normalize;
    case GL_RESCALE_NORMAL: return transform_.rescale_normal;
    case GL_COLOR_MATERIAL: return lighting_.color_material;
    case GL_TEXTURE_2D: return texture_.enabled;
    case GL_TEXTURE_1D: return texture_.enabled_1d;
    case GL_TEXTURE_3D: return texture_.enabled_3d;
    case GL_BLEND: return raster_.blend;
    case GL_COLOR_LOGIC_OP: return raster_.logic_op;
    case GL_LINE_STIPPLE: return raster_.line_stipple;
    case GL_POLYGON_STIPPLE: return raster_.polygon_stipple;
    case GL_ALPHA_TEST: return raster_.alpha_test;
    case GL_FOG: return raster_.fog;
    case GL_SCISSOR_TEST: return raster_.scissor_test;
    case GL_STENCIL_TEST: return stencil_.test;
    case GL_POLYGON_OFFSET_FILL: return raster_.offset_fill;
    case GL_POLYGON_OFFSET_LINE: return raster_.offset_line;
    case GL_POLYGON_OFFSET_POINT: return raster_.offset_point;
    case GL_VERTEX_ARRAY: return arrays.vertex.enabled;
    case GL_NORMAL_ARRAY: return arrays.normal.enabled;
    case GL_COLOR_ARRAY: return arrays.color.enabled;
    case GL_TEXTURE_COORD_ARRAY: return arrays.texcoord.enabled;
    case GL_EDGE_FLAG_ARRAY: return arrays.edge_enabled;
    case GL_DITHER: return true;
    default: *known = false; return false;
  }
}

}  // namespace velocity::gl
