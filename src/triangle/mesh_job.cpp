// The triangle stage for mesh draws: per triangle, reject, cull and clip, then set up
// what survives (the varyings its material's kernel needs) and bin it.
#include <algorithm>
#include <cmath>

#include "core/srgb.hpp"

#include "triangle/clip.hpp"
#include "triangle/cull.hpp"
#include "triangle/setup.hpp"
#include "triangle/stage.hpp"

namespace velocity::triangle {

namespace {

using raster::RecordHeader;

// Orientation of a triangle in homogeneous clip space: the sign of det[x y w] is the
// sign of its window-space area even when vertices lie behind the eye, so clipped
// triangles are culled before any clipping work (counter-clockwise, positive, is front).
bool front_facing_homogeneous(const Vec4& a, const Vec4& b, const Vec4& c) {
  double det = double(a.x) * (double(b.y) * c.w - double(c.y) * b.w) -
               double(a.y) * (double(b.x) * c.w - double(c.x) * b.w) +
               double(a.w) * (double(b.x) * c.y - double(c.x) * b.y);
  return det > 0;
}

Vec3 clamp01(Vec3 c) { return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)}; }

class MeshTriangles {
 public:
  MeshTriangles(const geometry::DrawList& plan, const geometry::MeshDrawPlan& draw, StageContext& cx)
      : plan_(plan), d_(draw), mesh_(*draw.mesh), cx_(cx), stats_(cx.stats) {
    const geometry::VertexArrays& va = plan.vertices;
    projected_ = va.projected.data() + draw.vertex_base;
    codes_ = va.codes.data() + draw.vertex_base;
    if (draw.light) diffuse_ = va.diffuse.data() + draw.vertex_base;
    if (draw.vertex_specular_terms) specular_ = va.specular.data() + draw.vertex_base;
    if (draw.normal) normal_ = va.normal.data() + draw.vertex_base;
    if (draw.eye) eye_ = va.eye.data() + draw.vertex_base;
    if (plan.linear) srgb_ = &color::srgb_tables();
  }

  void run(uint32_t begin, uint32_t end) {
    if (d_.fill_only && cx_.direct) return run_culled(begin, end);
    for (uint32_t f = begin; f < end; ++f) triangle(f);
  }

  // The first pass drops most triangles N at a time (cull.hpp); the rest are
  // set up here, in their order.
  void run_culled(uint32_t begin, uint32_t end) {
    CullJob job;
    job.triangles = mesh_.triangles.data(), job.begin = begin, job.end = end;
    job.projected = projected_, job.codes = codes_;
    job.cull_back = d_.cull_all, job.drop_empty = true;
    const geometry::SetupParams& box = plan_.mesh_setup;
    job.x0 = box.x0, job.y0 = box.y0, job.x1 = box.x1, job.y1 = box.y1;
    size_t nd = 0, nc = 0;
    CullCounts counts;
    cull_triangles(job, cx_.direct, cx_.info, nd, cx_.clipped, nc, counts);
    stats_.triangles += end - begin;
    stats_.triangles_nonfinite += counts.nonfinite, cx_.nonfinite += counts.nonfinite;
    stats_.triangles_rejected += counts.rejected;
    stats_.triangles_culled += counts.culled;
    for (size_t i = 0, j = 0; i < nd || j < nc;) {
      if (j == nc || (i < nd && cx_.direct[i] < cx_.clipped[j])) accepted(cx_.direct[i], false, cx_.info[i]), ++i;
      else accepted(cx_.clipped[j++], true, 0);
    }
  }

 private:
  const geometry::SlotPlan& slot_of(uint32_t f) const {
    uint32_t local = 0;
    if (!d_.override_material) {
      if (!mesh_.face_materials.empty()) local = mesh_.face_materials[f] + 1;
      else if (!mesh_.materials.empty()) local = 1;
    }
    return plan_.slots[d_.slot_begin + local];
  }

  ScreenVertex screen(uint32_t v) const { return ScreenVertex::projected(projected_[v], codes_[v]); }

