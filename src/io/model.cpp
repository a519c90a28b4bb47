// Choosing a reader by file extension, Model's counts, and putting a model in a scene.
#include <cstdint>
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

// The values of an alpha map (MTL map_d) as the alpha of `base` (or of a white image
// of the map's size when there is no base): the map's own alpha where it has one, else
// its grey level; sampled at the nearest texel where the sizes differ.
std::shared_ptr<const Texture> with_alpha(const std::shared_ptr<const Texture>& base, const Texture& map) {
  const Texture::Level& a = map.levels()[0];
  bool has_alpha = false;
  for (uint32_t t : a.texels) has_alpha |= (t >> 24) != 255;
  const int w = base ? base->width() : a.width, h = base ? base->height() : a.height;
  Image out(w, h, 0xffffffffu);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint32_t t = a.texels[size_t(int64_t(y) * a.height / h) * size_t(a.width) + size_t(int64_t(x) * a.width / w)];
      const uint32_t value = has_alpha ? t >> 24 : ((t & 0xff) + ((t >> 8) & 0xff) + ((t >> 16) & 0xff)) / 3;
      uint8_t* p = out.pixel(x, y);
      if (base) {
        const uint32_t b = base->levels()[0].texels[size_t(y) * size_t(w) + size_t(x)];
        p[0] = uint8_t(b), p[1] = uint8_t(b >> 8), p[2] = uint8_t(b >> 16);
        p[3] = uint8_t((b >> 24) * value / 255);
      } else {
        p[3] = uint8_t(value);
      }
    }
  return std::make_shared<const Texture>(out);
}

// Loads the texture files the materials name (the base texture, the PBR maps, an alpha
// map), each file once, found next to the model (case-insensitively: files copied from
// DOS and Windows rarely keep their case). A missing or unreadable texture is not a
// broken model: the material keeps its colour and a warning says which file was wanted.
void load_textures(Model& model, const LoadOptions& options) {
  std::map<std::string, std::shared_ptr<const Texture>> loaded;  // by the name as written
  size_t budget = options.max_memory;
  auto load = [&](const std::string& name) {
    auto [it, fresh] = loaded.try_emplace(name);
    if (!fresh) return it->second;
    std::string file = resolve_texture_path(model.path, name);
    if (file.empty()) {
      warn(model.path + ": texture '" + name + "' not found next to the model");
      return it->second;
    }
    try {
      it->second = load_texture(file);
      size_t bytes = it->second->memory_bytes();
      if (bytes > budget) throw Error(file + ": textures exceed the memory limit");
      budget -= bytes;
    } catch (const Error& e) {
      warn(std::string(e.what()) + " (texture of " + model.path + ")");
      it->second = nullptr;
    }
    return it->second;
  };
  for (ModelNode& node : model.nodes) {
    if (!node.mesh) continue;
    for (Material& m : node.mesh->materials) {
      if (!m.texture_file.empty() && !m.texture) m.texture = load(m.texture_file);
      for (TextureRef* ref : {&m.pbr.metallic_roughness, &m.pbr.normal, &m.pbr.occlusion, &m.pbr.emissive_map})
        if (!ref->file.empty() && !ref->texture) ref->texture = load(ref->file);
      if (!m.alpha_file.empty())
        if (auto map = load(m.alpha_file)) m.texture = with_alpha(m.texture, *map);
    }
  }
}

}  // namespace

Model load_model(const std::string& path, const LoadOptions& options) {
  Model model = read_model(path, options);
  if (options.load_textures) load_textures(model, options);
  // Marked: caches trust the revision (Mesh::revision); whoever edits one touches it.
  for (ModelNode& node : model.nodes)
    if (node.mesh) node.mesh->touch();
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
