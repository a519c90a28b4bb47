// Unpacking client pixel rectangles for glDrawPixels and glBitmap: GL's layout rules
// (GL 1.5 section 3.6.4: row length, skipped rows and pixels, row alignment, byte
// swapping, bitmap bit order), its formats and types (the packed types of GL 1.2
// included) and its conversion of components to floats.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "pixel_ops.hpp"

namespace velocity::gl {

namespace {

// Components of a format glDrawPixels takes (0: none).
int components(GLenum format) {
  switch (format) {
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_LUMINANCE: case GL_ALPHA: case GL_RED: case GL_GREEN: case GL_BLUE: case GL_DEPTH_COMPONENT: return 1;
    default: return 0;
  }
}

// A packed type's bytes and its fields' widths, first component first; `rev`: the
// first component is in the lowest bits (the _REV types), else in the highest.
struct Packed {
  int bytes = 0;
  int bits[4] = {0, 0, 0, 0};
  int fields = 0;
  bool rev = false;
};

Packed packed(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: return {1, {3, 3, 2, 0}, 3, false};
    case GL_UNSIGNED_BYTE_2_3_3_REV: return {1, {3, 3, 2, 0}, 3, true};
    case GL_UNSIGNED_SHORT_5_6_5: return {2, {5, 6, 5, 0}, 3, false};
    case GL_UNSIGNED_SHORT_5_6_5_REV: return {2, {5, 6, 5, 0}, 3, true};
    case GL_UNSIGNED_SHORT_4_4_4_4: return {2, {4, 4, 4, 4}, 4, false};
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return {2, {4, 4, 4, 4}, 4, true};
    case GL_UNSIGNED_SHORT_5_5_5_1: return {2, {5, 5, 5, 1}, 4, false};
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return {2, {5, 5, 5, 1}, 4, true};
    case GL_UNSIGNED_INT_8_8_8_8: return {4, {8, 8, 8, 8}, 4, false};
    case GL_UNSIGNED_INT_8_8_8_8_REV: return {4, {8, 8, 8, 8}, 4, true};
    case GL_UNSIGNED_INT_10_10_10_2: return {4, {10, 10, 10, 2}, 4, false};
    case GL_UNSIGNED_INT_2_10_10_10_REV: return {4, {10, 10, 10, 2}, 4, true};
    default: return {};
  }
}

// Bytes of one component of a plain type (0: not one).
int type_bytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
  }
}

// An element of `bytes` bytes at p, byte-swapped if asked, as an unsigned integer.
uint32_t load(const uint8_t* p, int bytes, bool swap) {
  uint8_t b[4] = {0, 0, 0, 0};
  for (int i = 0; i < bytes; ++i) b[i] = p[swap ? bytes - 1 - i : i];
  if (bytes == 1) return b[0];
  if (bytes == 2) {
    uint16_t v;
    std::memcpy(&v, b, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, b, 4);
  return v;
}

// GL 1.5 table 2.9: unsigned c / (2^b - 1), signed (2c + 1) / (2^b - 1).
float to_float(uint32_t raw, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return float(raw) / 255.0f;
    case GL_BYTE: return (2.0f * float(int8_t(raw)) + 1.0f) / 255.0f;
    case GL_UNSIGNED_SHORT: return float(raw) / 65535.0f;
    case GL_SHORT: return (2.0f * float(int16_t(raw)) + 1.0f) / 65535.0f;
    case GL_UNSIGNED_INT: return float(double(raw) / 4294967295.0);
    case GL_INT: return float((2.0 * double(int32_t(raw)) + 1.0) / 4294967295.0);
    default: {
      float f;
      std::memcpy(&f, &raw, 4);
      return f;
    }
  }
}

// Where row `row` (0 the first after the skipped ones) begins, for groups of `group`
// bytes made of elements of `element` bytes (GL 1.5 equation 3.11 and the skips).
size_t row_offset(const PixelStore& s, int width, int row, size_t group, size_t element) {
  const size_t length = size_t(s.row_length > 0 ? s.row_length : width);
  const size_t align = size_t(std::max(s.alignment, 1));
  size_t stride = length * group;
  if (element < align) stride = (stride + align - 1) / align * align;
  return (size_t(s.skip_rows) + size_t(row)) * stride + size_t(s.skip_pixels) * group;
}

}  // namespace

size_t pixel_row_bytes(GLenum format, GLenum type, int width, const PixelStore& store) {
  const Packed p = packed(type);
  const size_t element = size_t(p.bytes ? p.bytes : type_bytes(type));
  const size_t group = p.bytes ? element : element * size_t(components(format));
  return row_offset(store, width, 1, group, element) - row_offset(store, width, 0, group, element);
}