  // Eye-space values: from the vertex stage when it produced them, else computed here.
  Vec3 eye_normal(uint32_t v) const {
    if (normal_) return normal_[v];
    return normalize(d_.normal_matrix.transform_vector((*d_.normals)[v]));
  }
  Vec3 eye_position(uint32_t v) const {
    if (eye_) return eye_[v];
    return d_.model_view.transform_point(mesh_.positions[v]);
  }
  Vec4 clip_position(uint32_t v) const {
    const Vec3 p = mesh_.positions[v];
    return d_.mvp * Vec4{p.x, p.y, p.z, 1.0f};
  }

  // The base colour of a corner, in the frame's pipeline (geometry::pipeline_color).
  Vec3 base_color(uint32_t v, uint32_t f, const Material& mat) const {
    return geometry::pipeline_color(file_color(v, f, mat), mat.color_space, plan_.linear);
  }
  Vec3 file_color(uint32_t v, uint32_t f, const Material& mat) const {
    if (d_.override_material) return mat.color;
    if (!mesh_.face_colors.empty()) return mesh_.face_colors[f];
    if (!mesh_.colors.empty()) return mesh_.colors[v];
    return mat.color;
  }

  // A colour as the flat kernel writes it: linear light encoded to sRGB in a Linear
  // frame (the textured flat kernel multiplies it first: light, not encoded).
  uint32_t pack_flat(Vec3 c, bool encode) const {
    if (!srgb_ || !encode) return raster::pack_rgba(c.x, c.y, c.z);
    return uint32_t(color::encode8(*srgb_, c.x)) | uint32_t(color::encode8(*srgb_, c.y)) << 8 |
           uint32_t(color::encode8(*srgb_, c.z)) << 16 | 0xff000000u;
  }

  // The texture coordinates of a corner: the uv set and KHR_texture_transform the
  // material names (the Pbr kernel applies each texture's transform per pixel).
  Vec2 corner_uv(uint32_t v, int uv_set) const {
    const std::vector<Vec2>& uvs = uv_set == 1 && !mesh_.uvs1.empty() ? mesh_.uvs1 : mesh_.uvs;
    return uvs.empty() ? Vec2{} : uvs[v];
  }

  // Varyings of one corner, in the layout of the slot's kernel (raster/rasterize.hpp);
  // `flip` lights the back of a two-sided face.
  void corner(const geometry::SlotPlan& s, uint32_t v, uint32_t f, bool flip, float* out) const {
    const Material& mat = *s.material;
    const raster::KernelId k = raster::kernel_family(s.kernel);
    if (k == raster::KernelId::Pbr) return pbr_corner(s, v, flip, out);
    const Vec3 base = s.shading == Shading::Unlit && !mesh_.colors.empty()
                          ? geometry::pipeline_color(mesh_.colors[v], mat.color_space, plan_.linear)
                          : base_color(v, f, mat);
    int uv_at = -1;
    switch (k) {
      case raster::KernelId::Smooth:
      case raster::KernelId::SmoothTex: {
        Vec3 c = base;
        if (s.lit) {
          if (!flip && s.vertex_color) c = diffuse_[v];  // lit and clamped by the vertex stage
          else if (!flip && s.vertex_light_ok) c = clamp01(base * diffuse_[v] + (specular_ ? specular_[v] : Vec3{}));
          else c = clamp01(apply(light(plan_.lights, flip ? -eye_normal(v) : eye_normal(v), eye_position(v), s.specular), base));
          // (clamped as OpenGL clamps vertex colours before interpolating)
        }
        out[raster::varying::kColor] = c.x, out[raster::varying::kColor + 1] = c.y, out[raster::varying::kColor + 2] = c.z;
        if (k == raster::KernelId::SmoothTex) uv_at = raster::varying::kSmoothUv;
        break;
      }
      case raster::KernelId::FlatTex: uv_at = raster::varying::kFlatUv; break;
      case raster::KernelId::Flat: return;
      default: {  // the Phong family
        Vec3 n = eye_normal(v);
        if (flip) n = -n;
        const Vec3 e = eye_position(v);
        using namespace raster::varying;
        out[kColor] = base.x, out[kColor + 1] = base.y, out[kColor + 2] = base.z;
        out[kNormal] = n.x, out[kNormal + 1] = n.y, out[kNormal + 2] = n.z;
        out[kEye] = e.x, out[kEye + 1] = e.y, out[kEye + 2] = e.z;
        if (k != raster::KernelId::Phong) uv_at = kPhongUv;
        break;
      }
    }
    if (uv_at < 0) return;
    Vec2 uv;
    if (s.uv_from_env) {
      Vec3 n = eye_normal(v);
      if (flip) n = -n;
      uv = {0.5f + 0.5f * n.x, 0.5f - 0.5f * n.y};  // seed 000's sphere map (top row at Ny = 1), per vertex
    } else {
      uv = transform_uv(mat.texture_uv, corner_uv(v, mat.texture_uv.uv_set));
    }
    out[uv_at] = uv.x, out[uv_at + 1] = uv.y;
  }

