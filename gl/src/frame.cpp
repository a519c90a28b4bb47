// Frames and batches: the vertex stage's primitives go to the renderer in batches of
// one kind and one per-fragment state (PixelState, from the raster and texture state)
// and one viewport, depth range, point size and line width, each taken when the batch
// opens: state set after drawing changes only what is drawn after it;
// a frame runs when the pixels are needed, and its colour (and depth) go to the
// caller's buffer.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
CompareFunc compare_func(GLenum f) { return CompareFunc(f - GL_NEVER); }

BlendFactor blend_factor(GLenum f) {
  switch (f) {
    case GL_ZERO: return BlendFactor::Zero;
    case GL_ONE: return BlendFactor::One;
    case GL_SRC_COLOR: return BlendFactor::SrcColor;
    case GL_ONE_MINUS_SRC_COLOR: return BlendFactor::OneMinusSrcColor;
    case GL_DST_COLOR: return BlendFactor::DstColor;
    case GL_ONE_MINUS_DST_COLOR: return BlendFactor::OneMinusDstColor;
    case GL_SRC_ALPHA: return BlendFactor::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return BlendFactor::OneMinusSrcAlpha;
    case GL_DST_ALPHA: return BlendFactor::DstAlpha;
    case GL_ONE_MINUS_DST_ALPHA: return BlendFactor::OneMinusDstAlpha;
    case GL_CONSTANT_COLOR: return BlendFactor::ConstantColor;
    case GL_ONE_MINUS_CONSTANT_COLOR: return BlendFactor::OneMinusConstantColor;
    case GL_CONSTANT_ALPHA: return BlendFactor::ConstantAlpha;
    case GL_ONE_MINUS_CONSTANT_ALPHA: return BlendFactor::OneMinusConstantAlpha;
    default: return BlendFactor::SrcAlphaSaturate;
  }
}
}  // namespace

void Context::ensure_frame() {
  if (in_frame_) return;
  if (fbo_) prepare_framebuffer();  // (framebuffer_objects.cpp: loaded again if its images changed)
  if (!renderer_) return;
  if (fbo_) fbo_->drawn = true;
  FrameStart start;
  start.clear_color_buffer = start.clear_depth_buffer = first_frame_;
  // Without a stencil buffer, clearing the renderer's keeps its empty tiles skippable.
  start.clear_stencil_buffer = first_frame_ || stencil_bits_ == 0;
  start.color = {0, 0, 0, 0};
  start.depth = 1;
  start.stencil = 0;
  if (start_clear_) {
    // A whole-framebuffer glClear before anything else in the frame: the frame starts
    // cleared, which lets the renderer skip tiles that stay empty and clean.
    start.clear_color_buffer = start_clear_color_ || first_frame_;
    start.clear_depth_buffer = start_clear_depth_ || first_frame_;
    if (start_clear_color_) start.color = start_color_;
    if (start_clear_depth_) start.depth = start_depth_;
    if (start_clear_stencil_) start.clear_stencil_buffer = true, start.stencil = start_stencil_;
    start_clear_ = start_clear_color_ = start_clear_depth_ = start_clear_stencil_ = false;
  }
  // GL_FRONT_AND_BACK: the other colour buffer is drawn in the same frame (buffers.cpp).
  if (double_buffered_ && drawn_ == 3 && !mirror_) start_mirror();
  renderer_->begin_frame(Camera{}, {}, start);
  if (mirror_) mirror_->begin_frame(Camera{}, {}, start);
  first_frame_ = false;
  in_frame_ = true;
}

