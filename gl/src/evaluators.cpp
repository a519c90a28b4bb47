// Evaluators (GL 1.5, 5.1): glMap1 and glMap2 give a Bezier curve's or surface's
// control points for a vertex attribute; glEvalCoord1 and glEvalCoord2 evaluate every
// enabled map at (u) or (u, v) and issue the values as glColor, glNormal, glTexCoord
// and glVertex would — without changing the current values, as GL says (and Mesa
// does) —; GL_AUTO_NORMAL gives a surface's vertices the normal of its partial
// derivatives; glMapGrid with glEvalMesh and glEvalPoint evaluate on an even grid.
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
// Components of each GL_MAP1_* (and GL_MAP2_*) target, in the enums' order (COLOR_4 first).
constexpr int kComponents[kMap1Targets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

// The Bernstein polynomials of degree n at t, b[0..n], by de Casteljau's recurrence
// B(d, i) = (1 - t) B(d - 1, i) + t B(d - 1, i - 1); and, if db is given, their
// derivatives in t, n (B(n - 1, i - 1) - B(n - 1, i)).
void bernstein(int n, float t, float* b, float* db) {
  b[0] = 1;
  if (db) db[0] = 0;
  for (int d = 1; d <= n; ++d) {
    if (d == n && db)
      for (int i = 0; i <= n; ++i) db[i] = float(n) * ((i > 0 ? b[i - 1] : 0.0f) - (i < n ? b[i] : 0.0f));
    b[d] = t * b[d - 1];
    for (int i = d - 1; i > 0; --i) b[i] = (1 - t) * b[i] + t * b[i - 1];
    b[0] *= 1 - t;
  }
}

void assign(Vec4& v, const float* c, int k) {
  float* dst[4] = {&v.x, &v.y, &v.z, &v.w};
  for (int i = 0; i < k; ++i) *dst[i] = c[i];
}

// Point i of n segments from a to b; the last is b exactly (as Mesa's meshes).
float grid_point(const EvalGrid& g, GLint i) {
  if (i == g.n) return g.b;
  return g.a + float(i) * (g.b - g.a) / float(g.n);
}
}  // namespace

int Context::map1_components(GLenum target) {
  return target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4 ? kComponents[target - GL_MAP1_COLOR_4] : 0;
}

int Context::map2_components(GLenum target) {
  return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4 ? kComponents[target - GL_MAP2_COLOR_4] : 0;
}

EvalState::EvalState() {
  // The initial maps: order 1, domain [0, 1], GL's initial attribute values.
  static const float initial[kMap1Targets][4] = {{1, 1, 1, 1}, {1}, {0, 0, 1}, {0}, {0, 0}, {0, 0, 0}, {0, 0, 0, 1},
                                                 {0, 0, 0}, {0, 0, 0, 1}};
  for (int m = 0; m < kMap1Targets; ++m) maps[m].points.assign(initial[m], initial[m] + kComponents[m]);
  for (int m = 0; m < kMap2Targets; ++m) maps2[m].points.assign(initial[m], initial[m] + kComponents[m]);
}

void Context::map1(GLenum target, float u1, float u2, GLint stride, GLint order, const std::vector<float>& points) {
  if (in_begin_error()) return;
  const int k = map1_components(target);
  if (!k) return error(GL_INVALID_ENUM);
  if (u1 == u2 || stride < k || order < 1 || order > kMaxEvalOrder) return error(GL_INVALID_VALUE);
  if (points.size() != size_t(order) * size_t(k)) return;  // (the entry point packs them)
  Map1& m = eval_.maps[target - GL_MAP1_COLOR_4];
  m.u1 = u1, m.u2 = u2, m.order = order;
  m.points = points;
}

void Context::map2(GLenum target, const Map2& map, GLint ustride, GLint vstride) {
  if (in_begin_error()) return;
  const int k = map2_components(target);
  if (!k) return error(GL_INVALID_ENUM);
  if (map.u1 == map.u2 || map.v1 == map.v2 || ustride < k || vstride < k || map.uorder < 1 ||
      map.uorder > kMaxEvalOrder || map.vorder < 1 || map.vorder > kMaxEvalOrder)
    return error(GL_INVALID_VALUE);
  if (map.points.size() != size_t(map.uorder) * size_t(map.vorder) * size_t(k)) return;  // (packed by the entry point)
  eval_.maps2[target - GL_MAP2_COLOR_4] = map;
}

