// The context's state, its batches and frames (see context.hpp).
#include "context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "velocity/error.hpp"

namespace velocity::gl {

M4 M4::operator*(const M4& b) const {
  M4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      r.m[c * 4 + row] = m[0 * 4 + row] * b.m[c * 4 + 0] + m[1 * 4 + row] * b.m[c * 4 + 1] +
                         m[2 * 4 + row] * b.m[c * 4 + 2] + m[3 * 4 + row] * b.m[c * 4 + 3];
  return r;
}

bool M4::is_identity() const {
  static const M4 id;
  return std::memcmp(m, id.m, sizeof m) == 0;
}

bool invert(const M4& a, M4& out) {
  // Gauss-Jordan elimination with partial pivoting, in double.
  double w[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) w[r][c] = a.m[c * 4 + r], w[r][c + 4] = r == c ? 1 : 0;
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(w[r][c]) > std::fabs(w[p][c])) p = r;
    if (!(std::fabs(w[p][c]) > 1e-30)) return false;
    if (p != c)
      for (int k = 0; k < 8; ++k) std::swap(w[p][k], w[c][k]);
    const double inv = 1.0 / w[c][c];
    for (int k = 0; k < 8; ++k) w[c][k] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = w[r][c];
      if (f != 0)
        for (int k = 0; k < 8; ++k) w[r][k] -= f * w[c][k];
    }
  }
  // Round-off residues of zero entries (1e-40 and the like) would become float
  // denormals, which make every multiply with them dozens of times slower.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const double v = w[r][c + 4];
      out.m[c * 4 + r] = std::fabs(v) < 1e-30 ? 0.0f : float(v);
    }
  return true;
}

namespace {
thread_local Context* g_current = nullptr;

int threads_from_environment() {
  const char* s = std::getenv("VELOCITY_THREADS");
  if (!s) return 0;
  char* end = nullptr;
  const long n = std::strtol(s, &end, 10);
  return end != s && n > 0 && n <= 1024 ? int(n) : 0;
}

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
    default: return BlendFactor::SrcAlphaSaturate;
  }
}

bool is_blend_factor(GLenum f, bool /*source*/) {
  switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR:
      return true;
    case GL_SRC_ALPHA_SATURATE: return true;  // also as a destination factor (Mesa, GL 3.3)
    default: return false;
  }
}

bool is_compare(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }
float clamp01(double v) { return unit(v); }
}  // namespace

Context* current() { return g_current; }
void set_current(Context* c) { g_current = c; }

Context::Context(GLenum format, int depth_bits) : format_(format), depth_bits_(depth_bits) {
  lights_[0].diffuse = lights_[0].specular = {1, 1, 1, 1};
  textures_.clear();
}

Context::~Context() = default;

// --- OSMesa ---------------------------------------------------------------------

bool Context::make_current(void* buffer, GLenum type, int width, int height) {
  if (!buffer || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 || width > kMaxViewport || height > kMaxViewport)
    return false;
  if (in_frame_) run_frame();
  const bool first = !renderer_;
  try {
    if (!renderer_) {
      renderer_ = std::make_unique<Renderer>(width, height);
      renderer_->options.threads = threads_from_environment();
      renderer_->options.cull_back_faces = false;
    } else if (width != width_ || height != height_) {
      renderer_->resize(width, height);
      first_frame_ = true;
    }
  } catch (const std::exception&) {
    return false;
  }
  buffer_ = buffer;
  if (first || width != width_ || height != height_) {
    width_ = width, height_ = height;
    colour_.assign(size_t(width) * height * 4, 0);
  }
  if (first) {
    viewport(0, 0, width, height);
    sc_x_ = sc_y_ = 0, sc_w_ = width, sc_h_ = height;
  }
  return true;
}

void Context::release() {
  if (in_frame_) run_frame();
}

bool Context::depth_buffer(GLint* width, GLint* height, GLint* bytes_per_value, void** buffer) {
  if (depth_bits_ <= 0 || !renderer_) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (bytes_per_value) *bytes_per_value = 0;
    if (buffer) *buffer = nullptr;
    return false;
  }
  if (in_frame_) run_frame();
  if (!depth_requested_) {
    depth_requested_ = true;
    copy_depth();
  }
  if (width) *width = width_;
  if (height) *height = height_;
  if (bytes_per_value) *bytes_per_value = 4;
  if (buffer) *buffer = depth_out_.data();
  return true;
}

