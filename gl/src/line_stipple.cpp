// Line stipple (GL 1.5 section 3.4.2): glLineStipple's 16-bit pattern, each bit `factor`
// fragments long, counted from the start of each independent line or of each strip,
// loop or polygon outline. The vertex stage cuts a stippled line into its "on" pieces
// before the renderer sees it, as Mesa's llvmpipe does (gallium's draw module): after
// clipping to the view volume, the counter steps once per pixel of the line's major-axis
// length in window space, and each run of set bits becomes one line from its first step
// to its last. The pieces are ordinary lines, so width, colour, texture, fog, depth and
// user clip planes apply to them as to any line.
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
Vertex lerp_vertex(const Vertex& a, const Vertex& b, float t) {
  Vertex v = a;
  v.clip = a.clip + (b.clip - a.clip) * t;
  v.front = a.front + (b.front - a.front) * t;
  v.back = a.back + (b.back - a.back) * t;
  v.tex = a.tex + (b.tex - a.tex) * t;
  v.fog = a.fog + (b.fog - a.fog) * t;
  for (int k = 0; k < kMaxClipPlanes; ++k) v.clip_distance[k] = a.clip_distance[k] + (b.clip_distance[k] - a.clip_distance[k]) * t;
  return v;
}
}  // namespace

void Context::line_stipple(GLint factor, GLushort pattern) {
  if (in_begin_error()) return;
  raster_.stipple_factor = std::clamp(factor, 1, 256);  // (GL clamps it)
  raster_.stipple_pattern = pattern;
}

void Context::stippled_line(uint32_t a, uint32_t b, Vec4 color_a, Vec4 color_b, bool offset) {
  // The part inside the view volume, [t0, t1] of a to b (NaN: nothing).
  const Vertex va = prim_[a], vb = prim_[b];
  const Vec4 pa = va.clip, pb = vb.clip;
  float t0 = 0, t1 = 1;
  const float da[6] = {pa.w + pa.x, pa.w - pa.x, pa.w + pa.y, pa.w - pa.y, pa.w + pa.z, pa.w - pa.z};
  const float db[6] = {pb.w + pb.x, pb.w - pb.x, pb.w + pb.y, pb.w - pb.y, pb.w + pb.z, pb.w - pb.z};
  for (int k = 0; k < 6; ++k) {
    if (!(da[k] >= 0) && !(db[k] >= 0)) return;
    if (!(da[k] >= 0)) t0 = std::max(t0, da[k] / (da[k] - db[k]));
    else if (!(db[k] >= 0)) t1 = std::min(t1, da[k] / (da[k] - db[k]));
  }
  if (!(t0 < t1)) return;
  const Vec4 c0 = pa + (pb - pa) * t0, c1 = pa + (pb - pa) * t1;
  if (!(c0.w > 0 && c1.w > 0)) return;
  // The ends in window space, on the rasterizer's 1/256-pixel grid (24.8 fixed point),
  // so that a line one pixel long is 1, not 1.000001 (which would count two steps).
  const Box& vp = transform_.viewport;
  const auto window = [](double ndc, int size) { return std::round((ndc + 1) * 0.5 * size * 256) / 256; };
  const double dx = window(double(c1.x) / c1.w, vp.width) - window(double(c0.x) / c0.w, vp.width);
  const double dy = window(double(c1.y) / c1.w, vp.height) - window(double(c0.y) / c0.w, vp.height);
  const float length = float(std::max(std::fabs(dx), std::fabs(dy)));
  if (!(length > 0) || length > float(4 * kMaxViewport)) return;  // (clipped: within the viewport)
  const int steps = int(std::ceil(length));
  const int factor = raster_.stipple_factor;
  const uint32_t pattern = raster_.stipple_pattern;
  // One piece from s0 to s1 (fractions of the clipped line in window space): window
  // fractions become clip-space ones through the ends' w (perspective).
  auto piece = [&](float s0, float s1) {
    if (prim_.size() + 2 > 2 * kMaxPrimitiveVertices) return error(GL_OUT_OF_MEMORY);
    uint32_t ends[2];
    const float s[2] = {s0, s1};
    for (int e = 0; e < 2; ++e) {
      const float u = s[e] * c0.w / ((1 - s[e]) * c1.w + s[e] * c0.w);
      const float t = t0 + u * (t1 - t0);
      Vertex v = lerp_vertex(va, vb, t);
      v.front = color_a + (color_b - color_a) * t;
      ends[e] = uint32_t(prim_.size());
      prim_.push_back(v);
      emitted_.emplace_back();
      if (unit1_on_) {  // unit 1's coordinates along it (multitexture.cpp)
        const Vec4 ta = prim_tex1_[a], tb = prim_tex1_[b];
        prim_tex1_.push_back(ta + (tb - ta) * t);
      }
      if (color_sum_on_) {  // the secondary colours along the line (color_sum.cpp)
        const Secondary sa = prim_secondary_[a], sb = prim_secondary_[b];
        prim_secondary_.push_back({sa.front + (sb.front - sa.front) * t, sa.back + (sb.back - sa.back) * t});
      }
    }
    target(PrimitiveKind::Lines, offset);
    emit_vertex(ends[0], prim_[ends[0]].front, false, secondary_of(ends[0], false));
    emit_vertex(ends[1], prim_[ends[1]].front, false, secondary_of(ends[1], false));
  };
  bool on = false;
  int start = 0;
  for (int i = 0; i < steps; ++i, ++stipple_counter_) {
    const bool bit = (pattern >> ((stipple_counter_ / uint32_t(factor)) & 15)) & 1;
    if (bit == on) continue;
    if (on) piece(float(start) / length, float(i) / length);
    else start = i;
    on = bit;
  }
  if (on) piece(float(start) / length, 1);
}

}  // namespace velocity::gl
