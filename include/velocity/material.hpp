// Surface appearance: colour, shading mode, specular highlight, sidedness.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "velocity/math.hpp"

namespace velocity {

// How a surface is shaded. Chosen once per draw, never per pixel.
enum class Shading {
  Flat,         // one colour per triangle: Lambert by the face normal plus ambient
  Gouraud,      // lighting per vertex, colour interpolated
  Phong,        // normal interpolated, lighting and specular per pixel
  VertexColor,  // the mesh's per-vertex colours interpolated, unlit (seed 002)
  Wireframe,    // triangle edges as lines, unlit, with depth
  Points,       // vertices as points, unlit, with depth
};

std::string_view to_string(Shading shading);
// Parses "flat", "gouraud", "phong", "color", "wire" or "points".
std::optional<Shading> parse_shading(std::string_view name);

struct Material {
  std::string name;
  Vec3 color{0.8f, 0.8f, 0.8f};  // diffuse and ambient reflectance
  Shading shading = Shading::Gouraud;
  // Phong specular term Ks * max(R.V, 0)^shininess, white, added after the diffuse.
  float specular = 0.0f;
  float shininess = 32.0f;
  // Two-sided: back faces are drawn (not culled) and lit with the normal flipped.
  bool two_sided = false;
};

}  // namespace velocity
