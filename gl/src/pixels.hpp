// Client pixel data (glTexImage2D's format and type, glPixelStore's unpack state) to RGBA8.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "pixel_ops.hpp"

namespace velocity::gl {

// Components per pixel of `format`, or 0 for a format glTexImage2D does not take.
int format_components(GLenum format);

// The width x height pixels at `data` as RGBA8 texels (byte 0 red), laid out as
// `store` says (row length, skipped rows and pixels, alignment, byte swapping).
// nullopt: a format or type that is not supported (GL_INVALID_ENUM). The caller has
// bounded width and height.
// `transfer`: glPixelTransfer's scale, bias and maps, applied before the clamp.
std::optional<std::vector<uint32_t>> unpack_rgba(GLenum format, GLenum type, int width, int height,
                                                 const PixelStore& store, const void* data,
                                                 const PixelTransfer& transfer = {});

// A 3-D image of `depth` such images (glTexImage3D), slice after slice, laid out as
// `store` says (its image height and skipped images too).
std::optional<std::vector<uint32_t>> unpack_rgba_3d(GLenum format, GLenum type, int width, int height, int depth,
                                                    const PixelStore& store, const void* data,
                                                    const PixelTransfer& transfer = {});

}  // namespace velocity::gl
