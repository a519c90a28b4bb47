// One-dimensional evaluators (GL 1.5, 5.1): glMap1 gives a Bezier curve's control
// points for a vertex attribute, glEvalCoord1 evaluates every enabled map at u and
// issues the values as glColor, glNormal, glTexCoord and glVertex would — without
// changing the current values, as GL says (and Mesa does) —, glMapGrid1 with
// glEvalMesh1 and glEvalPoint1 evaluate on an even grid. Two-dimensional maps
// (glMap2, glEvalMesh2) and GL_AUTO_NORMAL do not exist.
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
// Components of each GL_MAP1_* target, in the enums' order (GL_MAP1_COLOR_4 first).
constexpr int kComponents[kMap1Targets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
}  // namespace

int Context::map1_components(GLenum target) {
  return target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4 ? kComponents[target - GL_MAP1_COLOR_4] : 0;
}

EvalState::EvalState() {
  // The initial maps: order 1, domain [0, 1], GL's initial attribute values.
  static const float initial[kMap1Targets][4] = {{1, 1, 1, 1}, {1}, {0, 0, 1}, {0}, {0, 0}, {0, 0, 0}, {0, 0, 0, 1},
                                                 {0, 0, 0}, {0, 0, 0, 1}};
  for (int m = 0; m < kMap1Targets; ++m) maps[m].points.assign(initial[m], initial[m] + kComponents[m]);
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

bool Context::enable_map1(GLenum cap, bool on) {
  if (!map1_components(cap)) return false;
  eval_.enabled[cap - GL_MAP1_COLOR_4] = on;
  return true;
}

bool Context::map1_enabled(GLenum cap, bool* known) const {
  *known = map1_components(cap) != 0;
  return *known && eval_.enabled[cap - GL_MAP1_COLOR_4];
}

// The curve of map `m` at u: Bernstein polynomials of degree order - 1 in t.
Vec4 Context::evaluate1(const Map1& m, int k, float u, Vec4 v) const {
  const float t = (u - m.u1) / (m.u2 - m.u1), s = 1 - t;
  float out[4] = {0, 0, 0, 0};
  const int n = m.order - 1;
  float binomial = 1;  // C(n, i)
  for (int i = 0; i <= n; ++i) {
    const float b = binomial * std::pow(t, float(i)) * std::pow(s, float(n - i));
    for (int c = 0; c < k; ++c) out[c] += b * m.points[size_t(i) * size_t(k) + size_t(c)];
    binomial = binomial * float(n - i) / float(i + 1);
  }
  float* dst[4] = {&v.x, &v.y, &v.z, &v.w};
  for (int c = 0; c < k; ++c) *dst[c] = out[c];
  return v;
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

void Context::map_grid1(GLint n, float u1, float u2) {
  if (in_begin_error()) return;
  if (n <= 0) return error(GL_INVALID_VALUE);
  eval_.grid_n = n, eval_.grid_u1 = u1, eval_.grid_u2 = u2;
}

float Context::grid_u(GLint i) const {
  // The last point is u2 exactly (as Mesa), not u1 plus n steps.
  if (i == eval_.grid_n) return eval_.grid_u2;
  return eval_.grid_u1 + float(i) * (eval_.grid_u2 - eval_.grid_u1) / float(eval_.grid_n);
}

void Context::eval_mesh1(GLenum mode, GLint i1, GLint i2) {
  if (in_begin_error()) return;
  if (mode != GL_POINT && mode != GL_LINE) return error(GL_INVALID_ENUM);
  begin(mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
  // (At most kMaxPrimitiveVertices points are kept by the vertex stage: more is its
  // GL_OUT_OF_MEMORY, so the loop is bounded by that, not by i2 - i1.)
  for (int64_t i = i1; i <= i2 && i - i1 <= int64_t(kMaxPrimitiveVertices); ++i) eval_coord1(grid_u(GLint(i)));
  end();
}

bool Context::get_map1(GLenum target, GLenum query, std::vector<double>& out) {
  const int k = map1_components(target);
  if (!k) return error(GL_INVALID_ENUM), false;
  const Map1& m = eval_.maps[target - GL_MAP1_COLOR_4];
  switch (query) {
    case GL_COEFF: out.assign(m.points.begin(), m.points.end()); return true;
    case GL_ORDER: out = {double(m.order)}; return true;
    case GL_DOMAIN: out = {m.u1, m.u2}; return true;
    default: return error(GL_INVALID_ENUM), false;
  }
}

bool Context::get_eval(GLenum pname, std::vector<double>& out) const {
  switch (pname) {
    case GL_MAX_EVAL_ORDER: out = {double(kMaxEvalOrder)}; return true;
    case GL_MAP1_GRID_DOMAIN: out = {eval_.grid_u1, eval_.grid_u2}; return true;
    case GL_MAP1_GRID_SEGMENTS: out = {double(eval_.grid_n)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
