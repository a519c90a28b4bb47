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
// 1 / (c + l d + q d^2).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "velocity/math.hpp"
#include "velocity/scene.hpp"

namespace velocity::shading {

// A frame's lights in eye space, as the model reads them.
struct EyeLights {
  struct Directional {
    Vec3 to_light;  // unit, eye space
    Vec3 color;
  };
  struct Point {
    Vec3 position;  // eye space
    Vec3 color;
    float constant, linear, quadratic;
  };
  Vec3 ambient;
  std::vector<Directional> directional;
  std::vector<Point> point;
};

// The light arriving at a surface point, split so that the surface's base colour can be
// applied later (per face or per vertex): colour = base * diffuse + specular.
struct LightTerms {
  Vec3 diffuse;   // ambient + sum of diffuse
  Vec3 specular;  // sum of specular, already scaled by Ks
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

namespace detail {
inline void add_light(LightTerms& t, Vec3 n, Vec3 to_light, Vec3 color, Vec3 to_eye, const Specular& s) {
  float nl = dot(n, to_light);
  t.diffuse += color * std::max(nl, 0.0f);
  if (s.ks > 0) {
    Vec3 r = n * (2 * nl) - to_light;
    float rv = dot(r, to_eye);
    // As the reference (GLSL) computes it: the highlight is not gated on N.L.
    if (rv > s.cutoff) t.specular += color * (s.ks * std::pow(rv, s.exponent));
  }
}
}  // namespace detail

// `n` unit normal and `p` position, eye space.
inline LightTerms light(const EyeLights& lights, Vec3 n, Vec3 p, const Specular& s) {
  LightTerms t{lights.ambient, {}};
  Vec3 to_eye = s.ks > 0 ? normalize(-p) : Vec3{};
  for (const auto& d : lights.directional) detail::add_light(t, n, d.to_light, d.color, to_eye, s);
  for (const auto& pl : lights.point) {
    Vec3 v = pl.position - p;
    float dist = length(v);
    float att = 1.0f / std::max(pl.constant + pl.linear * dist + pl.quadratic * dist * dist, 1e-6f);
    detail::add_light(t, n, dist > 0 ? v / dist : n, pl.color * att, to_eye, s);
  }
  return t;
}

inline Vec3 apply(const LightTerms& t, Vec3 base) { return base * t.diffuse + t.specular; }

// The scene's lights in eye space (`view`: world to eye), into `out` (its vectors keep
// their storage). No lights: velocity::kDefaultLight, which is given in eye space.
void eye_lights(const Mat4& view, const std::vector<Light>& lights, EyeLights& out);

// For tests: the SIMD form (lighting-inl.h, the instruction set chosen at run time) at
// `count` points, normals `n` (unit) and positions `p`, into `out`.
void light_for_test(const EyeLights& lights, const Vec3* n, const Vec3* p, size_t count, const Specular& s,
                    LightTerms* out);

}  // namespace velocity::shading
