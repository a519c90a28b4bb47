// GL 1.3's multitexture: two texture units (GL_MAX_TEXTURE_UNITS 2), each with its own
// enables, bindings, environment and level-of-detail bias, texture matrix stack and
// glTexGen state, current coordinates and coordinate array; glActiveTexture selects the
// unit the texture calls work on, glClientActiveTexture the array glTexCoordPointer
// and GL_TEXTURE_COORD_ARRAY name.
//
// The context keeps the active unit's state in the fields every texture call already
// works on (TextureState, transform_.texture, tex_gen_) and the other unit's in
// parked_unit_, exchanged by glActiveTexture; between glBegin and glEnd unit 0's is
// live, so the vertex stage computes unit 0's coordinates as before and unit 1's from
// the parked state (unit1_texcoord). A draw hands the renderer the enabled units in
// order (PixelState::texture, then texture1), each unit's environment applied to the
// last one's result.
#include "context.hpp"

#include <utility>

namespace velocity::gl {

void Context::swap_units() {
  TextureUnitState& p = parked_unit_;
  std::swap(p.enabled, texture_.enabled), std::swap(p.enabled_1d, texture_.enabled_1d);
  std::swap(p.bound, texture_.bound), std::swap(p.bound_1d, texture_.bound_1d);
  std::swap(p.enabled_3d, texture_.enabled_3d), std::swap(p.bound_3d, texture_.bound_3d);
  std::swap(p.env_mode, texture_.env_mode), std::swap(p.env_color, texture_.env_color);
  std::swap(p.lod_bias, texture_.lod_bias);
  std::swap(p.combine, texture_.combine);
  std::swap(p.matrix, transform_.texture), std::swap(p.matrix_identity, transform_.texture_identity);
  std::swap(p.tex_gen, tex_gen_);
  live_unit_ = 1 - live_unit_;
  transform_.derived_dirty = true;  // (the live texture matrix's identity flag)
}

void Context::make_live(int u) {
  if (live_unit_ != u) swap_units();
}

void Context::make_client_live(int u) {
  if (live_client_unit_ == u) return;
  std::swap(arrays.texcoord, parked_texcoord_);
  live_client_unit_ = u;
}

void Context::active_texture(GLenum unit) {
  if (in_begin_error()) return;
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kTextureUnits) return error(GL_INVALID_ENUM);
  active_unit_ = int(unit - GL_TEXTURE0);
  make_live(active_unit_);
}

void Context::client_active_texture(GLenum unit) {
  if (unit < GL_TEXTURE0 || unit >= GL_TEXTURE0 + kTextureUnits) return error(GL_INVALID_ENUM);
  client_unit_ = int(unit - GL_TEXTURE0);
  make_client_live(client_unit_);
}

// glMultiTexCoord (allowed between glBegin and glEnd, as glTexCoord). Mesa ignores a
// unit past the last without an error; so does pGL.
void Context::multi_tex_coord(GLenum unit, Vec4 t) {
  if (unit == GL_TEXTURE0) texcoord_ = t;
  else if (unit == GL_TEXTURE1) texcoord1_ = t;
}

bool Context::get_multitexture(GLenum pname, std::vector<double>& out) const {
  switch (pname) {
    case GL_MAX_TEXTURE_UNITS: out = {double(kTextureUnits)}; return true;
    case GL_ACTIVE_TEXTURE: out = {double(GL_TEXTURE0 + active_unit_)}; return true;
    case GL_CLIENT_ACTIVE_TEXTURE: out = {double(GL_TEXTURE0 + client_unit_)}; return true;
    case GL_CURRENT_TEXTURE_COORDS:  // the active unit's
      if (active_unit_ == 0) return false;
      out = {texcoord1_.x, texcoord1_.y, texcoord1_.z, texcoord1_.w};
      return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS:
      if (active_unit_ == 0) return false;
      out = {raster_texcoord1_.x, raster_texcoord1_.y, raster_texcoord1_.z, raster_texcoord1_.w};
      return true;
    default: return false;
  }
}

