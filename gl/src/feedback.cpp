// Feedback (glRenderMode(GL_FEEDBACK), GL 1.5 section 5.3): nothing is drawn; each
// point, line and polygon that survives culling is clipped to the view volume and
// written to the program's buffer as a token and its vertices in window coordinates,
// with the colour and texture coordinates glFeedbackBuffer's type asks for. As Mesa
// does, a polygon is written as the triangles it is drawn with. glRenderMode returns
// the number of values written, or -1 when the buffer overflowed.
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
struct FbVertex {
  Vec4 clip, color, tex;
};

FbVertex lerp(const FbVertex& a, const FbVertex& b, float t) {
  return {a.clip + (b.clip - a.clip) * t, a.color + (b.color - a.color) * t, a.tex + (b.tex - a.tex) * t};
}

// Signed distance to clip plane `plane` of -w <= x, y, z <= w (>= 0 inside).
float plane_distance(const Vec4& v, int plane) {
  const float c = plane < 2 ? v.x : plane < 4 ? v.y : v.z;
  return plane % 2 ? v.w - c : v.w + c;
}

// Sutherland-Hodgman on a closed polygon, attributes interpolated with the position
// (in clip space, with y negated as the renderer has it).
void clip_polygon(std::vector<FbVertex>& poly) {
  std::vector<FbVertex> out;
  for (int plane : {1, 0, 2, 3, 4, 5}) {  // Mesa's order: right, left, top, bottom, near, far
    if (poly.empty()) break;
    out.clear();
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
      const FbVertex &a = poly[i], &b = poly[(i + 1) % n];
      const float da = plane_distance(a.clip, plane), db = plane_distance(b.clip, plane);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
    }
    poly.swap(out);
  }
}

// A segment's part inside the volume; false when none is.
bool clip_segment(FbVertex& a, FbVertex& b) {
  float t0 = 0, t1 = 1;
  for (int plane = 0; plane < 6; ++plane) {
    const float da = plane_distance(a.clip, plane), db = plane_distance(b.clip, plane);
    if (!(da >= 0) && !(db >= 0)) return false;
    if (da < 0) t0 = std::max(t0, da / (da - db));
    if (db < 0) t1 = std::min(t1, da / (da - db));
  }
  if (t0 > t1) return false;
  const FbVertex a0 = a;
  if (t0 > 0) a = lerp(a0, b, t0);
  if (t1 < 1) b = lerp(a0, b, t1);
  return true;
}
}  // namespace

void Context::feedback_value(GLfloat v) {
  FeedbackState& f = feedback_;
  if (f.used < f.size) f.buffer[f.used] = v;
  ++f.used;  // past `size`: glRenderMode reports the overflow
}

void Context::feedback_buffer(GLsizei size, GLenum type, GLfloat* buffer) {
  if (in_begin_error()) return;
  if (feeding_back()) return error(GL_INVALID_OPERATION);
  if (size < 0 || (!buffer && size > 0)) return error(GL_INVALID_VALUE);
  if (type < GL_2D || type > GL_4D_COLOR_TEXTURE) return error(GL_INVALID_ENUM);
  feedback_.type = type, feedback_.buffer = buffer, feedback_.size = size_t(size);
}

void Context::pass_through(GLfloat token) {
  if (in_begin_error() || !feeding_back()) return;
  feedback_value(GLfloat(GL_PASS_THROUGH_TOKEN));
  feedback_value(token);
}

namespace {
// One vertex's values, as glFeedbackBuffer's type lists them (Table 5.2): window x and
// y; z through the depth range; w (clip w); RGBA; the four texture coordinates.
template <typename Put>
void put_vertex(Put put, GLenum type, Vec4 window, const Vec4& color, const Vec4& tex) {
  put(window.x), put(window.y);
  if (type != GL_2D) put(window.z);
  if (type == GL_4D_COLOR_TEXTURE) put(window.w);
  if (type >= GL_3D_COLOR) put(color.x), put(color.y), put(color.z), put(color.w);
  if (type >= GL_3D_COLOR_TEXTURE) put(tex.x), put(tex.y), put(tex.z), put(tex.w);
}

// The renderer's clip coordinates (y negated) to GL's window coordinates (x, y, z after
// the depth range, clip w).
Vec4 window_of(const TransformState& t, const Vec4& c) {
  const float d = c.w == 0 ? 1.0f : 1.0f / c.w;
  const Box& vp = t.viewport;
  return {float(vp.x) + (c.x * d + 1) * 0.5f * float(vp.width), float(vp.y) + (1 - c.y * d) * 0.5f * float(vp.height),
          t.depth_near + (c.z * d + 1) * 0.5f * (t.depth_far - t.depth_near), c.w};
}
}  // namespace