// --- frames and batches ---------------------------------------------------------

void Context::ensure_frame() {
  if (in_frame_ || !renderer_) return;
  FrameStart start;
  start.clear_color_buffer = start.clear_depth_buffer = first_frame_;
  start.color = {0, 0, 0, 0};
  start.depth = 1;
  if (start_clear_) {
    // A whole-framebuffer glClear before anything else in the frame: the frame starts
    // cleared, which lets the renderer skip tiles that stay empty and clean.
    start.clear_color_buffer = start_clear_color_ || first_frame_;
    start.clear_depth_buffer = start_clear_depth_ || first_frame_;
    if (start_clear_color_) start.color = start_color_;
    if (start_clear_depth_) start.depth = start_depth_;
    start_clear_ = start_clear_color_ = start_clear_depth_ = false;
  }
  renderer_->begin_frame(Camera{}, {}, start);
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
  b.vertex_count = uint32_t(kept.position.size());
  b.indices = kept.index.data();
  b.index_count = uint32_t(kept.index.size());
  b.viewport.x = vp_x_;
  b.viewport.y = vp_y_;  // the framebuffer is kept bottom row first (see update_derived)
  b.viewport.width = std::max(vp_w_, 1);
  b.viewport.height = std::max(vp_h_, 1);
  b.viewport.depth_near = depth_near_, b.viewport.depth_far = depth_far_;
  b.point_size = std::max(1.0f, point_size_);
  b.line_width = std::max(1.0f, line_width_);
  if (vp_w_ == 0 || vp_h_ == 0) return;  // nothing is drawn in an empty viewport
  renderer_->draw(b, kept.state);
  frame_vertices_ += kept.index.size();
  if (frame_vertices_ > kMaxVerticesPerFrame) run_frame();  // bounded memory in a frame never flushed
}

