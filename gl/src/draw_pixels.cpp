// Pixel rectangles (GL 1.5 sections 3.6-3.7, 4.3.3): glBitmap, glDrawPixels and
// glCopyPixels make fragments at the raster position, which go through the same
// per-fragment operations as primitives' (texture with the raster position's
// coordinates, fog with its distance, scissor, alpha and depth tests, blending, masks).
// They are drawn in the same pipeline: each run of equal pixels in a row is a
// window-space rectangle, two triangles whose covered pixel centres are exactly the
// fragments GL's zoomed pixel rectangles give. Also glPixelZoom and glPixelStore.
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
// glCopyPixels' GL_DEPTH_STENCIL (GL_EXT_packed_depth_stencil's name; <GL/gl.h> is 1.4's).
constexpr GLenum kDepthStencil = kDepthStencilFormat;

bool same(const Vec4& a, const Vec4& b) { return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w; }
}  // namespace

void Context::draw_window_rects(const std::vector<WindowRect>& rects) {
  if (!renderer_ || rects.empty() || width_ <= 0 || height_ <= 0) return;
  // The batch maps clip space onto the whole framebuffer with the depth range [0, 1];
  // the context's viewport and depth range are put back after, and the next primitive
  // opens a batch of its own.
  // User clip planes apply to the raster position, not to its fragments.
  const Box viewport = transform_.viewport;
  const float near = transform_.depth_near, far = transform_.depth_far;
  const uint32_t clip_planes = user_clip.count;
  transform_.viewport = {0, 0, width_, height_};
  transform_.depth_near = 0, transform_.depth_far = 1;
  user_clip.count = 0;
  changed();
  const float sx = 2.0f / float(width_), sy = 2.0f / float(height_);
  const RasterPosition& rp = pixels.raster;
  for (const WindowRect& r : rects) {
    Pending& p = target(PrimitiveKind::Triangles, false);
    const uint32_t base = uint32_t(p.position.size());
    const float xs[4] = {r.x0, r.x1, r.x1, r.x0}, ys[4] = {r.y0, r.y0, r.y1, r.y1};
    for (int k = 0; k < 4; ++k) {
      // (Clip-space y is negated: the framebuffer is kept bottom row first.)
      p.position.push_back({xs[k] * sx - 1, 1 - ys[k] * sy, 2 * r.z - 1, 1});
      p.color.push_back(r.color);
      if (p.state.texture.texture) p.texcoord.push_back(rp.texcoord);
      if (p.state.texture1.texture) p.texcoord1.push_back(rp.texcoord);  // (unit 0's: the one kept)
      if (p.state.fog) p.fog.push_back(rp.distance);
      if (p.state.color_sum) p.secondary.push_back({0, 0, 0, 0});  // (no secondary colour of its own)
    }
    for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) p.index.push_back(base + k);
  }
  transform_.viewport = viewport;
  transform_.depth_near = near, transform_.depth_far = far;
  user_clip.count = clip_planes;
  changed();
}

// The w x h pixels of `image` (bottom row first) zoomed at the raster position (xr, yr):
// pixel (i, j) covers [xr + zx i, xr + zx (i + 1)) x [yr + zy j, yr + zy (j + 1)). Runs of
// equal pixels in a row become one rectangle; what lies outside the framebuffer is cut
// off, so the work is bounded by the framebuffer's size as well as the image's.
// `depth`: image[].x is each pixel's depth, drawn in the raster colour.
void Context::zoomed_rects(GLsizei w, GLsizei h, const Vec4* image, bool depth, std::vector<WindowRect>& out) {
  const RasterPosition& rp = pixels.raster;
  const float zx = pixels.zoom_x, zy = pixels.zoom_y;
  const float fw = float(width_), fh = float(height_);
  // The raster position is rounded to a whole pixel first, as Mesa does (GL's rule has
  // it as it is; a program places images at whole pixels either way). A fragment centre
  // exactly on the edge between two zoomed pixels (a fractional zoom) goes to the one
  // the rasterizer's edge rule gives it: GL leaves that open, and Mesa's choice follows
  // its texture coordinates' rounding.
  const float ox = std::round(rp.window.x), oy = std::round(rp.window.y);
  for (GLsizei j = 0; j < h; ++j) {
    float y0 = oy + zy * float(j), y1 = oy + zy * float(j + 1);
    if (y0 > y1) std::swap(y0, y1);
    if (!(y1 > 0 && y0 < fh) || y0 == y1) continue;
    y0 = std::max(y0, 0.0f), y1 = std::min(y1, fh);
    const Vec4* row = image + size_t(j) * size_t(w);
    for (GLsizei i = 0; i < w;) {
      GLsizei e = i + 1;
      while (e < w && same(row[e], row[i])) ++e;
      float x0 = ox + zx * float(i), x1 = ox + zx * float(e);
      if (x0 > x1) std::swap(x0, x1);
      if (x1 > 0 && x0 < fw && x0 != x1) {
        const Vec4& v = row[i];
        out.push_back({std::max(x0, 0.0f), y0, std::min(x1, fw), y1, depth ? v.x : rp.window.z, depth ? rp.color : v});
      }
      i = e;
    }
  }
}

