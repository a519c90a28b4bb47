// Client pixel data (glTexImage2D's format and type, GL_UNPACK_ALIGNMENT) to RGBA8.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace velocity::gl {

// Components per pixel of `format`, or 0 for a format glTexImage2D does not take.
int format_components(GLenum format);

// The width x height pixels at `data` as RGBA8 texels (byte 0 red), rows `alignment`
// bytes aligned. nullopt: a format or type that is not supported (GL_INVALID_ENUM).
// The caller has bounded width and height.
std::optional<std::vector<uint32_t>> unpack_rgba(GLenum format, GLenum type, int width, int height, int alignment,
                                                 const void* data);

}  // namespace velocity::gl