void Context::run_frame() {
  submit_pending();
  if (!renderer_ || (!in_frame_ && !start_clear_)) return;  // nothing drawn or cleared since the last frame
  ensure_frame();
  renderer_->end_frame();
  in_frame_ = false;
  for (size_t i = 0; i < submitted_used_; ++i) submitted_[i].clear();
  submitted_used_ = 0;
  frame_textures_.clear();
  frame_vertices_ = 0;
  // The framebuffer's rows are GL's, bottom first, as OSMesa's buffer (Y_UP): an RGBA
  // buffer of the framebuffer's width takes the colour directly.
  direct_ = format_ == GL_RGBA && y_up && (row_length == 0 || row_length == width_);
  if (direct_) {
    renderer_->read_color(static_cast<uint8_t*>(buffer_), size_t(width_) * 4, 4);
    if (depth_requested_) copy_depth();
    return;
  }
  renderer_->read_color(colour_.data(), size_t(width_) * 4, 4);
  const int stride_px = row_length > 0 ? row_length : width_;
  const int bpp = format_ == GL_RGB || format_ == 0x4 /* OSMESA_BGR */ ? 3 : 4;
  uint8_t* out = static_cast<uint8_t*>(buffer_);
  for (int y = 0; y < height_; ++y) {
    const uint8_t* src = colour_.data() + size_t(y) * width_ * 4;
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

PixelState Context::pixel_state(bool offset) {
  PixelState s;
  if (texture_2d_) {
    TextureObject* t = bound_texture();
    if (const Texture* tex = texture_for_draw(*t)) {
      TextureStage& st = s.texture;
      st.texture = tex;
      st.format = t->format;
      st.env = env_mode_ == GL_REPLACE ? TexEnvMode::Replace
               : env_mode_ == GL_DECAL ? TexEnvMode::Decal
               : env_mode_ == GL_BLEND ? TexEnvMode::Blend
               : env_mode_ == 0x0104   ? TexEnvMode::Add
                                       : TexEnvMode::Modulate;
      st.env_color = env_color_;
      using T = SamplerState::Texel;
      using Mp = SamplerState::Mip;
      SamplerState& sm = st.sampler;
      sm.mag = t->mag_filter == GL_NEAREST ? T::Nearest : T::Linear;
      switch (t->min_filter) {
        case GL_NEAREST: sm.min = T::Nearest, sm.mip = Mp::None; break;
        case GL_LINEAR: sm.min = T::Linear, sm.mip = Mp::None; break;
        case GL_NEAREST_MIPMAP_NEAREST: sm.min = T::Nearest, sm.mip = Mp::Nearest; break;
        case GL_LINEAR_MIPMAP_NEAREST: sm.min = T::Linear, sm.mip = Mp::Nearest; break;
        case GL_NEAREST_MIPMAP_LINEAR: sm.min = T::Nearest, sm.mip = Mp::Linear; break;
        default: sm.min = T::Linear, sm.mip = Mp::Linear; break;
      }
      auto wrap = [](GLenum w) {
        // GL_CLAMP clamps s to [0, 1] and filters with the border: for GL_NEAREST that
        // is the edge texel; with GL_LINEAR it differs from the edge only in the last
        // half texel, where GL blends in the border colour (not done here: docs/gl.md).
        return w == GL_CLAMP || w == GL_CLAMP_TO_EDGE ? Wrap::Clamp
               : w == GL_MIRRORED_REPEAT ? Wrap::MirroredRepeat
                                         : Wrap::Repeat;
      };
      sm.wrap_s = wrap(t->wrap_s), sm.wrap_t = wrap(t->wrap_t);
      sm.border_color = t->border;
    }
  }
  s.fog = fog_;
  s.fog_mode = fog_mode_ == GL_LINEAR ? FogMode::Linear : fog_mode_ == GL_EXP2 ? FogMode::Exp2 : FogMode::Exp;
  s.fog_start = fog_start_, s.fog_end = fog_end_, s.fog_density = fog_density_;
  s.fog_color = fog_color_;
  s.scissor = scissor_test_;
  if (scissor_test_) {
    s.scissor_x0 = sc_x_, s.scissor_x1 = sc_x_ + sc_w_;
    s.scissor_y0 = sc_y_, s.scissor_y1 = sc_y_ + sc_h_;
  }
  s.alpha_test = alpha_test_;
  s.alpha_func = compare_func(alpha_func_);
  s.alpha_ref = alpha_ref_;
  const bool depth = depth_test_ && depth_bits_ > 0;
  s.depth_test = depth;
  s.depth_func = compare_func(depth_func_);
  s.depth_write = depth && depth_write_;
  s.polygon_offset = offset;
  s.offset_factor = offset_factor_, s.offset_units = offset_units_;
  s.blend = blend_;
  s.blend_src_rgb = s.blend_src_alpha = blend_factor(blend_src_);
  s.blend_dst_rgb = s.blend_dst_alpha = blend_factor(blend_dst_);
  s.color_mask = uint8_t((mask_[0] ? 1 : 0) | (mask_[1] ? 2 : 0) | (mask_[2] ? 4 : 0) | (mask_[3] ? 8 : 0));
  return s;
}

Context::Pending& Context::target(PrimitiveKind kind, bool offset) {
  if (have_pending_ && (pixel_dirty_ || pending_.kind != kind || pending_.offset != offset ||
                        pending_.index.size() >= kMaxBatchVertices))
    submit_pending();
  if (!have_pending_) {
    pending_.clear();
    pending_.kind = kind;
    pending_.offset = offset;
    pending_.state = pixel_state(offset);
    have_pending_ = true;
    if (++pending_gen_ == 0) {  // wrapped: forget every old mark
      for (Emitted& e : emitted_) e = {};
      pending_gen_ = 1;
    }
    pixel_dirty_ = false;
  }
  return pending_;
}

void Context::emit_vertex(uint32_t i, const Vec4& color, bool shared) {
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
  if (p.state.texture.texture) p.texcoord.push_back(v.tex);
  if (p.state.fog) p.fog.push_back(v.fog);
}

// --- matrices -------------------------------------------------------------------

M4& Context::top() {
  switch (matrix_mode_) {
    case GL_PROJECTION: return projection_.back();
    case GL_TEXTURE: return texture_matrix_.back();
    default: return modelview_.back();
  }
}

void Context::matrix_mode(GLenum mode) {
  if (in_begin_error()) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return error(GL_INVALID_ENUM);
  matrix_mode_ = mode;
}

void Context::load(const M4& m) {
  if (in_begin_error()) return;
  top() = m;
  derived_dirty_ = true;
}

void Context::multiply(const M4& m) {
  if (in_begin_error()) return;
  top() = top() * m;
  derived_dirty_ = true;
}

void Context::push_matrix() {
  if (in_begin_error()) return;
  std::vector<M4>& s = matrix_mode_ == GL_PROJECTION ? projection_ : matrix_mode_ == GL_TEXTURE ? texture_matrix_ : modelview_;
  const size_t limit = matrix_mode_ == GL_PROJECTION ? kMaxProjectionDepth
                       : matrix_mode_ == GL_TEXTURE  ? kMaxTextureDepth
                                                     : kMaxModelviewDepth;
  if (s.size() >= limit) return error(GL_STACK_OVERFLOW);
  s.push_back(s.back());
}

void Context::pop_matrix() {
  if (in_begin_error()) return;
  std::vector<M4>& s = matrix_mode_ == GL_PROJECTION ? projection_ : matrix_mode_ == GL_TEXTURE ? texture_matrix_ : modelview_;
  if (s.size() <= 1) return error(GL_STACK_UNDERFLOW);
  s.pop_back();
  derived_dirty_ = true;
}

const M4& Context::matrix(GLenum which) const {
  return which == GL_PROJECTION ? projection_.back() : which == GL_TEXTURE ? texture_matrix_.back() : modelview_.back();
}

int Context::stack_depth(GLenum which) const {
  return int(which == GL_PROJECTION ? projection_.size() : which == GL_TEXTURE ? texture_matrix_.size() : modelview_.size());
}

void Context::update_derived() {
  if (!derived_dirty_) return;
  derived_dirty_ = false;
  // Clip-space y is negated: the renderer's row 0 (its top) is then GL's bottom row, so
  // the framebuffer is in GL's (and OSMesa's) row order and is read out without a flip.
  mvp_ = projection_.back() * modelview_.back();
  for (int c = 0; c < 4; ++c) mvp_.m[c * 4 + 1] = -mvp_.m[c * 4 + 1];
  M4 inv;
  if (!invert(modelview_.back(), inv)) inv = M4{};
  // The transpose of the inverse.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) normal_matrix_.m[c * 4 + r] = inv.m[r * 4 + c];
  texture_identity_ = texture_matrix_.back().is_identity();
}

// --- per-fragment and rasterization state ---------------------------------------

void Context::enable(GLenum cap, bool on) {
  if (in_begin_error()) return;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return void(lights_[cap - GL_LIGHT0].enabled = on);
  switch (cap) {
    case GL_DEPTH_TEST: depth_test_ = on; break;
    case GL_CULL_FACE: cull_ = on; return;
    case GL_LIGHTING: lighting_ = on; return;
    case GL_NORMALIZE: normalize_ = on; return;
    case GL_RESCALE_NORMAL: rescale_normal_ = on; return;
    case GL_COLOR_MATERIAL:
      color_material_ = on;
      if (on) apply_color_material();
      return;
    case GL_TEXTURE_2D: texture_2d_ = on; break;
    case GL_BLEND: blend_ = on; break;
    case GL_ALPHA_TEST: alpha_test_ = on; break;
    case GL_FOG: fog_ = on; break;
    case GL_SCISSOR_TEST: scissor_test_ = on; break;
    case GL_POLYGON_OFFSET_FILL: offset_fill_ = on; return;
    case GL_POLYGON_OFFSET_LINE: offset_line_ = on; return;
    case GL_POLYGON_OFFSET_POINT: offset_point_ = on; return;
    // Accepted and without effect on what is drawn here (aliased points and lines,
    // colour dithering of an 8-bit framebuffer):
    case 0x0BD0: /* GL_DITHER */ return;
    default: return error(GL_INVALID_ENUM);
  }
  changed();
}

bool Context::is_enabled(GLenum cap, bool* known) const {
  *known = true;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) return lights_[cap - GL_LIGHT0].enabled;
  switch (cap) {
    case GL_DEPTH_TEST: return depth_test_;
    case GL_CULL_FACE: return cull_;
    case GL_LIGHTING: return lighting_;
    case GL_NORMALIZE: return normalize_;
    case GL_RESCALE_NORMAL: return rescale_normal_;
    case GL_COLOR_MATERIAL: return color_material_;
    case GL_TEXTURE_2D: return texture_2d_;
    case GL_BLEND: return blend_;
    case GL_ALPHA_TEST: return alpha_test_;
    case GL_FOG: return fog_;
    case GL_SCISSOR_TEST: return scissor_test_;
    case GL_POLYGON_OFFSET_FILL: return offset_fill_;
    case GL_POLYGON_OFFSET_LINE: return offset_line_;
    case GL_POLYGON_OFFSET_POINT: return offset_point_;
    case GL_VERTEX_ARRAY: return vertex_array.enabled;
    case GL_NORMAL_ARRAY: return normal_array.enabled;
    case GL_COLOR_ARRAY: return color_array.enabled;
    case GL_TEXTURE_COORD_ARRAY: return texcoord_array.enabled;
    case 0x0BD0: return true;  // GL_DITHER
    default: *known = false; return false;
  }
}

void Context::viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  vp_x_ = std::clamp(x, -kMaxViewport, kMaxViewport), vp_y_ = std::clamp(y, -kMaxViewport, kMaxViewport);
  vp_w_ = std::min(w, kMaxViewport), vp_h_ = std::min(h, kMaxViewport);
  changed();
}