bool Context::enable_evaluator(GLenum cap, bool on) {
  if (map1_components(cap)) return eval_.enabled[cap - GL_MAP1_COLOR_4] = on, true;
  if (map2_components(cap)) return eval_.enabled2[cap - GL_MAP2_COLOR_4] = on, true;
  if (cap == GL_AUTO_NORMAL) return eval_.auto_normal = on, true;
  return false;
}

bool Context::evaluator_enabled(GLenum cap, bool* known) const {
  *known = true;
  if (map1_components(cap)) return eval_.enabled[cap - GL_MAP1_COLOR_4];
  if (map2_components(cap)) return eval_.enabled2[cap - GL_MAP2_COLOR_4];
  if (cap == GL_AUTO_NORMAL) return eval_.auto_normal;
  *known = false;
  return false;
}

// The curve of map `m` at u.
Vec4 Context::evaluate1(const Map1& m, int k, float u, Vec4 v) const {
  float b[kMaxEvalOrder];
  bernstein(m.order - 1, (u - m.u1) / (m.u2 - m.u1), b, nullptr);
  float out[4] = {0, 0, 0, 0};
  for (int i = 0; i < m.order; ++i)
    for (int c = 0; c < k; ++c) out[c] += b[i] * m.points[size_t(i) * size_t(k) + size_t(c)];
  assign(v, out, k);
  return v;
}

// The surface of map `m` at (u, v) into out[0..k); with du and dv, its partial
// derivatives in the map's unit parameters too.
void Context::evaluate2(const Map2& m, int k, float u, float v, float* out, float* du, float* dv) const {
  float bu[kMaxEvalOrder], bv[kMaxEvalOrder], dbu[kMaxEvalOrder], dbv[kMaxEvalOrder];
  bernstein(m.uorder - 1, (u - m.u1) / (m.u2 - m.u1), bu, du ? dbu : nullptr);
  bernstein(m.vorder - 1, (v - m.v1) / (m.v2 - m.v1), bv, dv ? dbv : nullptr);
  for (int c = 0; c < k; ++c) out[c] = 0;
  if (du)
    for (int c = 0; c < k; ++c) du[c] = dv[c] = 0;
  for (int i = 0; i < m.uorder; ++i)
    for (int j = 0; j < m.vorder; ++j) {
      const float* p = &m.points[(size_t(i) * size_t(m.vorder) + size_t(j)) * size_t(k)];
      const float w = bu[i] * bv[j];
      for (int c = 0; c < k; ++c) out[c] += w * p[c];
      if (!du) continue;
      for (int c = 0; c < k; ++c) du[c] += dbu[i] * bv[j] * p[c], dv[c] += bu[i] * dbv[j] * p[c];
    }
}

void Context::eval_coord1(float u) {
  const bool* on = eval_.enabled;
  auto map = [&](GLenum target) -> const Map1& { return eval_.maps[target - GL_MAP1_COLOR_4]; };
  const Vec4 color = color_, texcoord = texcoord_;
  const Vec3 normal = normal_;
  const bool colored = on[GL_MAP1_COLOR_4 - GL_MAP1_COLOR_4];
  if (colored) set_color(evaluate1(map(GL_MAP1_COLOR_4), 4, u, color_));
  if (on[GL_MAP1_NORMAL - GL_MAP1_COLOR_4]) normal_ = evaluate1(map(GL_MAP1_NORMAL), 3, u, {}).xyz();
  // The texture map of the most coordinates that is enabled.
  for (GLenum t = GL_MAP1_TEXTURE_COORD_4; t >= GL_MAP1_TEXTURE_COORD_1; --t)
    if (on[t - GL_MAP1_COLOR_4]) {
      texcoord_ = evaluate1(map(t), int(t - GL_MAP1_TEXTURE_COORD_1) + 1, u, {0, 0, 0, 1});
      break;
    }
  if (on[GL_MAP1_VERTEX_4 - GL_MAP1_COLOR_4]) vertex(evaluate1(map(GL_MAP1_VERTEX_4), 4, u, {0, 0, 0, 1}));
  else if (on[GL_MAP1_VERTEX_3 - GL_MAP1_COLOR_4]) vertex(evaluate1(map(GL_MAP1_VERTEX_3), 3, u, {0, 0, 0, 1}));
  // The current values are the ones before (the colour material's too: set_color fed it).
  if (colored) set_color(color);
  texcoord_ = texcoord, normal_ = normal;
}

