// Framebuffer objects (GL_ARB_framebuffer_object / GL_EXT_framebuffer_object):
// framebuffers, renderbuffers, attachments, completeness, glGenerateMipmap.
//
// Each framebuffer object draws into a renderer of its own, the size of its
// attachments (the smallest of them, as ARB_framebuffer_object allows mixed sizes). The
// context keeps the framebuffer it draws into as its own members (renderer_, colour_,
// width_, the draw and read buffers...: a Surface, framebuffer_objects.hpp), so every
// drawing, clearing and reading path works on an FBO unchanged; binding another
// framebuffer runs the frame and exchanges the surfaces (swap_surface), the window's
// being parked in window_ meanwhile.
//
// The attachments' images (texture levels, renderbuffers) are where their contents
// live while their framebuffer is not drawn into. Switching away from an FBO that drew
// writes its renderer's colour, depth and stencil back into them once (write_back): a
// render-to-texture loop costs one copy of each attached image per switch, and a
// texture sampled afterwards is built from the level as drawn. Coming back, the renderer
// is loaded from the images again only when one of them changed meanwhile (a serial per
// texture and renderbuffer, bumped by every write outside a renderer). A texture written
// (glTexImage, glTexSubImage, glCopyTexImage, glGenerateMipmap) while attached to the
// framebuffer being drawn into is written back first, then loaded again after.
#include <algorithm>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
constexpr int kColour = 0, kDepth = 1, kStencil = 2;

bool framebuffer_target(GLenum target) {
  return target == GL_FRAMEBUFFER || target == GL_DRAW_FRAMEBUFFER || target == GL_READ_FRAMEBUFFER;
}

// What a renderbuffer's internal format stores (its bits; red 0 and depth 0 and
// stencil 0: not a format renderbuffers take).
bool renderbuffer_format(GLenum f, Renderbuffer& rb) {
  rb.red = rb.green = rb.blue = rb.alpha = rb.depth = rb.stencil = 0;
  switch (f) {
    case GL_RGB: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_R3_G3_B2: case GL_RGB10: case GL_RGB12: case GL_RGB16:
      rb.red = rb.green = rb.blue = 8;
      return true;
    case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8: case GL_RGB10_A2: case GL_RGBA12:
    case GL_RGBA16:
      rb.red = rb.green = rb.blue = rb.alpha = 8;
      return true;
    case GL_DEPTH_COMPONENT16: rb.depth = 16; return true;
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT24: rb.depth = 24; return true;
    case GL_DEPTH_COMPONENT32: rb.depth = 32; return true;
    case GL_STENCIL_INDEX: case GL_STENCIL_INDEX1: case GL_STENCIL_INDEX4: case GL_STENCIL_INDEX8:
    case GL_STENCIL_INDEX16:
      rb.stencil = 8;
      return true;
    case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: rb.depth = 24, rb.stencil = 8; return true;
    default: return false;
  }
}

// A texel of a texture of base format `base` as its colour buffer holds it: luminance
// and intensity in red (GL 3.0's rule for luminance buffers, as Mesa reads them back),
// alpha alone, RGB opaque.
uint32_t framebuffer_texel(GLenum base, uint32_t p) {
  switch (base) {
    case GL_LUMINANCE: case GL_INTENSITY: return (p & 0xffu) | 0xff000000u;
    case GL_LUMINANCE_ALPHA: return (p & 0xffu) | (p & 0xff000000u);
    case GL_ALPHA: return p & 0xff000000u;
    default: return p;
  }
}

// The channels a colour buffer of base format `base` keeps (RGBA bits).
uint8_t channels_of(GLenum base) {
  switch (base) {
    case GL_LUMINANCE: case GL_INTENSITY: return 0x1;
    case GL_LUMINANCE_ALPHA: return 0x9;
    case GL_ALPHA: return 0x8;
    case GL_RGB: return 0x7;
    default: return 0xf;
  }
}