void Context::depth_range(double n, double f) {
  if (in_begin_error()) return;
  depth_near_ = clamp01(n), depth_far_ = clamp01(f);
  changed();
}

void Context::scissor(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  // Kept within reach of the framebuffer's limits, so that x + width cannot overflow.
  sc_x_ = std::clamp(x, -kMaxViewport, kMaxViewport), sc_y_ = std::clamp(y, -kMaxViewport, kMaxViewport);
  sc_w_ = std::min(w, kMaxViewport), sc_h_ = std::min(h, kMaxViewport);
  changed();
}

void Context::clear(GLbitfield mask) {
  if (in_begin_error()) return;
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | 0x400 /* stencil */ | 0x200 /* accum */))
    return error(GL_INVALID_VALUE);
  if (!renderer_) return;
  submit_pending();
  const bool color = mask & GL_COLOR_BUFFER_BIT, depth = (mask & GL_DEPTH_BUFFER_BIT) && depth_bits_ > 0;
  const bool all_channels = mask_[0] && mask_[1] && mask_[2] && mask_[3];
  if (!in_frame_ && !scissor_test_ && (!color || all_channels) && (!depth || depth_write_) && (color || depth)) {
    start_clear_ = true;  // the frame begins with it (ensure_frame)
    if (color) {
      start_clear_color_ = true;
      start_color_ = {clamp01(clear_color_.x), clamp01(clear_color_.y), clamp01(clear_color_.z), clamp01(clear_color_.w)};
    }
    if (depth) start_clear_depth_ = true, start_depth_ = clear_depth_;
    return;
  }
  ensure_frame();
  ClearRequest q;
  q.color = mask & GL_COLOR_BUFFER_BIT;
  q.depth = (mask & GL_DEPTH_BUFFER_BIT) && depth_bits_ > 0;
  q.color_value = {clamp01(clear_color_.x), clamp01(clear_color_.y), clamp01(clear_color_.z), clamp01(clear_color_.w)};
  q.depth_value = clear_depth_;
  q.color_mask = uint8_t((mask_[0] ? 1 : 0) | (mask_[1] ? 2 : 0) | (mask_[2] ? 4 : 0) | (mask_[3] ? 8 : 0));
  q.depth_write = depth_write_;
  q.scissor = scissor_test_;
  if (scissor_test_) q.x0 = sc_x_, q.x1 = sc_x_ + sc_w_, q.y0 = sc_y_, q.y1 = sc_y_ + sc_h_;
  if (q.color || q.depth) renderer_->clear(q);
}