void Context::bitmap(GLsizei w, GLsizei h, float xorig, float yorig, float xmove, float ymove,
                     const std::vector<uint8_t>* bits) {
  if (in_begin_error()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (framebuffer_incomplete()) return;
  RasterPosition& rp = pixels.raster;
  if (!rp.valid) return;
  if (pixels_not_rendered(GL_BITMAP_TOKEN)) bits = nullptr;  // (the raster position still moves)
  if (bits && w > 0 && h > 0 && renderer_) {
    // The lower left fragment (GL 1.5 section 3.7): floor(raster - origin). Mesa adds
    // 1e-4 first, so that a position computed as 9.99999 for 10 lands on 10; so does pGL.
    const float x0 = std::floor(rp.window.x + 1e-4f - xorig), y0 = std::floor(rp.window.y + 1e-4f - yorig);
    std::vector<WindowRect> rects;
    for (GLsizei j = 0; j < h; ++j) {
      const uint8_t* row = bits->data() + size_t(j) * size_t(w);
      for (GLsizei i = 0; i < w;) {
        if (!row[i]) {
          ++i;
          continue;
        }
        GLsizei e = i + 1;
        while (e < w && row[e]) ++e;
        const float y = y0 + float(j);
        if (y + 1 > 0 && y < float(height_))
          rects.push_back({std::max(x0 + float(i), -1.0f), y, std::min(x0 + float(e), float(width_) + 1), y + 1,
                           rp.window.z, rp.color});
        i = e;
      }
    }
    draw_window_rects(rects);
  }
  rp.window.x += xmove, rp.window.y += ymove;
}

void Context::draw_pixels(GLsizei w, GLsizei h, GLenum format, const std::vector<Vec4>& image) {
  if (in_begin_error() || framebuffer_incomplete()) return;
  if (format == GL_DEPTH_COMPONENT && depth_bits_ <= 0) return error(GL_INVALID_OPERATION);
  if (pixels_not_rendered(GL_DRAW_PIXEL_TOKEN) || !pixels.raster.valid || !renderer_ || w <= 0 || h <= 0) return;
  std::vector<WindowRect> rects;
  zoomed_rects(w, h, image.data(), format == GL_DEPTH_COMPONENT, rects);
  draw_window_rects(rects);
}

// Stencil indices (glDrawPixels' GL_STENCIL_INDEX, glCopyPixels' GL_STENCIL): GL 1.5
// section 4.3.1 writes them through the pixel ownership and scissor tests and the
// stencil write mask only (not the stencil or depth test, not into colour). A batch
// for each index value: its rectangles replace the stencil under the mask (pixel_state
// reads stencil_write_).
void Context::draw_stencil_rects(const std::vector<WindowRect>& rects) {
  std::vector<WindowRect> by_value[256];
  for (const WindowRect& r : rects) by_value[uint8_t(r.color.x)].push_back(r);
  for (int v = 0; v < 256; ++v) {
    if (by_value[v].empty()) continue;
    stencil_write_ = v;
    changed();
    draw_window_rects(by_value[v]);
  }
  stencil_write_ = -1;
  changed();
}

void Context::draw_stencil_pixels(GLsizei w, GLsizei h, const std::vector<uint8_t>& indices) {
  if (in_begin_error() || framebuffer_incomplete()) return;
  if (stencil_bits_ <= 0) return error(GL_INVALID_OPERATION);
  if (pixels_not_rendered(GL_DRAW_PIXEL_TOKEN) || !pixels.raster.valid || !renderer_ || w <= 0 || h <= 0) return;
  std::vector<Vec4> image(indices.size());
  for (size_t i = 0; i < indices.size(); ++i) image[i] = {float(indices[i]), 0, 0, 1};
  std::vector<WindowRect> rects;
  zoomed_rects(w, h, image.data(), false, rects);
  draw_stencil_rects(rects);
}

// GL_EXT_packed_depth_stencil: the depth, as GL_DEPTH_COMPONENT's fragments with no
// colour written, then the stencil indices, as glCopyPixels' GL_DEPTH_STENCIL does.
void Context::draw_depth_stencil_pixels(GLsizei w, GLsizei h, const std::vector<Vec4>& depth,
                                        const std::vector<uint8_t>& indices) {
  if (in_begin_error()) return;
  if (depth_bits_ <= 0 || stencil_bits_ <= 0) return error(GL_INVALID_OPERATION);
  const RasterState saved = raster_;
  for (bool& m : raster_.color_mask) m = false;
  changed();
  draw_pixels(w, h, GL_DEPTH_COMPONENT, depth);
  raster_ = saved;
  changed();
  draw_stencil_pixels(w, h, indices);
}

void Context::copy_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type) {
  if (in_begin_error() || read_framebuffer_incomplete() || framebuffer_incomplete()) return;
  if (type == kDepthStencil) {  // (packed depth-stencil's: the depth, then the stencil, no colour)
    if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
    if (depth_bits_ <= 0 || stencil_bits_ <= 0) return error(GL_INVALID_OPERATION);
    const RasterState saved = raster_;
    for (bool& m : raster_.color_mask) m = false;
    changed();
    copy_pixels(x, y, w, h, GL_DEPTH);
    raster_ = saved;
    changed();
    return copy_pixels(x, y, w, h, GL_STENCIL);
  }
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) return error(GL_INVALID_ENUM);
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  // No depth or stencil buffer without their bits.
  if ((type == GL_STENCIL && stencil_bits_ <= 0) || (type == GL_DEPTH && depth_bits_ <= 0))
    return error(GL_INVALID_OPERATION);
  if (type == GL_COLOR && no_read_buffer()) return;  // glReadBuffer(GL_NONE)
  if (pixels_not_rendered(GL_COPY_PIXEL_TOKEN) || !pixels.raster.valid || !renderer_ || w == 0 || h == 0) return;
  // Only the part of the source inside the framebuffer is copied (its pixels outside
  // are undefined), to the same place relative to the raster position.
  const int64_t x0 = std::max<int64_t>(x, 0), y0 = std::max<int64_t>(y, 0);
  const int64_t x1 = std::min<int64_t>(int64_t(x) + w, width_), y1 = std::min<int64_t>(int64_t(y) + h, height_);
  if (x0 >= x1 || y0 >= y1) return;
  run_frame();
  const GLsizei cw = GLsizei(x1 - x0), ch = GLsizei(y1 - y0);
  std::vector<Vec4> image(size_t(cw) * size_t(ch));
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  if (type == GL_DEPTH) depth = renderer_->window_depth();
  if (type == GL_STENCIL) {
    stencil.resize(size_t(width_) * size_t(height_));
    renderer_->read_stencil(stencil.data());
  }
  const bool has_alpha = !(format_ == GL_RGB || format_ == 0x4 /* OSMESA_BGR */);
  for (GLsizei j = 0; j < ch; ++j)
    for (GLsizei i = 0; i < cw; ++i) {
      const size_t at = size_t(y0 + j) * size_t(width_) + size_t(x0 + i);
      Vec4& v = image[size_t(j) * size_t(cw) + size_t(i)];
      if (type == GL_DEPTH) {
        v = {depth[at], 0, 0, 1};
      } else if (type == GL_STENCIL) {
        v = {float(stencil[at]), 0, 0, 1};
      } else {
        const uint8_t* p = colour_rows() + at * 4;
        v = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, has_alpha ? p[3] / 255.0f : 1.0f};
      }
    }
  // The clipped source's offset, zoomed, moves the destination with it.
  RasterPosition& rp = pixels.raster;
  const Vec4 saved = rp.window;
  rp.window.x += float(x0 - x) * pixels.zoom_x, rp.window.y += float(y0 - y) * pixels.zoom_y;
  std::vector<WindowRect> rects;
  zoomed_rects(cw, ch, image.data(), type == GL_DEPTH, rects);
  rp.window = saved;
  if (type == GL_STENCIL) return draw_stencil_rects(rects);
  draw_window_rects(rects);
}

