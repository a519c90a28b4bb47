// The context's construction and its OSMesa side: binding the caller's buffer, the
// depth buffer OSMesaGetDepthBuffer hands out, the current context (see context.hpp).
#include "context.hpp"

#include <cstdio>
#include <cstdlib>

#include "velocity/error.hpp"

namespace velocity::gl {

constinit thread_local Context* detail::current_context = nullptr;

namespace {

int threads_from_environment() {
  const char* s = std::getenv("VELOCITY_THREADS");
  if (!s) return 0;
  char* end = nullptr;
  const long n = std::strtol(s, &end, 10);
  return end != s && n > 0 && n <= 1024 ? int(n) : 0;
}

// VELOCITY_BACKEND=cpu|gpu|auto picks what draws (docs/gpu.md); unset: the CPU.
BackendChoice backend_from_environment() {
  const char* s = std::getenv("VELOCITY_BACKEND");
  if (!s || !*s) return BackendChoice::Cpu;
  if (auto b = parse_backend(s)) return *b;
  throw Error(std::string("VELOCITY_BACKEND: expected cpu, gpu or auto, got '") + s + "'");
}
}  // namespace

Context::Context(GLenum format, int depth_bits, int stencil_bits, int accum_bits)
    : format_(format), depth_bits_(depth_bits), stencil_bits_(stencil_bits > 0 ? 8 : 0), accum_bits_(accum_bits > 0 ? 16 : 0) {}

Context::~Context() = default;

// --- OSMesa ---------------------------------------------------------------------

bool Context::make_current(void* buffer, GLenum type, int width, int height) {
  if (!buffer || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 || width > kMaxViewport || height > kMaxViewport)
    return false;
  if (fbo_) {  // a framebuffer object is bound: the window's surface is the one made current
    bool ok = false;
    with_window([&] { ok = make_current(buffer, type, width, height); });
    return ok;
  }
  if (in_frame_) run_frame();
  const bool first = !renderer_;
  try {
    if (!renderer_) {
      backend_ = backend_from_environment();
      renderer_ = std::make_unique<Renderer>(width, height, backend_);
      renderer_->options.threads = threads_from_environment();
      renderer_->options.cull_back_faces = false;
      renderer_->options.ssaa = ssaa_;  // (multisample.cpp)
    } else if (width != width_ || height != height_) {
      if (const int k = samples_side_for(width, height); k != ssaa_) {
        // Another number of samples fits the new size (multisample.cpp): a new renderer,
        // as the old one's samples could not be resized to it.
        auto fresh = std::make_unique<Renderer>(width, height, backend_);
        fresh->options = renderer_->options;
        fresh->options.ssaa = ssaa_ = k;
        renderer_ = std::move(fresh);
      } else {
        renderer_->resize(width, height);
      }
      first_frame_ = true;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pGL: OSMesaMakeCurrent: %s\n", e.what());  // (GL reports only GL_FALSE)
    return false;
  }
  buffer_ = buffer;
  if (first || width != width_ || height != height_) {
    width_ = width, height_ = height;
    colour_.assign(size_t(width) * height * 4, 0);
    accum_.clear();  // (undefined after a resize; allocated again when first used)
    mirror_.reset();  // (so is the other colour buffer: buffers.cpp)
    if (!parked_.empty()) park_colour();
  }
  if (first) {
    viewport(0, 0, width, height);
    raster_.scissor = {0, 0, width, height};
  }
  return true;
}

void Context::release() {
  if (in_frame_) run_frame();
}

bool Context::depth_buffer(GLint* width, GLint* height, GLint* bytes_per_value, void** buffer) {
  if (fbo_) {
    bool ok = false;
    with_window([&] { ok = depth_buffer(width, height, bytes_per_value, buffer); });
    return ok;
  }
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

}  // namespace velocity::gl
