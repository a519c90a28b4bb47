// The C entry points of 3-D textures (texture_3d.cpp): glTexImage3D, glTexSubImage3D
// and glCopyTexSubImage3D, compiled into display lists as the 2-D calls are
// (glTexImage3D on GL_PROXY_TEXTURE_3D is never compiled). glTexParameter,
// glGetTexLevelParameter, glGetTexImage, glBindTexture and glEnable take GL_TEXTURE_3D.
#include <GL/gl.h>

#include <memory>

#include "api_entry.hpp"
#include "context.hpp"
#include "pixels.hpp"

using velocity::gl::Context;
using velocity::gl::entry::compiled;

extern "C" {

void glTexImage3D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d, GLint border,
                  GLenum format, GLenum type, const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      const bool proxy = target == GL_PROXY_TEXTURE_3D;
      if (target != GL_TEXTURE_3D && !proxy) return c.error(GL_INVALID_ENUM);
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || h < 0 || d < 0 || border < 0 || border > 1 ||
          !Context::base_format(internal))
          return c.error(GL_INVALID_VALUE);
      if (proxy) {
        if (c.in_begin_error()) return;
        if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
        if (!velocity::gl::unpack_rgba(format, type, 0, 0, c.pixels.unpack, nullptr)) return c.error(GL_INVALID_ENUM);
        return c.proxy_tex_image_3d(level, internal, w, h, d, border);
      }
      const int max = (velocity::gl::kMax3DTextureSize >> level) + 2 * border;
      if (w > max || h > max || d > max) return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      auto texels = velocity::gl::unpack_rgba_3d(format, type, w, h, d, c.pixels.unpack, pixels, c.pixels.transfer);
      if (!texels) return c.error(GL_INVALID_ENUM);
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      const bool given = pixels != nullptr;
      compiled([=](Context& k) { k.tex_image(target, level, internal, w, h, border, given ? data.get() : nullptr, d); }));
}

void glTexSubImage3D(GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei w, GLsizei h, GLsizei d,
                     GLenum format, GLenum type, const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (target != GL_TEXTURE_3D) return c.error(GL_INVALID_ENUM);
      const int max = velocity::gl::kMax3DTextureSize + 2;
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || h < 0 || d < 0 || w > max || h > max ||
          d > max)
          return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      // Null pixels: the ranges are still checked (tex_sub_image), nothing is written.
      auto texels = velocity::gl::unpack_rgba_3d(format, type, pixels ? w : 0, h, pixels ? d : 0, c.pixels.unpack,
                                                 pixels, c.pixels.transfer);
      if (!texels) return c.error(GL_INVALID_ENUM);
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      compiled([=](Context& k) { k.tex_sub_image(target, level, x, y, w, h, *data, z, d); }));
}

void glCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y,
                         GLsizei w, GLsizei h) {
  LIST(if (target != GL_TEXTURE_3D) return c.error(GL_INVALID_ENUM);
       c.copy_tex_sub_image_3d(level, xoffset, yoffset, zoffset, x, y, w, h));
}

// GL_EXT_texture3D's names (the extension GL 1.2 took in whole).
void glTexImage3DEXT(GLenum target, GLint level, GLenum internal, GLsizei w, GLsizei h, GLsizei d, GLint border,
                     GLenum format, GLenum type, const GLvoid* pixels) {
  glTexImage3D(target, level, GLint(internal), w, h, d, border, format, type, pixels);
}
void glTexSubImage3DEXT(GLenum target, GLint level, GLint x, GLint y, GLint z, GLsizei w, GLsizei h, GLsizei d,
                        GLenum format, GLenum type, const GLvoid* pixels) {
  glTexSubImage3D(target, level, x, y, z, w, h, d, format, type, pixels);
}

}  // extern "C"