// (Each vertex keeps its own colour under GL_FLAT too, as in Mesa's feedback.)
void Context::feedback_polygon(const uint32_t* idx, int n, int provoking, bool back_colors) {
  auto fb = [&](uint32_t i) {
    const Vertex& v = prim_[i];
    return FbVertex{v.clip, back_colors ? v.back : v.front, v.tex};
  };
  auto put = [this](GLfloat v) { feedback_value(v); };
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    std::vector<FbVertex> poly{fb(a), fb(b), fb(c)};
    const bool inside = std::all_of(poly.begin(), poly.end(), [](const FbVertex& v) {
      return std::fabs(v.clip.x) <= v.clip.w && std::fabs(v.clip.y) <= v.clip.w && std::fabs(v.clip.z) <= v.clip.w;
    });
    std::vector<size_t> order{0, 1, 2};
    if (!inside) clip_polygon(poly);
    for (size_t k = 2; k < poly.size(); ++k) {
      // What the clipper left, as Mesa's clipper emits it: a fan with the first last.
      if (!inside) order = {k - 1, k, 0};
      feedback_value(GLfloat(GL_POLYGON_TOKEN));
      feedback_value(3);
      for (size_t i : order) put_vertex(put, feedback_.type, window_of(transform_, poly[i].clip), poly[i].color, poly[i].tex);
    }
  };
  // The triangles Mesa's draw module makes: a quad (its provoking vertex last) as
  // 0 1 3 and 1 2 3, a polygon as a fan with its first vertex last.
  if (n == 3) return triangle(idx[0], idx[1], idx[2]);
  if (n == 4 && provoking != 0) {
    uint32_t q[4];
    for (int k = 0; k < 4; ++k) q[k] = idx[(provoking + 1 + k) % 4];
    triangle(q[0], q[1], q[3]);
    return triangle(q[1], q[2], q[3]);
  }
  for (int k = 1; k + 1 < n; ++k) triangle(idx[k], idx[k + 1], idx[0]);
}

void Context::feedback_line(uint32_t a, uint32_t b) {
  FbVertex va{prim_[a].clip, prim_[a].front, prim_[a].tex};
  FbVertex vb{prim_[b].clip, prim_[b].front, prim_[b].tex};
  if (!clip_segment(va, vb)) return;
  // (Mesa writes GL_LINE_TOKEN for every segment, never GL_LINE_RESET_TOKEN; so does pGL.)
  feedback_value(GLfloat(GL_LINE_TOKEN));
  auto put = [this](GLfloat v) { feedback_value(v); };
  put_vertex(put, feedback_.type, window_of(transform_, va.clip), va.color, va.tex);
  put_vertex(put, feedback_.type, window_of(transform_, vb.clip), vb.color, vb.tex);
}

void Context::feedback_point(uint32_t a) {
  const Vec4& c = prim_[a].clip;
  if (!(std::fabs(c.x) <= c.w && std::fabs(c.y) <= c.w && std::fabs(c.z) <= c.w)) return;
  feedback_value(GLfloat(GL_POINT_TOKEN));
  put_vertex([this](GLfloat v) { feedback_value(v); }, feedback_.type, window_of(transform_, c), prim_[a].front, prim_[a].tex);
}

// The raster position's token in feedback mode, a hit at its depth in select mode
// (GL 1.5 sections 5.2, 5.3); either way no fragments.
bool Context::pixels_not_rendered(GLenum token) {
  if (select_.mode == GL_RENDER) return false;
  const RasterPosition& r = pixels.raster;
  if (!r.valid) return true;
  if (selecting()) {
    select_.hit = true;
    select_.min_z = std::min(select_.min_z, r.window.z), select_.max_z = std::max(select_.max_z, r.window.z);
    return true;
  }
  feedback_value(GLfloat(token));
  put_vertex([this](GLfloat v) { feedback_value(v); }, feedback_.type, r.window, r.color, r.texcoord);
  return true;
}

}  // namespace velocity::gl
