// The vertex stage: glBegin/glEnd, transform, GL lighting, primitive assembly for the
// ten modes (with GL's provoking vertices), face culling and polygon modes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>

#include "context.hpp"
#include "shading/gl_vertices.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace velocity::gl {

namespace {
[[gnu::always_inline]] inline Vec4 clamp_color(Vec4 c) { return {unit(c.x), unit(c.y), unit(c.z), unit(c.w)}; }

// A lit colour clamped as clamp_color does, into two places. In one register and
// stored whole where there is SSE: four scalar stores read back whole (the back colour
// copied from the front) stall store forwarding once a vertex, a quarter of its cost.
[[gnu::always_inline]] inline void store_clamped(Vec4 c, Vec4& a, Vec4& b) {
#if defined(__SSE2__)
  // max(c, 0) is 0 for NaN (the second operand wins), min(., 1): unit() lane by lane.
  const __m128 v = _mm_min_ps(_mm_max_ps(_mm_setr_ps(c.x, c.y, c.z, c.w), _mm_setzero_ps()), _mm_set1_ps(1.0f));
  _mm_storeu_ps(&a.x, v);
  _mm_storeu_ps(&b.x, v);
#else
  a = b = clamp_color(c);
#endif
}
// Vertices kept before independent primitives are assembled (a multiple of 3 and 4).
constexpr size_t kAssembleEvery = 3072;
}  // namespace

void Context::begin(GLenum mode) {
  if (mode > GL_POLYGON) return error(GL_INVALID_ENUM);
  if (in_begin_) return error(GL_INVALID_OPERATION);
  if (fbo_) framebuffer_incomplete();  // (its error; nothing is drawn into an incomplete FBO)
  in_begin_ = true;
  mode_ = mode;
  make_live(0);  // unit 0's state in the live fields until glEnd (multitexture.cpp)
  unit1_on_ = unit1_texturing();
  prim_.clear(), order_.clear(), emitted_.clear(), prim_secondary_.clear(), prim_tex1_.clear();
  run_position_.clear(), run_normal_.clear();
  stipple_counter_ = 0;
  ++pending_gen_;  // prim_ indices start again
  if (pending_gen_ == 0) pending_gen_ = 1;
  update_derived();
  prepare_lighting();
  if (unit1_on_) {  // (multitexture.cpp)
    parked_unit_.matrix_identity = parked_unit_.matrix.back() == Mat4{};
    if (tex_gen_needs_eye(parked_unit_.tex_gen)) need_eye_ = true;
  }
  vertex_extras_ = unit1_on_ || (color_sum_on_ && !separate_on_) || color_sum_.fog_coord_src == GL_FOG_COORD;
  // Runs light the primary colour alone, with no eye position and no GL 1.3/1.4 extras.
  if (vertex_extras_ || separate_on_ || need_eye_) run_vertices_ = false;
  // The quick path (context.hpp): what polygon() would do with such triangles is
  // facing, culling and the batch, nothing else (no selection, feedback or polygon mode).
  quick_ = run_vertices_ && mode == GL_TRIANGLES && !compiling() && !selecting() &&
           raster_.polygon_mode[0] == GL_FILL && raster_.polygon_mode[1] == GL_FILL;
  if (quick_) {
    quick_count_ = quick_lit_ = 0;
    grow_quick_arrays(kQuickRun);  // (once per context)
  }
}

void Context::end() {
  if (!in_begin_) return error(GL_INVALID_OPERATION);
  flush_vertices();
  if (!quick_) assemble(true);
  quick_ = false;  // (a triangle's one or two vertices left over are dropped)
  in_begin_ = false;
  prim_.clear(), order_.clear(), emitted_.clear(), prim_secondary_.clear(), prim_tex1_.clear();
  make_live(active_unit_);
}

