// Loading models and images from files.
//
// Files are untrusted: every loader validates what it reads and throws velocity::Error
// with the file name, the line (text formats) and what was expected. A failed load
// leaves nothing behind; no count read from a file is trusted for an allocation.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "velocity/image.hpp"
#include "velocity/mesh.hpp"
#include "velocity/scene.hpp"

namespace velocity {

struct LoadOptions {
  // 3D Studio stores Z up; Velocity is Y up. Swapping Y and Z (and so flipping the
  // winding back to counter-clockwise) is seed 000's "Errors found" fix. ASC only.
  bool swap_yz = true;
  // Most the loader may allocate for one file, in bytes (vertices, faces, images).
  size_t max_memory = size_t(2) << 30;
};

// One named part of a model: a mesh (or none, for a pure transform node), its matrix
// relative to its parent node, and the parent's index in Model::nodes (-1 for a root).
// Parents come before their children.
struct ModelNode {
  std::string name;
  std::shared_ptr<Mesh> mesh;
  Mat4 local;
  int parent = -1;
};

struct NamedCamera {
  std::string name;
  Camera camera;
};

// Everything a file held: meshes in a node hierarchy, its lights and cameras.
struct Model {
  std::string path;
  std::vector<ModelNode> nodes;
  std::vector<Light> lights;
  std::vector<NamedCamera> cameras;

  size_t vertex_count() const;
  size_t triangle_count() const;
};

// Loads a model, choosing the reader by the file's extension (case-insensitive):
// .asc (3D Studio ASCII), .plg/.plx (REND386 / Black Art / T3D), .obj.
Model load_model(const std::string& path, const LoadOptions& options = {});

// The readers themselves; `name` is used in error messages.
Model load_asc(const std::string& path, const LoadOptions& options = {});
Model parse_asc(std::string_view text, const std::string& name, const LoadOptions& options = {});
Model load_plg(const std::string& path, const LoadOptions& options = {});
Model parse_plg(std::string_view text, const std::string& name, const LoadOptions& options = {});
Model load_obj(const std::string& path, const LoadOptions& options = {});

// Adds every node of `model` to `scene` as objects (names and hierarchy kept) under
// `parent`, and its lights. Returns the ids of the root nodes' objects.
std::vector<ObjectId> add_to_scene(Scene& scene, const Model& model, ObjectId parent = kNoParent);

}  // namespace velocity