// The attachment point `attachment` names: kColour, kDepth, kStencil, 3 for
// GL_DEPTH_STENCIL_ATTACHMENT; -1 with GL's error set in *err.
int attachment_index(GLenum attachment, GLenum* err) {
  switch (attachment) {
    case GL_COLOR_ATTACHMENT0: return kColour;
    case GL_DEPTH_ATTACHMENT: return kDepth;
    case GL_STENCIL_ATTACHMENT: return kStencil;
    case GL_DEPTH_STENCIL_ATTACHMENT: return 3;
    default:
      // GL_COLOR_ATTACHMENT1..15 exist, past GL_MAX_COLOR_ATTACHMENTS (1).
      *err = attachment > GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15 ? GL_INVALID_OPERATION
                                                                                       : GL_INVALID_ENUM;
      return -1;
  }
}
}  // namespace

// --- names ----------------------------------------------------------------------

FramebufferObject* Context::framebuffer_object(GLuint id) {
  auto it = fb_.objects.find(id);
  return it == fb_.objects.end() ? nullptr : it->second.get();
}

Renderbuffer* Context::renderbuffer_object(GLuint id) {
  auto it = fb_.renderbuffers.find(id);
  return it == fb_.renderbuffers.end() ? nullptr : it->second.get();
}

void Context::gen_framebuffers(GLsizei n, GLuint* out) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!out) return;
  for (GLsizei i = 0; i < n; ++i) {
    while (fb_.next_framebuffer == 0 || fb_.objects.count(fb_.next_framebuffer)) ++fb_.next_framebuffer;
    if (fb_.objects.size() >= kMaxFramebufferObjects) return error(GL_OUT_OF_MEMORY);
    fb_.objects[fb_.next_framebuffer] = nullptr;  // reserved: the object is made on its first bind
    out[i] = fb_.next_framebuffer++;
  }
}

void Context::gen_renderbuffers(GLsizei n, GLuint* out) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!out) return;
  for (GLsizei i = 0; i < n; ++i) {
    while (fb_.next_renderbuffer == 0 || fb_.renderbuffers.count(fb_.next_renderbuffer)) ++fb_.next_renderbuffer;
    if (fb_.renderbuffers.size() >= kMaxFramebufferObjects) return error(GL_OUT_OF_MEMORY);
    fb_.renderbuffers[fb_.next_renderbuffer] = nullptr;  // (as framebuffers)
    out[i] = fb_.next_renderbuffer++;
  }
}

void Context::bind_framebuffer(GLenum target, GLuint id) {
  if (in_begin_error()) return;
  if (!framebuffer_target(target)) return error(GL_INVALID_ENUM);
  if (id != 0 && !framebuffer_object(id)) {
    // A name never generated is made on its first bind (a compatibility context's rule).
    if (!fb_.objects.count(id) && fb_.objects.size() >= kMaxFramebufferObjects) return error(GL_OUT_OF_MEMORY);
    fb_.objects[id] = std::make_unique<FramebufferObject>();
  }
  if (target != GL_DRAW_FRAMEBUFFER) fb_.read = id;
  if (target != GL_READ_FRAMEBUFFER) {
    fb_.draw = id;
    use_surface(id);
  }
}

void Context::bind_renderbuffer(GLenum target, GLuint id) {
  if (in_begin_error()) return;
  if (target != GL_RENDERBUFFER) return error(GL_INVALID_ENUM);
  if (id != 0 && !renderbuffer_object(id)) {
    if (!fb_.renderbuffers.count(id) && fb_.renderbuffers.size() >= kMaxFramebufferObjects)
      return error(GL_OUT_OF_MEMORY);
    fb_.renderbuffers[id] = std::make_unique<Renderbuffer>();
  }
  fb_.renderbuffer = id;
}

void Context::delete_framebuffers(GLsizei n, const GLuint* ids) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint id = ids[i];
    if (id == 0 || !fb_.objects.count(id)) continue;
    // A bound framebuffer is unbound first (its binding reverts to the window's).
    if (fb_.read == id) fb_.read = 0;
    if (fb_.draw == id) fb_.draw = 0;
    if (fb_.in_use == id) use_surface(0);
    fb_.objects.erase(id);
  }
}

