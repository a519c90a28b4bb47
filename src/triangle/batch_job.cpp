// The triangle stage for pre-transformed batches (the fixed-function path) and clears:
// per primitive, reject and clip, then set up and bin. Culling, polygon modes and
// lighting were the front end's work.
#include <algorithm>
#include <cmath>

#include "triangle/clip.hpp"
#include "triangle/setup.hpp"
#include "triangle/stage.hpp"

namespace velocity::triangle {

namespace {

using raster::RecordHeader;

class BatchPrimitives {
 public:
  BatchPrimitives(const geometry::BatchDrawPlan& draw, StageContext& cx)
      : d_(draw), b_(draw.batch), cx_(cx), stats_(cx.stats) {
    projected_ = draw.projected;
    codes_ = draw.codes;
    info_ = {draw.kernel, draw.draw_state, 0};
    extras_ = draw.units > 1 || draw.color_sum;
  }

  void run(uint32_t begin, uint32_t end) {
    const int k = b_.kind == PrimitiveKind::Triangles ? 3 : b_.kind == PrimitiveKind::Lines ? 2 : 1;
    for (uint32_t p = begin; p < end; ++p) {
      uint32_t v[3];
      bool ok = true;
      for (int j = 0; j < k; ++j) {
        const uint32_t at = p * uint32_t(k) + uint32_t(j);
        v[j] = b_.indices ? b_.indices[at] : at;
        ok = ok && v[j] < b_.vertex_count;
      }
      if (!ok) continue;  // an index past the vertices: the primitive is dropped
      switch (b_.kind) {
        case PrimitiveKind::Triangles: triangle(v[0], v[1], v[2]); break;
        case PrimitiveKind::Lines: line(v[0], v[1]); break;
        case PrimitiveKind::Points: point(v[0]); break;
      }
    }
  }

 private:
  ScreenVertex screen(uint32_t v) const { return ScreenVertex::projected(projected_[v], codes_[v]); }

  ScreenVertex to_screen(const Vec4& c) const { return ScreenVertex::window(d_.viewport, c); }

  // Vertex v's user clip distances (PrimitiveBatch::clip_distance), or null without.
  const float* distances(uint32_t v) const {
    return b_.clip_planes ? b_.clip_distance + size_t(v) * b_.clip_planes : nullptr;
  }
  // The user clip planes vertex v is outside of (bit k: plane k); a NaN distance counts
  // as outside every plane, so that its primitive is dropped.
  uint32_t user_code(uint32_t v) const {
    uint32_t c = 0;
    const float* d = distances(v);
    for (uint32_t k = 0; k < b_.clip_planes; ++k) {
      if (std::isnan(d[k])) return (1u << b_.clip_planes) - 1;
      if (d[k] < 0) c |= 1u << k;
    }
    return c;
  }

  // Varyings of vertex v: RGBA, then s, t, q per texture unit (a 3-D texture: s, t, r,
  // q), then the secondary colour's RGB, then the fog coordinate.
  void varyings(uint32_t v, float* out) const {
    const Vec4 c = b_.color ? b_.color[v] : Vec4{1, 1, 1, 1};
    using namespace raster::varying;
    out[kFixedColor] = c.x, out[kFixedColor + 1] = c.y, out[kFixedColor + 2] = c.z, out[kFixedColor + 3] = c.w;
    int at = kFixedTex;
    if (d_.textured) {
      const Vec4 t = b_.texcoord ? b_.texcoord[v] : Vec4{0, 0, 0, 1};
      out[at++] = t.x, out[at++] = t.y;
      if (d_.volumes & 1) out[at++] = t.z;
      out[at++] = t.w;
    }
    if (extras_) at = more_varyings(v, out, at);
    if (d_.fog) out[at] = b_.fog ? b_.fog[v] : 0.0f;
  }

