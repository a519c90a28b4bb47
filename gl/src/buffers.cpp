// Front and back colour buffers: glDrawBuffer and glReadBuffer (GL 1.5 sections 4.2.1
// and 4.3.2) and the swap of a double-buffered GLX drawable. An OSMesa context has one
// colour buffer, the front; a GLX context on a double-buffered window has a back
// buffer too, sharing the depth, stencil and accumulation buffers.
//
// The renderer holds one colour buffer, the one drawn into (held_); the other is kept
// here, as RGBA rows bottom first (parked_). When glDrawBuffer turns to the other one,
// the two are exchanged: the renderer's colour is read out and the parked rows are
// written into it. GL_FRONT_AND_BACK draws every batch and clear into a second
// renderer as well (mirror_), which starts with the parked colour and the first one's
// depth and stencil, so that each colour buffer gets its own blending and masks.
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
constexpr int kFront = 1, kBack = 2;

// The buffers `mode` names (kFront | kBack), -1 for an enum that is no buffer's name
// (GL_INVALID_ENUM) and 0 for GL_NONE or buffers no context has (right, auxiliary:
// with `exists` false, GL_INVALID_OPERATION). `read`: glReadBuffer's, where a name of
// two buffers reads the front (GL_FRONT_AND_BACK too, as Mesa takes it).
int buffers_named(GLenum mode, bool read, bool* exists) {
  *exists = true;
  switch (mode) {
    case GL_NONE: return 0;
    case GL_FRONT: case GL_FRONT_LEFT: return kFront;
    case GL_BACK: case GL_BACK_LEFT: return kBack;
    case GL_LEFT: return read ? kFront : kFront | kBack;
    case GL_FRONT_AND_BACK: return read ? kFront : kFront | kBack;
    case GL_RIGHT: case GL_FRONT_RIGHT: case GL_BACK_RIGHT:
    case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
      *exists = false;
      return 0;
    default: return -1;
  }
}

// A framebuffer object's colour buffers (framebuffer_objects.cpp): GL_COLOR_ATTACHMENT0
// as kFront, GL_NONE 0; the window's names and the attachments past the first are
// no buffer it has (0 and GL_INVALID_OPERATION), anything else -1.
int attachment_named(GLenum mode) {
  if (mode == GL_COLOR_ATTACHMENT0) return kFront;
  if (mode == GL_NONE || (mode > GL_COLOR_ATTACHMENT0 && mode <= GL_COLOR_ATTACHMENT15)) return 0;
  bool exists = true;
  return buffers_named(mode, false, &exists) < 0 ? -1 : 0;
}

}  // namespace

// A frame of `r` that writes the given colour, depth and stencil rows (bottom first;
// null: left as they are) as clears of the runs of equal values in each row: exact
// values, whatever the backend. `fresh`: the buffers start cleared (a new renderer).
// `k`: samples a pixel's side (multisample.cpp); every sample of a pixel gets its value.
// (Also what loads a framebuffer object's renderer, k = 1: framebuffer_objects.cpp.)
void write_surface_rows(Renderer& r, int w, int h, int k, const uint8_t* rgba, const float* depth,
                        const uint8_t* stencil, bool fresh) {
  FrameStart start;
  start.clear_color_buffer = start.clear_depth_buffer = start.clear_stencil_buffer = fresh;
  start.color = {0, 0, 0, 0};
  r.begin_frame(Camera{}, {}, start);
  auto run_end = [w](int x, auto same) {
    int e = x + 1;
    while (e < w && same(e)) ++e;
    return e;
  };
  for (int y = 0; y < h; ++y) {
    const size_t row = size_t(y) * size_t(w);
    ClearRequest q;
    q.scissor = true;
    q.y0 = y * k, q.y1 = (y + 1) * k;
    for (int x = 0; rgba && x < w;) {
      const uint8_t* p = rgba + (row + size_t(x)) * 4;
      const int e = run_end(x, [&](int i) { return std::memcmp(rgba + (row + size_t(i)) * 4, p, 4) == 0; });
      q.color = true, q.depth = false, q.stencil = false;
      q.color_value = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
      q.x0 = x * k, q.x1 = e * k;
      r.clear(q);
      x = e;
    }
    for (int x = 0; depth && x < w;) {
      const float d = depth[row + size_t(x)];
      const int e = run_end(x, [&](int i) { return depth[row + size_t(i)] == d; });
      q.color = false, q.depth = true, q.stencil = false;
      q.depth_value = d;
      q.x0 = x * k, q.x1 = e * k;
      r.clear(q);
      x = e;
    }
    for (int x = 0; stencil && x < w;) {
      const uint8_t s = stencil[row + size_t(x)];
      const int e = run_end(x, [&](int i) { return stencil[row + size_t(i)] == s; });
      q.color = false, q.depth = false, q.stencil = true;
      q.stencil_value = s, q.stencil_mask = 0xff;
      q.x0 = x * k, q.x1 = e * k;
      r.clear(q);
      x = e;
    }
  }
  r.end_frame();
}

