// Multisample buffers (GL 1.5 section 3.2.1, GLX_ARB_multisample): a context made on a
// GLX configuration with samples draws every primitive, clear and pixel rectangle into
// k x k samples a pixel, the renderer's super-sampling (RenderOptions::ssaa), and shows
// and reads colour as their mean (the resolve). The renderer's window coordinates are
// samples: the viewport, the scissor box, point sizes and line widths go to it scaled
// by k (frame.cpp, raster_state.cpp, buffers.cpp). Depth and stencil reads take one
// value a pixel: the nearest sample's depth, the first sample's stencil index.
#include <algorithm>

#include "context.hpp"

namespace velocity::gl {

void Context::set_samples_side(int k) {
  ssaa_wanted_ = std::clamp(k, 1, 4);
  fit_samples();
}

// The sample buffer is at most kMaxViewport a side (the renderer's limit): a drawable
// wider or taller than kMaxViewport / k gets fewer samples (GL_SAMPLES says how many).
int Context::samples_side_for(int width, int height) const {
  int k = ssaa_wanted_;
  while (k > 1 && int64_t(std::max(width, height)) * k > kMaxViewport) --k;
  return k;
}

void Context::fit_samples() {
  const int k = samples_side_for(width_, height_);
  if (k == ssaa_) return;
  if (in_frame_) run_frame();
  ssaa_ = k;
  if (renderer_) {
    // The sample buffers are made again at the next frame: their contents start cleared.
    renderer_->options.ssaa = k;
    first_frame_ = true;
  }
  mirror_.reset();
  changed();
}

void Context::sample_scissor(const Box& b, int& x0, int& y0, int& x1, int& y1) const {
  x0 = to_samples(b.x), y0 = to_samples(b.y);
  x1 = to_samples(b.x + b.width), y1 = to_samples(b.y + b.height);
}

bool Context::get_multisample(GLenum pname, std::vector<double>& out) const {
  switch (pname) {
    case GL_SAMPLE_BUFFERS: out = {ssaa_ > 1 ? 1.0 : 0.0}; return true;
    case GL_SAMPLES: out = {ssaa_ > 1 ? double(ssaa_ * ssaa_) : 0.0}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