  // Unit 1's s, t, (r,) q and the secondary colour, where the draw has them; the next slot.
  int more_varyings(uint32_t v, float* out, int at) const {
    if (d_.units > 1) {
      const Vec4 t = b_.texcoord1 ? b_.texcoord1[v] : Vec4{0, 0, 0, 1};
      out[at++] = t.x, out[at++] = t.y;
      if (d_.volumes & 2) out[at++] = t.z;
      out[at++] = t.w;
    }
    if (d_.color_sum) {
      const Vec4 s = b_.secondary ? b_.secondary[v] : Vec4{0, 0, 0, 0};
      out[at++] = s.x, out[at++] = s.y, out[at++] = s.z;
    }
    return at;
  }

  void triangle(uint32_t i0, uint32_t i1, uint32_t i2) {
    const uint32_t c0 = codes_[i0], c1 = codes_[i1], c2 = codes_[i2];
    const uint32_t any = c0 | c1 | c2;
    stats_.triangles++;
    if (any & geometry::kOutNonFinite) {
      stats_.triangles_nonfinite++;
      cx_.nonfinite++;
      return;
    }
    if (c0 & c1 & c2 & geometry::kViewPlanes) return void(stats_.triangles_rejected++);
    const uint32_t u0 = user_code(i0), u1 = user_code(i1), u2 = user_code(i2);
    if (u0 & u1 & u2) return void(stats_.triangles_rejected++);
    const uint32_t user = u0 | u1 | u2;
    if (!(any & geometry::kMustClipPlanes) && !user) {  // the usual case: no clip vertices made
      float var[3][raster::kMaxVaryings];
      varyings(i0, var[0]), varyings(i1, var[1]), varyings(i2, var[2]);
      return emit(screen(i0), screen(i1), screen(i2), var[0], var[1], var[2]);
    }
    const int nvar = d_.num_varyings;
    ClipVertex poly[kMaxClippedVertices];
    const uint32_t corners[3] = {i0, i1, i2};
    for (int k = 0; k < 3; ++k) poly[k].src = k, varyings(corners[k], poly[k].var);
    stats_.triangles_clipped++;
    for (int k = 0; k < 3; ++k) poly[k].pos = b_.position[corners[k]];
    int n = 3;
    if (user) {
      for (int k = 0; k < 3; ++k)
        for (uint32_t p = 0; p < b_.clip_planes; ++p) poly[k].dist[p] = distances(corners[k])[p];
      n = clip_polygon_user(poly, n, user, b_.clip_planes, nvar);
    }
    n = clip_polygon(poly, n, any, d_.viewport.guard, nvar);
    if (n < 3) return void(stats_.triangles_culled++);
    ScreenVertex sv[kMaxClippedVertices];
    for (int k = 0; k < n; ++k)
      sv[k] = poly[k].src >= 0 && !(codes_[corners[poly[k].src]] & geometry::kMustClipPlanes) ? screen(corners[poly[k].src])
                                                                                   : to_screen(poly[k].pos);
    for (int k = 1; k + 1 < n; ++k) emit(sv[0], sv[k], sv[k + 1], poly[0].var, poly[k].var, poly[k + 1].var);
  }

  void emit(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, const float* va, const float* vb,
            const float* vc) {
    uint32_t offset;
    RecordHeader* r = setup_triangle(cx_.bins, a, b, c, va, vb, vc, d_.num_varyings, info_, d_.setup, offset);
    if (!r) return void(stats_.triangles_culled++);
    cx_.emit(*r, offset, (a.z + b.z + c.z) / 3.0f);
    stats_.triangles_rasterized++;
  }