void Context::set_double_buffered(bool on) {
  if (fbo_) return with_window([&] { set_double_buffered(on); });  // (the window's buffers)
  if (on == double_buffered_) return;
  double_buffered_ = on;
  // GL's initial draw and read buffer: the back one where there is one.
  draw_buffer_ = read_buffer_ = on ? GL_BACK : GL_FRONT;
  drawn_ = read_ = held_ = on ? kBack : kFront;
  mirror_.reset();
  parked_.clear();
}

void Context::draw_buffer(GLenum mode) {
  if (in_begin_error()) return;
  bool exists = true;
  int named = fbo_ ? attachment_named(mode) : buffers_named(mode, false, &exists);
  if (named < 0) return error(GL_INVALID_ENUM);
  if (!double_buffered_) named &= kFront;
  if (mode != GL_NONE && named == 0) return error(GL_INVALID_OPERATION);
  if (fbo_) framebuffer_buffers_changing();  // (its completeness depends on them)
  draw_buffer_ = mode;
  if (named == drawn_) return;
  run_frame();  // what was drawn goes to the buffers it was drawn to
  mirror_.reset();  // (run_frame parked the mirror's colour)
  drawn_ = named;
  changed();
  // One buffer drawn (or both, with the mirror): the renderer holds it (or either).
  if (double_buffered_ && named != 0 && named != (kFront | kBack) && named != held_) hold(named);
}

void Context::read_buffer(GLenum mode) {
  if (in_begin_error()) return;
  bool exists = true;
  int named = fbo_ ? attachment_named(mode) : buffers_named(mode, true, &exists);
  if (named < 0) return error(GL_INVALID_ENUM);
  if (!double_buffered_) named &= kFront;
  if (mode != GL_NONE && named == 0) return error(GL_INVALID_OPERATION);
  if (fbo_) framebuffer_buffers_changing();
  read_buffer_ = mode;
  read_ = named;
}

bool Context::no_read_buffer() {
  if (read_ != 0) return false;
  error(GL_INVALID_OPERATION);
  return true;
}

void Context::park_colour() {
  if (parked_.size() != size_t(width_) * size_t(height_) * 4) parked_.assign(size_t(width_) * size_t(height_) * 4, 0);
}

// The renderer's colour becomes the `which` buffer: the two are exchanged.
void Context::hold(int which) {
  park_colour();
  if (!renderer_ || width_ <= 0) return void(held_ = which);
  run_frame();
  // colour_ is the renderer's colour as the last frame left it (run_frame keeps it).
  write_surface_rows(*renderer_, width_, height_, ssaa_, parked_.data(), nullptr, nullptr, first_frame_);
  first_frame_ = false;
  colour_.swap(parked_);
  held_ = which;
}

// GL_FRONT_AND_BACK: the second renderer, with the parked buffer's colour and the
// first one's depth and stencil (begun before the frame that draws into both).
void Context::start_mirror() {
  park_colour();
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  if (!first_frame_) {
    if (depth_bits_ > 0) depth = renderer_->window_depth();
    if (stencil_bits_ > 0) {
      stencil.resize(size_t(width_) * size_t(height_));
      renderer_->read_stencil(stencil.data());
    }
  }
  auto m = std::make_unique<Renderer>(width_, height_, backend_);
  m->options = renderer_->options;
  write_surface_rows(*m, width_, height_, ssaa_, parked_.data(), depth.empty() ? nullptr : depth.data(),
             stencil.empty() ? nullptr : stencil.data(), true);
  mirror_ = std::move(m);
}