GLenum check_draw_format(GLenum format, GLenum type) {
  // (GL_BITMAP is for the index formats, which pGL's glDrawPixels does not take.)
  if (type == GL_BITMAP) return GL_INVALID_ENUM;
  const int n = components(format);
  const Packed p = packed(type);
  if (!n || (!p.bytes && !type_bytes(type))) return GL_INVALID_ENUM;
  if (p.bytes && (p.fields != n || (n == 3 && format != GL_RGB) || (n == 4 && format == GL_DEPTH_COMPONENT)))
    return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

std::vector<Vec4> unpack_pixels(GLenum format, GLenum type, int width, int height, const PixelStore& store,
                                const void* data, const PixelTransfer& transfer) {
  std::vector<Vec4> out(size_t(width) * size_t(height), Vec4{0, 0, 0, 1});
  if (!data) return out;
  const uint8_t* src = static_cast<const uint8_t*>(data);
  const int n = components(format);
  const Packed p = packed(type);
  const size_t element = size_t(p.bytes ? p.bytes : type_bytes(type));
  const size_t group = p.bytes ? element : element * size_t(n);
  const bool swap = store.swap_bytes && element > 1;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = src + row_offset(store, width, y, group, element);
    for (int x = 0; x < width; ++x) {
      const uint8_t* at = row + size_t(x) * group;
      float c[4] = {0, 0, 0, 1};
      if (p.bytes) {
        // Fields from the top bits down (or, _REV, from the bottom up).
        const uint32_t v = load(at, p.bytes, swap);
        int shift = p.rev ? 0 : p.bytes * 8;
        for (int k = 0; k < p.fields; ++k) {
          const int b = p.bits[k];
          if (!p.rev) shift -= b;
          c[k] = float((v >> shift) & ((1u << b) - 1)) / float((1u << b) - 1);
          if (p.rev) shift += b;
        }
      } else {
        for (int k = 0; k < n; ++k) c[k] = to_float(load(at + size_t(k) * element, int(element), swap), type);
      }
      Vec4 rgba{0, 0, 0, 1};
      switch (format) {
        case GL_RGBA: rgba = {c[0], c[1], c[2], c[3]}; break;
        case GL_BGRA: rgba = {c[2], c[1], c[0], c[3]}; break;
        case GL_RGB: rgba = {c[0], c[1], c[2], 1}; break;
        case GL_BGR: rgba = {c[2], c[1], c[0], 1}; break;
        case GL_LUMINANCE_ALPHA: rgba = {c[0], c[0], c[0], c[1]}; break;
        case GL_LUMINANCE: rgba = {c[0], c[0], c[0], 1}; break;
        case GL_ALPHA: rgba = {0, 0, 0, c[0]}; break;
        case GL_RED: rgba = {c[0], 0, 0, 1}; break;
        case GL_GREEN: rgba = {0, c[0], 0, 1}; break;
        case GL_BLUE: rgba = {0, 0, c[0], 1}; break;
        default: rgba = {c[0], 0, 0, 1}; break;  // GL_DEPTH_COMPONENT
      }
      if (format == GL_DEPTH_COMPONENT) {
        rgba.x = transfer.depth(rgba.x);
      } else if (!transfer.colour_identity()) {
        float t[4] = {rgba.x, rgba.y, rgba.z, rgba.w};
        transfer.colour(t);
        rgba = {t[0], t[1], t[2], t[3]};
      }
      // Colours and depth are clamped to [0, 1] after the transfer (NaN reads 0).
      auto clamp01 = [](float f) { return f > 0 ? (f < 1 ? f : 1.0f) : 0.0f; };
      out[size_t(y) * size_t(width) + size_t(x)] = {clamp01(rgba.x), clamp01(rgba.y), clamp01(rgba.z), clamp01(rgba.w)};
    }
  }
  return out;
}

int packed_type_bytes(GLenum type) { return packed(type).bytes; }

void pack_packed(GLenum type, const float* c, uint8_t* dst, bool swap) {
  const Packed p = packed(type);
  // Fields from the top bits down (or, _REV, from the bottom up), as unpack_pixels reads them.
  uint32_t v = 0;
  int shift = p.rev ? 0 : p.bytes * 8;
  for (int k = 0; k < p.fields; ++k) {
    const int b = p.bits[k];
    if (!p.rev) shift -= b;
    const float f = c[k] > 0 ? (c[k] < 1 ? c[k] : 1.0f) : 0.0f;
    v |= uint32_t(std::lround(f * float((1u << b) - 1))) << shift;
    if (p.rev) shift += b;
  }
  uint8_t bytes[4];
  if (p.bytes == 1) {
    bytes[0] = uint8_t(v);
  } else if (p.bytes == 2) {
    const uint16_t s = uint16_t(v);
    std::memcpy(bytes, &s, 2);
  } else {
    std::memcpy(bytes, &v, 4);
  }
  for (int i = 0; i < p.bytes; ++i) dst[i] = bytes[swap ? p.bytes - 1 - i : i];
}

