// Reading a frame back into caller memory (Renderer::read_color, read_window_depth,
// read_view_depth: what Python's render() and pGL's glReadPixels use). The read-back is
// memory-bound, so it runs on the renderer's threads, in bands of 64 rows (a tile row of
// samples without super-sampling).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/thread_pool.hpp"
#include "framebuffer/framebuffer.hpp"
#include "velocity/math.hpp"

namespace velocity {

// The output image (the samples resolved k x k) as RGBA8 (channels 4) or RGB8 (3) rows,
// `row_bytes` apart. `pool` may be null (the calling thread does it all).
void read_color(const Framebuffer& samples, int k, ThreadPool* pool, uint8_t* rgba, size_t row_bytes, int channels);
// The same from an image already resolved (w x h packed RGBA8 pixels, `stride` a row).
void read_color(const uint32_t* pixels, int w, int h, size_t stride, ThreadPool* pool, uint8_t* rgba,
                size_t row_bytes, int channels);
// Per output pixel, the window depth of its nearest sample (1 where nothing was drawn).
void read_window_depth(const Framebuffer& samples, int k, ThreadPool* pool, float* out);
// Per output pixel, the stencil value of its first sample.
void read_stencil(const Framebuffer& samples, int k, uint8_t* out);
// Per output pixel, the distance along the view axis (-z in eye space) for the camera
// whose `projection` drew the frame, 0 where nothing was drawn.
void read_view_depth(const Framebuffer& samples, int k, ThreadPool* pool, const Mat4& projection, float* out);

}  // namespace velocity