void Context::clear_depth(double d) {
  if (in_begin_error()) return;
  clear_depth_ = clamp01(d);
}

void Context::depth_func(GLenum f) {
  if (in_begin_error()) return;
  if (!is_compare(f)) return error(GL_INVALID_ENUM);
  depth_func_ = f;
  changed();
}

void Context::depth_mask(bool on) {
  if (in_begin_error()) return;
  depth_write_ = on;
  changed();
}

void Context::color_mask(bool r, bool g, bool b, bool a) {
  if (in_begin_error()) return;
  mask_[0] = r, mask_[1] = g, mask_[2] = b, mask_[3] = a;
  changed();
}

void Context::blend_func(GLenum s, GLenum d) {
  if (in_begin_error()) return;
  if (!is_blend_factor(s, true) || !is_blend_factor(d, false)) return error(GL_INVALID_ENUM);
  blend_src_ = s, blend_dst_ = d;
  changed();
}

void Context::alpha_func(GLenum f, float ref) {
  if (in_begin_error()) return;
  if (!is_compare(f)) return error(GL_INVALID_ENUM);
  alpha_func_ = f, alpha_ref_ = clamp01(ref);
  changed();
}

void Context::fog(GLenum pname, const float* v) {
  if (in_begin_error()) return;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum m = to_enum(v[0]);
      if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) return error(GL_INVALID_ENUM);
      fog_mode_ = m;
      break;
    }
    case GL_FOG_DENSITY:
      if (v[0] < 0) return error(GL_INVALID_VALUE);
      fog_density_ = v[0];
      break;
    case GL_FOG_START: fog_start_ = v[0]; break;
    case GL_FOG_END: fog_end_ = v[0]; break;
    case GL_FOG_COLOR: fog_color_ = {clamp01(v[0]), clamp01(v[1]), clamp01(v[2]), clamp01(v[3])}; break;
    case 0x0B61: /* GL_FOG_INDEX */ break;
    default: return error(GL_INVALID_ENUM);
  }
  changed();
}

