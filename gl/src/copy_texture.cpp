// glCopyTexImage2D and glCopyTexSubImage2D: the frame is run and a rectangle of its
// colour buffer (GL's rows, bottom first: the texture's first row is the rectangle's
// bottom row) becomes a texture image, through tex_image / tex_sub_image (texture.cpp).
// Pixels outside the framebuffer are undefined in GL; here they read as opaque black.
// glGetTexLevelParameter and glGetTexImage read a level's size, format and texels back.
#include <algorithm>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

std::vector<uint32_t> Context::read_colour_rect(GLint x, GLint y, GLsizei w, GLsizei h) {
  std::vector<uint32_t> texels(size_t(w) * size_t(h), 0xff000000u);
  if (fb_.read != fb_.in_use) {  // GL_READ_FRAMEBUFFER is another framebuffer (framebuffer_objects.cpp)
    use_read_framebuffer();
    texels = read_colour_rect(x, y, w, h);
    use_draw_framebuffer();
    return texels;
  }
  if (!renderer_) return texels;
  run_frame();
  const uint8_t* rows = colour_rows();
  const bool alpha = format_ != GL_RGB && format_ != 0x4 /* OSMESA_BGR */;
  for (GLsizei j = 0; j < h; ++j) {
    const int64_t fy = int64_t(y) + j;
    if (fy < 0 || fy >= height_) continue;
    for (GLsizei i = 0; i < w; ++i) {
      const int64_t fx = int64_t(x) + i;
      if (fx < 0 || fx >= width_) continue;
      const uint8_t* p = rows + (size_t(fy) * size_t(width_) + size_t(fx)) * 4;
      texels[size_t(j) * size_t(w) + size_t(i)] =
          uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(alpha ? p[3] : 255) << 24;
    }
  }
  return texels;
}

void Context::copy_tex_image(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w, GLsizei h,
                             GLint border) {
  if (in_begin_error()) return;
  if (target == GL_TEXTURE_3D) return error(GL_INVALID_ENUM);  // (glCopyTexImage3D does not exist)
  if (!target_texture(target)) return;
  // GL 1.1, 3.8: unlike glTexImage, the copies do not take 1, 2, 3 or 4 as formats;
  // an internal format that is none is GL_INVALID_ENUM here (as Mesa, and GL 3's copies).
  if ((internal >= 1 && internal <= 4) || !base_format(GLint(internal))) return error(GL_INVALID_ENUM);
  // (A border, texture_border.cpp, is copied with the image: the rectangle counts it.)
  const BorderAxes b = border_axes(target, border);
  if (level < 0 || level >= kMaxTextureLevels || border < 0 || border > 1 || w - 2 * b.x < 0 || h - 2 * b.y < 0 ||
      w - 2 * b.x > (kMaxTextureSize >> level) || h - 2 * b.y > (kMaxTextureSize >> level))
    return error(GL_INVALID_VALUE);
  if (read_framebuffer_incomplete()) return;
  const std::vector<uint32_t> texels = read_colour_rect(x, y, w, h);
  tex_image(target, level, GLint(internal), w, h, border, &texels);
}

void Context::copy_tex_sub_image(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei w,
                                 GLsizei h) {
  if (in_begin_error()) return;
  if (target == GL_TEXTURE_3D) return error(GL_INVALID_ENUM);  // (glCopyTexSubImage3D's: texture_3d.cpp)
  const TextureObject* t = target_texture(target);
  if (!t) return;
  if (level < 0 || level >= kMaxTextureLevels || w < 0 || h < 0) return error(GL_INVALID_VALUE);
  const Texture::Level& l = t->levels[size_t(level)];
  if (l.width == 0) return error(GL_INVALID_OPERATION);
  if (!sub_image_inside(target, l, xoffset, yoffset, 0, w, h, 1)) return error(GL_INVALID_VALUE);
  if (read_framebuffer_incomplete()) return;
  tex_sub_image(target, level, xoffset, yoffset, w, h, read_colour_rect(x, y, w, h));
}

