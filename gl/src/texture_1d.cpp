// 1-D textures (glTexImage1D and the rest, GL_TEXTURE_1D): a 1-D image is kept and
// sampled as a 2-D one of height 1, in the same texture objects, by the same sampler:
// GL's wrap and filter rules along s are the 2-D ones, t is not read (the vertex stage
// sets it to 0 and the sampler repeats it), and the level of detail comes from s
// alone. A texture object is 1-D or 2-D from its first glBindTexture. GL_TEXTURE_2D
// enabled takes precedence over GL_TEXTURE_1D, as in GL.
#include "context.hpp"

namespace velocity::gl {

TextureObject* Context::target_texture(GLenum target) {
  GLuint id;
  TextureObject* name_zero;
  switch (target) {
    case GL_TEXTURE_2D: id = texture_.bound, name_zero = &texture_.default_object; break;
    case GL_TEXTURE_1D: id = texture_.bound_1d, name_zero = &texture_.default_1d; break;
    case GL_TEXTURE_3D: id = texture_.bound_3d, name_zero = &texture_.default_3d; break;  // (texture_3d.cpp)
    default: error(GL_INVALID_ENUM); return nullptr;
  }
  if (id == 0) return name_zero;
  auto it = texture_.objects.find(id);
  return it == texture_.objects.end() ? name_zero : it->second.get();
}

}  // namespace velocity::gl
