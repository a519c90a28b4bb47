// Texture objects: glGenTextures, glBindTexture, glTexImage2D and friends. Texels are
// stored RGBA8 per level; the velocity::Texture the renderer samples is built from
// them when the texture is first drawn after a change.
#include <algorithm>
#include <cmath>

#include "context.hpp"
#include "velocity/error.hpp"

namespace velocity::gl {

GLenum Context::base_format(GLint internal) {
  switch (internal) {
    case 1: case GL_LUMINANCE: case GL_LUMINANCE8: return GL_LUMINANCE;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE8_ALPHA8: return GL_LUMINANCE_ALPHA;
    case 3: case GL_RGB: case GL_RGB8: return GL_RGB;
    case 4: case GL_RGBA: case GL_RGBA8: return GL_RGBA;
    case GL_ALPHA: case GL_ALPHA8: return GL_ALPHA;
    case GL_INTENSITY: case GL_INTENSITY8: return GL_INTENSITY;
    default: return sized_base_format(internal);  // (texture_formats.cpp)
  }
}

TextureObject* Context::bound_texture() {
  if (texture_.bound == 0) return &texture_.default_object;
  auto it = texture_.objects.find(texture_.bound);
  return it == texture_.objects.end() ? &texture_.default_object : it->second.get();
}

void Context::gen_textures(GLsizei n, GLuint* out) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!out) return;
  for (GLsizei i = 0; i < n; ++i) {
    while (texture_.next_name == 0 || texture_.objects.count(texture_.next_name)) ++texture_.next_name;
    if (texture_.objects.size() >= 65536) return error(GL_OUT_OF_MEMORY);
    texture_.objects[texture_.next_name] = std::make_unique<TextureObject>();
    out[i] = texture_.next_name++;
  }
}

void Context::delete_textures(GLsizei n, const GLuint* ids) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    if (ids[i] == 0) continue;
    if (ids[i] == texture_.bound) texture_.bound = 0, changed();
    if (ids[i] == texture_.bound_1d) texture_.bound_1d = 0, changed();
    unbind_deleted_unit_texture(ids[i]);  // (multitexture.cpp: the other unit)
    if (texture_.objects.count(ids[i])) detach_everywhere(GL_TEXTURE, ids[i]);  // (framebuffer_objects.cpp)
    if (ids[i] == texture_.bound_3d) texture_.bound_3d = 0, changed();
    texture_.objects.erase(ids[i]);  // draws already recorded keep their built texture
  }
}

void Context::bind_texture(GLenum target, GLuint id) {
  if (in_begin_error()) return;
  if (target != GL_TEXTURE_2D && target != GL_TEXTURE_1D && target != GL_TEXTURE_3D) return error(GL_INVALID_ENUM);
  if (id != 0 && !texture_.objects.count(id)) {
    if (texture_.objects.size() >= 65536) return error(GL_OUT_OF_MEMORY);
    texture_.objects[id] = std::make_unique<TextureObject>();  // a name never generated is created on first bind
  }
  if (id != 0) {
    // A texture is 1-D, 2-D or 3-D from its first bind on (GL 1.5, 3.8.12).
    TextureObject& t = *texture_.objects[id];
    if (t.target && t.target != target) return error(GL_INVALID_OPERATION);
    t.target = target;
  }
  GLuint& bound = target == GL_TEXTURE_2D ? texture_.bound : target == GL_TEXTURE_3D ? texture_.bound_3d : texture_.bound_1d;
  if (id != bound) changed();
  bound = id;
}

// An RGBA8 texel (R in the low byte) as a texture of internal format `base` keeps it:
// RGB opaque, luminance (L, L, L, 1), luminance-alpha (L, L, L, A), alpha (0, 0, 0, A),
// intensity (GL_INTENSITY) (I, I, I, I); RGBA as it is.
uint32_t stored_texel(GLenum base, uint32_t p) {
  const uint32_t r = p & 0xff, a = p >> 24;
  switch (base) {
    case GL_RGB: return p | 0xff000000u;
    case GL_LUMINANCE: return r | r << 8 | r << 16 | 0xff000000u;
    case GL_LUMINANCE_ALPHA: return r | r << 8 | r << 16 | a << 24;
    case GL_ALPHA: return a << 24;
    case GL_INTENSITY: return r | r << 8 | r << 16 | r << 24;
    default: return p;
  }
}