  // The Pbr kernels' varyings (raster/contract.hpp): normal, position, uv, and the
  // tangent and vertex colour when the kernel reads them; a back face of a
  // double-sided material flips its whole tangent frame, as three.js does.
  void pbr_corner(const geometry::SlotPlan& s, uint32_t v, bool flip, float* out) const {
    using namespace raster::varying;
    Vec3 n = eye_normal(v);
    if (flip) n = -n;
    const Vec3 e = eye_position(v);
    const Vec2 uv = corner_uv(v, s.uv_set);
    out[kPbrNormal] = n.x, out[kPbrNormal + 1] = n.y, out[kPbrNormal + 2] = n.z;
    out[kPbrEye] = e.x, out[kPbrEye + 1] = e.y, out[kPbrEye + 2] = e.z;
    out[kPbrUv] = uv.x, out[kPbrUv + 1] = uv.y;
    int at = kPbrTangent;
    if (s.pbr_tangents) {
      const Vec4 t = (*d_.tangents)[v];
      Vec3 te = normalize(d_.model_view.transform_vector(t.xyz()));
      float w = t.w < 0 ? -1.0f : 1.0f;
      if (flip) te = -te, w = -w;
      out[at] = te.x, out[at + 1] = te.y, out[at + 2] = te.z, out[at + 3] = w;
      at += 4;
    }
    if (s.pbr_colors) {
      const Vec3 c = mesh_.colors.empty() ? Vec3{1, 1, 1}
                                          : geometry::pipeline_color(mesh_.colors[v], s.material->color_space, plan_.linear);
      out[at] = c.x, out[at + 1] = c.y, out[at + 2] = c.z;
      out[at + 3] = mesh_.alphas.empty() ? 1.0f : mesh_.alphas[v];
    }
  }

  // One colour per face: lit by the face normal at the centroid.
  uint32_t flat_color(uint32_t f, const geometry::SlotPlan& s, bool flip) const {
    const Material& mat = *s.material;
    const Triangle& t = mesh_.triangles[f];
    if (s.white) return 0xffffffffu;
    Vec3 base = d_.override_material || !mesh_.face_colors.empty() || mesh_.colors.empty()
                    ? base_color(t.v[0], f, mat)
                    : geometry::pipeline_color((mesh_.colors[t.v[0]] + mesh_.colors[t.v[1]] + mesh_.colors[t.v[2]]) / 3.0f,
                                               mat.color_space, plan_.linear);
    const bool encode = s.kernel == uint8_t(raster::KernelId::Flat);
    if (!s.lit) return pack_flat(base, encode);
    Vec3 n = normalize(d_.normal_matrix.transform_vector(face_normal(mesh_, t)));
    if (flip) n = -n;
    Vec3 centroid = (mesh_.positions[t.v[0]] + mesh_.positions[t.v[1]] + mesh_.positions[t.v[2]]) / 3.0f;
    Vec3 c = apply(light(plan_.lights, n, d_.model_view.transform_point(centroid), s.specular), base);
    return pack_flat(c, encode);
  }