void Context::submit_pending() {
  if (!have_pending_) return;
  have_pending_ = false;
  if (pending_.position.empty() || !renderer_) return;
  ensure_frame();
  if (submitted_used_ == submitted_.size()) submitted_.emplace_back();
  Pending& kept = submitted_[submitted_used_++];
  std::swap(kept, pending_);
  pending_.clear();
  PrimitiveBatch b;
  b.kind = kept.kind;
  b.position = kept.position.data();
  b.color = kept.color.data();
  b.texcoord = kept.texcoord.empty() ? nullptr : kept.texcoord.data();
  b.fog = kept.fog.empty() ? nullptr : kept.fog.data();
  b.texcoord1 = kept.texcoord1.empty() ? nullptr : kept.texcoord1.data();
  if (kept.state.color_sum) {  // (color_sum.cpp; a vertex given none has black)
    kept.secondary.resize(kept.position.size());
    b.secondary = kept.secondary.data();
  }
  b.vertex_count = uint32_t(kept.position.size());
  b.indices = kept.index.data();
  b.index_count = uint32_t(kept.index.size());
  // The viewport, depth range and sizes the batch's primitives were drawn with (set
  // when it opened, in target()), not the context's now.
  b.viewport = kept.viewport;
  b.point_size = kept.point_size;
  b.line_width = kept.line_width;
  b.clip_planes = kept.clip_planes;
  b.clip_distance = kept.clip_planes ? kept.clip_distance.data() : nullptr;
  if (kept.viewport.width == 0 || kept.viewport.height == 0) return;  // nothing is drawn in an empty viewport
  renderer_->draw(b, kept.state);
  if (mirror_) mirror_->draw(b, kept.state);
  frame_vertices_ += kept.index.size();
  // Bounded memory in a frame never flushed: its vertices, and the textures it holds.
  if (frame_vertices_ > kMaxVerticesPerFrame || frame_texture_bytes_ > kMaxTextureBytesPerFrame) run_frame();
}

void Context::run_frame() {
  if (fbo_ && !in_frame_) prepare_framebuffer();
  submit_pending();
  if (double_buffered_) park_colour();
  if (!renderer_ || (!in_frame_ && !start_clear_)) return;  // nothing drawn or cleared since the last frame
  ensure_frame();
  // The framebuffer's rows are GL's, bottom first, as OSMesa's buffer (Y_UP): an RGBA
  // buffer of the framebuffer's width takes the colour directly, unless there is a back
  // buffer (buffers.cpp). Either way each tile is copied out by the thread that drew it,
  // as soon as it is drawn.
  direct_ = buffer_ && format_ == GL_RGBA && y_up && (row_length == 0 || row_length == width_) && !double_buffered_;
  renderer_->end_frame_into(direct_ ? static_cast<uint8_t*>(buffer_) : colour_.data(), size_t(width_) * 4, 4);
  if (mirror_) {
    mirror_->end_frame();
    mirror_->read_color(parked_.data(), size_t(width_) * 4, 4);
  }
  in_frame_ = false;
  for (size_t i = 0; i < submitted_used_; ++i) submitted_[i].clear();
  submitted_used_ = 0;
  frame_textures_.clear();
  frame_texture_bytes_ = 0;
  frame_vertices_ = 0;
  if (direct_) {
    if (depth_requested_) copy_depth();
    return;
  }
  if (!buffer_) return;  // a framebuffer object's: its colour stays in colour_
  const int stride_px = row_length > 0 ? row_length : width_;
  const int bpp = format_ == GL_RGB || format_ == 0x4 /* OSMESA_BGR */ ? 3 : 4;
  uint8_t* out = static_cast<uint8_t*>(buffer_);
  // The caller's buffer is the back buffer where there is one (buffers.cpp).
  const uint8_t* shown = back_rows();
  for (int y = 0; y < height_; ++y) {
    const uint8_t* src = shown + size_t(y) * width_ * 4;
    uint8_t* dst = out + size_t(y_up ? y : height_ - 1 - y) * stride_px * bpp;
    switch (format_) {
      case GL_RGBA: std::memcpy(dst, src, size_t(width_) * 4); break;
      case GL_RGB:
        for (int x = 0; x < width_; ++x) dst[3 * x] = src[4 * x], dst[3 * x + 1] = src[4 * x + 1], dst[3 * x + 2] = src[4 * x + 2];
        break;
      case 0x4:  // OSMESA_BGR
        for (int x = 0; x < width_; ++x) dst[3 * x] = src[4 * x + 2], dst[3 * x + 1] = src[4 * x + 1], dst[3 * x + 2] = src[4 * x];
        break;
      case 0x1:  // OSMESA_BGRA
        for (int x = 0; x < width_; ++x)
          dst[4 * x] = src[4 * x + 2], dst[4 * x + 1] = src[4 * x + 1], dst[4 * x + 2] = src[4 * x], dst[4 * x + 3] = src[4 * x + 3];
        break;
      default:  // OSMESA_ARGB
        for (int x = 0; x < width_; ++x)
          dst[4 * x] = src[4 * x + 3], dst[4 * x + 1] = src[4 * x], dst[4 * x + 2] = src[4 * x + 1], dst[4 * x + 3] = src[4 * x + 2];
        break;
    }
  }
  if (depth_requested_) copy_depth();
}