void Context::eval_coord2(float u, float v) {
  const bool* on = eval_.enabled2;
  auto map = [&](GLenum target) -> const Map2& { return eval_.maps2[target - GL_MAP2_COLOR_4]; };
  const Vec4 color = color_, texcoord = texcoord_;
  const Vec3 normal = normal_;
  float value[4];
  const bool colored = on[GL_MAP2_COLOR_4 - GL_MAP2_COLOR_4];
  if (colored) {
    Vec4 c = color_;
    evaluate2(map(GL_MAP2_COLOR_4), 4, u, v, value, nullptr, nullptr);
    assign(c, value, 4);
    set_color(c);
  }
  if (on[GL_MAP2_NORMAL - GL_MAP2_COLOR_4]) {
    evaluate2(map(GL_MAP2_NORMAL), 3, u, v, value, nullptr, nullptr);
    normal_ = {value[0], value[1], value[2]};
  }
  for (GLenum t = GL_MAP2_TEXTURE_COORD_4; t >= GL_MAP2_TEXTURE_COORD_1; --t)
    if (on[t - GL_MAP2_COLOR_4]) {
      const int k = int(t - GL_MAP2_TEXTURE_COORD_1) + 1;
      evaluate2(map(t), k, u, v, value, nullptr, nullptr);
      texcoord_ = {0, 0, 0, 1};
      assign(texcoord_, value, k);
      break;
    }
  const GLenum vertex_map = on[GL_MAP2_VERTEX_4 - GL_MAP2_COLOR_4]   ? GL_MAP2_VERTEX_4
                            : on[GL_MAP2_VERTEX_3 - GL_MAP2_COLOR_4] ? GL_MAP2_VERTEX_3
                                                                     : GL_NONE;
  if (vertex_map != GL_NONE) {
    const int k = vertex_map == GL_MAP2_VERTEX_4 ? 4 : 3;
    float du[4], dv[4];
    const bool auto_normal = eval_.auto_normal;
    evaluate2(map(vertex_map), k, u, v, value, auto_normal ? du : nullptr, auto_normal ? dv : nullptr);
    if (k == 3) value[3] = 1;
    if (auto_normal) {
      // The derivatives of the projected point (x/w, y/w, z/w) up to the factor 1/w²,
      // which the normalization removes (as Mesa).
      if (k == 4)
        for (int c = 0; c < 3; ++c)
          du[c] = du[c] * value[3] - du[3] * value[c], dv[c] = dv[c] * value[3] - dv[3] * value[c];
      const Vec3 n = cross(Vec3{du[0], du[1], du[2]}, Vec3{dv[0], dv[1], dv[2]});
      const float len = length(n);
      normal_ = len > 0 ? n * (1 / len) : n;  // (a degenerate point keeps a zero normal, as Mesa)
    }
    vertex({value[0], value[1], value[2], value[3]});
  }
  // The current values are the ones before, as glEvalCoord1 leaves them.
  if (colored) set_color(color);
  texcoord_ = texcoord, normal_ = normal;
}

void Context::map_grid1(GLint n, float u1, float u2) {
  if (in_begin_error()) return;
  if (n <= 0) return error(GL_INVALID_VALUE);
  eval_.grid1 = {n, u1, u2};
}

void Context::map_grid2(GLint un, float u1, float u2, GLint vn, float v1, float v2) {
  if (in_begin_error()) return;
  if (un <= 0 || vn <= 0) return error(GL_INVALID_VALUE);
  eval_.grid2u = {un, u1, u2}, eval_.grid2v = {vn, v1, v2};
}

float Context::grid_u(GLint i) const { return grid_point(eval_.grid1, i); }

void Context::eval_point2(GLint i, GLint j) { eval_coord2(grid_point(eval_.grid2u, i), grid_point(eval_.grid2v, j)); }

