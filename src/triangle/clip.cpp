#include "triangle/clip.hpp"

#include <algorithm>
#include <cmath>

namespace velocity::triangle {

namespace {

// Signed distance of a clip-space point to a plane, >= 0 inside.
double distance(const Vec4& p, uint32_t plane, geometry::GuardBand g) {
  const double x = p.x, y = p.y, z = p.z, w = p.w;
  switch (plane) {
    case geometry::kOutNear: return z + w;
    case geometry::kOutFar: return w - z;
    case geometry::kOutGuardLeft: return x + g.x * w;
    case geometry::kOutGuardRight: return g.x * w - x;
    case geometry::kOutGuardBottom: return y + g.y * w;
    case geometry::kOutGuardTop: return g.y * w - y;
  }
  return 0;
}

// The position is interpolated in double: with a vertex 1e7 units away, float
// arithmetic would land the new vertex visibly off the plane it was clipped to.
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t, int nvar, uint32_t ndist) {
  ClipVertex r;
  r.src = -1;
  auto mix = [t](float p, float q) { return float(double(p) + (double(q) - double(p)) * t); };
  r.pos = {mix(a.pos.x, b.pos.x), mix(a.pos.y, b.pos.y), mix(a.pos.z, b.pos.z), mix(a.pos.w, b.pos.w)};
  for (int i = 0; i < nvar; ++i) r.var[i] = a.var[i] + (b.var[i] - a.var[i]) * float(t);
  for (uint32_t k = 0; k < ndist; ++k) r.dist[k] = a.dist[k] + (b.dist[k] - a.dist[k]) * float(t);
  return r;
}

// One Sutherland-Hodgman pass: the part of poly where inside(vertex) >= 0.
template <class Distance>
int clip_against(ClipVertex* poly, int n, int nvar, uint32_t ndist, Distance distance) {
  ClipVertex scratch[kMaxClippedVertices];
  int m = 0;
  // Convex input gains at most one vertex per plane; the bound only guards against
  // degenerate input (it can never write past `scratch`).
  auto push = [&](const ClipVertex& v) {
    if (m < kMaxClippedVertices) scratch[m++] = v;
  };
  for (int i = 0; i < n; ++i) {
    const ClipVertex& a = poly[i];
    const ClipVertex& b = poly[(i + 1) % n];
    const double da = distance(a), db = distance(b);
    if (da >= 0) push(a);
    // The edge crosses the plane: add the crossing point. Always interpolating from
    // the inside vertex makes the new vertex bit-identical for both triangles that
    // share this edge, so clipped meshes stay watertight.
    if ((da >= 0) != (db >= 0)) push(da >= 0 ? lerp(a, b, da / (da - db), nvar, ndist) : lerp(b, a, db / (db - da), nvar, ndist));
  }
  for (int i = 0; i < m; ++i) poly[i] = scratch[i];
  return m;
}

}  // namespace

int clip_polygon(ClipVertex* poly, int n, uint32_t planes, geometry::GuardBand guard, int nvar) {
  for (uint32_t plane = 1; plane <= geometry::kOutGuardTop && n > 0; plane <<= 1) {
    if (!(planes & plane & geometry::kMustClipPlanes)) continue;
    n = clip_against(poly, n, nvar, 0, [&](const ClipVertex& v) { return distance(v.pos, plane, guard); });
  }
  return n;
}

int clip_polygon_user(ClipVertex* poly, int n, uint32_t planes, uint32_t nplanes, int nvar) {
  for (uint32_t k = 0; k < nplanes && n > 0; ++k)
    if (planes >> k & 1) n = clip_against(poly, n, nvar, nplanes, [k](const ClipVertex& v) { return double(v.dist[k]); });
  return n;
}

bool clip_line_user(const float* da, const float* db, uint32_t n, float* t0, float* t1) {
  *t0 = 0, *t1 = 1;
  for (uint32_t k = 0; k < n; ++k) {
    const double a = da[k], b = db[k];
    if (std::isnan(a) || std::isnan(b) || (a < 0 && b < 0)) return false;
    if (a < 0) *t0 = std::max(*t0, float(a / (a - b)));
    if (b < 0) *t1 = std::min(*t1, float(a / (a - b)));
    if (*t0 > *t1) return false;
  }
  return true;
}

bool clip_line(Vec4& a, Vec4& b, uint32_t planes, geometry::GuardBand guard, float* t0_out, float* t1_out) {
  float t0 = 0, t1 = 1;
  for (uint32_t plane = 1; plane <= geometry::kOutGuardTop; plane <<= 1) {
    if (!(planes & plane & geometry::kMustClipPlanes)) continue;
    double da = distance(a, plane, guard), db = distance(b, plane, guard);
    if (da < 0 && db < 0) return false;
    if (da < 0) t0 = std::max(t0, float(da / (da - db)));
    if (db < 0) t1 = std::min(t1, float(da / (da - db)));
    if (t0 > t1) return false;
  }
  Vec4 a0 = a, d = b - a;
  a = a0 + d * t0;
  b = a0 + d * t1;
  if (t0_out) *t0_out = t0;
  if (t1_out) *t1_out = t1;
  return true;
}

}  // namespace velocity::triangle
