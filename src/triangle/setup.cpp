#include "triangle/setup.hpp"

#include "triangle/small_coverage.hpp"

#include <algorithm>
#include <cmath>

namespace velocity::triangle {

using namespace velocity::raster;  // set-up writes the contract's records

namespace {

// Edge coefficients are snapped-coordinate differences; the guard band keeps them
// below 2^25 (about 131,000 pixels), which the coverage's int32 arithmetic relies on.
// Anything larger can only come from a degenerate projection and is dropped.
constexpr int64_t kMaxEdgeDelta = int64_t(1) << 25;

// Interpolation plane through the values v[0..2] at the points (x, y)[0..2] (pixels),
// anchored at (ax, ay). inv_area is 1 / twice the signed area in pixels^2.
inline Plane make_plane(const float x[3], const float y[3], const float v[3], float inv_area, float ax, float ay) {
  const float d1 = v[1] - v[0], d2 = v[2] - v[0];
  const float dx = (d1 * (y[2] - y[0]) - d2 * (y[1] - y[0])) * inv_area;
  const float dy = (d2 * (x[1] - x[0]) - d1 * (x[2] - x[0])) * inv_area;
  return {v[0] + dx * (ax - x[0]) + dy * (ay - y[0]), dx, dy};
}

inline void fill_header(RecordHeader& r, RecordKind kind, const RecordInfo& info, int nvar, int x0, int y0, int x1,
                        int y1) {
  r.kind = kind;
  r.kernel = info.kernel;
  r.num_varyings = uint8_t(nvar);
  r.flags = 0;
  r.draw = info.draw;
  r.min_x = int16_t(x0), r.min_y = int16_t(y0), r.max_x = int16_t(x1), r.max_y = int16_t(y1);
  r.flat_color = info.flat_color;
  r.sort_key = 0;
}

// OpenGL's polygon offset: factor * the largest depth slope + units * r, r the smallest
// resolvable difference. r is 2^-23, as llvmpipe's: vertex coordinates are floats, so
// near the near plane two surfaces closer than that in window z cannot be told apart
// (piglit's gl-1.4-polygon-offset measures 2^-23 there), whatever the depth buffer keeps.
float polygon_offset(const Plane& depth, const geometry::SetupParams& p) {
  const float slope = std::max(std::fabs(depth.dx), std::fabs(depth.dy));
  return p.offset_factor * slope + p.offset_units * (1.0f / 8388608.0f);
}

// The depth, 1/w and varying planes of a triangle wound positively (area2 > 0),
// anchored at the centre of the record's first box pixel; from the snapped positions,
// so that they agree with coverage.
void write_planes(RecordHeader& r, const ScreenVertex* const v[3], const float* const var[3], const int64_t X[3],
                  const int64_t Y[3], int64_t area2, int nvar, const geometry::SetupParams& p) {
  float x[3], y[3];
  for (int i = 0; i < 3; ++i)
    x[i] = float(X[i] - X[0]) * (1.0f / kSubpixelOne), y[i] = float(Y[i] - Y[0]) * (1.0f / kSubpixelOne);
  const float inv_area = float(kSubpixelOne) * float(kSubpixelOne) / float(area2);
  // The anchor, the centre of the box's first pixel, relative to vertex 0.
  const float ax = float(int64_t(r.min_x) * kSubpixelOne + kSubpixelHalf - X[0]) * (1.0f / kSubpixelOne);
  const float ay = float(int64_t(r.min_y) * kSubpixelOne + kSubpixelHalf - Y[0]) * (1.0f / kSubpixelOne);
  float vals[3] = {v[0]->z, v[1]->z, v[2]->z};
  r.depth = make_plane(x, y, vals, inv_area, ax, ay);
  if (p.offset) r.depth.c += polygon_offset(r.depth, p);
  Plane* planes = varyings(r);
  // Varyings the same at the three vertices (a flat-shaded face) are the same at every
  // pixel: constant planes, exact, and no perspective to correct.
  bool constant = true;
  for (int k = 0; k < nvar && constant; ++k) constant = var[0][k] == var[1][k] && var[1][k] == var[2][k];
  if (constant) {
    r.flags |= kConstantVaryings;
    r.inv_w = {1.0f, 0.0f, 0.0f};
    for (int k = 0; k < nvar; ++k) planes[k] = {var[0][k], 0.0f, 0.0f};
    return;
  }
  float iw[3] = {v[0]->inv_w, v[1]->inv_w, v[2]->inv_w};
  if (p.affine) iw[0] = iw[1] = iw[2] = 1.0f;
  r.inv_w = make_plane(x, y, iw, inv_area, ax, ay);
  for (int k = 0; k < nvar; ++k) {
    for (int i = 0; i < 3; ++i) vals[i] = var[i][k] * iw[i];
    planes[k] = make_plane(x, y, vals, inv_area, ax, ay);
  }
}

// floor(n / 256) and the pixel-centre box of a snapped extent.
inline int first_centre(int64_t lo) { return int((lo - kSubpixelHalf + kSubpixelOne - 1) >> kSubpixelBits); }
inline int last_centre(int64_t hi) { return int((hi - kSubpixelHalf) >> kSubpixelBits); }

}  // namespace

Facing facing(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  if (!a.snapped || !b.snapped || !c.snapped) return Facing::Degenerate;
  int64_t x0 = a.fx, y0 = a.fy, x1 = b.fx, y1 = b.fy, x2 = c.fx, y2 = c.fy;
  int64_t area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  return area2 < 0 ? Facing::Front : area2 > 0 ? Facing::Back : Facing::Degenerate;
}

RecordHeader* setup_triangle(WorkerBins& bins, const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
                             const float* var0, const float* var1, const float* var2, int nvar,
                             const RecordInfo& info, const geometry::SetupParams& p, uint32_t& offset) {
  if (!v0.snapped || !v1.snapped || !v2.snapped) return nullptr;
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  const float* var[3] = {var0, var1, var2};
  int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) X[i] = v[i]->fx, Y[i] = v[i]->fy;
  int64_t area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area2 == 0) return nullptr;
  // The edge functions below want a positive area (interior on the positive side of
  // every edge): swap two vertices of a triangle wound the other way.
  if (area2 < 0) {
    std::swap(v[1], v[2]), std::swap(var[1], var[2]);
    std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    area2 = -area2;
  }

  // Bounding box of the pixel centres inside the triangle's box: centre x + 0.5 must lie
  // in [min X, max X], i.e. x in [ceil(minX - 0.5), floor(maxX - 0.5)].
  const int64_t min_x = std::min({X[0], X[1], X[2]}), max_x = std::max({X[0], X[1], X[2]});
  const int64_t min_y = std::min({Y[0], Y[1], Y[2]}), max_y = std::max({Y[0], Y[1], Y[2]});
  if (max_x - min_x >= kMaxEdgeDelta || max_y - min_y >= kMaxEdgeDelta) return nullptr;
  int bx0 = std::max(p.x0, first_centre(min_x)), by0 = std::max(p.y0, first_centre(min_y));
  int bx1 = std::min(p.x1, last_centre(max_x)), by1 = std::min(p.y1, last_centre(max_y));
  if (bx0 > bx1 || by0 > by1) return nullptr;

  // Edge i runs from vertex i to vertex i+1: E(p) = (p - v_i) x (v_{i+1} - v_i), in the
  // form a*px + b*py + c. Top-left rule: a centre exactly on an edge belongs to the
  // triangle only if the edge is a top edge (horizontal, interior below) or a left
  // edge (interior to its right); other edges lose the tie by the -1 on c.
  TriangleEdges e;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    e.a[i] = int32_t(-dy);
    e.b[i] = int32_t(dx);
    e.c[i] = dy * X[i] - dx * Y[i];
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    if (!top_left) e.c[i] -= 1;
  }

  // Small triangles (centres within 8x8, the usual case in dense meshes): find the
  // centres they cover here, exactly, a vector of centres at a time; cover
  // none and they are dropped, cover some and they need no edge functions later. With
  // coordinates relative to the box and below 10 pixels apart, everything fits int32.
  // (Small by the triangle's own box, not the part left inside the scissor.)
  if (last_centre(max_x) - first_centre(min_x) < kSmallSide && last_centre(max_y) - first_centre(min_y) < kSmallSide) {
    const int64_t px = int64_t(bx0) * kSubpixelOne + kSubpixelHalf, py = int64_t(by0) * kSubpixelOne + kSubpixelHalf;
    SmallEdges se;
    for (int i = 0; i < 3; ++i) {
      se.row_start[i] = int32_t(int64_t(e.a[i]) * px + int64_t(e.b[i]) * py + e.c[i]);
      se.step_x[i] = e.a[i] * kSubpixelOne, se.step_y[i] = e.b[i] * kSubpixelOne;
    }
    const uint64_t mask = small_coverage(se, bx1 - bx0 + 1, by1 - by0 + 1);
    if (!mask) return nullptr;
    uint64_t cols = 0;
    for (int y = 0; y < kSmallSide; ++y) cols |= mask >> (kSmallSide * y);
    cols &= 0xff;
    RecordHeader* r = bins.allocate(record_bytes(RecordKind::Small, nvar), offset);
    if (!r) return nullptr;
    fill_header(*r, RecordKind::Small, info, nvar, bx0, by0, bx0 + 63 - __builtin_clzll(cols),
                by0 + (63 - __builtin_clzll(mask)) / kSmallSide);
    shape<SmallShape>(*r) = {mask};
    write_planes(*r, v, var, X, Y, area2, nvar, p);
    return r;
  }

  RecordHeader* r = bins.allocate(record_bytes(RecordKind::Triangle, nvar), offset);
  if (!r) return nullptr;
  fill_header(*r, RecordKind::Triangle, info, nvar, bx0, by0, bx1, by1);
  shape<TriangleEdges>(*r) = e;

  write_planes(*r, v, var, X, Y, area2, nvar, p);
  return r;
}

