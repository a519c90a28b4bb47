// Internal: a glTF 2.0 file's materials, images and KHR_lights_punctual lights, read
// from its JSON by Velocity itself rather than through Assimp.
//
// Why not Assimp's aiMaterial and aiLight: Assimp 5.2.5 aborts on a damaged
// KHR_texture_transform (so io/gltf_check.hpp removes that extension from its copy),
// keeps no texture transform per texture, loses a spot light's range, and gives
// embedded images as "*N" names whose order is its own. The JSON is small and already
// checked (prepare_gltf runs first); reading it here keeps every value as the spec
// defines it, with one error per bad value naming the material or light.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "velocity/animation.hpp"
#include "velocity/load.hpp"
#include "velocity/material.hpp"
#include "velocity/scene.hpp"

namespace velocity::detail {

struct GltfAppearance {
  // One per entry of the file's "materials", in order, then the spec's default
  // material for primitives without one.
  std::vector<Material> materials;
  // KHR_lights_punctual lights placed by the nodes of the scene shown, in world space.
  std::vector<Light> lights;
  // Node animations; NodeAnimation::node is the glTF node's index (the adapter finds
  // the Model node through kNodeTag).
  std::vector<Animation> animations;
  // Skins; Skin::node and joints are glTF node indices, `base` is left to the adapter.
  std::vector<Skin> skins;
};

// Reads `bytes` (a .gltf or .glb file that prepare_gltf accepted) from `path`. Every
// material becomes Shading::Pbr in ColorSpace::Linear; with options.load_textures its
// textures are decoded: images in a .glb's binary chunk or another buffer, data URIs
// and files beside the model, PNG or JPEG, each image once, all within
// options.max_memory. An image that cannot be read is a warning (the material keeps
// its factors), as a missing texture file is. Throws velocity::Error naming `path` and
// the material, texture or light for a value of the wrong type or out of range.
GltfAppearance read_gltf_appearance(std::string_view bytes, const std::string& path, const LoadOptions& options);

// The bytes a "data:" URI holds ("data:[<media type>][;base64],<data>"), base64 or
// percent-encoded. Throws velocity::Error naming `where` for a URI that is not a data
// URI or whose base64 is malformed.
std::string decode_data_uri(std::string_view uri, const std::string& where);

}  // namespace velocity::detail
