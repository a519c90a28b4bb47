#include "pixels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace velocity::gl {

int format_components(GLenum format) {
  switch (format) {
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_LUMINANCE: case GL_ALPHA: case GL_RED: return 1;
    case GL_GREEN: case GL_BLUE: return 1;  // (GL 1.0's, as glDrawPixels takes them)
    default: return 0;
  }
}

namespace {
// unpack_rgba of the other types (GL_BYTE ... GL_INT, the packed ones of GL 1.2):
// glDrawPixels' reader (pixel_unpack.cpp), then 8 bits a component. nullopt for a type
// that is no type, or a packed one of another number of components than the format's
// (check_draw_format).
std::optional<std::vector<uint32_t>> unpack_rgba_any(GLenum format, GLenum type, int width, int height,
                                                     const PixelStore& store, const void* data,
                                                     const PixelTransfer& transfer) {
  if (check_draw_format(format, type) != GL_NO_ERROR) return std::nullopt;
  std::vector<uint32_t> out(size_t(width) * size_t(height), 0xff000000u);
  if (!data) return out;
  const std::vector<Vec4> rgba = unpack_pixels(format, type, width, height, store, data, transfer);
  auto byte = [](float f) { return uint32_t(std::lround(f * 255.0f)); };  // (already clamped to [0, 1])
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = byte(rgba[i].x) | byte(rgba[i].y) << 8 | byte(rgba[i].z) << 16 | byte(rgba[i].w) << 24;
  return out;
}

// unpack_rgba with glPixelTransfer's scale, bias and maps: each component as a float
// (a missing colour component 0, alpha 1; luminance to red, green and blue), then the
// transfer, then the clamp and the 8 bits a texel keeps.
std::vector<uint32_t> transferred(GLenum format, GLenum type, int width, int height, const uint8_t* src,
                                  size_t row_bytes, bool swap, const PixelTransfer& transfer) {
  const int comps = format_components(format);
  const size_t tsize = type == GL_FLOAT ? 4 : 1;
  std::vector<uint32_t> out(size_t(width) * size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = src + size_t(y) * row_bytes + size_t(x) * size_t(comps) * tsize;
      float c[4] = {0, 0, 0, 1};
      for (int k = 0; k < comps && k < 4; ++k) {
        if (tsize == 1) {
          c[k] = p[k] / 255.0f;
        } else {
          uint8_t bytes[4];
          for (int i = 0; i < 4; ++i) bytes[i] = p[4 * k + (swap ? 3 - i : i)];
          float f;
          std::memcpy(&f, bytes, 4);
          c[k] = f;
        }
      }
      float v[4] = {0, 0, 0, 1};
      switch (format) {
        case GL_RGBA: v[0] = c[0], v[1] = c[1], v[2] = c[2], v[3] = c[3]; break;
        case GL_BGRA: v[2] = c[0], v[1] = c[1], v[0] = c[2], v[3] = c[3]; break;
        case GL_RGB: v[0] = c[0], v[1] = c[1], v[2] = c[2]; break;
        case GL_BGR: v[2] = c[0], v[1] = c[1], v[0] = c[2]; break;
        case GL_LUMINANCE_ALPHA: v[0] = v[1] = v[2] = c[0], v[3] = c[1]; break;
        case GL_LUMINANCE: v[0] = v[1] = v[2] = c[0]; break;
        case GL_ALPHA: v[3] = c[0]; break;
        case GL_GREEN: v[1] = c[0]; break;
        case GL_BLUE: v[2] = c[0]; break;
        default: v[0] = c[0]; break;  // GL_RED
      }
      transfer.colour(v);
      uint32_t texel = 0;
      for (int k = 0; k < 4; ++k) {
        const float f = v[k] > 0 ? (v[k] < 1 ? v[k] : 1.0f) : 0.0f;  // (NaN reads 0)
        texel |= uint32_t(std::lround(f * 255.0f)) << (8 * k);
      }
      out[size_t(y) * size_t(width) + size_t(x)] = texel;
    }
  return out;
}
}  // namespace