void Context::unbind_deleted_unit_texture(GLuint id) {
  if (id == parked_unit_.bound) parked_unit_.bound = 0, changed();
  if (id == parked_unit_.bound_1d) parked_unit_.bound_1d = 0, changed();
  if (id == parked_unit_.bound_3d) parked_unit_.bound_3d = 0, changed();
}

Vec4 Context::unit1_texcoord(const Vec4& object, const Vec4& eye) const {
  const TextureUnitState& u = parked_unit_;
  const Vec4 t = u.tex_gen.any() ? generate_texcoord(u.tex_gen, texcoord1_, object, eye) : texcoord1_;
  Vec4 out = u.matrix_identity ? t : u.matrix.back() * t;
  if (!u.enabled && !u.enabled_3d && u.enabled_1d) out.y = 0;  // a 1-D texture reads s alone (texture_1d.cpp)
  return out;
}

// One unit's stage from its state; false when it does not texture (off, or incomplete).
bool Context::unit_stage(TextureStage& st, const TextureUnitState& u) {
  if (!u.enabled && !u.enabled_1d && !u.enabled_3d) return false;
  // GL_TEXTURE_3D takes precedence, then GL_TEXTURE_2D (texture_3d.cpp, texture_1d.cpp).
  const bool three_d = u.enabled_3d, one_d = !three_d && !u.enabled;
  const GLuint id = three_d ? u.bound_3d : one_d ? u.bound_1d : u.bound;
  TextureObject* t = three_d ? &texture_.default_3d : one_d ? &texture_.default_1d : &texture_.default_object;
  if (id != 0)
    if (auto it = texture_.objects.find(id); it != texture_.objects.end()) t = it->second.get();
  const Texture* tex = texture_for_draw(*t);
  if (!tex) return false;
  st.texture = tex;
  st.format = t->format;
  st.env = u.env_mode == GL_REPLACE ? TexEnvMode::Replace
           : u.env_mode == GL_DECAL ? TexEnvMode::Decal
           : u.env_mode == GL_BLEND ? TexEnvMode::Blend
           : u.env_mode == GL_ADD   ? TexEnvMode::Add
           : u.env_mode == GL_COMBINE ? TexEnvMode::Combine
                                    : TexEnvMode::Modulate;
  st.env_color = u.env_color;
  st.combine = u.combine;
  using T = SamplerState::Texel;
  using Mp = SamplerState::Mip;
  SamplerState& sm = st.sampler;
  sm.mag = t->mag_filter == GL_NEAREST ? T::Nearest : T::Linear;
  switch (t->min_filter) {
    case GL_NEAREST: sm.min = T::Nearest, sm.mip = Mp::None; break;
    case GL_LINEAR: sm.min = T::Linear, sm.mip = Mp::None; break;
    case GL_NEAREST_MIPMAP_NEAREST: sm.min = T::Nearest, sm.mip = Mp::Nearest; break;
    case GL_LINEAR_MIPMAP_NEAREST: sm.min = T::Linear, sm.mip = Mp::Nearest; break;
    case GL_NEAREST_MIPMAP_LINEAR: sm.min = T::Nearest, sm.mip = Mp::Linear; break;
    default: sm.min = T::Linear, sm.mip = Mp::Linear; break;
  }
  auto wrap = [](GLenum w) {
    // GL_CLAMP clamps s to [0, 1] and filters with the border: for GL_NEAREST that
    // is the edge texel; with GL_LINEAR the last half texel blends in the border
    // colour. GL_CLAMP_TO_BORDER reads the border wherever s is outside the image.
    return w == GL_CLAMP_TO_EDGE       ? Wrap::Clamp
           : w == GL_CLAMP             ? Wrap::ClampHalfBorder
           : w == GL_CLAMP_TO_BORDER   ? Wrap::ClampToBorder
           : w == GL_MIRRORED_REPEAT   ? Wrap::MirroredRepeat
                                       : Wrap::Repeat;
  };
  sm.wrap_s = wrap(t->wrap_s), sm.wrap_t = wrap(t->wrap_t);
  if (one_d) sm.wrap_t = Wrap::Repeat;  // a 1-D image is one row: t is not read
  sm.wrap_r = wrap(t->wrap_r);          // (read by 3-D textures only)
  sm.border_color = t->border;
  // GL 1.4: the object's and the unit's bias, their sum clamped to GL_MAX_TEXTURE_LOD_BIAS.
  const float bias = t->lod_bias + u.lod_bias;
  sm.lod_bias = bias > -kMaxLodBias ? (bias < kMaxLodBias ? bias : kMaxLodBias) : -kMaxLodBias;
  sm.min_lod = t->min_lod, sm.max_lod = t->max_lod;
  return true;
}

