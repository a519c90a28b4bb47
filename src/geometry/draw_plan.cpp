// Planning a draw: everything decided once per draw, before any vertex is touched.
#include "geometry/draw_plan.hpp"

#include <algorithm>
#include <cmath>

#include "core/srgb.hpp"

#include "velocity/error.hpp"

namespace velocity::geometry {

namespace {

using raster::KernelId;

// The kernel and varyings for a material's shading mode and textures.
void choose_kernel(SlotPlan& s, const Texture* tex, const Texture* env, bool replace, Filter filter) {
  auto with = [&](KernelId k) { return raster::kernel_with_filter(k, filter); };
  s.flat = false;
  if (s.shading == Shading::Pbr) {
    s.kernel = raster::pbr_kernel(s.pbr_tangents, s.pbr_colors, filter);
    s.num_varyings = raster::pbr_varyings(s.pbr_tangents, s.pbr_colors);
    return;
  }
  if (tex && replace) {
    s.kernel = with(KernelId::FlatTex), s.num_varyings = raster::kFlatTexVaryings, s.white = true, s.flat = true;
    return;
  }
  switch (s.shading) {
    case Shading::Flat:
      s.flat = true;
      if (tex || env) s.kernel = with(KernelId::FlatTex), s.num_varyings = raster::kFlatTexVaryings, s.uv_from_env = !tex;
      else s.kernel = uint8_t(KernelId::Flat), s.num_varyings = 0;
      return;
    case Shading::Gouraud:
    case Shading::Unlit:
      if (tex || env) s.kernel = with(KernelId::SmoothTex), s.num_varyings = raster::kSmoothTexVaryings, s.uv_from_env = !tex;
      else s.kernel = uint8_t(KernelId::Smooth), s.num_varyings = raster::kSmoothVaryings;
      return;
    case Shading::Phong:
      s.kernel = tex && env ? with(KernelId::PhongTexEnv)
                 : tex      ? with(KernelId::PhongTex)
                 : env      ? with(KernelId::PhongEnv)
                            : uint8_t(KernelId::Phong);
      s.num_varyings = (tex || env) ? raster::kPhongTexVaryings : raster::kPhongVaryings;
      return;
    default:  // wireframe, points: the flat kernel with the material's colour
      s.kernel = uint8_t(KernelId::Flat), s.num_varyings = 0;
      return;
  }
}

// velocity::transform_uv (material.hpp) as an affine map: u' = a u + b v + c, v' = d u + e v + f.
raster::UvAffine uv_affine(const UvTransform& t) {
  const float c = std::cos(t.rotation), s = std::sin(t.rotation);
  return {c * t.scale.x, s * t.scale.y, t.offset.x, -s * t.scale.x, c * t.scale.y, t.offset.y};
}

// glTF's metallic-roughness parameters as the Pbr kernels read them (colours are put
// into the pipeline's space by finish_color_plan).
void plan_pbr(const Material& mat, Filter filter, raster::PbrState& p) {
  const PbrParams& m = mat.pbr;
  p.metallic = m.metallic, p.roughness = m.roughness;
  p.normal_scale = m.normal_scale, p.occlusion_strength = m.occlusion_strength;
  p.alpha_mode = mat.alpha_mode, p.alpha_cutoff = mat.alpha_cutoff;
  p.unlit = m.unlit;
  auto view = [&](const TextureRef& t, raster::SamplerView& v, raster::UvAffine& a) {
    if (!t) return;
    v = raster::SamplerView(*t.texture, filter, mat.wrap);
    a = uv_affine(t.uv);
  };
  view(m.metallic_roughness, p.metallic_roughness, p.mr_uv);
  view(m.normal, p.normal, p.normal_uv);
  view(m.occlusion, p.occlusion, p.occlusion_uv);
  view(m.emissive_map, p.emissive_map, p.emissive_uv);
  p.base_uv = uv_affine(mat.texture_uv);
  if (!m.metallic_roughness) {
    const float rough = m.roughness >= 0.045f ? std::min(m.roughness, 1.0f) : 0.045f;  // as the kernel clamps it
    constexpr int n = shading::kGgxAlbedoSize;
    for (int j = 0; j < n; ++j) p.lost_energy[j] = 1.0f / shading::ggx_albedo(rough, (float(j) + 0.5f) / n) - 1.0f;
  }
}

// The uv set a Pbr material's textures read: the base colour texture's, else the
// first other texture's (one set per material).
int pbr_uv_set(const Material& mat) {
  if (mat.texture) return mat.texture_uv.uv_set;
  for (const TextureRef* t : {&mat.pbr.metallic_roughness, &mat.pbr.normal, &mat.pbr.occlusion, &mat.pbr.emissive_map})
    if (*t) return t->uv.uv_set;
  return 0;
}

bool same_specular(const shading::Specular& a, const shading::Specular& b) { return a.ks == b.ks && a.exponent == b.exponent; }

}  // namespace

void plan_mesh_draw(DrawList& plan, std::vector<raster::DrawState>& states, MeshDrawPlan& d, const Material* override,
                    const Material& default_material) {
  const Mesh& mesh = *d.mesh;
  const RenderOptions& o = plan.options;
  // Slot 0: the override (or the default material); slots 1..n: the mesh's materials.
  d.slot_begin = uint32_t(plan.slots.size());
  d.slot_count = override ? 1 : uint32_t(1 + mesh.materials.size());
  bool first_lit = true;
  // The one slot every face uses, when there is one, and whether faces share its colour.
  const uint32_t only_slot = override ? 0 : mesh.face_materials.empty() ? (mesh.materials.empty() ? 0 : 1) : UINT32_MAX;
  const bool uniform = only_slot != UINT32_MAX && mesh.face_colors.empty() && mesh.colors.empty();
  for (uint32_t i = 0; i < d.slot_count; ++i) {
    const Material& mat = override ? *override : i == 0 ? default_material : mesh.materials[i - 1];
    SlotPlan s;
    s.material = &mat;
    s.shading = o.shading.value_or(mat.shading);
    s.cull = o.cull_back_faces && !mat.two_sided;
    s.lit = s.shading != Shading::Unlit;
    s.specular = shading::Specular(mat.specular, mat.shininess);
    s.line_color = raster::pack_rgba(mat.color.x, mat.color.y, mat.color.z);
    const Texture* tex = o.texture ? o.texture.get() : mat.texture.get();
    const Texture* env = o.env_map ? o.env_map.get() : mat.env_map.get();
    const Filter filter = o.filter.value_or(mat.filter);
    if (s.shading == Shading::Pbr) {
      s.pbr_tangents = bool(mat.pbr.normal);
      s.pbr_colors = !mesh.colors.empty() || !mesh.alphas.empty();  // vertex alpha alone: white vertices
      s.blend = mat.alpha_mode == AlphaMode::Blend;
      s.uv_set = pbr_uv_set(mat);
      s.cull = o.cull_back_faces && !mat.two_sided;
      d.needs_tangents = d.needs_tangents || s.pbr_tangents;
      d.blend = d.blend || s.blend;
    }
    choose_kernel(s, tex, env, mat.texture_mode == TextureMode::Replace && s.shading != Shading::Pbr, filter);

    raster::DrawState st;
    st.object_id = d.object_id;
    st.specular = s.specular;
    if (tex) st.texture = raster::SamplerView(*tex, filter, mat.wrap);
    // Environment maps are addressed by the normal: clamped, never wrapped.
    if (env) st.env_map = raster::SamplerView(*env, filter, Wrap::Clamp);
    st.env_mix = mat.env_mix;
    if (s.shading == Shading::Pbr) plan_pbr(mat, filter, st.pbr);
    s.draw_state = uint32_t(states.size());
    states.push_back(st);

    // What the vertex stage computes for this draw.
    const bool smooth = s.kernel == uint8_t(KernelId::Smooth) ||
                        (s.kernel >= uint8_t(KernelId::SmoothTex) && s.kernel < uint8_t(KernelId::Phong));
    const bool phong = s.kernel >= uint8_t(KernelId::Phong) && s.kernel < uint8_t(KernelId::Fixed);
    if (smooth && s.lit) {
      if (first_lit) d.light = true, d.vertex_specular = s.specular, first_lit = false;
      s.vertex_light_ok = same_specular(s.specular, d.vertex_specular);
      if (mat.two_sided) d.normal = d.eye = true;
      if (i == only_slot && uniform && s.vertex_light_ok) {
        d.vertex_color = s.vertex_color = true;
        d.uniform_color = mat.color;
      }
    }
    if (phong) d.normal = d.eye = true;
    d.cull_all = d.cull_all && s.cull;
    d.fill_only = d.fill_only && s.shading != Shading::Wireframe && s.shading != Shading::Points;
    if (s.uv_from_env) d.normal = true;
    plan.slots.push_back(s);
  }
  d.vertex_specular_terms = d.light && !d.vertex_color && d.vertex_specular.ks > 0;
}

Vec3 pipeline_color(Vec3 c, ColorSpace space, bool linear) {
  if (linear == (space == ColorSpace::Linear)) return c;
  if (linear) return {color::srgb_to_linear(c.x), color::srgb_to_linear(c.y), color::srgb_to_linear(c.z)};
  return {color::linear_to_srgb(c.x), color::linear_to_srgb(c.y), color::linear_to_srgb(c.z)};
}

void finish_color_plan(DrawList& plan, std::vector<raster::DrawState>& states) {
  bool pbr = false;
  for (const SlotPlan& s : plan.slots) pbr = pbr || s.shading == Shading::Pbr;
  const ColorPipeline c = plan.options.color;
  plan.linear = c == ColorPipeline::Linear || (c == ColorPipeline::Auto && pbr);
  for (SlotPlan& s : plan.slots) {
    const Material& mat = *s.material;
    raster::DrawState& st = states[s.draw_state];
    // Colour textures (base, environment, emissive) are sRGB-encoded in every format.
    st.texture.read_as_srgb(plan.linear), st.env_map.read_as_srgb(plan.linear);
    st.pbr.emissive_map.read_as_srgb(plan.linear);
    if (mat.color_space == ColorSpace::Linear) {  // lines are display values
      const Vec3 l = pipeline_color(mat.color, ColorSpace::Linear, false);
      s.line_color = raster::pack_rgba(l.x, l.y, l.z);
    }
    if (s.shading != Shading::Pbr) continue;
    const Vec3 base = pipeline_color(mat.color, mat.color_space, plan.linear);
    const Vec3 em = pipeline_color(mat.pbr.emissive, mat.color_space, plan.linear);
    st.pbr.base[0] = base.x, st.pbr.base[1] = base.y, st.pbr.base[2] = base.z, st.pbr.base[3] = mat.alpha;
    st.pbr.emissive[0] = em.x, st.pbr.emissive[1] = em.y, st.pbr.emissive[2] = em.z;
  }
  for (MeshDrawPlan& d : plan.meshes) {
    if (!d.vertex_color) continue;
    const SlotPlan& s = plan.slots[d.slot_begin + (d.slot_count > 1 ? 1 : 0)];
    d.uniform_color = pipeline_color(d.uniform_color, s.material->color_space, plan.linear);
  }
}

BatchDrawPlan plan_batch_draw(const DrawList& plan, std::vector<raster::DrawState>& states, const PrimitiveBatch& batch,
                              const PixelState& state, uint32_t primitives) {
  BatchDrawPlan d;
  d.batch = batch;
  d.primitive_count = primitives;
  d.textured = state.texture.texture != nullptr;
  d.units = d.textured ? (state.texture1.texture ? 2 : 1) : 0;
  d.volumes = (d.units > 0 && state.texture.texture->volume() ? 1 : 0) |
              (d.units > 1 && state.texture1.texture->volume() ? 2 : 0);
  d.fog = state.fog;
  d.color_sum = state.color_sum;
  d.kernel = raster::fixed_kernel(d.units, d.fog, d.color_sum, d.volumes);
  d.num_varyings = raster::fixed_varyings(d.units, d.fog, d.color_sum, d.volumes);

  // The viewport, within the guard band's reach of the framebuffer (as OpenGL's
  // GL_MAX_VIEWPORT_DIMS bounds it).
  const int fw = plan.width, fh = plan.height;
  const Viewport& v = batch.viewport;
  const int vw = v.width > 0 ? std::min(v.width, kMaxFramebufferSide) : fw;
  const int vh = v.height > 0 ? std::min(v.height, kMaxFramebufferSide) : fh;
  const int vx = v.width > 0 ? std::clamp(v.x, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  const int vy = v.height > 0 ? std::clamp(v.y, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  d.viewport = viewport_map(vx, vy, vw, vh, std::clamp(v.depth_near, 0.0f, 1.0f), std::clamp(v.depth_far, 0.0f, 1.0f));
  // Triangles stay inside the viewport (the view volume's sides are not clipped, they
  // are this box); points and wide lines may reach past it by half their size.
  SetupParams& s = d.setup;
  int sx0 = 0, sy0 = 0, sx1 = fw - 1, sy1 = fh - 1;
  if (state.scissor) {
    sx0 = std::max(sx0, state.scissor_x0), sy0 = std::max(sy0, state.scissor_y0);
    sx1 = std::min(sx1, state.scissor_x1 - 1), sy1 = std::min(sy1, state.scissor_y1 - 1);
  }
  s.x0 = std::max(sx0, vx), s.y0 = std::max(sy0, vy), s.x1 = std::min(sx1, vx + vw - 1), s.y1 = std::min(sy1, vy + vh - 1);
  const int reach = int(std::max(batch.point_size, batch.line_width) * 0.5f) + 1;
  s.px0 = std::max(sx0, vx - reach), s.py0 = std::max(sy0, vy - reach);
  s.px1 = std::min(sx1, vx + vw - 1 + reach), s.py1 = std::min(sy1, vy + vh - 1 + reach);
  s.offset = state.polygon_offset;
  s.offset_factor = state.offset_factor, s.offset_units = state.offset_units;

  raster::DrawState st;
  st.pixel = state;
  if (d.textured) st.texture = raster::SamplerView(*state.texture.texture, state.texture.sampler);
  if (d.units > 1) st.texture1 = raster::SamplerView(*state.texture1.texture, state.texture1.sampler);
  d.draw_state = uint32_t(states.size());
  states.push_back(st);
  return d;
}

}  // namespace velocity::geometry