// Detaches `name` (a texture or renderbuffer being deleted) from every framebuffer
// object, the bound one written back first.
void Context::detach_everywhere(GLenum type, GLuint name) {
  for (auto& [id, f] : fb_.objects) {
    if (!f) continue;  // (a name reserved, never bound)
    for (Attachment* a : {&f->colour, &f->depth, &f->stencil}) {
      if (a->type != type || a->name != name) continue;
      if (id == fb_.in_use) {
        run_frame();
        write_back(*f);
      }
      *a = Attachment{};
      f->stale = true;
    }
  }
}

void Context::delete_renderbuffers(GLsizei n, const GLuint* ids) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    if (ids[i] == 0 || !fb_.renderbuffers.count(ids[i])) continue;
    detach_everywhere(GL_RENDERBUFFER, ids[i]);
    if (fb_.renderbuffer == ids[i]) fb_.renderbuffer = 0;
    fb_.renderbuffers.erase(ids[i]);
  }
}

void Context::renderbuffer_storage(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  if (target != GL_RENDERBUFFER) return error(GL_INVALID_ENUM);
  Renderbuffer probe;
  if (!renderbuffer_format(internal, probe)) return error(GL_INVALID_ENUM);
  if (w < 0 || h < 0 || w > kMaxRenderbufferSize || h > kMaxRenderbufferSize) return error(GL_INVALID_VALUE);
  if (samples < 0 || samples > 0) return error(GL_INVALID_VALUE);  // GL_MAX_SAMPLES is 0: no multisample buffers
  Renderbuffer* rb = renderbuffer_object(fb_.renderbuffer);
  if (!rb) return error(GL_INVALID_OPERATION);  // renderbuffer 0
  image_writing(GL_RENDERBUFFER, fb_.renderbuffer);
  const size_t n = size_t(w) * size_t(h);
  probe.internal_format = internal;
  probe.width = w, probe.height = h;
  // New storage's contents are undefined: here black, depth 1, stencil 0.
  if (probe.red) probe.colour.assign(n, 0xff000000u);
  if (probe.depth) probe.depth_values.assign(n, 1.0f);
  if (probe.stencil) probe.stencil_values.assign(n, 0);
  probe.serial = ++fb_.serial;
  *rb = std::move(probe);
  image_written();
}

// --- attachments ----------------------------------------------------------------

// The framebuffer object bound to `target`: null with GL_INVALID_ENUM (a bad target) or
// GL_INVALID_OPERATION (the window's framebuffer, 0).
FramebufferObject* Context::bound_framebuffer(GLenum target) {
  if (!framebuffer_target(target)) return error(GL_INVALID_ENUM), nullptr;
  FramebufferObject* f = framebuffer_object(target == GL_READ_FRAMEBUFFER ? fb_.read : fb_.draw);
  if (!f) error(GL_INVALID_OPERATION);
  return f;
}

void Context::set_attachment(GLenum target, GLenum attachment, const Attachment& a) {
  FramebufferObject* f = bound_framebuffer(target);
  if (!f) return;
  GLenum err = GL_NO_ERROR;
  const int index = attachment_index(attachment, &err);
  if (index < 0) return error(err);
  const GLuint id = target == GL_READ_FRAMEBUFFER ? fb_.read : fb_.draw;
  if (id == fb_.in_use) {  // what was drawn goes to the images attached until now
    run_frame();
    write_back(*f);
  }
  if (index == kColour) f->colour = a;
  if (index == kDepth || index == 3) f->depth = a;
  if (index == kStencil || index == 3) f->stencil = a;
  f->stale = true;
  changed();
}

void Context::framebuffer_texture(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level,
                                  int dims) {
  if (in_begin_error()) return;
  if (!framebuffer_target(target)) return error(GL_INVALID_ENUM);
  Attachment a;
  if (texture != 0) {
    auto it = texture_.objects.find(texture);
    if (it == texture_.objects.end()) return error(GL_INVALID_OPERATION);
    const TextureObject& t = *it->second;
    const GLenum expected = dims == 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D;
    // 3-D textures, cube maps and arrays do not exist: no texture is one of them.
    if (dims == 3 || textarget != expected || (t.target != 0 && t.target != expected))
      return error(textarget == GL_TEXTURE_1D || textarget == GL_TEXTURE_2D || dims == 3 ? GL_INVALID_OPERATION
                                                                                        : GL_INVALID_ENUM);
    if (level < 0 || level >= kMaxTextureLevels) return error(GL_INVALID_VALUE);
    a.type = GL_TEXTURE, a.name = texture, a.level = level, a.textarget = textarget;
  }
  set_attachment(target, attachment, a);
}

