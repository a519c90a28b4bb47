// Super-sampling resolve: from the sample buffers (k x k samples per output pixel) to
// output-size images.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framebuffer/framebuffer.hpp"
#include "velocity/image.hpp"

namespace velocity {

// Each output pixel is the mean of its k x k colour samples (a box filter), rounded.
Image resolve_color(const Framebuffer& samples, int k);
// Each output pixel shows the nearest of its k x k depth samples, then as
// Framebuffer::depth_image.
Image resolve_depth(const Framebuffer& samples, int k);

// resolve_color into caller memory: width/k x height/k rows of RGBA8 (channels 4) or
// RGB8 (channels 3) pixels, `row_bytes` apart.
void resolve_color_into(const Framebuffer& samples, int k, uint8_t* rgba, size_t row_bytes, int channels = 4);
// The same for output rows [y0, y1) only (`rgba` is still the image's first row): bands
// of rows are independent, so threads can share the work.
void resolve_color_rows(const Framebuffer& samples, int k, uint8_t* rgba, size_t row_bytes, int channels, int y0, int y1);
// The output pixels whose k x k samples all lie in tile `tile` (k <= 16), as packed RGBA8
// into `out` (the output image's first pixel, `stride` pixels a row): what the frame's
// tile workers do right after drawing a tile, while its samples are still in cache.
// Tiles write disjoint pixels, so they may run concurrently.
void resolve_tile_color(const Framebuffer& samples, int k, int tile, uint32_t* out, size_t stride);
// The output rows and columns whose samples straddle two tiles (none unless 64 % k != 0:
// k = 3 is the one such factor a renderer takes), the rest of a resolve_tile_color
// image. Line i of resolve_seam_count: rows first, then columns (without the pixels of
// seam rows), so lines write disjoint pixels and may run concurrently.
int resolve_seam_count(const Framebuffer& samples, int k);
void resolve_seam(const Framebuffer& samples, int k, int line, uint32_t* out, size_t stride);
// Per output pixel, the window depth of its nearest sample (1 where nothing was drawn).
std::vector<float> resolve_window_depth(const Framebuffer& samples, int k);
// The same into `out` (width/k floats a row), output rows [y0, y1) only.
void resolve_window_depth_rows(const Framebuffer& samples, int k, float* out, int y0, int y1);
// Per output pixel, the object id of its nearest sample (the first of equal depths, in
// row order), never a mix of ids. Empty when the framebuffer keeps no ids.
std::vector<uint32_t> resolve_object_ids(const Framebuffer& samples, int k);

}  // namespace velocity