std::optional<std::vector<uint32_t>> unpack_rgba(GLenum format, GLenum type, int width, int height,
                                                 const PixelStore& store, const void* data,
                                                 const PixelTransfer& transfer) {
  const int comps = format_components(format);
  if (!comps) return std::nullopt;
  size_t tsize;
  switch (type) {
    case GL_UNSIGNED_BYTE: tsize = 1; break;
    case GL_FLOAT: tsize = 4; break;
    default: return unpack_rgba_any(format, type, width, height, store, data, transfer);
  }
  std::vector<uint32_t> out(size_t(width) * size_t(height), 0xff000000u);
  if (!data || out.empty()) return out;  // (zero width or height: out.data() may be null)
  // GL 1.5 section 3.6.4: rows of GL_UNPACK_ROW_LENGTH pixels (or width), padded to the
  // alignment unless a component is as large; skipped rows and pixels first.
  const size_t align = size_t(std::max(store.alignment, 1));
  const size_t length = size_t(store.row_length > 0 ? store.row_length : width);
  size_t row_bytes = length * comps * tsize;
  if (tsize < align) row_bytes = (row_bytes + align - 1) / align * align;
  const uint8_t* src = static_cast<const uint8_t*>(data) + size_t(store.skip_rows) * row_bytes +
                       size_t(store.skip_pixels) * comps * tsize;
  const bool swap = store.swap_bytes && tsize > 1;
  const bool identity = transfer.colour_identity();
  if (!identity) return transferred(format, type, width, height, src, row_bytes, swap, transfer);
  if (format == GL_RGBA && type == GL_UNSIGNED_BYTE && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__) {
    // The common upload is already the texels' layout (byte 0 red): rows copied whole.
    for (int y = 0; y < height; ++y)
      std::memcpy(out.data() + size_t(y) * width, src + size_t(y) * row_bytes, size_t(width) * 4);
    return out;
  }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = src + size_t(y) * row_bytes + size_t(x) * comps * tsize;
      uint32_t c[4];
      for (int k = 0; k < comps; ++k) {
        if (type == GL_UNSIGNED_BYTE) {
          c[k] = p[k];
        } else {
          uint8_t bytes[4];
          for (int i = 0; i < 4; ++i) bytes[i] = p[4 * k + (swap ? 3 - i : i)];
          float f;
          std::memcpy(&f, bytes, 4);
          c[k] = f > 0 ? uint32_t(std::lround(std::min(f, 1.0f) * 255.0f)) : 0u;  // NaN reads 0
        }
      }
      uint32_t r = 0, g = 0, b = 0, a = 255;
      switch (format) {
        case GL_RGBA: r = c[0], g = c[1], b = c[2], a = c[3]; break;
        case GL_BGRA: b = c[0], g = c[1], r = c[2], a = c[3]; break;
        case GL_RGB: r = c[0], g = c[1], b = c[2]; break;
        case GL_BGR: b = c[0], g = c[1], r = c[2]; break;
        case GL_LUMINANCE_ALPHA: r = g = b = c[0], a = c[1]; break;
        case GL_LUMINANCE: r = g = b = c[0]; break;
        case GL_ALPHA: a = c[0]; break;
        case GL_GREEN: g = c[0]; break;
        case GL_BLUE: b = c[0]; break;
        default: r = c[0]; break;  // GL_RED
      }
      out[size_t(y) * width + x] = r | g << 8 | b << 16 | a << 24;
    }
  return out;
}

// --- 3-D images (texture_3d.cpp) ---------------------------------------------------
std::optional<std::vector<uint32_t>> unpack_rgba_3d(GLenum format, GLenum type, int width, int height, int depth,
                                                    const PixelStore& store, const void* data,
                                                    const PixelTransfer& transfer) {
  if (!format_components(format) || check_draw_format(format, type) != GL_NO_ERROR) return std::nullopt;
  // GL 1.5 section 3.8.1: images of GL_UNPACK_IMAGE_HEIGHT rows (or height), each of
  // unpack_rgba's rows; GL_UNPACK_SKIP_IMAGES whole images skipped first.
  const size_t row_bytes = pixel_row_bytes(format, type, width, store);
  const size_t image_bytes = row_bytes * size_t(store.image_height > 0 ? store.image_height : height);
  std::vector<uint32_t> out;
  out.reserve(size_t(width) * size_t(height) * size_t(depth));
  for (int z = 0; z < depth; ++z) {
    const void* slice = data ? static_cast<const uint8_t*>(data) + (size_t(store.skip_images) + size_t(z)) * image_bytes : nullptr;
    auto texels = unpack_rgba(format, type, width, height, store, slice, transfer);
    if (!texels) return std::nullopt;
    out.insert(out.end(), texels->begin(), texels->end());
  }
  return out;
}

}  // namespace velocity::gl