// What lighting needs per light that stays the same through a glBegin/glEnd (lights
// and the light model cannot change inside it; materials can).
void Context::prepare_lighting() {
  lights_used_ = 0;
  color_sum_on_ = color_sum_applies();  // (color_sum.cpp)
  separate_on_ = lighting_.enabled && color_sum_.separate_specular;
  need_eye_ = raster_.fog || (lighting_.enabled && lighting_.local_viewer) || user_clip.count ||
              (texturing() && tex_gen_needs_eye());
  run_vertices_ = false;
  if (!lighting_.enabled) return;
  for (const Light& l : lighting_.lights) {
    if (!l.enabled) continue;
    shading::GlLight& u = light_use_[lights_used_++];
    u.colors = {l.ambient.xyz(), l.diffuse.xyz(), l.specular.xyz()};
    u.positional = l.position.w != 0;
    if (u.positional) u.position = l.position.xyz() / l.position.w;
    u.direction = normalize(l.position.xyz());
    u.half = normalize(u.direction + Vec3{0, 0, 1});  // with the viewer at +z
    u.spot = l.spot_cutoff != 180;
    u.spot_direction = normalize(l.spot_direction);
    u.cos_cutoff = std::cos(radians(l.spot_cutoff));
    u.spot_exponent = l.spot_exponent;
    u.constant = l.constant, u.linear = l.linear, u.quadratic = l.quadratic;
    if (u.positional) need_eye_ = true;
  }
  run_vertices_ = !need_eye_ && !lighting_.two_side && !lighting_.color_material && !texturing() && !feeding_back() &&
                  std::none_of(light_use_, light_use_ + lights_used_, [](const shading::GlLight& u) { return u.spot; });
}

void Context::light_vertices(const Vec4* position, const Vec3* normal, size_t n, Vec4* clip, Vec4* color) const {
  shading::GlVertexRun r;
  r.position = position, r.normal = normal, r.count = n;
  r.mvp = transform_.mvp, r.normal_matrix = transform_.normal_matrix;
  r.normalize = transform_.normalize || transform_.rescale_normal;
  r.lights = light_use_, r.light_count = lights_used_;
  r.model_ambient = lighting_.model_ambient.xyz();
  r.material = lighting_.materials[0];
  r.clip = clip, r.color = color;
  shading::gl_vertices(r);
}

void Context::flush_vertices() {
  if (quick_) return quick_flush();
  const size_t n = run_position_.size();
  if (n == 0) return;
  run_clip_.resize(n), run_color_.resize(n);
  light_vertices(run_position_.data(), run_normal_.data(), n, run_clip_.data(), run_color_.data());
  Vertex* out = prim_.data() + (prim_.size() - n);  // the last n vertices are the run's
  for (size_t i = 0; i < n; ++i) out[i].clip = run_clip_[i], out[i].front = out[i].back = run_color_[i];
  run_position_.clear(), run_normal_.clear();
}

// The quick path's run: lit after the one or two vertices left over from the last, its
// whole triangles assembled at once (glMaterial, which flushes the run, changes
// nothing assembly reads, so a triangle may be assembled before glEnd as after it).
void Context::quick_flush() {
  light_vertices(quick_position_.data(), quick_normal_.data(), quick_count_, quick_clip_.data() + quick_lit_,
                 quick_color_.data() + quick_lit_);
  const uint32_t lit = quick_lit_ + quick_count_, whole = lit / 3;
  quick_count_ = quick_lit_ = 0;  // (if the batch cannot grow, the run is dropped: GL_OUT_OF_MEMORY)
  quick_triangles<false>(quick_clip_.data(), quick_color_.data(), nullptr, whole);
  for (uint32_t k = 3 * whole; k < lit; ++k)
    quick_clip_[k - 3 * whole] = quick_clip_[k], quick_color_[k - 3 * whole] = quick_color_[k];
  quick_lit_ = lit - 3 * whole;
}