void Context::pixel_zoom(float x, float y) {
  if (in_begin_error()) return;
  // A NaN or infinite zoom would make no fragment or unbounded rectangles: kept finite.
  auto finite = [](float v) { return std::isfinite(v) ? std::clamp(v, -float(kMaxViewport), float(kMaxViewport)) : 1.0f; };
  pixels.zoom_x = finite(x), pixels.zoom_y = finite(y);
}

void Context::pixel_store(GLenum pname, double value) {
  if (in_begin_error()) return;
  PixelStore& u = pixels.unpack;
  GLint* count = nullptr;
  bool* flag = nullptr;
  switch (pname) {
    case GL_UNPACK_SWAP_BYTES: flag = &u.swap_bytes; break;
    case GL_UNPACK_LSB_FIRST: flag = &u.lsb_first; break;
    case GL_UNPACK_ROW_LENGTH: count = &u.row_length; break;
    case GL_UNPACK_SKIP_ROWS: count = &u.skip_rows; break;
    case GL_UNPACK_SKIP_PIXELS: count = &u.skip_pixels; break;
    case GL_UNPACK_IMAGE_HEIGHT: count = &u.image_height; break;
    case GL_UNPACK_SKIP_IMAGES: count = &u.skip_images; break;
    case GL_PACK_SWAP_BYTES: flag = &pixels.pack.swap_bytes; break;
    case GL_PACK_LSB_FIRST: flag = &pixels.pack.lsb_first; break;
    case GL_PACK_ROW_LENGTH: count = &pixels.pack.row_length; break;
    case GL_PACK_SKIP_ROWS: count = &pixels.pack.skip_rows; break;
    case GL_PACK_SKIP_PIXELS: count = &pixels.pack.skip_pixels; break;
    case GL_PACK_IMAGE_HEIGHT: count = &pixels.pack.image_height; break;
    case GL_PACK_SKIP_IMAGES: count = &pixels.pack.skip_images; break;
    case GL_UNPACK_ALIGNMENT: case GL_PACK_ALIGNMENT: {
      if (value != 1 && value != 2 && value != 4 && value != 8) return error(GL_INVALID_VALUE);
      if (pname == GL_UNPACK_ALIGNMENT)
        unpack_alignment = u.alignment = GLint(value);
      else
        pack_alignment = pixels.pack.alignment = GLint(value);
      return;
    }
    default: return error(GL_INVALID_ENUM);
  }
  if (flag) {
    *flag = value != 0;
    return;
  }
  // Counts: negative is GL_INVALID_VALUE; bounded so that offsets stay in size_t.
  if (!(value >= 0)) return error(GL_INVALID_VALUE);
  *count = GLint(std::min(value, double(kMaxPixelStoreCount)));
}