  void line(uint32_t a, uint32_t b) {
    const uint32_t ca = codes_[a], cb = codes_[b];
    if ((ca | cb) & geometry::kOutNonFinite) return;
    if (ca & cb & geometry::kViewPlanes) return;
    float va[raster::kMaxVaryings], vb[raster::kMaxVaryings];
    varyings(a, va), varyings(b, vb);
    ScreenVertex sa, sb;
    const bool user = (user_code(a) | user_code(b)) != 0;
    if (!((ca | cb) & geometry::kMustClipPlanes) && !user) {
      sa = screen(a), sb = screen(b);
    } else {
      Vec4 pa = b_.position[a], pb = b_.position[b];
      if (user) {
        // The user planes first: the segment and its varyings cut to [u0, u1].
        float u0, u1;
        if (!clip_line_user(distances(a), distances(b), b_.clip_planes, &u0, &u1)) return;
        const Vec4 d = pb - pa;
        pb = pa + d * u1, pa = pa + d * u0;
        for (int k = 0; k < d_.num_varyings; ++k) {
          const float from = va[k], to = vb[k];
          va[k] = from + (to - from) * u0, vb[k] = from + (to - from) * u1;
        }
      }
      float t0, t1;
      if (!clip_line(pa, pb, ca | cb, d_.viewport.guard, &t0, &t1)) return;
      for (int k = 0; k < d_.num_varyings; ++k) {
        const float from = va[k], to = vb[k];
        va[k] = from + (to - from) * t0, vb[k] = from + (to - from) * t1;
      }
      sa = to_screen(pa), sb = to_screen(pb);
    }
    uint32_t offset;
    RecordHeader* r =
        setup_line(cx_.bins, sa, sb, va, vb, d_.num_varyings, int(b_.line_width + 0.5f), info_, d_.setup, offset);
    if (!r) return;
    cx_.emit(*r, offset, (sa.z + sb.z) / 2);
    stats_.lines++;
  }

  void point(uint32_t v) {
    // A point whose centre is outside the view volume or a user clip plane is dropped
    // whole (OpenGL).
    if (codes_[v] & (geometry::kViewPlanes | geometry::kOutNonFinite | geometry::kOutUnsnapped)) return;
    if (user_code(v)) return;
    float var[raster::kMaxVaryings];
    varyings(v, var);
    const ScreenVertex p = screen(v);
    uint32_t offset;
    RecordHeader* r =
        setup_point(cx_.bins, p, var, d_.num_varyings, int(b_.point_size + 0.5f), info_, d_.setup, offset);
    if (!r) return;
    cx_.emit(*r, offset, p.z);
    stats_.points++;
  }

  const geometry::BatchDrawPlan& d_;
  const PrimitiveBatch& b_;
  StageContext& cx_;
  FrameStats& stats_;
  const geometry::ProjectedVertex* projected_;
  const uint32_t* codes_;
  RecordInfo info_;
  bool extras_ = false;  // a second texture unit or a secondary colour (more_varyings)
};

}  // namespace

void run_batch_job(const geometry::BatchDrawPlan& draw, uint32_t begin, uint32_t end, StageContext& cx) {
  BatchPrimitives(draw, cx).run(begin, end);
}

void run_clear_job(const geometry::ClearPlan& c, int width, int height, StageContext& cx) {
  const int x0 = std::max(c.x0, 0), y0 = std::max(c.y0, 0);
  const int x1 = std::min(c.x1, width - 1), y1 = std::min(c.y1, height - 1);
  if (x0 > x1 || y0 > y1) return;
  uint32_t offset;
  RecordHeader* r = cx.bins.allocate(raster::record_bytes(raster::RecordKind::Clear, 0), offset);
  if (!r) return;
  *r = {};
  r->kind = raster::RecordKind::Clear;
  r->min_x = int16_t(x0), r->min_y = int16_t(y0), r->max_x = int16_t(x1), r->max_y = int16_t(y1);
  const ClearRequest& q = c.request;
  uint32_t mask = 0;
  if (q.color)
    for (int ch = 0; ch < 4; ++ch)
      if (q.color_mask >> ch & 1) mask |= 0xffu << (8 * ch);
  raster::shape<raster::ClearShape>(*r) = {
      raster::pack_rgba(q.color_value.x, q.color_value.y, q.color_value.z, q.color_value.w),
      std::clamp(q.depth_value, 0.0f, 1.0f), mask, uint32_t(q.depth && q.depth_write), q.stencil_value,
      uint8_t(q.stencil ? q.stencil_mask : 0)};
  cx.emit(*r, offset, 2.0f);  // painter's mode: a clear sorts before everything
}

}  // namespace velocity::triangle