RecordHeader* setup_small_triangle(WorkerBins& bins, const ScreenVertex& v0, const ScreenVertex& v1,
                                   const ScreenVertex& v2, const float* var0, const float* var1, const float* var2,
                                   int nvar, uint32_t mask, const RecordInfo& info, const geometry::SetupParams& p,
                                   uint32_t& offset) {
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  const float* var[3] = {var0, var1, var2};
  int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) X[i] = v[i]->fx, Y[i] = v[i]->fy;
  int64_t area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area2 == 0 || mask == 0) return nullptr;
  if (area2 < 0) {
    std::swap(v[1], v[2]), std::swap(var[1], var[2]);
    std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    area2 = -area2;
  }
  // The box the mask is relative to: the first centre, as the first pass found it.
  const int bx0 = std::max(p.x0, first_centre(std::min({X[0], X[1], X[2]})));
  const int by0 = std::max(p.y0, first_centre(std::min({Y[0], Y[1], Y[2]})));
  // The columns and rows the mask uses.
  const uint32_t cols = (mask | mask >> 4 | mask >> 8 | mask >> 12) & 0xf;
  const int w = 32 - __builtin_clz(cols), h = (31 - __builtin_clz(mask)) / 4 + 1;
  RecordHeader* r = bins.allocate(record_bytes(RecordKind::Small, nvar), offset);
  if (!r) return nullptr;
  fill_header(*r, RecordKind::Small, info, nvar, bx0, by0, bx0 + w - 1, by0 + h - 1);
  shape<SmallShape>(*r) = {small_mask_from_4x4(mask)};
  write_planes(*r, v, var, X, Y, area2, nvar, p);
  return r;
}