bool Context::get_pixel_ops(GLenum pname, std::vector<double>& out, int& kind) {
  const RasterPosition& r = pixels.raster;
  const PixelStore& u = pixels.unpack;
  switch (pname) {
    case GL_CURRENT_RASTER_POSITION: out = {r.window.x, r.window.y, r.window.z, r.window.w}; return true;
    case GL_CURRENT_RASTER_POSITION_VALID: out = {r.valid ? 1.0 : 0.0}; return true;
    case GL_CURRENT_RASTER_COLOR: out = {r.color.x, r.color.y, r.color.z, r.color.w}, kind = 1; return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS: out = {r.texcoord.x, r.texcoord.y, r.texcoord.z, r.texcoord.w}; return true;
    case GL_CURRENT_RASTER_DISTANCE: out = {r.distance}; return true;
    case GL_CURRENT_RASTER_INDEX: out = {1}; return true;  // (as Mesa in RGBA mode)
    case GL_ZOOM_X: out = {pixels.zoom_x}; return true;
    case GL_ZOOM_Y: out = {pixels.zoom_y}; return true;
    case GL_UNPACK_SWAP_BYTES: out = {u.swap_bytes ? 1.0 : 0.0}; return true;
    case GL_UNPACK_LSB_FIRST: out = {u.lsb_first ? 1.0 : 0.0}; return true;
    case GL_UNPACK_ROW_LENGTH: out = {double(u.row_length)}; return true;
    case GL_UNPACK_SKIP_ROWS: out = {double(u.skip_rows)}; return true;
    case GL_UNPACK_SKIP_PIXELS: out = {double(u.skip_pixels)}; return true;
    case GL_UNPACK_IMAGE_HEIGHT: out = {double(u.image_height)}; return true;
    case GL_UNPACK_SKIP_IMAGES: out = {double(u.skip_images)}; return true;
    case GL_PACK_SWAP_BYTES: out = {pixels.pack.swap_bytes ? 1.0 : 0.0}; return true;
    case GL_PACK_LSB_FIRST: out = {pixels.pack.lsb_first ? 1.0 : 0.0}; return true;
    case GL_PACK_ROW_LENGTH: out = {double(pixels.pack.row_length)}; return true;
    case GL_PACK_SKIP_ROWS: out = {double(pixels.pack.skip_rows)}; return true;
    case GL_PACK_SKIP_PIXELS: out = {double(pixels.pack.skip_pixels)}; return true;
    case GL_PACK_IMAGE_HEIGHT: out = {double(pixels.pack.image_height)}; return true;
    case GL_PACK_SKIP_IMAGES: out = {double(pixels.pack.skip_images)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