// The inverse of run_frame's copy out: the caller's buffer, in its format and row order,
// becomes the renderer's colour (the back buffer's, where there is one).
void Context::load_buffer_colour() {
  if (fbo_) return with_window([&] { load_buffer_colour(); });  // (the window's buffers)
  if (in_frame_) run_frame();
  if (!renderer_ || !buffer_) return;
  // Where red, green, blue and alpha sit in one of the buffer's pixels (-1: no alpha,
  // opaque), by OSMesa format.
  struct Layout {
    int bytes;
    int at[4];
  };
  const Layout layout = format_ == GL_RGB ? Layout{3, {0, 1, 2, -1}}
                        : format_ == 0x4 /* OSMESA_BGR */ ? Layout{3, {2, 1, 0, -1}}
                        : format_ == 0x1 /* OSMESA_BGRA */ ? Layout{4, {2, 1, 0, 3}}
                        : format_ == GL_RGBA ? Layout{4, {0, 1, 2, 3}}
                                             : Layout{4, {1, 2, 3, 0}};  // OSMESA_ARGB
  const int stride_px = row_length > 0 ? row_length : width_;
  const uint8_t* in = static_cast<const uint8_t*>(buffer_);
  std::vector<uint8_t> rows(size_t(width_) * size_t(height_) * 4);
  for (int y = 0; y < height_; ++y) {
    const uint8_t* src = in + size_t(y_up ? y : height_ - 1 - y) * stride_px * layout.bytes;
    uint8_t* dst = rows.data() + size_t(y) * width_ * 4;
    for (int x = 0; x < width_; ++x, src += layout.bytes, dst += 4)
      for (int c = 0; c < 4; ++c) dst[c] = layout.at[c] < 0 ? 255 : src[layout.at[c]];
  }
  if (double_buffered_ && held_ == kFront) {  // the back buffer is the parked one
    park_colour();
    parked_ = std::move(rows);
    return;
  }
  write_surface_rows(*renderer_, width_, height_, ssaa_, rows.data(), nullptr, nullptr, first_frame_);
  first_frame_ = false;
  colour_ = std::move(rows);
}

void Context::swap_buffers() {
  if (fbo_) return with_window([&] { swap_buffers(); });
  if (!double_buffered_ || !renderer_) return;
  run_frame();
  park_colour();
  // GLX leaves the back buffer undefined after a swap; pGL's keeps its pixels (a
  // copy from back to front, as Mesa's xlib driver does).
  if (held_ == kBack) {
    parked_ = colour_;
  } else {
    write_surface_rows(*renderer_, width_, height_, ssaa_, parked_.data(), nullptr, nullptr, first_frame_);
    first_frame_ = false;
    colour_ = parked_;
  }
  mirror_.reset();  // the front changed under it: made again from parked_ when drawn into
}

const uint8_t* Context::front_rows() {
  if (fbo_) {  // (the rows stay where they are when the surfaces are exchanged back)
    const uint8_t* rows = nullptr;
    with_window([&] { rows = front_rows(); });
    return rows;
  }
  if (!double_buffered_ || !renderer_) return nullptr;
  run_frame();
  park_colour();
  return held_ == kFront ? colour_.data() : parked_.data();
}

const uint8_t* Context::back_rows() const {
  return double_buffered_ && held_ == kFront ? parked_.data() : colour_.data();
}

const uint8_t* Context::colour_rows() const {
  if (double_buffered_ && read_ != 0 && read_ != held_) return parked_.data();
  return direct_ ? static_cast<const uint8_t*>(buffer_) : colour_.data();
}

bool Context::get_buffers(GLenum pname, std::vector<double>& out) const {
  switch (pname) {
    case GL_DOUBLEBUFFER: out = {double_buffered_ ? 1.0 : 0.0}; return true;
    case GL_DRAW_BUFFER: out = {double(draw_buffer_)}; return true;
    case GL_READ_BUFFER: out = {double(read_buffer_)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