  void triangle(uint32_t f) {
    const Triangle& tri = mesh_.triangles[f];
    const uint32_t i0 = tri.v[0], i1 = tri.v[1], i2 = tri.v[2];
    const uint32_t c0 = codes_[i0], c1 = codes_[i1], c2 = codes_[i2];
    const uint32_t any = c0 | c1 | c2;
    stats_.triangles++;
    if (any & geometry::kOutNonFinite) {
      stats_.triangles_nonfinite++;
      cx_.nonfinite++;
      return;
    }
    if (c0 & c1 & c2 & geometry::kViewPlanes) return void(stats_.triangles_rejected++);
    accepted(f, any & geometry::kMustClipPlanes, 0);
  }

  // A triangle with finite corners, not outside one view plane; `learnt` is what the
  // first pass found out (cull.hpp), or 0.
  void accepted(uint32_t f, bool must_clip, uint32_t learnt) {
    const Triangle& tri = mesh_.triangles[f];
    const uint32_t i0 = tri.v[0], i1 = tri.v[1], i2 = tri.v[2];
    const uint32_t any = codes_[i0] | codes_[i1] | codes_[i2];
    const geometry::SlotPlan& s = slot_of(f);
    // A point cloud's points are triangles with one corner three times (Mesh): no
    // facing to cull by.
    if (s.shading == Shading::Points && i0 == i1 && i1 == i2) return points(tri, s);
    bool front;
    if (learnt & (kKnownFront | kKnownBack)) {
      front = learnt & kKnownFront;
    } else if (!must_clip) {
      Facing fc = facing(screen(i0), screen(i1), screen(i2));
      if (fc == Facing::Degenerate) return void(stats_.triangles_culled++);
      front = fc == Facing::Front;
    } else {
      front = front_facing_homogeneous(clip_position(i0), clip_position(i1), clip_position(i2));
    }
    if (!front && s.cull) return void(stats_.triangles_culled++);
    if (s.shading == Shading::Wireframe) return edges(tri, s);
    if (s.shading == Shading::Points) return points(tri, s);

    const bool flip = !front && s.material->two_sided;
    RecordInfo info{s.kernel, s.draw_state, 0};
    if (s.flat) info.flat_color = flat_color(f, s, flip);
    const int nvar = s.num_varyings;
    ClipVertex poly[kMaxClippedVertices];
    const uint32_t corners[3] = {i0, i1, i2};
    for (int k = 0; k < 3; ++k) {
      poly[k].src = k;
      if (nvar) corner(s, corners[k], f, flip, poly[k].var);
    }
    if (!must_clip) {
      const ScreenVertex a = screen(i0), b = screen(i1), c = screen(i2);
      if (learnt & kKnownSmall) return emit_small(info, a, b, c, poly[0].var, poly[1].var, poly[2].var, nvar, learnt & 0xffff);
      emit(info, a, b, c, poly[0].var, poly[1].var, poly[2].var, nvar);
      return;
    }
    stats_.triangles_clipped++;
    for (int k = 0; k < 3; ++k) poly[k].pos = clip_position(corners[k]);
    const int n = clip_polygon(poly, 3, any, plan_.guard, nvar);
    if (n < 3) return void(stats_.triangles_culled++);
    ScreenVertex sv[kMaxClippedVertices];
    for (int k = 0; k < n; ++k)
      sv[k] = poly[k].src >= 0 && !(codes_[corners[poly[k].src]] & geometry::kMustClipPlanes) ? screen(corners[poly[k].src])
                                                                                   : to_screen(poly[k].pos);
    for (int k = 1; k + 1 < n; ++k)  // the clipped polygon is convex: a fan
      emit(info, sv[0], sv[k], sv[k + 1], poly[0].var, poly[k].var, poly[k + 1].var, nvar);
  }

  ScreenVertex to_screen(const Vec4& c) const { return ScreenVertex::window(plan_.viewport, c); }