void Context::copy_depth() {
  {
    const std::vector<float> d = renderer_->window_depth();
    depth_out_.resize(d.size());
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x)
        depth_out_[size_t(y_up ? y : height_ - 1 - y) * width_ + x] =
            uint32_t(std::lround(double(std::clamp(d[size_t(y) * width_ + x], 0.0f, 1.0f)) * 4294967295.0));
  }
}

void Context::finish() {
  if (in_begin_error()) return;
  if (renderer_) run_frame();
}

PixelState Context::pixel_state(bool offset, bool stippled) {
  PixelState s;
  if (stencil_write_ >= 0) {  // stencil indices (draw_pixels.cpp): the scissor test and the write mask only
    s.scissor = raster_.scissor_test;
    if (raster_.scissor_test) sample_scissor(raster_.scissor, s.scissor_x0, s.scissor_y0, s.scissor_x1, s.scissor_y1);
    s.color_mask = 0;
    s.depth_test = s.depth_write = false;
    s.stencil_test = true;
    s.stencil_func = CompareFunc::Always;
    s.stencil_ref = uint8_t(stencil_write_);
    s.stencil_value_mask = 0xff;
    s.stencil_write_mask = uint8_t(stencil_.write_mask);
    s.stencil_fail = s.stencil_depth_fail = s.stencil_pass = StencilOp::Replace;
    return s;
  }
  if (accum_returning_) {  // glAccum(GL_RETURN): the scissor test and the colour mask only
    s.scissor = raster_.scissor_test;
    if (raster_.scissor_test) sample_scissor(raster_.scissor, s.scissor_x0, s.scissor_y0, s.scissor_x1, s.scissor_y1);
    s.color_mask = drawn_ ? raster_.color_mask_bits() & channel_mask_ : 0;
    s.depth_test = s.depth_write = false;
    return s;
  }
  stage0_unit1_ = texture_stages(s);  // (multitexture.cpp)
  s.fog = raster_.fog;
  s.color_sum = color_sum_applies();  // (color_sum.cpp)
  s.fog_mode = raster_.fog_mode == GL_LINEAR ? FogMode::Linear : raster_.fog_mode == GL_EXP2 ? FogMode::Exp2 : FogMode::Exp;
  s.fog_start = raster_.fog_start, s.fog_end = raster_.fog_end, s.fog_density = raster_.fog_density;
  s.fog_color = raster_.fog_color;
  s.scissor = raster_.scissor_test;
  if (raster_.scissor_test) sample_scissor(raster_.scissor, s.scissor_x0, s.scissor_y0, s.scissor_x1, s.scissor_y1);
  s.alpha_test = raster_.alpha_test;
  s.alpha_func = compare_func(raster_.alpha_func);
  s.alpha_ref = raster_.alpha_ref;
  const bool depth = raster_.depth_test && depth_bits_ > 0;
  s.depth_test = depth;
  s.depth_func = compare_func(raster_.depth_func);
  s.depth_write = depth && raster_.depth_write;
  s.polygon_offset = offset;
  s.offset_factor = raster_.offset_factor, s.offset_units = raster_.offset_units;
  s.blend = raster_.blend;
  s.logic_op = raster_.logic_op;
  s.logic = LogicOp(raster_.logic_op_mode - GL_CLEAR);
  s.blend_src_rgb = blend_factor(raster_.blend_src), s.blend_src_alpha = blend_factor(raster_.blend_src_alpha);
  s.blend_dst_rgb = blend_factor(raster_.blend_dst), s.blend_dst_alpha = blend_factor(raster_.blend_dst_alpha);
  s.blend_op = raster_.blend_equation == GL_FUNC_SUBTRACT           ? BlendOp::Subtract
               : raster_.blend_equation == GL_FUNC_REVERSE_SUBTRACT ? BlendOp::ReverseSubtract
               : raster_.blend_equation == GL_MIN                   ? BlendOp::Min
               : raster_.blend_equation == GL_MAX                   ? BlendOp::Max
                                                                    : BlendOp::Add;
  s.blend_color = raster_.blend_color;
  // (glDrawBuffer(GL_NONE): no colour written; an FBO's luminance or alpha buffer keeps
  // only its channels: framebuffer_objects.cpp)
  s.color_mask = drawn_ ? raster_.color_mask_bits() & channel_mask_ : 0;
  stencil_pixel_state(s);
  s.samples_passed = queries_.active_object ? &queries_.active_object->samples : nullptr;  // (occlusion.cpp)
  s.polygon_stipple = stippled && raster_.polygon_stipple;
  if (s.polygon_stipple) std::copy(raster_.stipple.begin(), raster_.stipple.end(), s.stipple);
  return s;
}