// The quick path's arrays hold at least n vertices (the lit ones two more: the one or two
// left over from the last run come first). They only grow, kept from draw to draw.
void Context::grow_quick_arrays(size_t n) {
  if (quick_position_.size() >= n) return;
  quick_position_.resize(n), quick_normal_.resize(n);
  quick_clip_.resize(n + 2), quick_color_.resize(n + 2);
}

void Context::quick_flush_checked() {
  try {
    quick_flush();
  } catch (const std::exception&) {
    error(GL_OUT_OF_MEMORY);
  }
}

// Which side of a triangle faces the viewer, from its clip positions: the signed area
// in window space (the viewport keeps its sign) has the sign of this homogeneous
// determinant when all w > 0, and it decides a triangle with a vertex behind the eye.
// (polygon() and the quick path: one expression, so that both round alike.)
[[gnu::always_inline]] static inline double facing_determinant(const Vec4& a, const Vec4& b, const Vec4& c) {
  return double(a.x) * (double(b.y) * c.w - double(c.y) * b.w) - double(b.x) * (double(a.y) * c.w - double(c.y) * a.w) +
         double(c.x) * (double(a.y) * b.w - double(b.y) * a.w);
}

template <bool kShared>
void Context::quick_triangles(const Vec4* clip, const Vec4* color, const uint32_t* order, size_t triangles) {
  const bool flat = lighting_.shade_model == GL_FLAT, shared = kShared && !flat;
  const bool ccw = raster_.front_face == GL_CCW, cull = raster_.cull;
  const GLenum cull_mode = raster_.cull_mode;
  const bool offset = raster_.offset_fill;
  for (size_t t = 0; t < triangles; ++t) {
    const uint32_t v[3] = {order ? order[3 * t] : uint32_t(3 * t), order ? order[3 * t + 1] : uint32_t(3 * t + 1),
                           order ? order[3 * t + 2] : uint32_t(3 * t + 2)};
    // (As polygon(): clip-space y is negated for the renderer, GL's counter-clockwise
    // is clockwise here.)
    const bool front = (facing_determinant(clip[v[0]], clip[v[1]], clip[v[2]]) <= 0) == ccw;
    if (cull && (cull_mode == GL_FRONT_AND_BACK || (cull_mode == GL_FRONT) == front)) continue;
    if (!pending_takes(PrimitiveKind::Triangles, offset, true)) target(PrimitiveKind::Triangles, offset, true);
    Pending& p = pending_;
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = v[k];
      if (shared) {
        const Emitted e = emitted_[i];
        if (e.gen == pending_gen_) {
          p.index.push_back(e.index);
          continue;
        }
        emitted_[i] = {pending_gen_, uint32_t(p.position.size())};
      }
      p.index.push_back(uint32_t(p.position.size()));
      p.position.push_back(clip[i]);
      p.color.push_back(color[flat ? v[2] : i]);  // (flat: the last vertex provokes)
    }
  }
}
template void Context::quick_triangles<true>(const Vec4*, const Vec4*, const uint32_t*, size_t);

// OpenGL's lighting equation (shading::light_gl) for one vertex and one side.
[[gnu::always_inline]] inline Vec4 Context::lit_unclamped(const Vec4& eye4, Vec3 n, bool back, Vec3* specular) const {
  Vec3 eye{};
  if (need_eye_) eye = eye4.w != 0 && eye4.w != 1 ? eye4.xyz() / eye4.w : eye4.xyz();
  return shading::light_gl(light_use_, lights_used_, lighting_.model_ambient.xyz(), lighting_.local_viewer,
                           lighting_.materials[back ? 1 : 0], back ? -n : n, eye, specular);
}

[[gnu::always_inline]] inline Vec4 Context::lit(const Vec4& eye4, Vec3 n, bool back, Vec3* specular) const {
  return clamp_color(lit_unclamped(eye4, n, back, specular));
}

