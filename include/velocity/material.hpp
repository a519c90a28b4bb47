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
  Pbr,          // glTF 2.0 metallic-roughness, per pixel (Material::pbr), in linear light
};

// How a base texture combines with the lighting.
enum class TextureMode {
  Modulate,  // texture colour times the lit colour (OpenGL's GL_MODULATE)
  Replace,   // the texture colour as it is, unlit
};

// How a texture or a colour's numbers relate to light. glTF's colour factors and vertex
// colours are linear; its base-colour and emissive images are sRGB-encoded, as are the
// images and colours of OBJ/MTL, 3DS, ASC and PLG files (display values).
enum class ColorSpace { Srgb, Linear };

// Alpha as glTF 2.0 defines it: ignored, a cut-out at `alpha_cutoff`, or blended.
enum class AlphaMode { Opaque, Mask, Blend };

// Which of the mesh's uv sets addresses a texture, and glTF's KHR_texture_transform
// (uv' = T(offset) R(rotation) S(scale) uv, as the extension writes it).
struct UvTransform {
  int uv_set = 0;  // 0: Mesh::uvs, 1: Mesh::uvs1
  Vec2 offset{0, 0};
  float rotation = 0;  // radians
  Vec2 scale{1, 1};
  bool identity() const { return uv_set == 0 && offset == Vec2{0, 0} && rotation == 0 && scale == Vec2{1, 1}; }
};

// `uv` transformed as `t` says (the uv set is the caller's choice): scale, then rotate,
// then offset, as KHR_texture_transform's matrix T * R * S with R = [cos sin; -sin cos]
// (rows): the direction three.js and the extension's TextureTransformTest sample agree on
// (a quarter turn with offset [0, 1] maps u' = v, v' = 1 - u).
Vec2 transform_uv(const UvTransform& t, Vec2 uv);

// A texture as a material uses it.
struct TextureRef {
  std::shared_ptr<const Texture> texture;
  UvTransform uv;
  // The file a model file names for it, as written (OBJ/MTL): load_model loads it
  // into `texture` as it does Material::texture_file.
  std::string file;
  explicit operator bool() const { return texture != nullptr; }
};

// glTF 2.0's metallic-roughness material (Shading::Pbr), the spec's parameters as they
// are, all factors linear. Material::color is the base colour factor's rgb and
// Material::texture the base-colour texture (sRGB); the rest is here.
struct PbrParams {
  float metallic = 1.0f, roughness = 1.0f;
  TextureRef metallic_roughness;  // linear: G roughness, B metallic
  TextureRef normal;              // linear, tangent space
  float normal_scale = 1.0f;
  TextureRef occlusion;           // linear, R
  float occlusion_strength = 1.0f;
  Vec3 emissive{0, 0, 0};
  TextureRef emissive_map;        // sRGB
  bool unlit = false;             // KHR_materials_unlit: base colour only
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
  // A file whose values are the surface's alpha (MTL map_d): load_model puts them in
  // the base texture's alpha channel (a white texture when there is none).
  std::string alpha_file;
  // Sphere environment map, addressed by the eye-space normal: u = 0.5 + 0.5 Nx,
  // v = 0.5 - 0.5 Ny, the image's top row at Ny = 1 (seed 000). Per vertex in flat and
  // Gouraud shading, per pixel in Phong. The base colour becomes mix(base, environment, env_mix).
  std::shared_ptr<const Texture> env_map;
  float env_mix = 1.0f;
  Filter filter = Filter::Trilinear;
  Wrap wrap = Wrap::Repeat;

  // The space of `color`, the mesh's vertex and face colours and `specular` (see
  // ColorSpace): Srgb for every format but glTF.
  ColorSpace color_space = ColorSpace::Srgb;
  // The base colour factor's alpha, multiplied by the texture's and the vertex's alpha,
  // and how it is used.
  float alpha = 1.0f;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  // The uv set and transform that address `texture` (glTF).
  UvTransform texture_uv;
  PbrParams pbr;  // read by Shading::Pbr
};

}  // namespace velocity
