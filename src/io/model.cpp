// Choosing a reader by file extension, Model's counts, and putting a model in a scene.
#include <string>

#include "io/read_file.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"

namespace velocity {

Model load_model(const std::string& path, const LoadOptions& options) {
  std::string ext = detail::lower_extension(path);
  if (ext == "asc") return load_asc(path, options);
  if (ext == "plg" || ext == "plx") return load_plg(path, options);
  if (ext == "obj") return load_obj(path, options);
  if (ext == "gltf" || ext == "glb" || ext == "3ds" || ext == "ply" || ext == "stl")
    return load_with_assimp(path, options);
  if (ext == "pcx") throw Error(path + ": a PCX file is an image, not a model (read it with read_pcx)");
  throw Error(path + ": unknown model extension '" + ext + "' (expected .asc, .plg, .plx, .obj, .gltf, .glb, .3ds, .ply or .stl)");
}

size_t Model::vertex_count() const {
  size_t n = 0;
  for (const ModelNode& node : nodes)
    if (node.mesh) n += node.mesh->vertex_count();
  return n;
}

size_t Model::triangle_count() const {
  size_t n = 0;
  for (const ModelNode& node : nodes)
    if (node.mesh) n += node.mesh->triangle_count();
  return n;
}

std::vector<ObjectId> add_to_scene(Scene& scene, const Model& model, ObjectId parent) {
  // Check the whole hierarchy before adding anything, so a bad model leaves the scene
  // as it was.
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    int p = model.nodes[i].parent;
    if (p >= int(i) || p < -1)
      throw Error(model.path + ": node '" + model.nodes[i].name + "' has parent " + std::to_string(p) +
                  ", expected -1 or an earlier node");
    if (model.nodes[i].mesh) model.nodes[i].mesh->validate();
  }
  std::vector<ObjectId> ids(model.nodes.size()), roots;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const ModelNode& node = model.nodes[i];
    ObjectId up = node.parent < 0 ? parent : ids[size_t(node.parent)];
    ids[i] = scene.add_object(node.name, node.mesh, up);
    scene.object(ids[i]).base = node.local;
    if (node.parent < 0) roots.push_back(ids[i]);
  }
  scene.lights.insert(scene.lights.end(), model.lights.begin(), model.lights.end());
  return roots;
}

}  // namespace velocity