void Context::tex_image(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                        const std::vector<uint32_t>* rgba, GLsizei depth) {
  if (in_begin_error()) return;
  TextureObject* tp = target_texture(target);
  if (!tp) return;
  const GLenum base = base_format(internal);
  if (!base) return error(GL_INVALID_VALUE);
  const int max = target == GL_TEXTURE_3D ? kMax3DTextureSize : kMaxTextureSize;
  if (border < 0 || border > 1) return error(GL_INVALID_VALUE);
  // With a border (texture_border.cpp) the sizes given count it: the image is inside.
  const BorderAxes b = border_axes(target, border);
  const GLsizei iw = w - 2 * b.x, ih = h - 2 * b.y, id = depth - 2 * b.z;
  if (level < 0 || level >= kMaxTextureLevels || iw < 0 || ih < 0 || id < 0 || iw > (max >> level) ||
      ih > (max >> level) || id > (max >> level) || (border && (iw == 0 || ih == 0 || id == 0)))
    return error(GL_INVALID_VALUE);
  TextureObject& t = *tp;
  texture_writing(t);  // (framebuffer_objects.cpp: an FBO drawing into it writes back first)
  Texture::Level& l = t.levels[size_t(level)];
  l.width = iw, l.height = ih, l.depth = id, l.border = border;
  // A 1-D image's border has no rows: the one row is kept three times (the sampler
  // never reads t outside it).
  const size_t rows = size_t(ih) + 2 * size_t(border);
  l.texels.assign(size_t(w) * rows * size_t(depth), 0xff000000u);
  if (rgba && rgba->size() * rows == l.texels.size() * size_t(h))
    for (size_t k = 0; k < l.texels.size(); ++k) l.texels[k] = (*rgba)[b.y == border ? k : k % size_t(w)];
  if (level == 0) {
    t.internal_format = base;
    t.format = base == GL_RGB         ? TexFormat::Rgb
               : base == GL_LUMINANCE ? TexFormat::Luminance
               : base == GL_LUMINANCE_ALPHA ? TexFormat::LuminanceAlpha
               : base == GL_ALPHA     ? TexFormat::Alpha
               : base == GL_INTENSITY ? TexFormat::Intensity
                                      : TexFormat::Rgba;
  }
  // The texels as the format keeps them: luminance (L, L, L, 1), alpha (0, 0, 0, A)...
  for (uint32_t& p : l.texels) p = stored_texel(base, p);
  t.dirty = true;
  t.serial = ++fb_.serial;
  changed();
}

void Context::proxy_tex_image(GLint level, GLint internal, GLsizei w, GLsizei h, GLint border) {
  const GLsizei iw = w - 2 * border, ih = h - 2 * border;
  const bool fits = iw >= 0 && ih >= 0 && iw <= (kMaxTextureSize >> level) && ih <= (kMaxTextureSize >> level);
  TextureObject& p = texture_.proxy;
  Texture::Level& l = p.levels[size_t(level)];
  l.width = fits ? iw : 0, l.height = fits ? ih : 0, l.border = fits ? border : 0;
  if (level == 0) p.internal_format = fits ? base_format(internal) : GLenum(0);
}

void Context::tex_sub_image(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                            const std::vector<uint32_t>& rgba, GLint z, GLsizei depth) {
  if (in_begin_error()) return;
  TextureObject* tp = target_texture(target);
  if (!tp) return;
  if (level < 0 || level >= kMaxTextureLevels || w < 0 || h < 0 || depth < 0) return error(GL_INVALID_VALUE);
  TextureObject& t = *tp;
  Texture::Level& l = t.levels[size_t(level)];
  if (l.width == 0) return error(GL_INVALID_OPERATION);
  if (!sub_image_inside(target, l, x, y, z, w, h, depth)) return error(GL_INVALID_VALUE);
  if (rgba.size() != size_t(w) * size_t(h) * size_t(depth)) return;
  texture_writing(t);
  const GLenum base = t.internal_format;
  // (x, y, z) count from the image's first texel: the border, if any, is at -1.
  const int bb = l.border, bz = border_axes(target, bb).z;
  const size_t stride = size_t(l.width) + 2 * size_t(bb), rows = size_t(l.height) + 2 * size_t(bb);
  for (int slice = 0; slice < depth; ++slice)
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) {
        const size_t at = (size_t(z + bz + slice) * rows + size_t(y + bb + row)) * stride + size_t(x + bb + col);
        l.texels[at] = stored_texel(base, rgba[(size_t(slice) * h + size_t(row)) * w + size_t(col)]);
      }
  t.dirty = true;
  t.serial = ++fb_.serial;
  changed();
}

