#include "shading/lighting.hpp"

namespace velocity::shading {

void eye_lights(const Mat4& view, const std::vector<Light>& lights, EyeLights& out) {
  out.ambient = {};
  out.directional.clear(), out.point.clear();
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
        out.point.push_back({view.transform_point(light.position), light.color, light.constant, light.linear,
                             light.quadratic});
        break;
    }
  }
}

}  // namespace velocity::shading
