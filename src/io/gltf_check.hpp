// Internal: the check a glTF file's JSON must pass before Assimp reads it, and what
// Assimp is then given to read.
//
// Assimp 5.2.5's glTF 2.0 importer parses the JSON with a recursive parser (a file
// nested 200,000 brackets deep overflows the stack and crashes the process), and it
// builds its node tree by following `children` from each scene root, copying a node
// once per path that reaches it: a 2 KB file whose 40 nodes each list the next one
// twice took 8 GB in 20 s and was still going. glTF requires the nodes to form disjoint
// trees whose roots the scenes list; Velocity checks that, the nesting depth, and that
// the file is glTF 2.0. Mutation testing found more crashes, all in parts of glTF
// Velocity does not use or can check: an image media type without '/' ("imagepng"), a
// skin without inverseBindMatrices (valid glTF), a string among KHR_texture_transform's
// numbers (Debian builds Assimp's JSON library with assertions on: a type mismatch
// aborts). So images' media types are checked, every array must hold one type, and
// Assimp reads a copy without skins, animations, morph targets, "extras" and the
// extensions that do not change what Velocity draws (Velocity draws meshes in their
// bind pose, as Assimp gives them anyway). Fuzzing found two more: an accessor
// claiming four billion elements (Assimp allocated 68 GB before reading them), and a
// line loop with an index out of range (a null pointer inside Assimp). So the binary
// data must hold what the accessors claim, and line loops, which Velocity does not draw,
// are read as line strips, on which Assimp drops bad indices.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace velocity::detail {

// Checks `bytes` (a .gltf file, or a .glb file: "glTF" magic, then the JSON chunk) and
// returns the file Assimp is to read in its place: the same JSON without "skins",
// "animations", nodes' "skin" and "weights", meshes' "weights", primitives' "targets",
// any "extras", every material's name (kMaterialTag + its index), and extensions other than KHR_materials_unlit,
// KHR_materials_pbrSpecularGlossiness, KHR_mesh_quantization and
// KHR_draco_mesh_compression, with line loops made line strips (mode 2 -> 3); as a
// .gltf or a .glb like the input (a .glb's binary chunk kept as it is). Throws
// velocity::Error naming `path` unless the JSON is nested at most 64 deep, parses, says
// "asset": {"version": "2.x"}, requires no other extension, has no array mixing types,
// its "nodes" and "scenes" form trees (every child index names a node, no node is the
// child of two nodes or its own ancestor, every node a scene lists is a root, listed
// once), and every image's media type, when it has one, has a '/'; and unless the
// binary data holds what the accessors claim: buffers no longer than a .glb's binary
// chunk or their data URI, buffer views inside their buffer, accessors (and sparse
// accessors' indices and values) inside their view, and accessors Assimp must allocate
// itself (no bufferView, or sparse) within `max_memory` / 4.
// The name each material has in the copy Assimp reads: this, then its index in the file.
inline constexpr const char* kMaterialTag = "velocity-gltf-material-";
// Each node an animation moves is renamed kNodeTag + its index + ":" + its name in the
// copy Assimp reads, so that the adapter finds the node an animation names.
inline constexpr const char* kNodeTag = "velocity-gltf-node-";

std::string prepare_gltf(std::string_view bytes, const std::string& path, size_t max_memory);

}  // namespace velocity::detail
