// Super-sampling resolve: from the sample buffers (k x k samples per output pixel) to
// output-size images.
#pragma once

#include "framebuffer/framebuffer.hpp"
#include "velocity/image.hpp"

namespace velocity {

// Each output pixel is the mean of its k x k colour samples (a box filter), rounded.
Image resolve_color(const Framebuffer& samples, int k);
// Each output pixel shows the nearest of its k x k depth samples, then as
// Framebuffer::depth_image.
Image resolve_depth(const Framebuffer& samples, int k);

}  // namespace velocity
