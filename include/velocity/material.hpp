// Surface appearance: colour, shading mode, specular highlight, sidedness.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "velocity/math.hpp"
#include "velocity/texture.hpp"

namespace velocity {

// How a surface is shaded. Chosen once per draw, never per pixel.
enum class Shading {
  Flat,         // one colour per triangle: Lambert by the face normal plus ambient
  Gouraud,      // lighting per vertex, colour interpolated
  Phong,        // normal interpolated, lighting and specular per pixel
  Unlit,        // no lighting: the mesh's per-vertex colours interpolated (seed 002's
                // gradient), else the face or material colour (PLG's constant shading)
  Wireframe,    // triangle edges as lines, unlit, with depth
  Points,       // vertices as points, unlit, with depth
};

// How a base texture combines with the lighting.
enum class TextureMode {
  Modulate,  // texture colour times the lit colour (OpenGL's GL_MODULATE)
  Replace,   // the texture colour as it is, unlit
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

  // Base-colour texture, addressed by the mesh's uvs; multiplies `color`.
  std::shared_ptr<const Texture> texture;
  // The texture file a model file names for this material, as written there. load_model
  // resolves it next to the model (resolve_texture_path) and loads it into `texture`; a
  // file that is missing or unreadable leaves `texture` empty, with a warning.
  std::string texture_file;
  TextureMode texture_mode = TextureMode::Modulate;
  // Sphere environment map, addressed by the eye-space normal: u = 0.5 + 0.5 Nx,
  // v = 0.5 + 0.5 Ny (seed 000). Per vertex in flat and Gouraud shading, per pixel in
  // Phong. The base colour becomes mix(base, environment, env_mix).
  std::shared_ptr<const Texture> env_map;
  float env_mix = 1.0f;
  Filter filter = Filter::Trilinear;
  Wrap wrap = Wrap::Repeat;
};

}  // namespace velocity