bool Context::texture_stages(PixelState& s) {
  // Unit u's state: the live fields' or the parked ones.
  const TextureUnitState& p = parked_unit_;
  const TextureState& l = texture_;
  TextureStage stage[kTextureUnits];
  bool on[kTextureUnits];
  for (int u = 0; u < kTextureUnits; ++u) {
    const bool live = u == live_unit_;
    TextureUnitState live_state;
    if (live) {
      live_state.enabled = l.enabled, live_state.enabled_1d = l.enabled_1d, live_state.enabled_3d = l.enabled_3d;
      live_state.bound = l.bound, live_state.bound_1d = l.bound_1d, live_state.bound_3d = l.bound_3d;
      live_state.env_mode = l.env_mode, live_state.env_color = l.env_color, live_state.lod_bias = l.lod_bias;
      live_state.combine = l.combine;
    }
    on[u] = unit_stage(stage[u], live ? live_state : p);
  }
  if (on[0]) {
    s.texture = stage[0];
    if (on[1]) s.texture1 = stage[1];
    return false;
  }
  if (on[1]) s.texture = stage[1];
  return on[1];
}

// The attribute stacks take the units with unit 0 live, so that a frame's fields are
// unit 0's and its unit1 unit 1's whichever was active.
void Context::save_units(AttribFrame& f) {
  make_live(0);
  f.unit1 = parked_unit_;
  f.active_unit = active_unit_;
  f.texcoord1 = texcoord1_, f.raster_texcoord1 = raster_texcoord1_;
}

void Context::restore_units(const AttribFrame& f) {
  const GLbitfield m = f.mask;
  TextureUnitState& u = parked_unit_;
  if (m & GL_CURRENT_BIT) texcoord1_ = f.texcoord1, raster_texcoord1_ = f.raster_texcoord1;
  if (m & GL_ENABLE_BIT) {
    u.enabled = f.unit1.enabled, u.enabled_1d = f.unit1.enabled_1d, u.enabled_3d = f.unit1.enabled_3d;
    for (int i = 0; i < 4; ++i) u.tex_gen.coords[i].enabled = f.unit1.tex_gen.coords[i].enabled;
  }
  if (m & GL_TEXTURE_BIT) {
    // Everything but the matrix stack (not an attribute); a binding comes back if its
    // texture still exists.
    std::vector<Mat4> matrix = std::move(u.matrix);
    const bool identity = u.matrix_identity;
    u = f.unit1;
    u.matrix = std::move(matrix), u.matrix_identity = identity;
    if (u.bound && !texture_.objects.count(u.bound)) u.bound = 0;
    if (u.bound_1d && !texture_.objects.count(u.bound_1d)) u.bound_1d = 0;
    active_unit_ = f.active_unit;
  }
}

void Context::save_client_units(ClientAttribFrame& f) {
  make_client_live(0);
  f.texcoord1 = parked_texcoord_;
  f.client_unit = client_unit_;
}

void Context::restore_client_units(const ClientAttribFrame& f) {
  if (f.mask & GL_CLIENT_VERTEX_ARRAY_BIT) parked_texcoord_ = f.texcoord1, client_unit_ = f.client_unit;
}

}  // namespace velocity::gl