Context::Pending& Context::target(PrimitiveKind kind, bool offset, bool stippled) {
  if (have_pending_ && !pending_takes(kind, offset, stippled)) submit_pending();
  if (!have_pending_) {
    pending_.clear();
    pending_.kind = kind;
    pending_.offset = offset;
    pending_.stippled = stippled;
    pending_.state = pixel_state(offset, stippled);
    pending_.stage0_unit1 = stage0_unit1_;
    pending_.extras = pending_.state.texture1.texture || pending_.state.color_sum;
    const Box& vp = transform_.viewport;
    // The framebuffer is kept bottom row first (see update_derived): GL's y as it is,
    // in samples (multisample.cpp).
    pending_.viewport = {to_samples(vp.x), to_samples(vp.y), to_samples(vp.width), to_samples(vp.height),
                         transform_.depth_near, transform_.depth_far};
    pending_.point_size = std::max(1.0f, raster_.point_size) * float(ssaa_);
    pending_.line_width = std::max(1.0f, raster_.line_width) * float(ssaa_);
    pending_.clip_planes = user_clip.count;
    have_pending_ = true;
    if (++pending_gen_ == 0) {  // wrapped: forget every old mark
      for (Emitted& e : emitted_) e = {};
      pending_gen_ = 1;
    }
    pixel_dirty_ = false;
  }
  return pending_;
}

void Context::emit_vertex(uint32_t i, const Vec4& color, bool shared, const Vec4* secondary) {
  Pending& p = pending_;
  if (shared) {
    const Emitted e = emitted_[i];
    if (e.gen == pending_gen_) return p.index.push_back(e.index);
    emitted_[i] = {pending_gen_, uint32_t(p.position.size())};
  }
  const Vertex& v = prim_[i];
  p.index.push_back(uint32_t(p.position.size()));
  p.position.push_back(v.clip);
  p.color.push_back(color);
  if (p.state.texture.texture) p.texcoord.push_back(p.stage0_unit1 ? prim_tex1_[i] : v.tex);
  if (p.state.fog) p.fog.push_back(v.fog);
  if (p.extras) {  // (multitexture.cpp, color_sum.cpp)
    if (p.state.texture1.texture) p.texcoord1.push_back(prim_tex1_[i]);
    if (p.state.color_sum) p.secondary.push_back(secondary ? *secondary : Vec4{0, 0, 0, 0});
  }
  for (uint32_t k = 0; k < p.clip_planes; ++k) p.clip_distance.push_back(v.clip_distance[k]);
}

}  // namespace velocity::gl
