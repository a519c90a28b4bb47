// Framebuffer objects (GL_EXT_framebuffer_object, GL_ARB_framebuffer_object): their
// state, and the framebuffer "surface" the context draws into (framebuffer_objects.cpp).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "velocity/renderer.hpp"

namespace velocity::gl {

// The largest renderbuffer (GL_MAX_RENDERBUFFER_SIZE): a framebuffer object's renderer
// is at most this square, as a texture is.
constexpr int kMaxRenderbufferSize = 4096;

// What one framebuffer keeps while it is not the one drawn into: its renderer (colour,
// depth and stencil as the renderer holds them) and the context's view of it. The
// context holds these as its own members for the framebuffer drawn into now
// (Context::swap_surface exchanges them); the window's are parked in Context::window_.
struct Surface {
  std::unique_ptr<Renderer> renderer, mirror;
  int width = 0, height = 0;
  std::vector<uint8_t> colour, parked;  // RGBA, bottom row first (context.hpp)
  void* buffer = nullptr;               // the caller's (OSMesa's, GLX's); null for an FBO
  GLenum format = GL_RGBA;
  bool y_up = true;
  int row_length = 0;
  bool direct = false, first_frame = true, double_buffered = false, depth_requested = false;
  int depth_bits = 0, stencil_bits = 0, accum_bits = 0;
  std::vector<int16_t> accum;
  std::vector<uint32_t> depth_out;
  GLenum draw_buffer = GL_COLOR_ATTACHMENT0_EXT, read_buffer = GL_COLOR_ATTACHMENT0_EXT;
  int drawn = 1, read = 1, held = 1;
  uint8_t channel_mask = 0xf;
  int ssaa = 1;  // samples a pixel's side (multisample.cpp)
};

// A renderbuffer: one image of colour (RGBA8), depth, stencil or both, kept here while
// no framebuffer object bound for drawing holds it in its renderer.
struct Renderbuffer {
  GLenum internal_format = GL_RGBA;
  int width = 0, height = 0;
  int red = 0, green = 0, blue = 0, alpha = 0, depth = 0, stencil = 0;  // bits
  std::vector<uint32_t> colour;  // R in the low byte, bottom row first
  std::vector<float> depth_values;
  std::vector<uint8_t> stencil_values;
  uint64_t serial = 0;  // changed whenever its contents change outside a renderer
};

// One attachment point: a texture level or a renderbuffer, by name.
struct Attachment {
  GLenum type = GL_NONE;  // GL_TEXTURE, GL_RENDERBUFFER_EXT or GL_NONE
  GLuint name = 0;
  GLint level = 0;
  GLenum textarget = 0;  // GL_TEXTURE_1D or GL_TEXTURE_2D
};

struct FramebufferObject {
  Attachment colour, depth, stencil;
  Surface surface;  // its renderer and state while another framebuffer is drawn into
  GLenum draw_buffer = GL_COLOR_ATTACHMENT0_EXT, read_buffer = GL_COLOR_ATTACHMENT0_EXT;
  // The attachments' serials when the renderer was last loaded from or written to
  // them; `stale`: attachments changed since (the renderer is loaded again).
  uint64_t synced[3] = {0, 0, 0};
  bool stale = true;
  bool drawn = false;  // a frame ran on its renderer since it was last written back
};

struct FramebufferState {
  // The names generated or bound; null: generated, no object until its first bind.
  std::map<GLuint, std::unique_ptr<FramebufferObject>> objects;
  std::map<GLuint, std::unique_ptr<Renderbuffer>> renderbuffers;
  GLuint next_framebuffer = 1, next_renderbuffer = 1;
  GLuint draw = 0, read = 0;  // GL_DRAW_FRAMEBUFFER and GL_READ_FRAMEBUFFER bindings
  GLuint in_use = 0;          // the framebuffer whose surface the context holds now
  GLuint renderbuffer = 0;    // GL_RENDERBUFFER binding
  uint64_t serial = 0;        // the last serial handed out
};

// An RGBA8 texel as a texture of base format `base` keeps it (texture.cpp).
uint32_t stored_texel(GLenum base, uint32_t p);
// A frame of `r` that writes the given colour, depth and stencil rows (bottom first;
// null: left as they are) exactly (buffers.cpp). `fresh`: the buffers start cleared.
void write_surface_rows(Renderer& r, int w, int h, int k, const uint8_t* rgba, const float* depth, const uint8_t* stencil,
                        bool fresh);

constexpr size_t kMaxFramebufferObjects = size_t(1) << 16;  // more is GL_OUT_OF_MEMORY

}  // namespace velocity::gl