bool Context::tex_level_parameter(GLenum target, GLint level, GLenum pname, GLint* out) {
  if (in_begin_error()) return false;
  const TextureObject* tp = target == GL_PROXY_TEXTURE_2D   ? &texture_.proxy
                            : target == GL_PROXY_TEXTURE_3D ? &texture_.proxy_3d
                                                            : target_texture(target);
  if (!tp) return false;
  if (level < 0 || level >= kMaxTextureLevels) return error(GL_INVALID_VALUE), false;
  const TextureObject& t = *tp;
  const Texture::Level& l = t.levels[size_t(level)];
  // Each channel the format has is kept in 8 bits (the texels are RGBA8).
  const GLenum base = l.width ? t.internal_format : GLenum(0);
  auto bits = [&](bool has) { return has ? 8 : 0; };
  const bool rgb = base == GL_RGB || base == GL_RGBA;
  // The sizes count the border (texture_border.cpp).
  const BorderAxes b = border_axes(target, l.border);
  switch (pname) {
    case GL_TEXTURE_WIDTH: *out = l.width ? l.width + 2 * b.x : 0; return true;
    case GL_TEXTURE_HEIGHT: *out = l.width ? l.height + 2 * b.y : 0; return true;
    case GL_TEXTURE_DEPTH: *out = l.width ? l.depth + 2 * b.z : 0; return true;
    case GL_TEXTURE_BORDER: *out = l.width ? l.border : 0; return true;
    case GL_TEXTURE_INTERNAL_FORMAT: *out = GLint(l.width ? t.internal_format : 1); return true;  // (GL_TEXTURE_COMPONENTS)
    case GL_TEXTURE_RED_SIZE: case GL_TEXTURE_GREEN_SIZE: case GL_TEXTURE_BLUE_SIZE: *out = bits(rgb); return true;
    case GL_TEXTURE_ALPHA_SIZE:
      *out = bits(base == GL_RGBA || base == GL_ALPHA || base == GL_LUMINANCE_ALPHA);
      return true;
    case GL_TEXTURE_LUMINANCE_SIZE: *out = bits(base == GL_LUMINANCE || base == GL_LUMINANCE_ALPHA); return true;
    case GL_TEXTURE_INTENSITY_SIZE: *out = bits(base == GL_INTENSITY); return true;
    // (The sized and generic compressed formats: texture_formats.cpp. Colour textures
    // have no depth or stencil bits and are kept uncompressed.)
    case GL_TEXTURE_DEPTH_SIZE: case GL_TEXTURE_STENCIL_SIZE: case GL_TEXTURE_COMPRESSED: *out = 0; return true;
    default: return error(GL_INVALID_ENUM), false;
  }
}

void Context::get_tex_image(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
  if (in_begin_error()) return;
  const TextureObject* tp = target_texture(target);
  if (!tp) return;
  if (level < 0 || level >= kMaxTextureLevels) return error(GL_INVALID_VALUE);
  texture_writing(*tp);  // (an FBO drawing into it writes back what it drew: framebuffer_objects.cpp)
  int comps;
  switch (format) {
    case GL_RGBA: case GL_BGRA: comps = 4; break;
    case GL_RGB: case GL_BGR: comps = 3; break;
    case GL_LUMINANCE_ALPHA: comps = 2; break;
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: comps = 1; break;
    default: return error(GL_INVALID_ENUM);
  }
  if (type != GL_UNSIGNED_BYTE && type != GL_FLOAT) return error(GL_INVALID_ENUM);
  const TextureObject& t = *tp;
  const Texture::Level& l = t.levels[size_t(level)];
  if (!pixels || l.width == 0) return;
  // The image with its border (texture_border.cpp): a 1-D one's is its middle row's ends.
  const BorderAxes ring = border_axes(target, l.border);
  const int width = l.width + 2 * ring.x, height = l.height + 2 * ring.y, depth = l.depth + 2 * ring.z;
  const size_t stride = size_t(l.width) + 2 * size_t(l.border), rows = size_t(l.height) + 2 * size_t(l.border);
  const size_t first_row = size_t(l.border - ring.y);
  const size_t tsize = type == GL_FLOAT ? 4 : 1, align = size_t(std::max(pack_alignment, 1));
  const size_t row_bytes = (size_t(width) * size_t(comps) * tsize + align - 1) / align * align;
  // A 3-D texture's slices one after another, each of GL_PACK_IMAGE_HEIGHT rows (or its
  // height), GL_PACK_SKIP_IMAGES of them skipped first.
  const PixelStore& pack = this->pixels.pack;
  const size_t image_bytes = row_bytes * size_t(pack.image_height > 0 ? pack.image_height : height);
  uint8_t* const first = static_cast<uint8_t*>(pixels) + size_t(target == GL_TEXTURE_3D ? pack.skip_images : 0) * image_bytes;
  const GLenum base = t.internal_format;
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const uint32_t p = l.texels[(size_t(z) * rows + first_row + size_t(y)) * stride + size_t(x)];
        float r = (p & 0xff) / 255.0f, g = (p >> 8 & 0xff) / 255.0f, b = (p >> 16 & 0xff) / 255.0f, a = (p >> 24) / 255.0f;
        // GL 1.5's table 6.1: a texture's components as R, G, B, A (luminance and
        // intensity as R), then the format's.
        if (base == GL_LUMINANCE || base == GL_INTENSITY) g = b = 0, a = 1;
        if (base == GL_LUMINANCE_ALPHA) g = b = 0;
        if (base == GL_RGB) a = 1;
        if (base == GL_ALPHA) r = g = b = 0;
        float c[4] = {r, g, b, a};
        switch (format) {
          case GL_BGRA: c[0] = b, c[2] = r; break;
          case GL_BGR: c[0] = b, c[2] = r; break;
          case GL_LUMINANCE_ALPHA: c[1] = a; break;
          case GL_GREEN: c[0] = g; break;
          case GL_BLUE: c[0] = b; break;
          case GL_ALPHA: c[0] = a; break;
          default: break;  // RGBA, RGB, RED, LUMINANCE: as they are
        }
        uint8_t* dst = first + size_t(z) * image_bytes + size_t(y) * row_bytes + size_t(x) * size_t(comps) * tsize;
        for (int k = 0; k < comps; ++k) {
          if (type == GL_FLOAT) std::memcpy(dst + 4 * k, &c[k], 4);
          else dst[k] = uint8_t(c[k] * 255.0f + 0.5f);
        }
      }
}

}  // namespace velocity::gl
