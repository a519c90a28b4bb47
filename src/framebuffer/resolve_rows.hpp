// The super-sampling box filter of one span of an output row, for k = 2, 3 and 4 (the
// factors a renderer takes), a vector of pixels at a time: what resolve.cpp runs for
// every pixel of a super-sampled frame.
#pragma once

#include <cstdint>

#include "framebuffer/framebuffer.hpp"

namespace velocity {

// Output pixels [x0, x1) of output row y into out[0, x1 - x0): each the rounded mean,
// channel by channel, of its k x k samples, packed RGBA8. k is 2, 3 or 4; the samples
// are read where the tiles hold them.
void resolve_span_simd(const Framebuffer& samples, int k, int y, int x0, int x1, uint32_t* out);

}  // namespace velocity
