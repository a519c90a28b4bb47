// Sized internal formats (GL 1.1's table 3.16: GL_RGB4 ... GL_RGBA16, GL_ALPHA4 ...
// GL_INTENSITY16, GL_LUMINANCE*_ALPHA*, GL_R3_G3_B2) and GL 1.3's generic compressed
// formats (GL_COMPRESSED_RGB and the rest). GL lets an implementation keep a texture at
// whatever precision it chooses, as long as each component the base format has gets
// some bits and the others none (GL 1.5 section 3.8.1): pGL keeps every texture RGBA8,
// so each of these is its base format, glGetTexLevelParameter answers 8 bits for each
// component the format has and 0 for the rest, and the generic compressed formats are
// kept uncompressed (GL_TEXTURE_COMPRESSED false, as GL 1.3 allows).
#include "context.hpp"

namespace velocity::gl {

GLenum Context::sized_base_format(GLint internal) {
  switch (internal) {
    case GL_ALPHA4: case GL_ALPHA12: case GL_ALPHA16: case GL_COMPRESSED_ALPHA: return GL_ALPHA;
    case GL_LUMINANCE4: case GL_LUMINANCE12: case GL_LUMINANCE16: case GL_COMPRESSED_LUMINANCE: return GL_LUMINANCE;
    case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2: case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12:
    case GL_LUMINANCE16_ALPHA16: case GL_COMPRESSED_LUMINANCE_ALPHA:
      return GL_LUMINANCE_ALPHA;
    case GL_INTENSITY4: case GL_INTENSITY12: case GL_INTENSITY16: case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
    case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB10: case GL_RGB12: case GL_RGB16: case GL_COMPRESSED_RGB:
      return GL_RGB;
    case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGB10_A2: case GL_RGBA12: case GL_RGBA16: case GL_COMPRESSED_RGBA:
      return GL_RGBA;
    default: return 0;
  }
}

}  // namespace velocity::gl
