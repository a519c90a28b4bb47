// The scene's lights in eye space, and the SIMD form's test entry point (compiled once
// per instruction set and dispatched at run time, as the kernels are).
#include "shading/lighting.hpp"

#include <cmath>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/lighting.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "shading/lighting-inl.h"
#include "simd/simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::shading {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

void LightForTest(const EyeLights& lights, const Vec3* n, const Vec3* p, size_t count, const Specular& s,
                  LightTerms* out) {
  const DF d;
  constexpr size_t N = kLanes;
  for (size_t i = 0; i < count; i += N) {
    const size_t k = std::min(N, count - i);
    alignas(64) float in[6][N] = {};
    for (size_t j = 0; j < k; ++j) {
      in[0][j] = n[i + j].x, in[1][j] = n[i + j].y, in[2][j] = n[i + j].z;
      in[3][j] = p[i + j].x, in[4][j] = p[i + j].y, in[5][j] = p[i + j].z;
    }
    const LightTermsN t = light(lights, {hn::Load(d, in[0]), hn::Load(d, in[1]), hn::Load(d, in[2])},
                                {hn::Load(d, in[3]), hn::Load(d, in[4]), hn::Load(d, in[5])}, s, hn::FirstN(d, k));
    alignas(64) float o[6][N];
    hn::Store(t.diffuse.x, d, o[0]), hn::Store(t.diffuse.y, d, o[1]), hn::Store(t.diffuse.z, d, o[2]);
    hn::Store(t.specular.x, d, o[3]), hn::Store(t.specular.y, d, o[4]), hn::Store(t.specular.z, d, o[5]);
    for (size_t j = 0; j < k; ++j) out[i + j] = {{o[0][j], o[1][j], o[2][j]}, {o[3][j], o[4][j], o[5][j]}};
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::shading
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace velocity::shading {

HWY_EXPORT(LightForTest);

void light_for_test(const EyeLights& lights, const Vec3* n, const Vec3* p, size_t count, const Specular& s,
                    LightTerms* out) {
  HWY_DYNAMIC_DISPATCH(LightForTest)(lights, n, p, count, s, out);
}

void eye_lights(const Mat4& view, const std::vector<Light>& lights, EyeLights& out) {
  out.ambient = {};
  out.directional.clear(), out.point.clear();
  out.shadows = false;  // until the frame's shadow maps are drawn (frame.cpp)
  if (lights.empty()) {
    out.ambient = kDefaultLight.ambient;
    out.directional.push_back({normalize(kDefaultLight.towards), kDefaultLight.diffuse});
    return;
  }
  for (const Light& light : lights) {
    switch (light.type) {
      case LightType::Ambient: out.ambient += light.color; break;
      case LightType::Directional:
        out.directional.push_back({normalize(view.transform_vector(light.direction)), light.color});
        break;
      case LightType::Point:
      case LightType::Spot: {
        EyeLights::Point p;
        p.position = view.transform_point(light.position), p.color = light.color;
        p.constant = light.constant, p.linear = light.linear, p.quadratic = light.quadratic;
        p.inverse_square = light.falloff == Falloff::InverseSquare;
        if (light.range > 0 && std::isfinite(light.range)) p.inv_range4 = 1.0f / (light.range * light.range * light.range * light.range);
        if (light.type == LightType::Spot) {
          p.spot = true;
          p.spot_axis = normalize(view.transform_vector(-light.direction));  // direction is towards the light
          detail::spot_cone(light.inner_cone, light.outer_cone, p.spot_scale, p.spot_offset);
        }
        out.point.push_back(p);
        break;
      }
    }
  }
}

}  // namespace velocity::shading
#endif  // HWY_ONCE