void Context::framebuffer_renderbuffer(GLenum target, GLenum attachment, GLenum rb_target, GLuint rb) {
  if (in_begin_error()) return;
  if (!framebuffer_target(target)) return error(GL_INVALID_ENUM);
  if (rb_target != GL_RENDERBUFFER) return error(GL_INVALID_ENUM);
  Attachment a;
  if (rb != 0) {
    if (!renderbuffer_object(rb)) return error(GL_INVALID_OPERATION);
    a.type = GL_RENDERBUFFER, a.name = rb;
  }
  set_attachment(target, attachment, a);
}

// --- images ---------------------------------------------------------------------

Context::AttachedImage Context::attached_image(const Attachment& a) {
  AttachedImage im;
  if (a.type == GL_TEXTURE) {
    auto it = texture_.objects.find(a.name);
    if (it == texture_.objects.end()) return im;
    TextureObject& t = *it->second;
    im.texture = &t;
    im.serial = t.serial;
    Texture::Level& l = t.levels[size_t(a.level)];
    im.width = l.width, im.height = l.height;
    im.colour = true;  // (every texture format pGL has is a colour format)
  } else if (a.type == GL_RENDERBUFFER) {
    Renderbuffer* rb = renderbuffer_object(a.name);
    if (!rb) return im;
    im.renderbuffer = rb;
    im.serial = rb->serial;
    im.width = rb->width, im.height = rb->height;
    im.colour = rb->red > 0, im.depth = rb->depth > 0, im.stencil = rb->stencil > 0;
  }
  return im;
}

GLenum Context::framebuffer_status(GLuint id, int* width, int* height) {
  if (id == 0) return GL_FRAMEBUFFER_COMPLETE;
  FramebufferObject* f = framebuffer_object(id);
  if (!f) return GL_FRAMEBUFFER_UNSUPPORTED;
  const AttachedImage im[3] = {attached_image(f->colour), attached_image(f->depth), attached_image(f->stencil)};
  const Attachment* att[3] = {&f->colour, &f->depth, &f->stencil};
  int w = kMaxRenderbufferSize, h = kMaxRenderbufferSize, attached = 0;
  for (int i = 0; i < 3; ++i) {
    if (att[i]->type == GL_NONE) continue;
    ++attached;
    const bool fits = i == kColour ? im[i].colour : i == kDepth ? im[i].depth : im[i].stencil;
    if (im[i].width <= 0 || im[i].height <= 0 || !fits) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    w = std::min(w, im[i].width), h = std::min(h, im[i].height);
  }
  if (attached == 0) return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  // (No GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER / READ_BUFFER: ARB_ES2_compatibility
  // dropped them, as Mesa does; a draw buffer with no image draws nothing.)
  if (width) *width = w;
  if (height) *height = h;
  return GL_FRAMEBUFFER_COMPLETE;
}

GLenum Context::check_framebuffer_status(GLenum target) {
  if (in_begin_error()) return 0;
  if (!framebuffer_target(target)) return error(GL_INVALID_ENUM), 0;
  return framebuffer_status(target == GL_READ_FRAMEBUFFER ? fb_.read : fb_.draw, nullptr, nullptr);
}

bool Context::framebuffer_incomplete() {
  if (fb_.in_use == 0) return false;
  prepare_framebuffer();
  if (renderer_) return false;
  error(GL_INVALID_FRAMEBUFFER_OPERATION);
  return true;
}

bool Context::read_framebuffer_incomplete() {
  if (fbo_) prepare_framebuffer();  // (attachments changed since the bind: the renderer is made now)
  if (framebuffer_status(fb_.read, nullptr, nullptr) == GL_FRAMEBUFFER_COMPLETE) return false;
  error(GL_INVALID_FRAMEBUFFER_OPERATION);
  return true;
}

// --- the surfaces ---------------------------------------------------------------