RecordHeader* setup_line(WorkerBins& bins, const ScreenVertex& a, const ScreenVertex& b, const float* va,
                         const float* vb, int nvar, int width, const RecordInfo& info, const geometry::SetupParams& p,
                         uint32_t& offset) {
  if (!a.snapped || !b.snapped) return nullptr;
  width = std::clamp(width, 1, 255);
  const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (!(len2 > 0)) return nullptr;
  const int reach = width / 2 + 1;
  const int x0 = std::max(p.px0, int(std::floor(std::min(a.x, b.x))) - reach);
  const int y0 = std::max(p.py0, int(std::floor(std::min(a.y, b.y))) - reach);
  const int x1 = std::min(p.px1, int(std::floor(std::max(a.x, b.x))) + reach);
  const int y1 = std::min(p.py1, int(std::floor(std::max(a.y, b.y))) + reach);
  if (x0 > x1 || y0 > y1) return nullptr;
  RecordHeader* r = bins.allocate(record_bytes(RecordKind::Line, nvar), offset);
  if (!r) return nullptr;
  fill_header(*r, RecordKind::Line, info, nvar, x0, y0, x1, y1);
  shape<LineShape>(*r) = {a.x, a.y, b.x, b.y, width, std::fabs(dx) >= std::fabs(dy) ? 1 : 0};
  // Values along the line: v(t) with t the projection of the pixel centre onto it, so
  // every pixel across a wide line gets the value of the centre it belongs to.
  const float gx = dx / len2, gy = dy / len2;
  const float t0 = (float(x0) + 0.5f - a.x) * gx + (float(y0) + 0.5f - a.y) * gy;
  auto along = [&](float from, float to) {
    const float d = to - from;
    return Plane{from + d * t0, d * gx, d * gy};
  };
  r->depth = along(a.z, b.z);
  // A polygon drawn as lines (GL_POLYGON_OFFSET_LINE): the slope is the edge's own.
  if (p.offset) r->depth.c += polygon_offset(r->depth, p);
  const float wa = p.affine ? 1.0f : a.inv_w, wb = p.affine ? 1.0f : b.inv_w;
  r->inv_w = along(wa, wb);
  Plane* planes = varyings(*r);
  for (int k = 0; k < nvar; ++k) planes[k] = along(va[k] * wa, vb[k] * wb);
  return r;
}

