// glBlitFramebuffer (GL_EXT_framebuffer_blit, GL_ARB_framebuffer_object): a rectangle
// of the read framebuffer's colour, depth or stencil copied, scaled and mirrored as the
// two rectangles say, into the draw framebuffer's. Nothing but the scissor test applies
// (GL 3.0, 4.3.3). The source is read once (the read framebuffer's surface, its frame
// run); each destination pixel takes the source pixel under its centre (GL_NEAREST) or
// the bilinear mix of the four nearest, clamped to the source framebuffer's edge
// (GL_LINEAR, colour only); destination pixels whose centre maps outside the source
// framebuffer are left as they are. The values are written as clears of runs of equal
// pixels in each row (as write_surface_rows, buffers.cpp): exact, whatever the backend.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
// The source coordinate of destination pixel `d`'s centre along one axis.
double source_coordinate(int d, int d0, int d1, int s0, int s1) {
  return s0 + (d + 0.5 - d0) * double(s1 - s0) / double(d1 - d0);
}
}  // namespace

void Context::blit_framebuffer(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
                               GLbitfield mask, GLenum filter) {
  if (in_begin_error()) return;
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) return error(GL_INVALID_VALUE);
  if (filter != GL_NEAREST && filter != GL_LINEAR) return error(GL_INVALID_ENUM);
  if (filter == GL_LINEAR && (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT))) return error(GL_INVALID_OPERATION);
  if (read_framebuffer_incomplete() || framebuffer_incomplete()) return;
  if (!renderer_) return;
  // Coordinates far outside any framebuffer are kept in reach (no overflow below).
  auto reach = [](GLint v) { return std::clamp(v, -4 * kMaxViewport, 4 * kMaxViewport); };
  sx0 = reach(sx0), sy0 = reach(sy0), sx1 = reach(sx1), sy1 = reach(sy1);
  dx0 = reach(dx0), dy0 = reach(dy0), dx1 = reach(dx1), dy1 = reach(dy1);

  // The source, read whole from the read framebuffer.
  use_read_framebuffer();
  run_frame();
  const int sw = width_, sh = height_, src_depth_bits = depth_bits_, src_stencil_bits = stencil_bits_;
  std::vector<uint8_t> colour;
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  const bool read_colour = (mask & GL_COLOR_BUFFER_BIT) && read_ != 0 && renderer_;
  if (read_colour) colour.assign(colour_rows(), colour_rows() + size_t(sw) * size_t(sh) * 4);
  if ((mask & GL_DEPTH_BUFFER_BIT) && depth_bits_ > 0 && renderer_) depth = renderer_->window_depth();
  if ((mask & GL_STENCIL_BUFFER_BIT) && stencil_bits_ > 0 && renderer_) {
    stencil.resize(size_t(sw) * size_t(sh));
    renderer_->read_stencil(stencil.data());
  }
  use_draw_framebuffer();
  if (!renderer_) return;
  // Depth and stencil copy only between buffers of one format (GL: else an error);
  // a framebuffer without the buffer takes no part.
  if (!depth.empty() && depth_bits_ > 0 && depth_bits_ != src_depth_bits) return error(GL_INVALID_OPERATION);
  if (!stencil.empty() && stencil_bits_ > 0 && stencil_bits_ != src_stencil_bits) return error(GL_INVALID_OPERATION);
  const bool do_colour = read_colour && drawn_ != 0, do_depth = !depth.empty() && depth_bits_ > 0;
  const bool do_stencil = !stencil.empty() && stencil_bits_ > 0;
  if (!do_colour && !do_depth && !do_stencil) return;
  if (dx0 == dx1 || dy0 == dy1 || sx0 == sx1 || sy0 == sy1) return;

  // The destination pixels: the rectangle within the framebuffer and the scissor box.
  int x_lo = std::max(std::min(dx0, dx1), 0), x_hi = std::min(std::max(dx0, dx1), width_);
  int y_lo = std::max(std::min(dy0, dy1), 0), y_hi = std::min(std::max(dy0, dy1), height_);
  if (raster_.scissor_test) {
    x_lo = std::max(x_lo, raster_.scissor.x), x_hi = std::min(x_hi, raster_.scissor.x + raster_.scissor.width);
    y_lo = std::max(y_lo, raster_.scissor.y), y_hi = std::min(y_hi, raster_.scissor.y + raster_.scissor.height);
  }
  if (x_lo >= x_hi || y_lo >= y_hi) return;
  submit_pending();
  ensure_frame();
  const int n = x_hi - x_lo;
  std::vector<int> src_x(static_cast<size_t>(n), -1);  // the nearest source column of each destination column, -1: outside
  std::vector<double> fx(static_cast<size_t>(n));      // the source coordinate (for GL_LINEAR)
  for (int i = 0; i < n; ++i) {
    fx[size_t(i)] = source_coordinate(x_lo + i, dx0, dx1, sx0, sx1);
    const double f = std::floor(fx[size_t(i)]);
    if (f >= 0 && f < sw) src_x[size_t(i)] = int(f);
  }
  // GL_LINEAR's samples clamp to the source framebuffer's edge (as Mesa's: the texels
  // just outside the rectangle take part).
  const int sx_min = 0, sx_max = sw - 1, sy_min = 0, sy_max = sh - 1;
  std::vector<uint32_t> row_colour(static_cast<size_t>(n));
  std::vector<float> row_depth(static_cast<size_t>(n));
  std::vector<uint8_t> row_stencil(static_cast<size_t>(n));
  auto texel = [&](int x, int y, int c) {
    x = std::clamp(x, sx_min, sx_max), y = std::clamp(y, sy_min, sy_max);
    return double(colour[(size_t(y) * size_t(sw) + size_t(x)) * 4 + size_t(c)]);
  };
  for (int y = y_lo; y < y_hi; ++y) {
    const double fy = source_coordinate(y, dy0, dy1, sy0, sy1);
    const double fyf = std::floor(fy);
    if (fyf < 0 || fyf >= sh) continue;
    const int sy = int(fyf);
    for (int i = 0; i < n; ++i) {
      const int sx = src_x[size_t(i)];
      if (sx < 0) continue;
      const size_t at = size_t(sy) * size_t(sw) + size_t(sx);
      if (do_colour) {
        uint32_t v;
        if (filter == GL_LINEAR) {
          const double ux = fx[size_t(i)] - 0.5, uy = fy - 0.5;
          const int x0 = int(std::floor(ux)), y0 = int(std::floor(uy));
          const double ax = ux - x0, ay = uy - y0;
          v = 0;
          for (int c = 0; c < 4; ++c) {
            const double top = texel(x0, y0, c) * (1 - ax) + texel(x0 + 1, y0, c) * ax;
            const double bottom = texel(x0, y0 + 1, c) * (1 - ax) + texel(x0 + 1, y0 + 1, c) * ax;
            v |= uint32_t(std::lround(top * (1 - ay) + bottom * ay)) << (8 * c);
          }
        } else {
          std::memcpy(&v, &colour[at * 4], 4);
        }
        row_colour[size_t(i)] = v;
      }
      if (do_depth) row_depth[size_t(i)] = depth[at];
      if (do_stencil) row_stencil[size_t(i)] = stencil[at];
    }
    // Runs of equal values, written as scissored clears of one row.
    auto write_runs = [&](auto same, auto set) {
      for (int i = 0; i < n;) {
        if (src_x[size_t(i)] < 0) {
          ++i;
          continue;
        }
        int e = i + 1;
        while (e < n && src_x[size_t(e)] >= 0 && same(i, e)) ++e;
        ClearRequest q;
        q.color = q.depth = q.stencil = false;
        q.scissor = true;
        q.color_mask = channel_mask_;
        // (In samples: a multisample framebuffer's every sample of the pixels, multisample.cpp.)
        q.x0 = to_samples(x_lo + i), q.x1 = to_samples(x_lo + e), q.y0 = to_samples(y), q.y1 = to_samples(y + 1);
        set(q, i);
        renderer_->clear(q);
        if (mirror_) mirror_->clear(q);
        i = e;
      }
    };
    if (do_colour)
      write_runs([&](int a, int b) { return row_colour[size_t(a)] == row_colour[size_t(b)]; },
                 [&](ClearRequest& q, int i) {
                   const uint32_t v = row_colour[size_t(i)];
                   q.color = true;
                   q.color_value = {float(v & 0xff) / 255, float(v >> 8 & 0xff) / 255, float(v >> 16 & 0xff) / 255,
                                    float(v >> 24) / 255};
                 });
    if (do_depth)
      write_runs([&](int a, int b) { return row_depth[size_t(a)] == row_depth[size_t(b)]; },
                 [&](ClearRequest& q, int i) { q.depth = true, q.depth_value = row_depth[size_t(i)]; });
    if (do_stencil)
      write_runs([&](int a, int b) { return row_stencil[size_t(a)] == row_stencil[size_t(b)]; },
                 [&](ClearRequest& q, int i) { q.stencil = true, q.stencil_value = row_stencil[size_t(i)]; });
  }
}

}  // namespace velocity::gl