Vec4 Context::lit_front(const Vec4& eye) {
  prepare_lighting();
  Vec3 n = transform_.normal_matrix.transform_vector(normal_);
  if (transform_.normalize || transform_.rescale_normal) n = normalize(n);
  return lit(eye, n, false);
}

// The texture coordinates and the colour sum's secondary colour of a vertex whose
// position, colours and fog coordinate are set, then the vertex to the primitive.
[[gnu::always_inline]] inline void Context::finish_vertex(Vertex& out, const Vec4& eye, const Vec4& v) {
  // (Feedback reports the coordinates untransformed while texturing is off, as Mesa does.)
  if (!texturing() && feeding_back()) out.tex = texcoord_;
  if (texturing()) {
    const Vec4 t = tex_gen_.any() ? generate_texcoord(v, eye) : texcoord_;  // (tex_gen.cpp)
    out.tex = transform_.texture_identity ? t : transform_.texture.back() * t;
    // A 1-D texture reads s alone: t = 0 keeps the level of detail s's own.
    if (texturing_1d() && !feeding_back()) out.tex.y = 0;
  }
  if (vertex_extras_) vertex_extras(out, eye, v);
  push_vertex(out);
}

// What GL 1.3 and 1.4 add to a vertex, when any is on (vertex_extras_, set by glBegin):
// the fog coordinate, the colour sum's secondary colour, unit 1's coordinates.
void Context::vertex_extras(Vertex& out, const Vec4& eye, const Vec4& v) {
  if (color_sum_.fog_coord_src == GL_FOG_COORD) out.fog = fog_coord_;  // (color_sum.cpp)
  if (order_.size() >= kMaxPrimitiveVertices) return;  // (push_vertex drops it)
  if (color_sum_on_ && !separate_on_) {
    // Without lighting's own, the current secondary colour (black with lighting on).
    const Vec4 c = lighting_.enabled ? Vec4{0, 0, 0, 0} : clamp_color(secondary_);
    prim_secondary_.push_back({c, c});
  }
  if (unit1_on_) prim_tex1_.push_back(unit1_texcoord(v, eye));  // (multitexture.cpp)
}

// A lit vertex with GL_SEPARATE_SPECULAR_COLOR: its primary colours without the
// specular part, which becomes its secondary colour (added after texturing).
void Context::vertex_separate_specular(Vertex& out, const Vec4& eye, Vec3 n, const Vec4& v) {
  Vec3 front, back;
  out.front = lit(eye, n, false, &front);
  out.back = lighting_.two_side ? lit(eye, n, true, &back) : out.front;
  if (!lighting_.two_side) back = front;
  out.fog = std::fabs(eye.z);
  if (order_.size() < kMaxPrimitiveVertices)
    prim_secondary_.push_back({clamp_color({front.x, front.y, front.z, 0}), clamp_color({back.x, back.y, back.z, 0})});
  finish_vertex(out, eye, v);
}

void Context::vertex(Vec4 v) {
  if (quick_vertex(v.x, v.y, v.z, v.w)) return;
  if (!in_begin_) return;  // outside glBegin/glEnd a vertex draws nothing (GL leaves it undefined)
  if (run_vertices_) {  // transformed and lit with its run (flush_vertices)
    Vertex* out = new_vertex();
    if (!out) return;
    out->edge = edge_flag_;
    // (Component by component: v came in registers; stored whole from the stack it
    // would be read back whole from two halves, a store-forwarding stall.)
    Vec4& p = run_position_.emplace_back();
    p.x = v.x, p.y = v.y, p.z = v.z, p.w = v.w;
    run_normal_.push_back(normal_);
    return vertex_added();
  }
  Vertex out;
  out.clip = transform_.mvp * v;
  out.edge = edge_flag_;
  Vec4 eye{};
  if (lighting_.enabled || need_eye_) {
    if (need_eye_) eye = transform_.modelview.back() * v;
    for (uint32_t k = 0; k < user_clip.count; ++k) {
      const Vec4& p = user_clip.active[k];
      out.clip_distance[k] = p.x * eye.x + p.y * eye.y + p.z * eye.z + p.w * eye.w;
    }
    if (lighting_.enabled) {
      Vec3 n = transform_.normal_matrix.transform_vector(normal_);
      if (transform_.normalize || transform_.rescale_normal) n = normalize(n);
      if (separate_on_) return vertex_separate_specular(out, eye, n, v);
      if (lighting_.two_side) out.front = lit(eye, n, false), out.back = lit(eye, n, true);
      else store_clamped(lit_unclamped(eye, n, false), out.front, out.back);
    }
    out.fog = std::fabs(eye.z);
  }
  if (!lighting_.enabled) out.front = out.back = clamp_color(color_);
  finish_vertex(out, eye, v);
}

