// The lighting model, one function in two forms: this scalar one and the SIMD one in
// lighting-inl.h (N points at a time), which computes the same terms in the same order.
// The vertex stage lights vertices with it (flat, Gouraud), the pixel kernels light
// pixels with it (Phong); a change to the model is made to both forms together (the
// unit test Lighting.SimdFormIsTheScalarForm holds them to each other).
//
//   colour = base * (ambient + sum_i diffuse_i * max(N.L_i, 0)) + Ks * sum_i light_i * max(R_i.V, 0)^n
//
// with N the unit normal, L_i the unit direction to light i, R_i = 2(N.L_i)N - L_i its
// mirror direction and V the unit direction to the eye, all in eye space (the eye at the
// origin). This is OpenGL's fixed-function model without emission and, for the specular
// term, the Phong model of seed 000 ("Ks (R.V)^n"). Point lights are attenuated by
// 1 / (c + l d + q d^2). OpenGL's model in full (emission, the lights' own ambient,
// diffuse and specular colours, spots, Blinn's highlight, a viewer at infinity) is
// light_gl below, pGL's lighting: the same terms (detail::add_light, point_light) with
// more inputs, of which this model is the special case.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "shading/shadow.hpp"
#include "velocity/math.hpp"
#include "velocity/scene.hpp"

