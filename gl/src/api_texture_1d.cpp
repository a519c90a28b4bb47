// The C entry points of 1-D textures (texture_1d.cpp): glTexImage1D, glTexSubImage1D,
// glCopyTexImage1D, glCopyTexSubImage1D, each the 2-D call with a height of 1 (and a
// y offset of 0), compiled into display lists as those are. glTexParameter,
// glGetTexLevelParameter, glGetTexImage and glBindTexture take GL_TEXTURE_1D too.
#include <GL/gl.h>

#include <memory>

#include "api_entry.hpp"
#include "context.hpp"
#include "pixels.hpp"

using velocity::gl::Context;
using velocity::gl::entry::compiled;

extern "C" {

void glTexImage1D(GLenum target, GLint level, GLint internal, GLsizei w, GLint border, GLenum format, GLenum type,
                  const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (target != GL_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || border < 0 || border > 1 ||
          w - 2 * border > (velocity::gl::kMaxTextureSize >> level) || !Context::base_format(internal))
          return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      auto texels = velocity::gl::unpack_rgba(format, type, w, 1, c.pixels.unpack, pixels);
      if (!texels) return c.error(GL_INVALID_ENUM);
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      const bool given = pixels != nullptr;
      compiled([=](Context& k) { k.tex_image(target, level, internal, w, 1, border, given ? data.get() : nullptr); }));
}

void glTexSubImage1D(GLenum target, GLint level, GLint x, GLsizei w, GLenum format, GLenum type, const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (target != GL_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || w > velocity::gl::kMaxTextureSize + 2)
          return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      auto texels = velocity::gl::unpack_rgba(format, type, w, 1, c.pixels.unpack, pixels);
      if (!texels) return c.error(GL_INVALID_ENUM);
      if (!pixels) return;
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      compiled([=](Context& k) { k.tex_sub_image(target, level, x, 0, w, 1, *data); }));
}

void glCopyTexImage1D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w, GLint border) {
  LIST(if (target != GL_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
       c.copy_tex_image(target, level, internal, x, y, w, 1, border));
}

void glCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei w) {
  LIST(if (target != GL_TEXTURE_1D) return c.error(GL_INVALID_ENUM);
       c.copy_tex_sub_image(target, level, xoffset, 0, x, y, w, 1));
}

}  // extern "C"
