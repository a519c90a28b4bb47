// The state of GL's pixel operations (the raster position, glPixelZoom, glPixelStore)
// and the unpacking of client pixel rectangles (glDrawPixels, glBitmap) that
// raster_pos.cpp and draw_pixels.cpp use. Kept apart from state.hpp: its own GL area.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "velocity/math.hpp"

namespace velocity::gl {

// glRasterPos / glWindowPos's result (GL 1.5 section 2.13).
struct RasterPosition {
  Vec4 window{0, 0, 0, 1};  // x, y, z in window coordinates; w: the clip-space w
  bool valid = true;
  Vec4 color{1, 1, 1, 1};
  Vec4 texcoord{0, 0, 0, 1};
  float distance = 0;  // the eye's distance to it: the fog coordinate of its fragments
};

// One direction of glPixelStore (GL_UNPACK_* or GL_PACK_*).
struct PixelStore {
  GLint row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4;
  GLint image_height = 0, skip_images = 0;  // (3-D images: kept and reported only)
  bool swap_bytes = false, lsb_first = false;
};

// glPixelStore's counts are kept below this, so that offsets into client memory are
// computed without overflow (GL_INVALID_VALUE for a negative one).
constexpr GLint kMaxPixelStoreCount = GLint(1) << 24;

// glPixelTransfer's state (GL 1.5 section 3.6.3). Colour maps, glPixelMap's tables, do
// not exist: each is GL's default, one entry of 0, so GL_MAP_COLOR and GL_MAP_STENCIL
// map every value to 0.
// glPixelMap's ten tables, GL_PIXEL_MAP_I_TO_I to GL_PIXEL_MAP_A_TO_A in the enums'
// order (pixel_transfer.cpp); each holds 1 to kMaxPixelMap values (GL's default: one 0).
constexpr int kPixelMaps = 10;
constexpr int kMaxPixelMap = 256;  // GL_MAX_PIXEL_MAP_TABLE (as Mesa's)
struct PixelMaps {
  std::vector<float> table[kPixelMaps];
  PixelMaps() {
    for (auto& t : table) t.assign(1, 0.0f);
  }
};

struct PixelTransfer {
  float scale[4] = {1, 1, 1, 1}, bias[4] = {0, 0, 0, 0};  // RGBA
  float depth_scale = 1, depth_bias = 0;
  bool map_color = false, map_stencil = false;
  GLint index_shift = 0, index_offset = 0;
  std::shared_ptr<const PixelMaps> maps = std::make_shared<const PixelMaps>();  // copied on write
  // Whether colour (or depth, or an index) comes through unchanged.
  bool colour_identity() const {
    return !map_color && scale[0] == 1 && scale[1] == 1 && scale[2] == 1 && scale[3] == 1 && bias[0] == 0 &&
           bias[1] == 0 && bias[2] == 0 && bias[3] == 0;
  }
  // c's RGBA scaled, biased and mapped, before the clamp to [0, 1].
  // With GL_MAP_COLOR, the value clamped to [0, 1] then looked up in R_TO_R .. A_TO_A
  // at round(value * (size - 1)), as Mesa.
  void colour(float* c) const {
    for (int k = 0; k < 4; ++k) {
      c[k] = c[k] * scale[k] + bias[k];
      if (!map_color) continue;
      const std::vector<float>& t = maps->table[6 + k];
      const float v = c[k] > 0 ? (c[k] < 1 ? c[k] : 1.0f) : 0.0f;  // (NaN reads 0)
      c[k] = t[size_t(std::lround(v * float(t.size() - 1)))];
    }
  }
  float depth(float d) const { return d * depth_scale + depth_bias; }
  // An index shifted and offset (in 64-bit modular arithmetic: only its low bits are kept).
  // With GL_MAP_STENCIL, then looked up in S_TO_S (its size a power of two) at the
  // index's low bits, as Mesa.
  int64_t index(int64_t i) const {
    const uint64_t shifted = index_shift >= 0 ? uint64_t(i) << std::min(index_shift, GLint(63))
                                              : uint64_t(i >> std::min(-int64_t(index_shift), int64_t(63)));
    const int64_t out = int64_t(shifted + uint64_t(int64_t(index_offset)));
    if (!map_stencil) return out;
    const std::vector<float>& t = maps->table[1];
    return int64_t(std::lround(t[size_t(uint64_t(out) & uint64_t(t.size() - 1))]));
  }
};

struct PixelOpsState {
  RasterPosition raster;
  float zoom_x = 1, zoom_y = 1;
  PixelTransfer transfer;  // glPixelTransfer (pixel_transfer.cpp)
  // Their alignments are Context::unpack_alignment's and pack_alignment's, kept in step.
  PixelStore unpack, pack;
};

// Whether glDrawPixels takes `format` and `type`: GL_NO_ERROR, GL_INVALID_ENUM (an
// unknown one, GL_COLOR_INDEX, or GL_BITMAP, which only the index formats take) or
// GL_INVALID_OPERATION (a packed type with a format of another number of components).
GLenum check_draw_format(GLenum format, GLenum type);

// The width x height pixels at `data`, laid out as `store` says, converted to floats
// as GL's pixel transfer does with its default state: RGBA in [0, 1] (a missing colour
// component 0, a missing alpha 1; luminance to red, green and blue); for
// GL_DEPTH_COMPONENT the depth in x. Rows bottom first, as given. The format and type
// are ones check_draw_format accepted; the caller bounds width and height.
// `transfer`: glPixelTransfer's scale, bias and maps, applied before the clamp.
std::vector<Vec4> unpack_pixels(GLenum format, GLenum type, int width, int height, const PixelStore& store,
                                const void* data, const PixelTransfer& transfer = {});

// The bytes from one row of a pixel rectangle to the next (GL 1.5 equation 3.11: the
// row length or width, in groups of `format` and `type`, padded to the alignment
// unless a component is as large), for formats and types check_draw_format accepted.
// 3-D images step by this times their image height (texture_3d.cpp).
size_t pixel_row_bytes(GLenum format, GLenum type, int width, const PixelStore& store);
// glReadPixels' packed types (GL 1.2's twelve): the bytes of one, 0 for another type;
// and c's components (the format's order, clamped to [0, 1]) packed into one at dst,
// byte-swapped if asked.
int packed_type_bytes(GLenum type);
void pack_packed(GLenum type, const float* c, uint8_t* dst, bool swap);

// glDrawPixels' stencil indices (GL_STENCIL_INDEX): GL_NO_ERROR for the integer types,
// GL_FLOAT and GL_BITMAP, GL_INVALID_OPERATION for a packed type, else GL_INVALID_ENUM.
GLenum check_stencil_type(GLenum type);
// The width x height stencil indices at `data` as `store` lays them out, each masked to
// the stencil buffer's 8 bits (a float's whole part; GL_BITMAP: 0 or 1). Rows bottom first.
std::vector<uint8_t> unpack_stencil(GLenum type, int width, int height, const PixelStore& store, const void* data,
                                    const PixelTransfer& transfer = {});

// GL_EXT_packed_depth_stencil for the default framebuffer: GL_DEPTH_STENCIL_EXT pixels
// of type GL_UNSIGNED_INT_24_8_EXT, each a 32-bit word of 24 bits of depth (high) and
// 8 of stencil (low). <GL/gl.h> is 1.4's: the extension's names are here.
constexpr GLenum kDepthStencilFormat = 0x84F9;  // GL_DEPTH_STENCIL_EXT
constexpr GLenum kUnsignedInt24_8 = 0x84FA;     // GL_UNSIGNED_INT_24_8_EXT
// glDrawPixels' and glReadPixels' check of the pair, where either is the extension's:
// GL_INVALID_ENUM for GL_DEPTH_STENCIL_EXT with another type, GL_INVALID_OPERATION for
// GL_UNSIGNED_INT_24_8_EXT with another format (as Mesa).
GLenum check_depth_stencil(GLenum format, GLenum type);
// The width x height words at `data` as `store` lays them out: the depth (through
// glPixelTransfer's depth scale and bias, clamped) in each Vec4's x and the stencil
// index (shifted and offset) in `stencil`. Rows bottom first.
void unpack_depth_stencil(int width, int height, const PixelStore& store, const void* data,
                          const PixelTransfer& transfer, std::vector<Vec4>& depth, std::vector<uint8_t>& stencil);

// glBitmap's width x height bits at `data` (GL_BITMAP with `store`'s row length, skips,
// alignment and bit order): one byte per pixel, 1 where a fragment is drawn.
std::vector<uint8_t> unpack_bitmap(int width, int height, const PixelStore& store, const void* data);

// glPolygonStipple's 32x32 bitmap at `data` as rows, bit x of row y set where the
// pattern keeps pixel (x, y) (polygon_stipple.cpp).
std::array<uint32_t, 32> stipple_rows(const PixelStore& store, const void* data);

}  // namespace velocity::gl
