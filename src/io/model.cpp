// Choosing a reader by file extension, Model's counts, and putting a model in a scene.
#include <map>
#include <string>

#include "io/read_file.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/texture.hpp"

namespace velocity {

namespace {

Model read_model(const std::string& path, const LoadOptions& options) {
  std::string ext = detail::lower_extension(path);
  if (ext == "asc") return load_asc(path, options);
  if (ext == "plg" || ext == "plx") return load_plg(path, options);
  if (ext == "obj") return load_obj(path, options);
  if (ext == "gltf" || ext == "glb" || ext == "3ds" || ext == "ply" || ext == "stl")
    return load_with_assimp(path, options);
  if (ext == "pcx") throw Error(path + ": a PCX file is an image, not a model (read it with read_pcx)");
  throw Error(path + ": unknown model extension '" + ext + "' (expected .asc, .plg, .plx, .obj, .gltf, .glb, .3ds, .ply or .stl)");
}

// Loads the texture files the materials name, each file once, found next to the model
// (case-insensitively: files copied from DOS and Windows rarely keep their case). A
// missing or unreadable texture is not a broken model: the material keeps its colour
// and a warning says which file was wanted.
void load_textures(Model& model, const LoadOptions& options) {
  std::map<std::string, std::shared_ptr<const Texture>> loaded;  // by the name as written
  size_t budget = options.max_memory;
  for (ModelNode& node : model.nodes) {
    if (!node.mesh) continue;
    for (Material& m : node.mesh->materials) {
      if (m.texture_file.empty() || m.texture) continue;
      auto [it, fresh] = loaded.try_emplace(m.texture_file);
      if (fresh) {
        std::string file = resolve_texture_path(model.path, m.texture_file);
        if (file.empty()) {
          warn(model.path + ": texture '" + m.texture_file + "' not found next to the model");
        } else {
          try {
            it->second = load_texture(file);
            size_t bytes = it->second->memory_bytes();
            if (bytes > budget) throw Error(file + ": textures exceed the memory limit");
            budget -= bytes;
          } catch (const Error& e) {
            warn(std::string(e.what()) + " (texture of " + model.path + ")");
            it->second = nullptr;
          }
        }
      }
      m.texture = it->second;
    }
  }
}

}  // namespace

Model load_model(const std::string& path, const LoadOptions& options) {
  Model model = read_model(path, options);
  if (options.load_textures) load_textures(model, options);
  return model;
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