RecordHeader* setup_point(WorkerBins& bins, const ScreenVertex& pt, const float* var, int nvar, int size,
                          const RecordInfo& info, const geometry::SetupParams& p, uint32_t& offset) {
  if (!pt.snapped) return nullptr;
  size = std::clamp(size, 1, 255);
  // The pixels whose centres lie in [x - size/2, x + size/2) (and likewise in y).
  const float h = float(size) * 0.5f;
  const int x0 = std::max(p.px0, int(std::ceil(pt.x - h - 0.5f))), x1 = std::min(p.px1, int(std::ceil(pt.x + h - 0.5f)) - 1);
  const int y0 = std::max(p.py0, int(std::ceil(pt.y - h - 0.5f))), y1 = std::min(p.py1, int(std::ceil(pt.y + h - 0.5f)) - 1);
  if (x0 > x1 || y0 > y1) return nullptr;
  RecordHeader* r = bins.allocate(record_bytes(RecordKind::Rect, nvar), offset);
  if (!r) return nullptr;
  fill_header(*r, RecordKind::Rect, info, nvar, x0, y0, x1, y1);
  r->depth = {pt.z, 0, 0};
  if (p.offset) r->depth.c += polygon_offset(r->depth, p);  // (GL_POLYGON_OFFSET_POINT: no slope)
  const float w = p.affine ? 1.0f : pt.inv_w;
  r->inv_w = {w, 0, 0};
  Plane* planes = varyings(*r);
  for (int k = 0; k < nvar; ++k) planes[k] = {var[k] * w, 0, 0};
  return r;
}

}  // namespace velocity::triangle