void Context::hint(GLenum target, GLenum mode) {
  if (in_begin_error()) return;
  if (target < GL_PERSPECTIVE_CORRECTION_HINT || target > GL_FOG_HINT) return error(GL_INVALID_ENUM);
  if (mode != GL_DONT_CARE && mode != GL_FASTEST && mode != GL_NICEST) return error(GL_INVALID_ENUM);
  // Hints allow any quality: Velocity always interpolates perspective-correct and fogs
  // per pixel.
  hints_[target - GL_PERSPECTIVE_CORRECTION_HINT] = mode;
}

void Context::cull_face(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_FRONT && m != GL_BACK && m != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  cull_mode_ = m;
}

void Context::front_face(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_CW && m != GL_CCW) return error(GL_INVALID_ENUM);
  front_face_ = m;
}

void Context::polygon_mode(GLenum face, GLenum mode) {
  if (in_begin_error()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return error(GL_INVALID_ENUM);
  if (face != GL_BACK) polygon_mode_[0] = mode;
  if (face != GL_FRONT) polygon_mode_[1] = mode;
}

void Context::polygon_offset(float factor, float units) {
  if (in_begin_error()) return;
  offset_factor_ = factor, offset_units_ = units;
  changed();
}

void Context::point_size(float s) {
  if (in_begin_error()) return;
  if (!(s > 0)) return error(GL_INVALID_VALUE);
  point_size_ = std::min(s, 64.0f);
  changed();
}

void Context::line_width(float w) {
  if (in_begin_error()) return;
  if (!(w > 0)) return error(GL_INVALID_VALUE);
  line_width_ = std::min(w, 64.0f);
  changed();
}

void Context::shade_model(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_FLAT && m != GL_SMOOTH) return error(GL_INVALID_ENUM);
  shade_model_ = m;
}

// --- lighting state -------------------------------------------------------------

void Context::light(GLenum which, GLenum pname, const float* v) {
  if (in_begin_error()) return;
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights) return error(GL_INVALID_ENUM);
  Light& l = lights_[which - GL_LIGHT0];
  switch (pname) {
    case GL_AMBIENT: l.ambient = {v[0], v[1], v[2], v[3]}; break;
    case GL_DIFFUSE: l.diffuse = {v[0], v[1], v[2], v[3]}; break;
    case GL_SPECULAR: l.specular = {v[0], v[1], v[2], v[3]}; break;
    case GL_POSITION: l.position = modelview_.back() * Vec4{v[0], v[1], v[2], v[3]}; break;
    case GL_SPOT_DIRECTION: {
      const M4& m = modelview_.back();
      l.spot_direction = {m.m[0] * v[0] + m.m[4] * v[1] + m.m[8] * v[2], m.m[1] * v[0] + m.m[5] * v[1] + m.m[9] * v[2],
                          m.m[2] * v[0] + m.m[6] * v[1] + m.m[10] * v[2]};
      break;
    }
    case GL_SPOT_EXPONENT:
      if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE);
      l.spot_exponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if ((v[0] < 0 || v[0] > 90) && v[0] != 180) return error(GL_INVALID_VALUE);
      l.spot_cutoff = v[0];
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
      if (v[0] < 0) return error(GL_INVALID_VALUE);
      (pname == GL_CONSTANT_ATTENUATION ? l.constant : pname == GL_LINEAR_ATTENUATION ? l.linear : l.quadratic) = v[0];
      break;
    default: return error(GL_INVALID_ENUM);
  }
}