void Context::push_vertex(const Vertex& v) {
  if (Vertex* out = new_vertex()) {
    *out = v;
    vertex_added();
  }
}

Vertex* Context::new_vertex() {
  if (order_.size() >= kMaxPrimitiveVertices) {
    error(GL_OUT_OF_MEMORY);  // (only the first error is kept until glGetError)
    return nullptr;
  }
  order_.push_back(uint32_t(prim_.size()));
  emitted_.emplace_back();
  // Copied from a constant (a few vector moves), not value-initialised (a rep stos,
  // slow to start, once a vertex).
  static constexpr Vertex kFresh{};
  return &prim_.emplace_back(kFresh);
}

void Context::vertex_added() {
  if (!caching_ && order_.size() >= kAssembleEvery &&
      (mode_ == GL_POINTS || mode_ == GL_LINES || mode_ == GL_TRIANGLES || mode_ == GL_QUADS)) {
    flush_vertices();
    assemble(false);
    prim_.clear(), order_.clear(), emitted_.clear(), prim_secondary_.clear(), prim_tex1_.clear();
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
      for (uint32_t i = 0; i + 1 < n; i += 2) {
        stipple_counter_ = 0;  // (each independent line starts the pattern again)
        line_segment(o[i], o[i + 1], o[i + 1]);
      }
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
    case GL_QUADS: {
      // Mesa (llvmpipe) splits a quad along v0 - v2 unless a vertex of the draw lies
      // outside the view volume: then its clipper splits every quad of it along v1 - v3.
      // The same here, for the quads of this glBegin/glEnd (or of this part of a long one).
      bool outside = false;
      for (uint32_t i = 0; i < n && !outside; ++i) {
        const Vec4& c = prim_[o[i]].clip;
        outside = !(std::fabs(c.x) <= c.w && std::fabs(c.y) <= c.w && std::fabs(c.z) <= c.w);
      }
      for (uint32_t i = 0; i + 3 < n; i += 4) {
        // The fan below from the first of q; the quad's fourth vertex provokes.
        const uint32_t q[4] = {o[i + (outside ? 1 : 0)], o[i + (outside ? 2 : 1)], o[i + (outside ? 3 : 2)],
                               o[i + (outside ? 0 : 3)]};
        polygon(q, 4, outside ? 2 : 3);
      }
      break;
    }
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
    area = facing_determinant(prim_[idx[0]].clip, prim_[idx[1]].clip, prim_[idx[2]].clip);
  }
  // (Clip-space y is negated for the renderer: GL's counter-clockwise is clockwise here.)
  const bool front = (area <= 0) == (raster_.front_face == GL_CCW);
  if (raster_.cull && (raster_.cull_mode == GL_FRONT_AND_BACK || (raster_.cull_mode == GL_FRONT) == front)) return;
  if (selecting()) return select_hit(idx, n, true);  // (select.cpp: hits, nothing drawn)
  const bool back_colors = lighting_.enabled && lighting_.two_side && !front;
  const bool flat = lighting_.shade_model == GL_FLAT;
  const Vertex& pv = prim_[idx[provoking]];
  const Vec4 flat_color = back_colors ? pv.back : pv.front;
  auto color = [&](uint32_t i) -> const Vec4& { return flat ? flat_color : back_colors ? prim_[i].back : prim_[i].front; };
  auto spec = [&](uint32_t i) { return secondary_of(flat ? idx[provoking] : i, back_colors); };
  const bool shared = !flat && !back_colors;
  const GLenum mode = raster_.polygon_mode[front ? 0 : 1];
  if (feeding_back() && mode == GL_FILL) return feedback_polygon(idx, n, provoking, back_colors);
  if (mode == GL_FILL) {
    target(PrimitiveKind::Triangles, raster_.offset_fill, true);
    auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
      emit_vertex(a, color(a), shared, spec(a)), emit_vertex(b, color(b), shared, spec(b));
      emit_vertex(c, color(c), shared, spec(c));
    };
    for (int k = 1; k + 1 < n; ++k) tri(idx[0], idx[k], idx[k + 1]);  // a fan from the first vertex
  } else {
    // Edge flags mark which boundary edges (and their first vertices) are drawn, for
    // independent triangles, quads and polygons; strips and fans draw every edge.
    const bool flags = mode_ == GL_TRIANGLES || mode_ == GL_QUADS || mode_ == GL_POLYGON;
    if (mode == GL_LINE) {
      target(PrimitiveKind::Lines, raster_.offset_line);
      stipple_counter_ = 0;
      for (int k = 0; k < n; ++k) {
        const uint32_t a = idx[k], b = idx[(k + 1) % n];
        if (flags && !prim_[a].edge) continue;
        if (feeding_back()) {
          feedback_line(a, b);
          continue;
        }
        if (raster_.line_stipple) stippled_line(a, b, color(a), color(b), raster_.offset_line);
        else emit_vertex(a, color(a), shared, spec(a)), emit_vertex(b, color(b), shared, spec(b));
      }
    } else {
      target(PrimitiveKind::Points, raster_.offset_point);
      for (int k = 0; k < n; ++k)
        if (feeding_back() && (!flags || prim_[idx[k]].edge)) feedback_point(idx[k]);
        else if (!flags || prim_[idx[k]].edge) emit_vertex(idx[k], color(idx[k]), shared, spec(idx[k]));
    }
  }
}

