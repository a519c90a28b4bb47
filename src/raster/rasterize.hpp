// The tile rasterizer: for one tile, clear it (or keep what the last frame left), then
// run its records in submission order, each through its coverage (triangle edges, a
// line, a rectangle) and the shading kernel it was set up with.
//
// Kernels are chosen once per draw (a KernelId in each record), never per pixel. They
// run on 4x4-pixel blocks, written once against Google Highway and compiled for
// AVX-512, AVX2, SSE4 and plain C++; the best the processor has is picked at run time
// (raster/rasterize.cpp, simd/simd-inl.h).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/bins.hpp"
#include "raster/contract.hpp"

namespace velocity {
struct Framebuffer;
}

namespace velocity::raster {

// Rasterizes tile `tile` into `fb`. Reads only shared, immutable frame data and writes
// only the tile's own pixels: tiles may run concurrently. False when the tile was left
// as it was (clean from the last frame, and nothing to draw there now).
bool rasterize_tile(const TileInputs& in, int tile, Framebuffer& fb);

// Coverage of one record in one tile, for tests: calls back with every 4x4 block
// (its top-left pixel) and the 16-bit mask of covered pixels (bit y * 4 + x). With
// `depth_only`, a triangle is walked as a depth-only draw walks it (a shadow map's
// caster: only each block row's run, coverage-inl.h's row_cover).
void coverage_for_test(const RecordHeader& record, int tile_x0, int tile_y0, int tile_w, int tile_h,
                       void (*callback)(void* user, int x, int y, uint32_t mask), void* user, bool depth_only = false);

// For tests: the kernels' sampler at (u, v) with level of detail `lod`, RGBA in [0, 1];
// and their level of detail for the given screen-space derivatives of (u, v).
void sample_for_test(const SamplerView& view, float u, float v, float lod, float rgba[4]);
// The same at n <= 16 points, a vector of them at a time (lane i at (u[i], v[i]), the
// lanes past n at point n - 1): RGBA of point i at rgba[4 * i].
void sample_points_for_test(const SamplerView& view, const float* u, const float* v, int n, float lod, float* rgba);
float level_of_detail_for_test(const SamplerView& view, float dudx, float dvdx, float dudy, float dvdy);
// A 3-D texture's sample at (u, v, w) (the view of a Texture::volume texture).
void sample3_for_test(const SamplerView& view, float u, float v, float w, float lod, float rgba[4]);

// For tests: whether the AVX-512 kernels shade in whole vectors (tile-inl.h's
// shade_packed; on unless a test turns it off). Off, they shade block by block as on
// the other instruction sets; a pixel's colour must not depend on which.
void set_pixel_packing_for_test(bool on);
bool pixel_packing();

// The instruction set the kernels run with ("AVX3", "AVX2", "SSE4", "EMU128", ...).
const char* simd_target();

}  // namespace velocity::raster