GLenum check_stencil_type(GLenum type) {
  if (type == GL_BITMAP || type_bytes(type)) return GL_NO_ERROR;
  return packed(type).bytes ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

std::vector<uint8_t> unpack_stencil(GLenum type, int width, int height, const PixelStore& store, const void* data,
                                    const PixelTransfer& transfer) {
  if (type == GL_BITMAP) {
    std::vector<uint8_t> bits = unpack_bitmap(width, height, store, data);
    for (uint8_t& b : bits) b = uint8_t(transfer.index(b) & 0xff);
    return bits;
  }
  std::vector<uint8_t> out(size_t(width) * size_t(height), 0);
  if (!data) return out;
  const uint8_t* src = static_cast<const uint8_t*>(data);
  const size_t element = size_t(type_bytes(type));
  const bool swap = store.swap_bytes && element > 1;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = src + row_offset(store, width, y, element, element);
    for (int x = 0; x < width; ++x) {
      const uint32_t raw = load(row + size_t(x) * element, int(element), swap);
      int64_t index = 0;
      switch (type) {
        case GL_BYTE: index = int8_t(raw); break;
        case GL_SHORT: index = int16_t(raw); break;
        case GL_INT: index = int32_t(raw); break;
        case GL_FLOAT: {  // an index in a float: its whole part (NaN and the far range: 0)
          float f;
          std::memcpy(&f, &raw, 4);
          index = f > -2147483648.0f && f < 2147483648.0f ? int64_t(f) : 0;
          break;
        }
        default: index = raw; break;
      }
      // Indices are masked to the stencil buffer's 8 bits (GL 1.5 section 4.3.1).
      out[size_t(y) * size_t(width) + size_t(x)] = uint8_t(transfer.index(index) & 0xff);
    }
  }
  return out;
}

GLenum check_depth_stencil(GLenum format, GLenum type) {
  if (format == kDepthStencilFormat) return type == kUnsignedInt24_8 ? GL_NO_ERROR : GLenum(GL_INVALID_ENUM);
  return type == kUnsignedInt24_8 ? GLenum(GL_INVALID_OPERATION) : GLenum(GL_NO_ERROR);
}

void unpack_depth_stencil(int width, int height, const PixelStore& store, const void* data,
                          const PixelTransfer& transfer, std::vector<Vec4>& depth, std::vector<uint8_t>& stencil) {
  depth.assign(size_t(width) * size_t(height), Vec4{0, 0, 0, 1});
  stencil.assign(size_t(width) * size_t(height), 0);
  if (!data) return;
  const uint8_t* src = static_cast<const uint8_t*>(data);
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = src + row_offset(store, width, y, 4, 4);
    for (int x = 0; x < width; ++x) {
      const uint32_t word = load(row + size_t(x) * 4, 4, store.swap_bytes);
      const size_t at = size_t(y) * size_t(width) + size_t(x);
      const float d = transfer.depth(float(double(word >> 8) / 16777215.0));
      depth[at].x = d > 0 ? (d < 1 ? d : 1.0f) : 0.0f;
      stencil[at] = uint8_t(transfer.index(int64_t(word & 0xff)) & 0xff);
    }
  }
}

std::vector<uint8_t> unpack_bitmap(int width, int height, const PixelStore& store, const void* data) {
  std::vector<uint8_t> out(size_t(width) * size_t(height), 0);
  if (!data) return out;
  const uint8_t* src = static_cast<const uint8_t*>(data);
  // Rows of ceil(length / 8) bytes, padded to the alignment; skip_pixels counts bits.
  const size_t length = size_t(store.row_length > 0 ? store.row_length : width);
  const size_t align = size_t(std::max(store.alignment, 1));
  const size_t stride = ((length + 7) / 8 + align - 1) / align * align;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = src + (size_t(store.skip_rows) + size_t(y)) * stride;
    for (int x = 0; x < width; ++x) {
      const size_t bit = size_t(store.skip_pixels) + size_t(x);
      const uint8_t byte = row[bit / 8];
      const int shift = store.lsb_first ? int(bit % 8) : 7 - int(bit % 8);
      out[size_t(y) * size_t(width) + size_t(x)] = uint8_t((byte >> shift) & 1);
    }
  }
  return out;
}

}  // namespace velocity::gl
