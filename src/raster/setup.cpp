#include "raster/setup.hpp"

#include <algorithm>
#include <cmath>

namespace velocity::raster {

namespace {

// floor(n / d) and ceil(n / d) for d > 0, correct for negative n.
inline int64_t floor_div(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }

// Interpolation plane through three values at three points, anchored at (ax, ay).
// Double precision: the set-up runs once per triangle and the anchor may be thousands
// of pixels from the vertices (guard band).
Plane make_plane(const double x[3], const double y[3], const double v[3], double inv_area, double ax, double ay) {
  double dx = ((v[1] - v[0]) * (y[2] - y[0]) - (v[2] - v[0]) * (y[1] - y[0])) * inv_area;
  double dy = ((v[2] - v[0]) * (x[1] - x[0]) - (v[1] - v[0]) * (x[2] - x[0])) * inv_area;
  return {float(v[0] + dx * (ax - x[0]) + dy * (ay - y[0])), float(dx), float(dy)};
}

}  // namespace

Facing facing(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  if (!a.snapped || !b.snapped || !c.snapped) return Facing::Degenerate;
  int64_t x0 = a.fx, y0 = a.fy, x1 = b.fx, y1 = b.fy, x2 = c.fx, y2 = c.fy;
  int64_t area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  return area2 < 0 ? Facing::Front : area2 > 0 ? Facing::Back : Facing::Degenerate;
}

bool setup_triangle(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2, const float* var0,
                    const float* var1, const float* var2, int nvar, int width, int height, bool affine,
                    TriangleSetup& t) {
  if (!v0.snapped || !v1.snapped || !v2.snapped) return false;
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  const float* var[3] = {var0, var1, var2};
  int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) X[i] = v[i]->fx, Y[i] = v[i]->fy;
  int64_t area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area2 == 0) return false;
  // The edge functions below want a positive area (interior on the positive side of
  // every edge): swap two vertices of a triangle wound the other way.
  if (area2 < 0) {
    std::swap(v[1], v[2]), std::swap(var[1], var[2]);
    std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    area2 = -area2;
  }

  // Bounding box of the pixel centres inside the triangle's box: centre x + 0.5 must lie
  // in [min X, max X], i.e. x in [ceil(minX - 0.5), floor(maxX - 0.5)].
  int64_t min_x = std::min({X[0], X[1], X[2]}), max_x = std::max({X[0], X[1], X[2]});
  int64_t min_y = std::min({Y[0], Y[1], Y[2]}), max_y = std::max({Y[0], Y[1], Y[2]});
  t.min_x = int(std::max<int64_t>(0, floor_div(min_x - kSubpixelHalf + kSubpixelOne - 1, kSubpixelOne)));
  t.min_y = int(std::max<int64_t>(0, floor_div(min_y - kSubpixelHalf + kSubpixelOne - 1, kSubpixelOne)));
  t.max_x = int(std::min<int64_t>(width - 1, floor_div(max_x - kSubpixelHalf, kSubpixelOne)));
  t.max_y = int(std::min<int64_t>(height - 1, floor_div(max_y - kSubpixelHalf, kSubpixelOne)));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return false;

  // Edge i runs from vertex i to vertex i+1: E(p) = (p - v_i) x (v_{i+1} - v_i), in the
  // form a*px + b*py + c. Top-left rule: a centre exactly on an edge belongs to the
  // triangle only if the edge is a top edge (horizontal, interior below) or a left
  // edge (interior to its right); other edges lose the tie by the -1 on c.
  for (int i = 0; i < 3; ++i) {
    int j = (i + 1) % 3;
    int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    t.a[i] = -dy;
    t.b[i] = dx;
    t.c[i] = dy * X[i] - dx * Y[i];
    bool top_left = dy < 0 || (dy == 0 && dx > 0);
    if (!top_left) t.c[i] -= 1;
  }

  // Interpolation planes, from the snapped positions so that they agree with coverage.
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) x[i] = double(X[i]) / kSubpixelOne, y[i] = double(Y[i]) / kSubpixelOne;
  double inv_area = double(kSubpixelOne) * double(kSubpixelOne) / double(area2);
  double ax = t.min_x + 0.5, ay = t.min_y + 0.5;
  double vals[3];
  for (int i = 0; i < 3; ++i) vals[i] = v[i]->z;
  t.depth = make_plane(x, y, vals, inv_area, ax, ay);
  double iw[3] = {v[0]->inv_w, v[1]->inv_w, v[2]->inv_w};
  if (affine) iw[0] = iw[1] = iw[2] = 1.0;
  t.inv_w = make_plane(x, y, iw, inv_area, ax, ay);
  for (int k = 0; k < nvar; ++k) {
    for (int i = 0; i < 3; ++i) vals[i] = double(var[i][k]) * iw[i];
    t.var[k] = make_plane(x, y, vals, inv_area, ax, ay);
  }
  t.sort_key = (v[0]->z + v[1]->z + v[2]->z) / 3.0f;
  return true;
}

bool setup_line(const ScreenVertex& a, const ScreenVertex& b, uint32_t color, int width, int height, LineSetup& l) {
  if (!a.snapped || !b.snapped) return false;
  l = {a.x, a.y, a.z, b.x, b.y, b.z, 0, 0, 0, 0, color, (a.z + b.z) / 2};
  l.min_x = std::max(0, int(std::floor(std::min(a.x, b.x))) - 1);
  l.min_y = std::max(0, int(std::floor(std::min(a.y, b.y))) - 1);
  l.max_x = std::min(width - 1, int(std::floor(std::max(a.x, b.x))) + 1);
  l.max_y = std::min(height - 1, int(std::floor(std::max(a.y, b.y))) + 1);
  return l.min_x <= l.max_x && l.min_y <= l.max_y;
}

bool setup_point(const ScreenVertex& p, uint32_t color, int width, int height, PointSetup& out) {
  if (!p.snapped) return false;
  float fx = std::floor(p.x), fy = std::floor(p.y);
  if (!(fx >= 0 && fy >= 0 && fx < float(width) && fy < float(height))) return false;
  out = {int(fx), int(fy), p.z, color, p.z};
  return true;
}

}  // namespace velocity::raster