void Context::eval_mesh1(GLenum mode, GLint i1, GLint i2) {
  if (in_begin_error()) return;
  if (mode != GL_POINT && mode != GL_LINE) return error(GL_INVALID_ENUM);
  begin(mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
  // (At most kMaxPrimitiveVertices points are kept by the vertex stage: more is its
  // GL_OUT_OF_MEMORY, so the loop is bounded by that, not by i2 - i1.)
  for (int64_t i = i1; i <= i2 && i - i1 <= int64_t(kMaxPrimitiveVertices); ++i) eval_coord1(grid_u(GLint(i)));
  end();
}

// The primitives of GL 1.5's 5.1 as Mesa issues them: points row by row; for lines,
// a strip along u for each v and then one along v for each u; for fill, a triangle
// strip between each two rows (Mesa's, so the quads split on its diagonal).
void Context::eval_mesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  if (in_begin_error()) return;
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return error(GL_INVALID_ENUM);
  if (i2 < i1 || j2 < j1) return;
  // A mesh of more points than a primitive may have is GL_OUT_OF_MEMORY, as one that
  // long would be in the vertex stage: the loops below stay bounded.
  const int64_t ni = int64_t(i2) - i1 + 1, nj = int64_t(j2) - j1 + 1, most = int64_t(kMaxPrimitiveVertices);
  if (ni > most || nj > most || ni * nj > most) return error(GL_OUT_OF_MEMORY);
  // (The loops count in 64 bits: an index range ending at INT_MAX must not overflow.)
  const EvalGrid &gu = eval_.grid2u, &gv = eval_.grid2v;
  auto at = [&](int64_t i, int64_t j) { eval_coord2(grid_point(gu, GLint(i)), grid_point(gv, GLint(j))); };
  if (mode == GL_POINT) {
    begin(GL_POINTS);
    for (int64_t j = j1; j <= j2; ++j)
      for (int64_t i = i1; i <= i2; ++i) at(i, j);
    end();
  } else if (mode == GL_LINE) {
    for (int64_t j = j1; j <= j2; ++j) {
      begin(GL_LINE_STRIP);
      for (int64_t i = i1; i <= i2; ++i) at(i, j);
      end();
    }
    for (int64_t i = i1; i <= i2; ++i) {
      begin(GL_LINE_STRIP);
      for (int64_t j = j1; j <= j2; ++j) at(i, j);
      end();
    }
  } else {
    for (int64_t j = j1; j < j2; ++j) {
      begin(GL_TRIANGLE_STRIP);
      for (int64_t i = i1; i <= i2; ++i) at(i, j), at(i, j + 1);
      end();
    }
  }
}

bool Context::get_map(GLenum target, GLenum query, std::vector<double>& out) {
  if (map1_components(target)) {
    const Map1& m = eval_.maps[target - GL_MAP1_COLOR_4];
    switch (query) {
      case GL_COEFF: out.assign(m.points.begin(), m.points.end()); return true;
      case GL_ORDER: out = {double(m.order)}; return true;
      case GL_DOMAIN: out = {m.u1, m.u2}; return true;
      default: return error(GL_INVALID_ENUM), false;
    }
  }
  if (!map2_components(target)) return error(GL_INVALID_ENUM), false;
  const Map2& m = eval_.maps2[target - GL_MAP2_COLOR_4];
  switch (query) {
    case GL_COEFF: out.assign(m.points.begin(), m.points.end()); return true;
    case GL_ORDER: out = {double(m.uorder), double(m.vorder)}; return true;
    case GL_DOMAIN: out = {m.u1, m.u2, m.v1, m.v2}; return true;
    default: return error(GL_INVALID_ENUM), false;
  }
}

bool Context::get_eval(GLenum pname, std::vector<double>& out) const {
  const EvalState& e = eval_;
  switch (pname) {
    case GL_MAX_EVAL_ORDER: out = {double(kMaxEvalOrder)}; return true;
    case GL_MAP1_GRID_DOMAIN: out = {e.grid1.a, e.grid1.b}; return true;
    case GL_MAP1_GRID_SEGMENTS: out = {double(e.grid1.n)}; return true;
    case GL_MAP2_GRID_DOMAIN: out = {e.grid2u.a, e.grid2u.b, e.grid2v.a, e.grid2v.b}; return true;
    case GL_MAP2_GRID_SEGMENTS: out = {double(e.grid2u.n), double(e.grid2v.n)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