void Context::swap_surface(Surface& s) {
  std::swap(renderer_, s.renderer), std::swap(mirror_, s.mirror);
  std::swap(width_, s.width), std::swap(height_, s.height);
  colour_.swap(s.colour), parked_.swap(s.parked);
  std::swap(buffer_, s.buffer), std::swap(format_, s.format), std::swap(y_up, s.y_up);
  std::swap(row_length, s.row_length);
  std::swap(direct_, s.direct), std::swap(first_frame_, s.first_frame);
  std::swap(double_buffered_, s.double_buffered), std::swap(depth_requested_, s.depth_requested);
  std::swap(depth_bits_, s.depth_bits), std::swap(stencil_bits_, s.stencil_bits), std::swap(accum_bits_, s.accum_bits);
  accum_.swap(s.accum), depth_out_.swap(s.depth_out);
  std::swap(draw_buffer_, s.draw_buffer), std::swap(read_buffer_, s.read_buffer);
  std::swap(drawn_, s.drawn), std::swap(read_, s.read), std::swap(held_, s.held);
  std::swap(channel_mask_, s.channel_mask);
  std::swap(ssaa_, s.ssaa);  // (an FBO's renderer: one sample a pixel)
  changed();
}

void Context::use_surface(GLuint id) {
  if (id == fb_.in_use) return;
  run_frame();  // what was drawn lands in the framebuffer it was drawn into
  FramebufferObject* from = framebuffer_object(fb_.in_use);
  if (from) write_back(*from);
  swap_surface(from ? from->surface : window_);  // the context's members are now empty ...
  FramebufferObject* to = framebuffer_object(id);
  swap_surface(to ? to->surface : window_);  // ... and then the other framebuffer's
  fb_.in_use = to ? id : 0;
  fbo_ = to;
  if (to) prepare_framebuffer();
}

void Context::prepare_framebuffer() {
  FramebufferObject* f = fbo_;
  if (!f) return;
  const AttachedImage im[3] = {attached_image(f->colour), attached_image(f->depth), attached_image(f->stencil)};
  if (!f->stale && im[0].serial == f->synced[0] && im[1].serial == f->synced[1] && im[2].serial == f->synced[2])
    return;
  f->stale = false;
  for (int i = 0; i < 3; ++i) f->synced[i] = im[i].serial;
  f->drawn = false;
  int w = 0, h = 0;
  if (framebuffer_status(fb_.in_use, &w, &h) != GL_FRAMEBUFFER_COMPLETE) {
    renderer_.reset();  // nothing is drawn (GL_INVALID_FRAMEBUFFER_OPERATION)
    width_ = height_ = 0;
    colour_.clear();
    return;
  }
  if (!renderer_ || renderer_->width() != w || renderer_->height() != h) {
    renderer_ = std::make_unique<Renderer>(w, h, backend_);
    if (window_.renderer) renderer_->options = window_.renderer->options;
  }
  width_ = w, height_ = h;
  const size_t n = size_t(w) * size_t(h);
  colour_.assign(n * 4, 0);
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  // The images' w x h corners (bottom left), as the renderer's rows.
  if (const AttachedImage& c = im[kColour]; c.width > 0) {
    const uint32_t* src = c.texture ? c.texture->levels[size_t(f->colour.level)].texels.data() : c.renderbuffer->colour.data();
    const GLenum base = c.texture ? c.texture->internal_format : GLenum(GL_RGBA);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint32_t v = framebuffer_texel(base, src[size_t(y) * size_t(c.width) + size_t(x)]);
        std::memcpy(&colour_[(size_t(y) * size_t(w) + size_t(x)) * 4], &v, 4);
      }
  }
  if (const AttachedImage& d = im[kDepth]; d.renderbuffer) {
    depth.resize(n);
    for (int y = 0; y < h; ++y)
      std::copy_n(d.renderbuffer->depth_values.data() + size_t(y) * size_t(d.width), w, depth.data() + size_t(y) * size_t(w));
  }
  if (const AttachedImage& s = im[kStencil]; s.renderbuffer) {
    stencil.resize(n);
    for (int y = 0; y < h; ++y)
      std::copy_n(s.renderbuffer->stencil_values.data() + size_t(y) * size_t(s.width), w,
                  stencil.data() + size_t(y) * size_t(w));
  }
  depth_bits_ = im[kDepth].renderbuffer ? im[kDepth].renderbuffer->depth : 0;
  const AttachedImage& c = im[kColour];
  channel_mask_ = c.texture ? channels_of(c.texture->internal_format)
                  : c.renderbuffer && c.renderbuffer->alpha == 0 ? channels_of(GL_RGB) : 0xf;
  stencil_bits_ = im[kStencil].renderbuffer ? 8 : 0;
  const bool colour = f->colour.type != GL_NONE;
  drawn_ = draw_buffer_ != GL_NONE && colour ? 1 : 0;
  read_ = read_buffer_ != GL_NONE && colour ? 1 : 0;
  write_surface_rows(*renderer_, w, h, 1, colour_.data(), depth.empty() ? nullptr : depth.data(),
                     stencil.empty() ? nullptr : stencil.data(), true);
  first_frame_ = false;
  changed();
}

