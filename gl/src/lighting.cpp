// Lighting state: glLight, glLightModel, glMaterial, glColorMaterial, glShadeModel and
// their queries. The lighting equation is shading::light_gl (src/shading/lighting.hpp),
// which the vertex stage runs (vertex.cpp).
#include "context.hpp"

namespace velocity::gl {

namespace {
// A colour or position as glGetLightfv and glGetMaterialfv return it.
void put(float* v, Vec4 c) { v[0] = c.x, v[1] = c.y, v[2] = c.z, v[3] = c.w; }
}  // namespace

void Context::light(GLenum which, GLenum pname, const float* v) {
  if (in_begin_error()) return;
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights) return error(GL_INVALID_ENUM);
  Light& l = lighting_.lights[which - GL_LIGHT0];
  switch (pname) {
    case GL_AMBIENT: l.ambient = {v[0], v[1], v[2], v[3]}; break;
    case GL_DIFFUSE: l.diffuse = {v[0], v[1], v[2], v[3]}; break;
    case GL_SPECULAR: l.specular = {v[0], v[1], v[2], v[3]}; break;
    case GL_POSITION: l.position = transform_.modelview.back() * Vec4{v[0], v[1], v[2], v[3]}; break;
    case GL_SPOT_DIRECTION: l.spot_direction = transform_.modelview.back().transform_vector({v[0], v[1], v[2]}); break;
    case GL_SPOT_EXPONENT:
      if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE);
      l.spot_exponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if ((v[0] < 0 || v[0] > 90) && v[0] != 180) return error(GL_INVALID_VALUE);
      l.spot_cutoff = v[0];
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
      if (v[0] < 0) return error(GL_INVALID_VALUE);
      (pname == GL_CONSTANT_ATTENUATION ? l.constant : pname == GL_LINEAR_ATTENUATION ? l.linear : l.quadratic) = v[0];
      break;
    default: return error(GL_INVALID_ENUM);
  }
}

bool Context::get_light(GLenum which, GLenum pname, float* v) {
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights) return false;
  const Light& l = lighting_.lights[which - GL_LIGHT0];
  switch (pname) {
    case GL_AMBIENT: put(v, l.ambient); return true;
    case GL_DIFFUSE: put(v, l.diffuse); return true;
    case GL_SPECULAR: put(v, l.specular); return true;
    case GL_POSITION: put(v, l.position); return true;
    case GL_SPOT_DIRECTION: v[0] = l.spot_direction.x, v[1] = l.spot_direction.y, v[2] = l.spot_direction.z; return true;
    case GL_SPOT_EXPONENT: v[0] = l.spot_exponent; return true;
    case GL_SPOT_CUTOFF: v[0] = l.spot_cutoff; return true;
    case GL_CONSTANT_ATTENUATION: v[0] = l.constant; return true;
    case GL_LINEAR_ATTENUATION: v[0] = l.linear; return true;
    case GL_QUADRATIC_ATTENUATION: v[0] = l.quadratic; return true;
    default: return false;
  }
}

void Context::light_model(GLenum pname, const float* v) {
  if (in_begin_error()) return;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: lighting_.model_ambient = {v[0], v[1], v[2], v[3]}; break;
    case GL_LIGHT_MODEL_TWO_SIDE: lighting_.two_side = v[0] != 0; break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: lighting_.local_viewer = v[0] != 0; break;
    default:
      if (light_model_color_control(pname, v[0])) break;  // (color_sum.cpp)
      return error(GL_INVALID_ENUM);
  }
}

void Context::material(GLenum face, GLenum pname, const float* v) {
  store_material(face, pname, v);
  // With GL_COLOR_MATERIAL on, the properties it tracks follow the current colour: a
  // glMaterial of them is overridden at once (as Mesa ignores it).
  if (lighting_.color_material) apply_color_material();
}

void Context::store_material(GLenum face, GLenum pname, const float* v) {
  // glMaterial is allowed between glBegin and glEnd: the vertices before it are lit
  // with the material they were given with.
  flush_vertices();
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  const Vec4 c{v[0], v[1], v[2], v[3]};
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 && face == GL_BACK) || (side == 1 && face == GL_FRONT)) continue;
    Material& m = lighting_.materials[side];
    switch (pname) {
      case GL_AMBIENT: m.ambient = c; break;
      case GL_DIFFUSE: m.diffuse = c; break;
      case GL_SPECULAR: m.specular = c; break;
      case GL_EMISSION: m.emission = c; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = c; break;
      case GL_SHININESS:
        if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE);
        m.shininess = v[0];
        break;
      default: return error(GL_INVALID_ENUM);
    }
  }
}

bool Context::get_material(GLenum face, GLenum pname, float* v) {
  if (face != GL_FRONT && face != GL_BACK) return false;
  const Material& m = lighting_.materials[face == GL_BACK ? 1 : 0];
  switch (pname) {
    case GL_AMBIENT: put(v, m.ambient); return true;
    case GL_DIFFUSE: put(v, m.diffuse); return true;
    case GL_SPECULAR: put(v, m.specular); return true;
    case GL_EMISSION: put(v, m.emission); return true;
    case GL_SHININESS: v[0] = m.shininess; return true;
    default: return false;
  }
}

void Context::color_material(GLenum face, GLenum mode) {
  if (in_begin_error()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return error(GL_INVALID_ENUM);
  lighting_.color_material_face = face, lighting_.color_material_mode = mode;
  if (lighting_.color_material) apply_color_material();
}

void Context::apply_color_material() {
  const float c[4] = {color_.x, color_.y, color_.z, color_.w};
  store_material(lighting_.color_material_face, lighting_.color_material_mode, c);
}

void Context::set_color(Vec4 c) {
  color_ = c;
  if (lighting_.color_material) apply_color_material();
}

void Context::shade_model(GLenum m) {
  if (in_begin_error()) return;
  if (m != GL_FLAT && m != GL_SMOOTH) return error(GL_INVALID_ENUM);
  lighting_.shade_model = m;
}

}  // namespace velocity::gl
