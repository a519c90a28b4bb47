// 3-D textures (GL 1.2's glTexImage3D and the rest, GL_TEXTURE_3D): a level is `depth`
// slices of width x height texels (Texture::Level::depth), in the same texture objects,
// built into a velocity::Texture marked volume and sampled by the engine's one sampler
// at (s/q, t/q, r/q) with GL_TEXTURE_WRAP_R on the third axis: nearest, or GL_LINEAR's
// eight texels within a level, mip levels chosen from the derivatives of all three and
// blended as 2-D textures' are (src/raster/sampler-inl.h). GL_TEXTURE_3D enabled takes
// precedence over GL_TEXTURE_2D and GL_TEXTURE_1D. Levels are at most
// kMax3DTextureSize a side; glTexImage3D, glTexSubImage3D and glGetTexImage honour
// GL_(UN)PACK_IMAGE_HEIGHT and GL_(UN)PACK_SKIP_IMAGES.
#include "context.hpp"

namespace velocity::gl {

void Context::proxy_tex_image_3d(GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d, GLint border) {
  const int max = kMax3DTextureSize >> level;
  w -= 2 * border, h -= 2 * border, d -= 2 * border;
  const bool fits = w >= 0 && h >= 0 && d >= 0 && w <= max && h <= max && d <= max;
  TextureObject& p = texture_.proxy_3d;
  Texture::Level& l = p.levels[size_t(level)];
  l.width = fits ? w : 0, l.height = fits ? h : 0, l.depth = fits ? d : 0, l.border = fits ? border : 0;
  if (level == 0) p.internal_format = fits ? base_format(internal) : GLenum(0);
}

void Context::copy_tex_sub_image_3d(GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y,
                                    GLsizei w, GLsizei h) {
  if (in_begin_error()) return;
  const TextureObject* t = target_texture(GL_TEXTURE_3D);
  if (level < 0 || level >= kMaxTextureLevels || w < 0 || h < 0) return error(GL_INVALID_VALUE);
  const Texture::Level& l = t->levels[size_t(level)];
  if (l.width == 0) return error(GL_INVALID_OPERATION);
  if (!sub_image_inside(GL_TEXTURE_3D, l, xoffset, yoffset, zoffset, w, h, 1)) return error(GL_INVALID_VALUE);
  tex_sub_image(GL_TEXTURE_3D, level, xoffset, yoffset, w, h, read_colour_rect(x, y, w, h), zoffset, 1);
}

}  // namespace velocity::gl