void Context::write_back(FramebufferObject& f) {
  if (!f.drawn || !renderer_ || &f != fbo_) return;
  f.drawn = false;
  const int w = width_, h = height_;
  const AttachedImage im[3] = {attached_image(f.colour), attached_image(f.depth), attached_image(f.stencil)};
  if (const AttachedImage& c = im[kColour]; c.width >= w && c.height >= h) {
    uint32_t* dst = c.texture ? c.texture->levels[size_t(f.colour.level)].texels.data() : c.renderbuffer->colour.data();
    const GLenum base = c.texture ? c.texture->internal_format : GLenum(GL_RGBA);
    for (int y = 0; y < h; ++y) {
      uint32_t* row = dst + size_t(y) * size_t(c.width);
      std::memcpy(row, &colour_[size_t(y) * size_t(w) * 4], size_t(w) * 4);  // (RGBA bytes: R in the low byte)
      if (base != GL_RGBA)
        for (int x = 0; x < w; ++x) row[x] = stored_texel(base, row[x]);
    }
    if (c.texture) {
      c.texture->dirty = true;
      c.texture->serial = ++fb_.serial;
    } else {
      c.renderbuffer->serial = ++fb_.serial;
    }
  }
  if (const AttachedImage& d = im[kDepth]; d.renderbuffer && d.width >= w && d.height >= h) {
    const std::vector<float> z = renderer_->window_depth();
    for (int y = 0; y < h; ++y)
      std::copy_n(z.data() + size_t(y) * size_t(w), w, d.renderbuffer->depth_values.data() + size_t(y) * size_t(d.width));
    d.renderbuffer->serial = ++fb_.serial;
  }
  if (const AttachedImage& s = im[kStencil]; s.renderbuffer && s.width >= w && s.height >= h) {
    std::vector<uint8_t> st(size_t(w) * size_t(h));
    renderer_->read_stencil(st.data());
    for (int y = 0; y < h; ++y)
      std::copy_n(st.data() + size_t(y) * size_t(w), w, s.renderbuffer->stencil_values.data() + size_t(y) * size_t(s.width));
    s.renderbuffer->serial = ++fb_.serial;
  }
  // The renderer holds what the images now hold: no reload on the way back.
  const AttachedImage now[3] = {attached_image(f.colour), attached_image(f.depth), attached_image(f.stencil)};
  for (int i = 0; i < 3; ++i) f.synced[i] = now[i].serial;
  changed();
}

// Before a texture's or renderbuffer's image is written outside a renderer: the
// framebuffer drawn into, if it has it attached, writes back what it drew.
void Context::image_writing(GLenum type, GLuint name) {
  FramebufferObject* f = fbo_;
  if (!f) return;
  for (const Attachment* a : {&f->colour, &f->depth, &f->stencil})
    if (a->type == type && a->name == name) {
      run_frame();
      write_back(*f);
      return;
    }
}

void Context::texture_writing(const TextureObject& t) {
  if (!fbo_) return;
  for (const auto& [name, object] : texture_.objects)
    if (object.get() == &t) return image_writing(GL_TEXTURE, name);
}

void Context::image_written() { changed(); }

void Context::framebuffer_buffers_changing() {
  run_frame();
  write_back(*fbo_);
  fbo_->stale = true;
}