void Context::tex_parameter(GLenum target, GLenum pname, const float* v) {
  if (in_begin_error()) return;
  TextureObject* tp = target_texture(target);
  if (!tp) return;
  TextureObject& t = *tp;
  const GLenum e = to_enum(v[0]);
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR && (e < GL_NEAREST_MIPMAP_NEAREST || e > GL_LINEAR_MIPMAP_LINEAR))
        return error(GL_INVALID_ENUM);
      t.min_filter = e;
      t.dirty = true;
      break;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return error(GL_INVALID_ENUM);
      t.mag_filter = e;
      break;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
      if (e != GL_REPEAT && e != GL_CLAMP && e != GL_CLAMP_TO_EDGE && e != GL_MIRRORED_REPEAT &&
          e != GL_CLAMP_TO_BORDER)  // (GL 1.3)
        return error(GL_INVALID_ENUM);
      (pname == GL_TEXTURE_WRAP_S ? t.wrap_s : t.wrap_t) = e;
      break;
    case GL_TEXTURE_WRAP_R:  // (3-D textures: texture_3d.cpp) the modes s and t take
      if (e != GL_REPEAT && e != GL_CLAMP && e != GL_CLAMP_TO_EDGE && e != GL_MIRRORED_REPEAT)
        return error(GL_INVALID_ENUM);
      t.wrap_r = e;
      break;
    case GL_TEXTURE_BORDER_COLOR:
      t.border = {unit(v[0]), unit(v[1]), unit(v[2]), unit(v[3])};
      break;
    case GL_GENERATE_MIPMAP:
      t.generate_mipmap = v[0] != 0;
      t.dirty = true;
      break;
    case GL_TEXTURE_BASE_LEVEL:  // GL 1.2's: the levels drawn start here ...
    case GL_TEXTURE_MAX_LEVEL:   // ... and end here (or at 1x1)
      if (!(v[0] >= 0)) return error(GL_INVALID_VALUE);
      (pname == GL_TEXTURE_BASE_LEVEL ? t.base_level : t.max_level) = v[0] < 1000 ? int(v[0]) : 1000;
      t.dirty = true;
      break;
    case GL_TEXTURE_MIN_LOD: t.min_lod = v[0]; break;  // (GL 1.2; the sampler's, in pixel_state)
    case GL_TEXTURE_MAX_LOD: t.max_lod = v[0]; break;
    case GL_TEXTURE_LOD_BIAS: t.lod_bias = v[0]; break;  // (GL 1.4)
    default: return error(GL_INVALID_ENUM);
  }
  changed();
}

void Context::tex_env(GLenum target, GLenum pname, const float* v) {
  if (in_begin_error()) return;
  if (target == GL_TEXTURE_FILTER_CONTROL) {  // GL 1.4: the texture unit's level-of-detail bias
    if (pname != GL_TEXTURE_LOD_BIAS) return error(GL_INVALID_ENUM);
    texture_.lod_bias = v[0];
    return changed();
  }
  if (target != GL_TEXTURE_ENV) return error(GL_INVALID_ENUM);
  if (pname == GL_TEXTURE_ENV_MODE) {
    const GLenum m = to_enum(v[0]);
    if (m != GL_MODULATE && m != GL_REPLACE && m != GL_DECAL && m != GL_BLEND && m != GL_ADD &&
        m != GL_COMBINE)  // (GL 1.3: tex_combine.cpp)
      return error(GL_INVALID_ENUM);
    texture_.env_mode = m;
  } else if (pname == GL_TEXTURE_ENV_COLOR) {
    texture_.env_color = {unit(v[0]), unit(v[1]), unit(v[2]), unit(v[3])};
  } else if (!tex_env_combine(pname, v)) {
    return error(GL_INVALID_ENUM);
  }
  changed();
}

// The texture the renderer samples for the next draws, or null when texturing is off
// for it (GL: an incomplete texture disables texturing).
const Texture* Context::texture_for_draw(TextureObject& t) {
  if (t.dirty) {
    t.dirty = false;
    t.built.reset();
    t.complete = false;
    // GL_TEXTURE_BASE_LEVEL and GL_TEXTURE_MAX_LEVEL choose the levels drawn: the chain
    // from the base level to the max level or 1x1, whichever comes first.
    if (t.base_level >= kMaxTextureLevels || t.max_level < t.base_level) return nullptr;
    const size_t first = size_t(t.base_level), last = size_t(std::min(t.max_level, kMaxTextureLevels - 1));
    const Texture::Level& base = t.levels[first];
    if (base.width == 0 || base.height == 0 || base.depth == 0) return nullptr;
    const bool mip = t.min_filter != GL_NEAREST && t.min_filter != GL_LINEAR;
    const bool volume = t.target == GL_TEXTURE_3D;
    if (t.generate_mipmap) {
      for (size_t i = first + 1;
           i < t.levels.size() && (t.levels[i - 1].width > 1 || t.levels[i - 1].height > 1 || t.levels[i - 1].depth > 1); ++i)
        t.levels[i] = t.levels[i - 1].border ? next_level_with_border(t.levels[i - 1], volume, t.target == GL_TEXTURE_1D)
                                             : next_mip_level(t.levels[i - 1]);
    }
    std::vector<Texture::Level> levels{base};
    if (mip) {
      for (size_t i = first + 1; (levels.back().width > 1 || levels.back().height > 1 || levels.back().depth > 1) && i <= last;
           ++i) {
        if (i >= t.levels.size()) return nullptr;
        const Texture::Level& l = t.levels[i];
        if (l.width != std::max(1, levels.back().width / 2) || l.height != std::max(1, levels.back().height / 2) ||
            l.depth != std::max(1, levels.back().depth / 2) || l.border != base.border)
          return nullptr;  // an incomplete mip chain
        levels.push_back(l);
      }
    }
    try {
      t.built = std::make_shared<const Texture>(std::move(levels), volume);
    } catch (const std::exception&) {
      return nullptr;
    }
    t.complete = true;
  }
  if (!t.built) return nullptr;
  if (frame_textures_.empty() || frame_textures_.back() != t.built) {
    frame_textures_.push_back(t.built);
    for (const Texture::Level& l : t.built->levels()) frame_texture_bytes_ += l.texels.size() * 4;
  }
  return t.built.get();
}

}  // namespace velocity::gl