void Context::line_segment(uint32_t a, uint32_t b, uint32_t provoking) {
  if (selecting()) {
    const uint32_t ab[2] = {a, b};
    return select_hit(ab, 2, false);
  }
  if (feeding_back()) return feedback_line(a, b);
  const bool flat = lighting_.shade_model == GL_FLAT;
  if (raster_.line_stipple) {  // (line_stipple.cpp)
    const Vec4 ca = flat ? prim_[provoking].front : prim_[a].front, cb = flat ? prim_[provoking].front : prim_[b].front;
    return stippled_line(a, b, ca, cb, false);
  }
  target(PrimitiveKind::Lines, false);
  emit_vertex(a, flat ? prim_[provoking].front : prim_[a].front, !flat, secondary_of(flat ? provoking : a, false));
  emit_vertex(b, flat ? prim_[provoking].front : prim_[b].front, !flat, secondary_of(flat ? provoking : b, false));
}

void Context::point_vertex(uint32_t a) {
  if (selecting()) return select_hit(&a, 1, false);
  if (feeding_back()) return feedback_point(a);
  target(PrimitiveKind::Points, false);
  emit_vertex(a, prim_[a].front, true, secondary_of(a, false));
}

void Context::rect(float x1, float y1, float x2, float y2) {
  if (in_begin_error()) return;
  begin(GL_QUADS);  // as Mesa's glRect, so that it is split as a quad
  vertex({x1, y1, 0, 1}), vertex({x2, y1, 0, 1}), vertex({x2, y2, 0, 1}), vertex({x1, y2, 0, 1});
  end();
}

}  // namespace velocity::gl
