#include "velocity/material.hpp"

#include <cmath>

namespace velocity {

namespace {
struct ShadingName {
  Shading shading;
  std::string_view name;
};
constexpr ShadingName kShadingNames[] = {
    {Shading::Flat, "flat"},         {Shading::Gouraud, "gouraud"},  {Shading::Phong, "phong"},
    {Shading::Unlit, "unlit"}, {Shading::Wireframe, "wire"},   {Shading::Points, "points"},
    {Shading::Pbr, "pbr"},
};
}  // namespace

std::string_view to_string(Shading shading) {
  for (const auto& s : kShadingNames)
    if (s.shading == shading) return s.name;
  return "unknown";
}

std::optional<Shading> parse_shading(std::string_view name) {
  if (name == "color") return Shading::Unlit;  // the older name, still accepted
  for (const auto& s : kShadingNames)
    if (s.name == name) return s.shading;
  return std::nullopt;
}

}  // namespace velocity

namespace velocity {

Vec2 transform_uv(const UvTransform& t, Vec2 uv) {
  const float su = uv.x * t.scale.x, sv = uv.y * t.scale.y;
  const float c = std::cos(t.rotation), s = std::sin(t.rotation);
  return {c * su + s * sv + t.offset.x, -s * su + c * sv + t.offset.y};
}

}  // namespace velocity