// --- glGenerateMipmap -----------------------------------------------------------

void Context::generate_mipmap(GLenum target) {
  if (in_begin_error()) return;
  if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) return error(GL_INVALID_ENUM);
  TextureObject* t = target_texture(target);
  if (!t) return;
  if (t->base_level >= kMaxTextureLevels) return;
  const size_t base = size_t(t->base_level), last = size_t(std::min(t->max_level, kMaxTextureLevels - 1));
  if (t->levels[base].width == 0) return;
  texture_writing(*t);
  // Each level the 2x2 box average of the one above, down to 1x1 or the max level.
  for (size_t i = base + 1; i <= last && (t->levels[i - 1].width > 1 || t->levels[i - 1].height > 1); ++i)
    t->levels[i] = next_mip_level(t->levels[i - 1]);
  t->dirty = true;
  t->serial = ++fb_.serial;
  changed();
}

// --- queries --------------------------------------------------------------------

// (A name generated but never bound names no object yet: GL_FALSE, as Mesa.)
bool Context::is_framebuffer(GLuint id) const {
  auto it = fb_.objects.find(id);
  return it != fb_.objects.end() && it->second;
}
bool Context::is_renderbuffer(GLuint id) const {
  auto it = fb_.renderbuffers.find(id);
  return it != fb_.renderbuffers.end() && it->second;
}

