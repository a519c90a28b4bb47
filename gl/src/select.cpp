// Selection (glRenderMode(GL_SELECT)): nothing is drawn; each point, line and polygon
// that survives culling and clipping to the view volume marks a hit for the name stack,
// with the least and greatest window depth of what is left of it. A hit record (the
// stack's depth, the depths scaled to 2^32 - 1, the names) is written to the program's
// buffer when the name stack changes and when the mode ends; glRenderMode returns the
// records written, or -1 when the buffer overflowed (GL 1.5 section 5.2).
#include <algorithm>
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

namespace {
// Sutherland-Hodgman in clip space against the six planes -w <= x, y, z <= w: what is
// left of polygon `in` (or of a segment, closed = false) goes to `out`.
void clip_to_volume(std::vector<Vec4>& poly, bool closed) {
  std::vector<Vec4> out;
  for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
    auto dist = [&](const Vec4& v) {
      const float c = plane < 2 ? v.x : plane < 4 ? v.y : v.z;
      return plane % 2 ? v.w - c : v.w + c;  // >= 0 inside
    };
    out.clear();
    const size_t n = poly.size();
    const size_t edges = closed ? n : n - 1;
    if (!closed && n == 1) {
      if (dist(poly[0]) >= 0) out.push_back(poly[0]);
    }
    for (size_t i = 0; i < edges; ++i) {
      const Vec4 &a = poly[i], &b = poly[(i + 1) % n];
      const float da = dist(a), db = dist(b);
      if (da >= 0 && (closed || i == 0)) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        const float t = da / (da - db);
        out.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, a.w + (b.w - a.w) * t});
      }
      if (!closed && db >= 0) out.push_back(b);
    }
    poly.swap(out);
  }
}
}  // namespace

void Context::select_hit(const uint32_t* idx, int n, bool closed) {
  std::vector<Vec4> poly;
  for (int k = 0; k < n; ++k) poly.push_back(prim_[idx[k]].clip);
  clip_to_volume(poly, closed && n > 2);
  for (const Vec4& v : poly) {
    if (!(v.w != 0)) continue;
    const float ndc = v.z / v.w;
    const float z = std::clamp(transform_.depth_near + (ndc * 0.5f + 0.5f) * (transform_.depth_far - transform_.depth_near),
                               0.0f, 1.0f);
    select_.hit = true;
    select_.min_z = std::min(select_.min_z, z), select_.max_z = std::max(select_.max_z, z);
  }
}

void Context::write_hit_record() {
  SelectState& s = select_;
  if (!s.hit) return;
  auto put = [&](GLuint v) {
    if (s.used < s.size) s.buffer[s.used] = v;
    else s.overflow = true;
    ++s.used;
  };
  put(GLuint(s.names.size()));
  put(GLuint(double(s.min_z) * 4294967295.0));
  put(GLuint(double(s.max_z) * 4294967295.0));
  for (GLuint name : s.names) put(name);
  ++s.hits;
  s.hit = false, s.min_z = 1, s.max_z = 0;
}

GLint Context::render_mode(GLenum mode) {
  if (in_begin_error()) return 0;
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) return error(GL_INVALID_ENUM), 0;
  SelectState& s = select_;
  if (mode == GL_SELECT && !s.buffer) return error(GL_INVALID_OPERATION), 0;
  if (mode == GL_FEEDBACK && feedback_.size == 0) return error(GL_INVALID_OPERATION), 0;
  GLint result = 0;
  if (s.mode == GL_SELECT) {
    write_hit_record();
    result = s.overflow ? -1 : GLint(s.hits);
  } else if (s.mode == GL_FEEDBACK) {
    result = feedback_.used > feedback_.size ? -1 : GLint(feedback_.used);  // (feedback.cpp)
  }
  submit_pending();
  s.mode = mode;
  s.used = 0, s.hits = 0, s.overflow = false, s.hit = false, s.min_z = 1, s.max_z = 0;
  s.names.clear();
  feedback_.used = 0;
  changed();
  return result;
}

void Context::select_buffer(GLsizei size, GLuint* buffer) {
  if (in_begin_error()) return;
  if (size < 0) return error(GL_INVALID_VALUE);
  if (select_.mode == GL_SELECT) return error(GL_INVALID_OPERATION);
  select_.buffer = buffer, select_.size = size_t(size);
}

void Context::init_names() {
  if (in_begin_error() || select_.mode != GL_SELECT) return;
  write_hit_record();
  select_.names.clear();
}

void Context::push_name(GLuint name) {
  if (in_begin_error() || select_.mode != GL_SELECT) return;
  write_hit_record();
  if (select_.names.size() >= size_t(kMaxNameDepth)) return error(GL_STACK_OVERFLOW);
  select_.names.push_back(name);
}

void Context::pop_name() {
  if (in_begin_error() || select_.mode != GL_SELECT) return;
  write_hit_record();
  if (select_.names.empty()) return error(GL_STACK_UNDERFLOW);
  select_.names.pop_back();
}

void Context::load_name(GLuint name) {
  if (in_begin_error() || select_.mode != GL_SELECT) return;
  if (select_.names.empty()) return error(GL_INVALID_OPERATION);
  write_hit_record();
  select_.names.back() = name;
}

}  // namespace velocity::gl
