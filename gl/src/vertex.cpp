// The vertex stage: glBegin/glEnd, transform, GL lighting, primitive assembly for the
// ten modes (with GL's provoking vertices), face culling and polygon modes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "context.hpp"


namespace velocity::gl {

namespace {
[[gnu::always_inline]] inline Vec4 clamp_color(Vec4 c) { return {unit(c.x), unit(c.y), unit(c.z), unit(c.w)}; }
float dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 normalized(Vec3 v) {
  const float l = std::sqrt(dot3(v, v));
  return l > 0 ? Vec3{v.x / l, v.y / l, v.z / l} : v;
}
// Vertices kept before independent primitives are assembled (a multiple of 3 and 4).
constexpr size_t kAssembleEvery = 3072;
}  // namespace

void Context::begin(GLenum mode) {
  if (mode > GL_POLYGON) return error(GL_INVALID_ENUM);
  if (in_begin_) return error(GL_INVALID_OPERATION);
  in_begin_ = true;
  mode_ = mode;
  prim_.clear(), order_.clear(), emitted_.clear();
  ++pending_gen_;  // prim_ indices start again
  if (pending_gen_ == 0) pending_gen_ = 1;
  update_derived();
  prepare_lighting();
}

void Context::end() {
  if (!in_begin_) return error(GL_INVALID_OPERATION);
  assemble(true);
  in_begin_ = false;
  prim_.clear(), order_.clear(), emitted_.clear();
}

// What lighting needs per light that stays the same through a glBegin/glEnd (lights
// and the light model cannot change inside it; materials can).
void Context::prepare_lighting() {
  lights_used_ = 0;
  need_eye_ = raster_.fog || (lighting_.enabled && lighting_.local_viewer);
  if (!lighting_.enabled) return;
  for (const Light& l : lighting_.lights) {
    if (!l.enabled) continue;
    LightUse& u = light_use_[lights_used_++];
    u.light = &l;
    u.positional = l.position.w != 0;
    u.spot = l.spot_cutoff != 180;
    u.cos_cutoff = std::cos(l.spot_cutoff * 3.14159265358979f / 180.0f);
    u.spot_direction = normalized(l.spot_direction);
    u.direction = normalized(l.position.xyz());
    u.half = normalized(Vec3{u.direction.x, u.direction.y, u.direction.z + 1});  // with the viewer at +z
    if (u.positional) need_eye_ = true;
  }
}

// OpenGL's lighting equation (GL 1.5 section 2.14.1) for one vertex and one side.
// Inlined into vertex(): returned through registers, the colour would be stored in two
// halves and reloaded whole, a store-forwarding stall per vertex.
[[gnu::always_inline]] inline Vec4 Context::lit(const Vec4& eye4, Vec3 n, bool back) const {
  const Material& m = lighting_.materials[back ? 1 : 0];
  if (back) n = {-n.x, -n.y, -n.z};
  float r = m.emission.x + m.ambient.x * lighting_.model_ambient.x;
  float g = m.emission.y + m.ambient.y * lighting_.model_ambient.y;
  float b = m.emission.z + m.ambient.z * lighting_.model_ambient.z;
  Vec3 eye{0, 0, 0}, view{0, 0, 1};
  if (need_eye_) {
    eye = eye4.w != 0 && eye4.w != 1 ? Vec3{eye4.x / eye4.w, eye4.y / eye4.w, eye4.z / eye4.w} : eye4.xyz();
    if (lighting_.local_viewer) view = normalized(Vec3{-eye.x, -eye.y, -eye.z});
  }
  for (int k = 0; k < lights_used_; ++k) {
    const LightUse& u = light_use_[k];
    const Light& l = *u.light;
    Vec3 to_light = u.direction;
    float att = 1;
    if (u.positional) {
      const Vec3 p{l.position.x / l.position.w - eye.x, l.position.y / l.position.w - eye.y,
                   l.position.z / l.position.w - eye.z};
      const float d = std::sqrt(dot3(p, p));
      to_light = d > 0 ? Vec3{p.x / d, p.y / d, p.z / d} : p;
      const float kd = l.constant + l.linear * d + l.quadratic * d * d;
      att = kd > 0 ? 1.0f / kd : 1.0f;
    }
    if (u.spot) {
      const float c = -dot3(to_light, u.spot_direction);
      if (c < u.cos_cutoff) continue;  // outside the cone: nothing
      att *= l.spot_exponent != 0 ? std::pow(std::max(c, 0.0f), l.spot_exponent) : 1.0f;
    }
    float lr = m.ambient.x * l.ambient.x, lg = m.ambient.y * l.ambient.y, lb = m.ambient.z * l.ambient.z;
    const float ndotl = dot3(n, to_light);
    if (ndotl > 0) {
      lr += ndotl * m.diffuse.x * l.diffuse.x, lg += ndotl * m.diffuse.y * l.diffuse.y,
          lb += ndotl * m.diffuse.z * l.diffuse.z;
      const Vec3 h = u.positional || lighting_.local_viewer
                         ? normalized(Vec3{to_light.x + view.x, to_light.y + view.y, to_light.z + view.z})
                         : u.half;
      const float ndoth = dot3(n, h);
      if (ndoth > 0) {
        const float sp = m.shininess != 0 ? std::pow(ndoth, m.shininess) : 1.0f;
        lr += sp * m.specular.x * l.specular.x, lg += sp * m.specular.y * l.specular.y,
            lb += sp * m.specular.z * l.specular.z;
      }
    }
    r += att * lr, g += att * lg, b += att * lb;
  }
  return clamp_color({r, g, b, m.diffuse.w});
}

void Context::vertex(Vec4 v) {
  if (!in_begin_) return;  // outside glBegin/glEnd a vertex draws nothing (GL leaves it undefined)
  Vertex out;
  out.clip = transform_.mvp * v;
  if (lighting_.enabled || raster_.fog) {
    const Vec4 eye = need_eye_ ? transform_.modelview.back() * v : Vec4{};
    if (lighting_.enabled) {
      Vec3 n = transform_.normal_matrix.transform_vector(normal_);
      if (transform_.normalize || transform_.rescale_normal) n = normalized(n);
      out.front = lit(eye, n, false);
      out.back = lighting_.two_side ? lit(eye, n, true) : out.front;
    }
    out.fog = std::fabs(eye.z);
  }
  if (!lighting_.enabled) out.front = out.back = clamp_color(color_);
  if (texture_.enabled) out.tex = transform_.texture_identity ? texcoord_ : transform_.texture.back() * texcoord_;
  push_vertex(out);
}

void Context::push_vertex(const Vertex& v) {
  if (order_.size() >= kMaxPrimitiveVertices) {
    error(GL_OUT_OF_MEMORY);  // (only the first error is kept until glGetError)
    return;
  }
  order_.push_back(uint32_t(prim_.size()));
  prim_.push_back(v);
  emitted_.emplace_back();
  if (!caching_ && order_.size() >= kAssembleEvery &&
      (mode_ == GL_POINTS || mode_ == GL_LINES || mode_ == GL_TRIANGLES || mode_ == GL_QUADS)) {
    assemble(false);
    prim_.clear(), order_.clear(), emitted_.clear();
    if (++pending_gen_ == 0) pending_gen_ = 1;
  }
}

void Context::assemble(bool final) {
  const uint32_t n = uint32_t(order_.size());
  const std::vector<uint32_t>& o = order_;
  switch (mode_) {
    case GL_POINTS:
      for (uint32_t i = 0; i < n; ++i) point_vertex(o[i]);
      break;
    case GL_LINES:
      for (uint32_t i = 0; i + 1 < n; i += 2) line_segment(o[i], o[i + 1], o[i + 1]);
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      if (!final) break;
      for (uint32_t i = 0; i + 1 < n; ++i) line_segment(o[i], o[i + 1], o[i + 1]);
      if (mode_ == GL_LINE_LOOP && n >= 2) line_segment(o[n - 1], o[0], o[0]);
      break;
    case GL_TRIANGLES:
      for (uint32_t i = 0; i + 2 < n; i += 3) {
        const uint32_t t[3] = {o[i], o[i + 1], o[i + 2]};
        polygon(t, 3, 2);
      }
      break;
    case GL_TRIANGLE_STRIP:
      if (!final) break;
      for (uint32_t i = 0; i + 2 < n; ++i) {
        const uint32_t t[3] = {o[i % 2 ? i + 1 : i], o[i % 2 ? i : i + 1], o[i + 2]};  // odd ones keep the winding
        polygon(t, 3, 2);
      }
      break;
    case GL_TRIANGLE_FAN:
      if (!final) break;
      for (uint32_t i = 0; i + 2 < n; ++i) {
        const uint32_t t[3] = {o[0], o[i + 1], o[i + 2]};
        polygon(t, 3, 2);
      }
      break;
    case GL_QUADS:
      for (uint32_t i = 0; i + 3 < n; i += 4) {
        const uint32_t q[4] = {o[i], o[i + 1], o[i + 2], o[i + 3]};
        polygon(q, 4, 3);
      }
      break;
    case GL_QUAD_STRIP:
      if (!final) break;
      for (uint32_t i = 0; i + 3 < n; i += 2) {
        // The quad (i, i+1, i+3, i+2): the fan below splits it along i - i+3, as
        // Mesa does; i+3 provokes.
        const uint32_t q[4] = {o[i], o[i + 1], o[i + 3], o[i + 2]};
        polygon(q, 4, 2);
      }
      break;
    case GL_POLYGON:
      if (!final || n < 3) break;
      {
        polygon(o.data(), int(n), 0);
      }
      break;
    default: break;
  }
}

// One polygon (a triangle, a quad, or GL_POLYGON's vertices) in boundary order:
// facing, culling, polygon mode, flat colour from `provoking` (an index into idx).
void Context::polygon(const uint32_t* idx, int n, int provoking) {
  // Facing from the signed area in window space (the viewport keeps its sign); with
  // a vertex behind the eye, from the homogeneous determinant of the first three.
  bool all_front = n > 3;  // a triangle's determinant has the sign of its area when all w > 0
  for (int k = 0; k < n && all_front; ++k) all_front = prim_[idx[k]].clip.w > 0;
  double area = 0;
  if (all_front) {
    for (int k = 0; k < n; ++k) {
      const Vec4& a = prim_[idx[k]].clip;
      const Vec4& b = prim_[idx[(k + 1) % n]].clip;
      area += double(a.x) / a.w * (double(b.y) / b.w) - double(b.x) / b.w * (double(a.y) / a.w);
    }
  } else {
    const Vec4 &a = prim_[idx[0]].clip, &b = prim_[idx[1]].clip, &c = prim_[idx[2]].clip;
    area = double(a.x) * (double(b.y) * c.w - double(c.y) * b.w) - double(b.x) * (double(a.y) * c.w - double(c.y) * a.w) +
           double(c.x) * (double(a.y) * b.w - double(b.y) * a.w);
  }
  // (Clip-space y is negated for the renderer: GL's counter-clockwise is clockwise here.)
  const bool front = (area <= 0) == (raster_.front_face == GL_CCW);
  if (raster_.cull && (raster_.cull_mode == GL_FRONT_AND_BACK || (raster_.cull_mode == GL_FRONT) == front)) return;
  const bool back_colors = lighting_.enabled && lighting_.two_side && !front;
  const bool flat = lighting_.shade_model == GL_FLAT;
  const Vertex& pv = prim_[idx[provoking]];
  const Vec4 flat_color = back_colors ? pv.back : pv.front;
  auto color = [&](uint32_t i) -> const Vec4& { return flat ? flat_color : back_colors ? prim_[i].back : prim_[i].front; };
  const bool shared = !flat && !back_colors;
  const GLenum mode = raster_.polygon_mode[front ? 0 : 1];
  if (mode == GL_FILL) {
    target(PrimitiveKind::Triangles, raster_.offset_fill);
    auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
      emit_vertex(a, color(a), shared), emit_vertex(b, color(b), shared), emit_vertex(c, color(c), shared);
    };
    for (int k = 1; k + 1 < n; ++k) tri(idx[0], idx[k], idx[k + 1]);  // a fan from the first vertex
  } else if (mode == GL_LINE) {
    target(PrimitiveKind::Lines, raster_.offset_line);
    for (int k = 0; k < n; ++k) {
      const uint32_t a = idx[k], b = idx[(k + 1) % n];
      emit_vertex(a, color(a), shared), emit_vertex(b, color(b), shared);
    }
  } else {
    target(PrimitiveKind::Points, raster_.offset_point);
    for (int k = 0; k < n; ++k) emit_vertex(idx[k], color(idx[k]), shared);
  }
}

void Context::line_segment(uint32_t a, uint32_t b, uint32_t provoking) {
  target(PrimitiveKind::Lines, false);
  const bool flat = lighting_.shade_model == GL_FLAT;
  emit_vertex(a, flat ? prim_[provoking].front : prim_[a].front, !flat);
  emit_vertex(b, flat ? prim_[provoking].front : prim_[b].front, !flat);
}

void Context::point_vertex(uint32_t a) {
  target(PrimitiveKind::Points, false);
  emit_vertex(a, prim_[a].front, true);
}

void Context::rect(float x1, float y1, float x2, float y2) {
  if (in_begin_error()) return;
  begin(GL_POLYGON);
  vertex({x1, y1, 0, 1}), vertex({x2, y1, 0, 1}), vertex({x2, y2, 0, 1}), vertex({x1, y2, 0, 1});
  end();
}

}  // namespace velocity::gl