void Context::get_renderbuffer_parameter(GLenum target, GLenum pname, GLint* out) {
  if (in_begin_error()) return;
  if (target != GL_RENDERBUFFER) return error(GL_INVALID_ENUM);
  const Renderbuffer* rb = renderbuffer_object(fb_.renderbuffer);
  if (!rb) return error(GL_INVALID_OPERATION);
  GLint v;
  switch (pname) {
    case GL_RENDERBUFFER_WIDTH: v = rb->width; break;
    case GL_RENDERBUFFER_HEIGHT: v = rb->height; break;
    case GL_RENDERBUFFER_INTERNAL_FORMAT: v = GLint(rb->internal_format); break;
    case GL_RENDERBUFFER_RED_SIZE: v = rb->red; break;
    case GL_RENDERBUFFER_GREEN_SIZE: v = rb->green; break;
    case GL_RENDERBUFFER_BLUE_SIZE: v = rb->blue; break;
    case GL_RENDERBUFFER_ALPHA_SIZE: v = rb->alpha; break;
    case GL_RENDERBUFFER_DEPTH_SIZE: v = rb->depth; break;
    case GL_RENDERBUFFER_STENCIL_SIZE: v = rb->stencil; break;
    case GL_RENDERBUFFER_SAMPLES: v = 0; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

// The window's framebuffer (ARB_framebuffer_object): its buffers by their own names.
void Context::window_attachment_parameter(GLenum attachment, GLenum pname, GLint* out) {
  const Surface& s = window_;
  const bool here = !fbo_;  // the window's surface is the context's own
  const int depth = here ? depth_bits_ : s.depth_bits, stencil = here ? stencil_bits_ : s.stencil_bits;
  const bool doubled = here ? double_buffered_ : s.double_buffered;
  bool exists;
  int kind;  // 0 colour, 1 depth, 2 stencil
  switch (attachment) {
    case GL_FRONT_LEFT: case GL_FRONT: case GL_LEFT: exists = true, kind = 0; break;
    case GL_BACK_LEFT: case GL_BACK: exists = doubled, kind = 0; break;
    case GL_DEPTH: exists = depth > 0, kind = 1; break;
    case GL_STENCIL: exists = stencil > 0, kind = 2; break;
    default: return error(GL_INVALID_ENUM);
  }
  GLint v = 0;
  if (!exists && pname != GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) return error(GL_INVALID_ENUM);
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: v = exists ? GL_FRAMEBUFFER_DEFAULT : GL_NONE; break;
    case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE: v = kind == 0 ? 8 : 0; break;
    case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: v = kind == 1 ? depth : 0; break;
    case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: v = kind == 2 ? stencil : 0; break;
    case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE: v = kind == 2 ? GL_UNSIGNED_INT : GL_UNSIGNED_NORMALIZED; break;
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING: v = GL_LINEAR; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

void Context::get_framebuffer_attachment_parameter(GLenum target, GLenum attachment, GLenum pname, GLint* out) {
  if (in_begin_error()) return;
  if (framebuffer_target(target) && (target == GL_READ_FRAMEBUFFER ? fb_.read : fb_.draw) == 0)
    return window_attachment_parameter(attachment, pname, out);
  FramebufferObject* f = bound_framebuffer(target);
  if (!f) return;
  GLenum err = GL_NO_ERROR;
  const int index = attachment_index(attachment, &err);
  if (index < 0) return error(err);
  if (index == 3 && (f->depth.type != f->stencil.type || f->depth.name != f->stencil.name))
    return error(GL_INVALID_OPERATION);  // two different images
  const Attachment& a = index == kColour ? f->colour : index == kStencil ? f->stencil : f->depth;
  GLint v = 0;
  if (a.type == GL_NONE) {
    if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) v = GL_NONE;
    else if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME) v = 0;
    else return error(GL_INVALID_ENUM);
    if (out) *out = v;
    return;
  }
  const AttachedImage im = attached_image(a);
  const Renderbuffer* rb = im.renderbuffer;
  const bool colour = index == kColour;
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: v = GLint(a.type); break;
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME: v = GLint(a.name); break;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL:
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET:
      if (a.type != GL_TEXTURE) return error(GL_INVALID_ENUM);
      v = pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL ? a.level : 0;
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING: v = GL_LINEAR; break;
    case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
      if (index == 3) return error(GL_INVALID_OPERATION);
      v = index == kStencil ? GL_UNSIGNED_INT : GL_UNSIGNED_NORMALIZED;
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE:
      if (colour && im.texture) {
        const GLenum base = im.texture->internal_format;
        v = base == GL_RGB || base == GL_RGBA || (pname == GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE &&
                                                  (base == GL_LUMINANCE || base == GL_LUMINANCE_ALPHA || base == GL_INTENSITY))
                ? 8 : 0;
      } else {
        v = colour && rb ? rb->red : 0;
      }
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE:
      if (colour && im.texture) {
        const GLenum base = im.texture->internal_format;
        v = base == GL_RGBA || base == GL_ALPHA || base == GL_LUMINANCE_ALPHA || base == GL_INTENSITY ? 8 : 0;
      } else {
        v = colour && rb ? rb->alpha : 0;
      }
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: v = index == kDepth && rb ? rb->depth : 0; break;
    case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: v = index == kStencil && rb ? rb->stencil : 0; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

bool Context::get_framebuffer(GLenum pname, std::vector<double>& out) const {
  if (fbo_) {  // the bits of the FBO drawn into: its image's channels, its depth renderbuffer's
    const bool luminance = (channel_mask_ & 0x6) == 0;  // (luminance and intensity bits are not red)
    switch (pname) {
      case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: out = {luminance ? 0.0 : 8.0}; return true;
      case GL_ALPHA_BITS: out = {channel_mask_ & 0x8 ? 8.0 : 0.0}; return true;
      case GL_DEPTH_BITS: out = {double(depth_bits_)}; return true;
      default: break;
    }
  }
  switch (pname) {
    case GL_FRAMEBUFFER_BINDING: out = {double(fb_.draw)}; return true;  // (= GL_DRAW_FRAMEBUFFER_BINDING)
    case GL_READ_FRAMEBUFFER_BINDING: out = {double(fb_.read)}; return true;
    case GL_RENDERBUFFER_BINDING: out = {double(fb_.renderbuffer)}; return true;
    case GL_MAX_COLOR_ATTACHMENTS: out = {1}; return true;
    case GL_MAX_RENDERBUFFER_SIZE: out = {double(kMaxRenderbufferSize)}; return true;
    case GL_MAX_SAMPLES: out = {0}; return true;
    default: return false;
  }
}

// --- the window's framebuffer while an FBO is bound -------------------------------

void Context::with_window(const std::function<void()>& f) {
  const GLuint was = fb_.in_use;
  use_surface(0);
  f();
  use_surface(was);
}

}  // namespace velocity::gl