  void emit(const RecordInfo& info, const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
            const float* va, const float* vb, const float* vc, int nvar) {
    uint32_t offset;
    RecordHeader* r = setup_triangle(cx_.bins, a, b, c, va, vb, vc, nvar, info, plan_.mesh_setup, offset);
    if (!r) return void(stats_.triangles_culled++);
    cx_.emit(*r, offset, (a.z + b.z + c.z) / 3.0f);
    stats_.triangles_rasterized++;
  }

  void emit_small(const RecordInfo& info, const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                  const float* va, const float* vb, const float* vc, int nvar, uint32_t mask) {
    uint32_t offset;
    RecordHeader* r = setup_small_triangle(cx_.bins, a, b, c, va, vb, vc, nvar, mask, info, plan_.mesh_setup, offset);
    if (!r) return void(stats_.triangles_culled++);
    cx_.emit(*r, offset, (a.z + b.z + c.z) / 3.0f);
    stats_.triangles_rasterized++;
  }

  void edges(const Triangle& tri, const geometry::SlotPlan& s) {
    const RecordInfo info{uint8_t(raster::KernelId::Flat), s.draw_state, s.line_color};
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = tri.v[k], b = tri.v[(k + 1) % 3];
      const uint32_t ca = codes_[a], cb = codes_[b];
      if (ca & cb & geometry::kViewPlanes) continue;
      ScreenVertex sa, sb;
      if (!((ca | cb) & geometry::kMustClipPlanes)) {
        sa = screen(a), sb = screen(b);
      } else {
        Vec4 pa = clip_position(a), pb = clip_position(b);
        if (!clip_line(pa, pb, ca | cb, plan_.guard)) continue;
        sa = to_screen(pa), sb = to_screen(pb);
      }
      uint32_t offset;
      RecordHeader* r = setup_line(cx_.bins, sa, sb, nullptr, nullptr, 0, 1, info, plan_.mesh_setup, offset);
      if (!r) continue;
      cx_.emit(*r, offset, (sa.z + sb.z) / 2);
      stats_.lines++;
    }
  }

  // RenderOptions::point_size in samples, 1..64 times the super-sampling factor.
  int point_size() const {
    const float size = std::isfinite(plan_.options.point_size) ? std::clamp(plan_.options.point_size, 1.0f, 64.0f) : 1.0f;
    return std::max(1, int(size * float(std::max(1, plan_.options.ssaa)) + 0.5f));
  }

  void points(const Triangle& tri, const geometry::SlotPlan& s) {
    // Each vertex once per job (a fixed range of faces, whatever the thread count),
    // however many of its faces share it.
    const RecordInfo info{uint8_t(raster::KernelId::Flat), s.draw_state, s.line_color};
    std::vector<uint8_t>& drawn = *cx_.marks;
    if (!marks_ready_) std::fill_n(drawn.begin(), mesh_.positions.size(), 0), marks_ready_ = true;
    for (uint32_t v : tri.v) {
      if (drawn[v] || (codes_[v] & (geometry::kViewPlanes | geometry::kOutNonFinite))) continue;
      drawn[v] = 1;
      uint32_t offset;
      const ScreenVertex p = screen(v);
      RecordHeader* r = setup_point(cx_.bins, p, nullptr, 0, point_size(), info, plan_.mesh_setup, offset);
      if (!r) continue;
      cx_.emit(*r, offset, p.z);
      stats_.points++;
    }
  }

  const geometry::DrawList& plan_;
  const geometry::MeshDrawPlan& d_;
  const Mesh& mesh_;
  StageContext& cx_;
  FrameStats& stats_;
  const geometry::ProjectedVertex* projected_ = nullptr;
  const uint32_t* codes_ = nullptr;
  const Vec3 *diffuse_ = nullptr, *specular_ = nullptr, *normal_ = nullptr, *eye_ = nullptr;
  const color::SrgbTables* srgb_ = nullptr;  // a Linear frame
  bool marks_ready_ = false;  // cx_.marks cleared for this job
};

}  // namespace

void run_mesh_job(const geometry::DrawList& plan, const geometry::MeshDrawPlan& draw, uint32_t begin, uint32_t end,
                  StageContext& cx) {
  MeshTriangles(plan, draw, cx).run(begin, end);
}

}  // namespace velocity::triangle
