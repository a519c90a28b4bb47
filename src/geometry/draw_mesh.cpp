#include "geometry/draw_mesh.hpp"

#include <algorithm>

namespace velocity::geometry {

namespace {

using raster::FramePrimitives;
using raster::Kernel;
using raster::ScreenVertex;

// Perspective divide and viewport transform, in OpenGL's order of operations (so the
// snapped positions agree with Mesa's): window x = (ndc_x + 1) * W / 2, and y flipped so
// that row 0 is the top.
ScreenVertex to_screen(const Vec4& c, int width, int height) {
  float inv_w = 1.0f / c.w;
  float x = (c.x * inv_w + 1.0f) * (float(width) * 0.5f);
  float y = float(height) - (c.y * inv_w + 1.0f) * (float(height) * 0.5f);
  return ScreenVertex::make(x, y, (c.z * inv_w) * 0.5f + 0.5f, inv_w);
}

// Orientation of a triangle in homogeneous clip space: the sign of det[x y w] is the
// sign of its window-space area even when vertices lie behind the eye, so clipped
// triangles are culled before any clipping work (counter-clockwise, positive, is front).
bool front_facing_homogeneous(const Vec4& a, const Vec4& b, const Vec4& c) {
  double det = double(a.x) * (double(b.y) * c.w - double(c.y) * b.w) -
               double(a.y) * (double(b.x) * c.w - double(c.x) * b.w) +
               double(a.w) * (double(b.x) * c.y - double(c.x) * b.y);
  return det > 0;
}

// How one face is drawn: the kernel, its varyings, and where its uvs come from.
struct FacePlan {
  Kernel kernel = Kernel::Flat;
  Filter filter = Filter::Nearest;
  int num_varyings = 0;
  bool uv_from_env = false;  // flat/Gouraud environment mapping: per-vertex normal -> uv
  bool white = false;        // "replace": the texture as it is, unlit
};

FacePlan plan_face(Shading shading, const Texture* tex, const Texture* env, bool replace, Filter filter) {
  FacePlan p;
  p.filter = filter;
  if (tex && replace) return p.kernel = Kernel::FlatTex, p.num_varyings = 2, p.white = true, p;
  switch (shading) {
    case Shading::Flat:
      if (tex || env) p.kernel = Kernel::FlatTex, p.num_varyings = 2, p.uv_from_env = !tex;
      return p;
    case Shading::Gouraud:
    case Shading::Unlit:
      if (tex || env) return p.kernel = Kernel::SmoothTex, p.num_varyings = 5, p.uv_from_env = !tex, p;
      return p.kernel = Kernel::Smooth, p.num_varyings = 3, p;
    case Shading::Phong:
      p.kernel = tex && env ? Kernel::PhongTexEnv : tex ? Kernel::PhongTex : env ? Kernel::PhongEnv : Kernel::Phong;
      p.num_varyings = (tex || env) ? raster::kPhongTexVaryings : raster::kPhongVaryings;
      return p;
    default: return p;
  }
}

Vec3 clamp01(Vec3 c) {
  return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

// The per-draw state of the geometry stage: the matrices, and lazily computed eye-space
// positions, normals and lighting per vertex (a vertex shared by six triangles is lit
// once, not six times).
class MeshDraw {
 public:
  MeshDraw(const FrameParams& p, const Mesh& m, const Mat4& world, const Material* override_material,
           VertexScratch& s, FramePrimitives& out, FrameStats& stats)
      : p_(p), mesh_(m), override_(override_material), s_(s), out_(out), stats_(stats) {
    model_view_ = p.view * world;
    mvp_ = p.projection * model_view_;
    normal_ = normal_matrix(model_view_);
  }

  void run() {
    normals_ = mesh_.normals.empty() ? &averaged_normals() : &mesh_.normals;
    transform_vertices();
    size_t nt = mesh_.triangles.size();
    for (size_t f = 0; f < nt; ++f) draw_face(uint32_t(f));
  }

 private:
  void transform_vertices() {
    size_t nv = mesh_.positions.size();
    if (s_.clip.size() < nv) {
      s_.clip.resize(nv), s_.codes.resize(nv), s_.screen.resize(nv);
      s_.eye_pos.resize(nv), s_.eye_normal.resize(nv), s_.light.resize(nv);
      s_.eye_stamp.resize(nv, 0), s_.light_stamp.resize(nv, 0);
    }
    generation_ = ++s_.generation;
    for (size_t v = 0; v < nv; ++v) {
      Vec3 q = mesh_.positions[v];
      Vec4 c = mvp_ * Vec4{q.x, q.y, q.z, 1.0f};
      uint32_t code = outcode(c, p_.guard);
      s_.clip[v] = c;
      s_.codes[v] = code;
      if (!(code & (kMustClipPlanes | kOutNonFinite))) s_.screen[v] = to_screen(c, p_.width, p_.height);
    }
  }

  // A mesh without normals is lit with normals averaged over the faces sharing each
  // vertex (area-weighted), computed into scratch memory for this draw. Loaders compute
  // normals once (compute_normals, with smoothing groups); this is for meshes built by
  // hand.
  const std::vector<Vec3>& averaged_normals() {
    std::vector<Vec3>& n = s_.averaged_normals;
    n.assign(mesh_.positions.size(), Vec3{});
    for (const Triangle& t : mesh_.triangles) {
      Vec3 a = mesh_.positions[t.v[0]], b = mesh_.positions[t.v[1]], c = mesh_.positions[t.v[2]];
      Vec3 fn = cross(b - a, c - a);
      for (uint32_t v : t.v) n[v] += fn;
    }
    return n;  // normalised when transformed to eye space
  }

  // The material of face f and the draw-state slot that goes with it.
  const Material& material_of(uint32_t f, uint32_t& slot) const {
    if (override_) return slot = 0, *override_;
    if (!mesh_.face_materials.empty()) {
      slot = mesh_.face_materials[f] + 1;
      return mesh_.materials[mesh_.face_materials[f]];
    }
    if (!mesh_.materials.empty()) return slot = 1, mesh_.materials[0];
    return slot = 0, default_material_;
  }

  void ensure_eye(uint32_t v) {
    if (s_.eye_stamp[v] == generation_) return;
    s_.eye_stamp[v] = generation_;
    s_.eye_pos[v] = model_view_.transform_point(mesh_.positions[v]);
    s_.eye_normal[v] = normalize(normal_.transform_vector((*normals_)[v]));
  }

  Vec3 eye_normal(uint32_t v) {
    ensure_eye(v);
    return s_.eye_normal[v];
  }

  const LightTerms& vertex_light(uint32_t v, uint32_t slot, const Material& mat) {
    uint64_t key = (generation_ << 20) | slot;
    if (s_.light_stamp[v] != key) {
      s_.light_stamp[v] = key;
      s_.light[v] = light(p_.lights, eye_normal(v), s_.eye_pos[v], Specular(mat.specular, mat.shininess));
    }
    return s_.light[v];
  }

  Vec3 base_color(uint32_t v, uint32_t f, const Material& mat) const {
    if (override_) return mat.color;
    if (!mesh_.face_colors.empty()) return mesh_.face_colors[f];
    if (!mesh_.colors.empty()) return mesh_.colors[v];
    return mat.color;
  }

  uint32_t draw_index(uint32_t slot, const Material& mat, const Texture* tex, const Texture* env) {
    if (slot != current_slot_) {
      current_slot_ = slot;
      current_draw_ = uint32_t(out_.draws.size());
      out_.draws.push_back({Specular(mat.specular, mat.shininess), tex, env, mat.env_mix, mat.wrap == Wrap::Repeat});
    }
    return current_draw_;
  }

  const Texture* texture_of(const Material& mat) const {
    return p_.options.texture ? p_.options.texture.get() : mat.texture.get();
  }
  const Texture* env_of(const Material& mat) const {
    return p_.options.env_map ? p_.options.env_map.get() : mat.env_map.get();
  }

  // Varyings of one corner (layout in raster::Kernel); `flip` lights the back of the face.
  void corner_varyings(const FacePlan& plan, Shading shading, uint32_t v, uint32_t f, uint32_t slot,
                       const Material& mat, bool flip, float* out) {
    // Vertex-colour shading shows the mesh's own colours whatever the material.
    Vec3 base = shading == Shading::Unlit && !mesh_.colors.empty() ? mesh_.colors[v] : base_color(v, f, mat);
    int uv_at = -1;
    switch (plan.kernel) {
      case Kernel::Smooth:
      case Kernel::SmoothTex: {
        Vec3 c = base;
        if (shading != Shading::Unlit) {
          if (flip) {
            ensure_eye(v);
            c = apply(light(p_.lights, -eye_normal(v), s_.eye_pos[v], Specular(mat.specular, mat.shininess)), base);
          } else {
            c = apply(vertex_light(v, slot, mat), base);
          }
          c = clamp01(c);  // as OpenGL clamps vertex colours before interpolating
        }
        out[0] = c.x, out[1] = c.y, out[2] = c.z;
        uv_at = plan.kernel == Kernel::SmoothTex ? 3 : -1;
        break;
      }
      case Kernel::FlatTex: uv_at = 0; break;
      case Kernel::Phong:
      case Kernel::PhongTex:
      case Kernel::PhongEnv:
      case Kernel::PhongTexEnv: {
        Vec3 n = eye_normal(v);
        if (flip) n = -n;
        const Vec3& e = s_.eye_pos[v];
        out[0] = base.x, out[1] = base.y, out[2] = base.z;
        out[3] = n.x, out[4] = n.y, out[5] = n.z;
        out[6] = e.x, out[7] = e.y, out[8] = e.z;
        uv_at = plan.kernel == Kernel::Phong ? -1 : 9;
        break;
      }
      default: break;
    }
    if (uv_at < 0) return;
    Vec2 uv;
    if (plan.uv_from_env) {
      Vec3 n = eye_normal(v);
      if (flip) n = -n;
      uv = {0.5f + 0.5f * n.x, 0.5f + 0.5f * n.y};  // seed 000's sphere map, per vertex
    } else if (!mesh_.uvs.empty()) {
      uv = mesh_.uvs[v];
    }
    out[uv_at] = uv.x, out[uv_at + 1] = uv.y;
  }

  uint32_t flat_color(uint32_t f, const Material& mat, bool flip) {
    const Triangle& t = mesh_.triangles[f];
    Vec3 base = override_ || !mesh_.face_colors.empty() || mesh_.colors.empty()
                    ? base_color(t.v[0], f, mat)
                    : (mesh_.colors[t.v[0]] + mesh_.colors[t.v[1]] + mesh_.colors[t.v[2]]) / 3.0f;
    Vec3 n = normalize(normal_.transform_vector(face_normal(mesh_, t)));
    if (flip) n = -n;
    Vec3 centroid = (mesh_.positions[t.v[0]] + mesh_.positions[t.v[1]] + mesh_.positions[t.v[2]]) / 3.0f;
    Vec3 c = apply(light(p_.lights, n, model_view_.transform_point(centroid), Specular(mat.specular, mat.shininess)), base);
    return raster::pack_rgba(c.x, c.y, c.z);
  }

  void draw_face(uint32_t f) {
    const Triangle& tri = mesh_.triangles[f];
    const uint32_t i0 = tri.v[0], i1 = tri.v[1], i2 = tri.v[2];
    const uint32_t c0 = s_.codes[i0], c1 = s_.codes[i1], c2 = s_.codes[i2];
    const uint32_t any = c0 | c1 | c2;
    stats_.triangles++;
    if (any & kOutNonFinite) return void(stats_.triangles_nonfinite++);
    if (c0 & c1 & c2 & kViewPlanes) return void(stats_.triangles_rejected++);

    uint32_t slot;
    const Material& mat = material_of(f, slot);
    const Shading shading = p_.options.shading.value_or(mat.shading);
    const bool cull = p_.options.cull_back_faces && !mat.two_sided;
    const bool must_clip = any & kMustClipPlanes;

    bool front;
    if (!must_clip) {
      raster::Facing fc = raster::facing(s_.screen[i0], s_.screen[i1], s_.screen[i2]);
      if (fc == raster::Facing::Degenerate) return void(stats_.triangles_culled++);
      front = fc == raster::Facing::Front;
    } else {
      front = front_facing_homogeneous(s_.clip[i0], s_.clip[i1], s_.clip[i2]);
    }
    if (!front && cull) return void(stats_.triangles_culled++);

    const uint32_t color = raster::pack_rgba(mat.color.x, mat.color.y, mat.color.z);
    if (shading == Shading::Wireframe) return draw_edges(tri, color);
    if (shading == Shading::Points) return draw_points(tri, color);

    const bool flip = !front && mat.two_sided;
    const Texture* tex = texture_of(mat);
    const Texture* env = env_of(mat);
    const FacePlan plan = plan_face(shading, tex, env, mat.texture_mode == TextureMode::Replace,
                                    p_.options.filter.value_or(mat.filter));
    const int nvar = plan.num_varyings;
    raster::TriangleSetup setup;
    setup.kernel = raster::kernel_id(plan.kernel, plan.filter);
    setup.draw = draw_index(slot, mat, tex, env);
    if (plan.white)
      setup.flat_color = 0xffffffffu;
    else if (plan.kernel == Kernel::Flat || plan.kernel == Kernel::FlatTex)
      setup.flat_color = flat_color(f, mat, flip);

    ClipVertex poly[kMaxClippedVertices];
    const uint32_t corners[3] = {i0, i1, i2};
    for (int k = 0; k < 3; ++k) {
      poly[k].pos = s_.clip[corners[k]];
      if (nvar) corner_varyings(plan, shading, corners[k], f, slot, mat, flip, poly[k].var);
    }
    if (!must_clip) {
      emit_triangle(setup, s_.screen[i0], s_.screen[i1], s_.screen[i2], poly[0].var, poly[1].var, poly[2].var, nvar);
      return;
    }
    stats_.triangles_clipped++;
    int n = clip_polygon(poly, 3, any, p_.guard, nvar);
    if (n < 3) return void(stats_.triangles_culled++);
    ScreenVertex sv[kMaxClippedVertices];
    for (int k = 0; k < n; ++k) sv[k] = to_screen(poly[k].pos, p_.width, p_.height);
    for (int k = 1; k + 1 < n; ++k)  // the clipped polygon is convex: a fan
      emit_triangle(setup, sv[0], sv[k], sv[k + 1], poly[0].var, poly[k].var, poly[k + 1].var, nvar);
  }

  void emit_triangle(const raster::TriangleSetup& proto, const ScreenVertex& a, const ScreenVertex& b,
                     const ScreenVertex& c, const float* va, const float* vb, const float* vc, int nvar) {
    if (out_.triangles.size() >= raster::kMaxPrimitivesPerFrame) return void(stats_.triangles_culled++);
    raster::TriangleSetup& t = out_.triangles.emplace_back(proto);
    if (!raster::setup_triangle(a, b, c, va, vb, vc, nvar, p_.width, p_.height, p_.options.affine, t)) {
      out_.triangles.pop_back();
      return void(stats_.triangles_culled++);
    }
    out_.order.push_back(raster::make_command(raster::CommandKind::Triangle, uint32_t(out_.triangles.size() - 1)));
    stats_.triangles_rasterized++;
  }

  void draw_edges(const Triangle& tri, uint32_t color) {
    for (int k = 0; k < 3; ++k) {
      uint32_t a = tri.v[k], b = tri.v[(k + 1) % 3];
      uint32_t ca = s_.codes[a], cb = s_.codes[b];
      if (ca & cb & kViewPlanes) continue;
      ScreenVertex sa, sb;
      if (!((ca | cb) & kMustClipPlanes)) {
        sa = s_.screen[a], sb = s_.screen[b];
      } else {
        Vec4 pa = s_.clip[a], pb = s_.clip[b];
        if (!clip_line(pa, pb, ca | cb, p_.guard)) continue;
        sa = to_screen(pa, p_.width, p_.height), sb = to_screen(pb, p_.width, p_.height);
      }
      if (out_.lines.size() >= raster::kMaxPrimitivesPerFrame) return;
      raster::LineSetup& l = out_.lines.emplace_back();
      if (!raster::setup_line(sa, sb, color, p_.width, p_.height, l)) {
        out_.lines.pop_back();
        continue;
      }
      out_.order.push_back(raster::make_command(raster::CommandKind::Line, uint32_t(out_.lines.size() - 1)));
      stats_.lines++;
    }
  }

  void draw_points(const Triangle& tri, uint32_t color) {
    // Each vertex once per draw, however many faces share it.
    if (point_drawn_.size() < mesh_.positions.size()) point_drawn_.assign(mesh_.positions.size(), false);
    for (uint32_t v : tri.v) {
      if (point_drawn_[v] || (s_.codes[v] & (kViewPlanes | kOutNonFinite))) continue;
      point_drawn_[v] = true;
      if (out_.points.size() >= raster::kMaxPrimitivesPerFrame) return;
      raster::PointSetup& pt = out_.points.emplace_back();
      if (!raster::setup_point(s_.screen[v], color, p_.width, p_.height, pt)) {
        out_.points.pop_back();
        continue;
      }
      out_.order.push_back(raster::make_command(raster::CommandKind::Point, uint32_t(out_.points.size() - 1)));
      stats_.points++;
    }
  }

  const FrameParams& p_;
  const Mesh& mesh_;
  const Material* override_;
  VertexScratch& s_;
  FramePrimitives& out_;
  FrameStats& stats_;
  Mat4 model_view_, mvp_, normal_;
  uint64_t generation_ = 0;
  const std::vector<Vec3>* normals_ = nullptr;
  uint32_t current_slot_ = UINT32_MAX, current_draw_ = 0;
  Material default_material_;
  std::vector<bool> point_drawn_;
};

}  // namespace

void draw_mesh(const FrameParams& params, const Mesh& mesh, const Mat4& world, const Material* override_material,
               VertexScratch& scratch, FramePrimitives& out, FrameStats& stats) {
  MeshDraw(params, mesh, world, override_material, scratch, out, stats).run();
}

}  // namespace velocity::geometry