namespace velocity::shading {

// A frame's lights in eye space, as the model reads them.
struct EyeLights {
  struct Directional {
    Vec3 to_light;  // unit, eye space
    Vec3 color;
    const LightShadow* shadow = nullptr;  // its shadow map, when the frame has shadows
  };
  // A point light, or a spot light (spot: its cone).
  struct Point {
    Vec3 position;  // eye space
    Vec3 color;
    float constant = 1, linear = 0, quadratic = 0;  // Falloff::Attenuation
    bool inverse_square = false;                    // Falloff::InverseSquare: 1 / max(d^2, 0.01)
    float inv_range4 = 0;                           // 1 / range^4; 0: no range
    bool spot = false;
    Vec3 spot_axis;  // unit, eye space: where the spot points (from the light)
    // The cone: saturate(cos * spot_scale + spot_offset)^2, cos the angle's between the
    // axis and the direction from the light to the point.
    float spot_scale = 0, spot_offset = 1;
    const LightShadow* shadow = nullptr;  // its shadow map(s), when the frame has shadows
  };
  Vec3 ambient;
  std::vector<Directional> directional;
  std::vector<Point> point;
  bool shadows = false;  // some light has a shadow: its contribution is scaled by its visibility
};

// The light arriving at a surface point, split so that the surface's colours can be
// applied later (per face or per vertex). The engine's model: colour = base * diffuse +
// specular (apply). OpenGL's (light_gl): the ambient is kept apart, for its own material
// colour.
struct LightTerms {
  Vec3 diffuse;    // ambient + sum of diffuse (OpenGL's: the sum of diffuse only)
  Vec3 specular;   // sum of specular, already scaled by Ks (OpenGL's: not scaled)
  Vec3 ambient{};  // OpenGL's: global ambient + sum of the lights' ambient
};

// The specular term of a material: Ks * max(R.V, 0)^exponent. Below `cutoff`,
// (R.V)^exponent < 2^-12 adds under a sixteenth of an 8-bit step even at Ks = 1, so
// pow() (the costliest call per pixel) is skipped there.
struct Specular {
  float ks = 0, exponent = 32, cutoff = 1;
  Specular() = default;
  Specular(float ks_, float exponent_)
      : ks(ks_), exponent(exponent_), cutoff(ks_ > 0 && exponent_ > 0 ? std::exp2(-12.0f / exponent_) : 0.0f) {}
};

// The highlight: Phong's Ks (R.V)^n, not gated on N.L, as the reference's GLSL and the
// engine's model; or OpenGL's, Blinn's (N.H)^n with H the half vector of L and V, only
// where N.L > 0 (GL 1.5 section 2.14.1).
enum class Highlight { Phong, Blinn };

// One light's colours (as add_light takes them: already attenuated). The engine's lights
// have one colour, for diffuse and specular, and no ambient of their own.
struct LightColors {
  Vec3 ambient, diffuse, specular;
};

namespace detail {
// One light's terms: the model for one light, in both its forms. `to_light` unit;
// `to_eye` unit (Phong: read only with s.ks > 0); `half`, for Blinn, the half vector if
// the caller has it, else it is computed; Blinn reads s.exponent as the shininess.
template <Highlight H>
inline void add_light(LightTerms& t, Vec3 n, Vec3 to_light, const LightColors& c, Vec3 to_eye, const Specular& s,
                      const Vec3* half = nullptr) {
  float nl = dot(n, to_light);
  if constexpr (H == Highlight::Phong) {
    t.diffuse += c.diffuse * std::max(nl, 0.0f);
    if (s.ks > 0) {
      Vec3 r = n * (2 * nl) - to_light;
      float rv = dot(r, to_eye);
      if (rv > s.cutoff) t.specular += c.specular * (s.ks * std::pow(rv, s.exponent));
    }
  } else {
    t.ambient += c.ambient;
    if (nl > 0) {  // (max(N.L, 0): nothing to add below)
      t.diffuse += c.diffuse * nl;
      const float nh = dot(n, half ? *half : normalize(to_light + to_eye));
      if (nh > 0) t.specular += c.specular * (s.exponent != 0 ? std::pow(nh, s.exponent) : 1.0f);
    }
  }
}

// A point light at `position` seen from `p`: returns its attenuation 1 / (c + l d + q d^2)
// (at most 10^6) and sets `to_light`; a light at the point itself lights it along `n`.
inline float point_light(Vec3 position, Vec3 p, Vec3 n, float constant, float linear, float quadratic,
                         Vec3& to_light) {
  Vec3 v = position - p;
  float dist = length(v);
  float att = 1.0f / std::max(constant + linear * dist + quadratic * dist * dist, 1e-6f);
  to_light = dist > 0 ? v / dist : n;
  return att;
}

// KHR_lights_punctual's spot cone, as its sample code writes it: a smooth falloff from
// full intensity at cos(inner) to none at cos(outer), saturate(cos * scale + offset)^2
// (three.js uses a smoothstep instead; the spec's is the one here).
inline void spot_cone(float inner, float outer, float& scale, float& offset) {
  scale = 1.0f / std::max(0.001f, std::cos(inner) - std::cos(outer));
  offset = -std::cos(outer) * scale;
}

inline float saturate(float x) { return x > 0 ? (x < 1 ? x : 1) : 0; }

// A point or spot light seen from `p`: its attenuation (falloff, range window and cone)
// and `to_light`, in the order the SIMD form computes them. A light at the point
// itself lights it along `n`.
inline float punctual(const EyeLights::Point& l, Vec3 p, Vec3 n, Vec3& to_light) {
  const Vec3 v = l.position - p;
  const float d2 = dot(v, v), dist = std::sqrt(d2);
  to_light = d2 > 0 ? v / dist : n;
  float att = l.inverse_square ? 1.0f / std::max(d2, 0.01f)
                               : 1.0f / std::max(l.constant + (l.quadratic * dist + l.linear) * dist, 1e-6f);
  if (l.inv_range4 > 0) {
    const float w = saturate(1.0f - d2 * d2 * l.inv_range4);
    att *= w * w;
  }
  if (l.spot) {
    const float a = saturate(-dot(l.spot_axis, to_light) * l.spot_scale + l.spot_offset);
    att *= a * a;
  }
  return att;
}
}  // namespace detail

// `n` unit normal and `p` position, eye space.
inline LightTerms light(const EyeLights& lights, Vec3 n, Vec3 p, const Specular& s) {
  LightTerms t{lights.ambient, {}};
  Vec3 to_eye = s.ks > 0 ? normalize(-p) : Vec3{};
  for (const auto& d : lights.directional) {
    const Vec3 color = d.shadow ? d.color * visibility(*d.shadow, p, n, d.to_light) : d.color;
    detail::add_light<Highlight::Phong>(t, n, d.to_light, {{}, color, color}, to_eye, s);
  }
  for (const auto& pl : lights.point) {
    Vec3 to_light;
    float att = detail::punctual(pl, p, n, to_light);
    if (pl.shadow) att *= visibility(*pl.shadow, p, n, to_light);
    Vec3 color = pl.color * att;
    detail::add_light<Highlight::Phong>(t, n, to_light, {{}, color, color}, to_eye, s);
  }
  return t;
}

inline Vec3 apply(const LightTerms& t, Vec3 base) { return base * t.diffuse + t.specular; }

// --- OpenGL's fixed-function lighting: the model in full ------------------------
//
//   colour = emission + ambient_m * (global ambient + sum_i a_i ambient_i)
//          + diffuse_m * sum_i a_i max(N.L_i, 0) diffuse_i + specular_m * sum_i a_i h_i specular_i
//
// with a_i light i's attenuation times its spot factor and h_i its highlight (Blinn's).
// The engine's model above is the case emission = 0, no light ambient, one colour per
// light, ambient_m = diffuse_m = base, specular_m = Ks, no spots, a local viewer and
// Phong's highlight: both take their terms from add_light and point_light.

// One OpenGL light, eye space, prepared for a run of vertices (lights cannot change
// between glBegin and glEnd).
struct GlLight {
  LightColors colors;   // GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR (not attenuated)
  bool positional = false, spot = false;
  Vec3 position;        // positional: divided by its w
  Vec3 direction;       // directional: unit, towards the light
  Vec3 half;            // directional: unit half vector of `direction` and a viewer at +z
  Vec3 spot_direction;  // unit
  float cos_cutoff = -1, spot_exponent = 0;
  float constant = 1, linear = 0, quadratic = 0;
};

struct GlMaterial {
  Vec4 ambient{0.2f, 0.2f, 0.2f, 1}, diffuse{0.8f, 0.8f, 0.8f, 1}, specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  float shininess = 0;
};

// The colour of one vertex seen from one side (not clamped; alpha is the material's
// diffuse alpha): `n` the unit normal facing that side, `eye` the vertex in eye space
// (read for positional lights and a local viewer). Always inlined: pGL calls it per
// vertex, and a colour returned through memory would be stored in two halves and
// reloaded whole, a store-forwarding stall per vertex.
//
// `specular`: null, or where the specular part goes (OpenGL's separate specular colour,
// GL_SEPARATE_SPECULAR_COLOR): the result is then without it.
[[gnu::always_inline]] inline Vec4 light_gl(const GlLight* lights, int count, Vec3 model_ambient, bool local_viewer,
                                            const GlMaterial& m, Vec3 n, Vec3 eye, Vec3* specular = nullptr) {
  LightTerms t{{}, {}, model_ambient};
  const Vec3 to_eye = local_viewer ? normalize(-eye) : Vec3{0, 0, 1};
  Specular s;
  s.exponent = m.shininess;
  for (int k = 0; k < count; ++k) {
    const GlLight& l = lights[k];
    Vec3 to_light = l.direction;
    float att = 1;
    if (l.positional)
      att = detail::point_light(l.position, eye, n, l.constant, l.linear, l.quadratic, to_light);
    if (l.spot) {
      const float c = -dot(to_light, l.spot_direction);
      if (c < l.cos_cutoff) continue;  // outside the cone: nothing
      if (l.spot_exponent != 0) att *= std::pow(std::max(c, 0.0f), l.spot_exponent);
    }
    const Vec3* half = l.positional || local_viewer ? nullptr : &l.half;
    if (att == 1)
      detail::add_light<Highlight::Blinn>(t, n, to_light, l.colors, to_eye, s, half);
    else
      detail::add_light<Highlight::Blinn>(
          t, n, to_light, {l.colors.ambient * att, l.colors.diffuse * att, l.colors.specular * att}, to_eye, s, half);
  }
  if (specular) {
    *specular = m.specular.xyz() * t.specular;
    const Vec3 c = m.emission.xyz() + m.ambient.xyz() * t.ambient + m.diffuse.xyz() * t.diffuse;
    return {c.x, c.y, c.z, m.diffuse.w};
  }
  const Vec3 c = m.emission.xyz() + m.ambient.xyz() * t.ambient + m.diffuse.xyz() * t.diffuse +
                 m.specular.xyz() * t.specular;
  return {c.x, c.y, c.z, m.diffuse.w};
}

// The scene's lights in eye space (`view`: world to eye), into `out` (its vectors keep
// their storage). No lights: velocity::kDefaultLight, which is given in eye space.
void eye_lights(const Mat4& view, const std::vector<Light>& lights, EyeLights& out);

// For tests: the SIMD form (lighting-inl.h, the instruction set chosen at run time) at
// `count` points, normals `n` (unit) and positions `p`, into `out`.
void light_for_test(const EyeLights& lights, const Vec3* n, const Vec3* p, size_t count, const Specular& s,
                    LightTerms* out);

}  // namespace velocity::shading