bool Context::get_light(GLenum which, GLenum pname, float* v) {
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights) return false;
  const Light& l = lights_[which - GL_LIGHT0];
  auto put = [&](Vec4 c) { v[0] = c.x, v[1] = c.y, v[2] = c.z, v[3] = c.w; };
  switch (pname) {
    case GL_AMBIENT: put(l.ambient); return true;
    case GL_DIFFUSE: put(l.diffuse); return true;
    case GL_SPECULAR: put(l.specular); return true;
    case GL_POSITION: put(l.position); return true;
    case GL_SPOT_DIRECTION: v[0] = l.spot_direction.x, v[1] = l.spot_direction.y, v[2] = l.spot_direction.z; return true;
    case GL_SPOT_EXPONENT: v[0] = l.spot_exponent; return true;
    case GL_SPOT_CUTOFF: v[0] = l.spot_cutoff; return true;
    case GL_CONSTANT_ATTENUATION: v[0] = l.constant; return true;
    case GL_LINEAR_ATTENUATION: v[0] = l.linear; return true;
    case GL_QUADRATIC_ATTENUATION: v[0] = l.quadratic; return true;
    default: return false;
  }
}

void Context::light_model(GLenum pname, const float* v) {
  if (in_begin_error()) return;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: model_ambient_ = {v[0], v[1], v[2], v[3]}; break;
    case GL_LIGHT_MODEL_TWO_SIDE: two_side_ = v[0] != 0; break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: local_viewer_ = v[0] != 0; break;
    default: return error(GL_INVALID_ENUM);
  }
}

void Context::material(GLenum face, GLenum pname, const float* v) {
  // glMaterial is allowed between glBegin and glEnd.
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  const Vec4 c{v[0], v[1], v[2], v[3]};
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 && face == GL_BACK) || (side == 1 && face == GL_FRONT)) continue;
    Material& m = materials_[side];
    switch (pname) {
      case GL_AMBIENT: m.ambient = c; break;
      case GL_DIFFUSE: m.diffuse = c; break;
      case GL_SPECULAR: m.specular = c; break;
      case GL_EMISSION: m.emission = c; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = c; break;
      case GL_SHININESS:
        if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE);
        m.shininess = v[0];
        break;
      default: return error(GL_INVALID_ENUM);
    }
  }
}

bool Context::get_material(GLenum face, GLenum pname, float* v) {
  if (face != GL_FRONT && face != GL_BACK) return false;
  const Material& m = materials_[face == GL_BACK ? 1 : 0];
  auto put = [&](Vec4 c) { v[0] = c.x, v[1] = c.y, v[2] = c.z, v[3] = c.w; };
  switch (pname) {
    case GL_AMBIENT: put(m.ambient); return true;
    case GL_DIFFUSE: put(m.diffuse); return true;
    case GL_SPECULAR: put(m.specular); return true;
    case GL_EMISSION: put(m.emission); return true;
    case GL_SHININESS: v[0] = m.shininess; return true;
    default: return false;
  }
}

void Context::color_material(GLenum face, GLenum mode) {
  if (in_begin_error()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return error(GL_INVALID_ENUM);
  color_material_face_ = face, color_material_mode_ = mode;
  if (color_material_) apply_color_material();
}

void Context::apply_color_material() {
  const float c[4] = {color_.x, color_.y, color_.z, color_.w};
  material(color_material_face_, color_material_mode_, c);
}

void Context::set_color(Vec4 c) {
  color_ = c;
  if (color_material_) apply_color_material();
}

}  // namespace velocity::gl
