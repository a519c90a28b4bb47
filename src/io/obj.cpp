// Wavefront OBJ through tinyobjloader (Debian's libtinyobjloader-dev): a small, well-kept
// reader that handles OBJ's corner cases (negative indices, polygons, MTL files).
// Velocity turns its output into one mesh per OBJ group (shape), with the MTL diffuse
// colours as materials; normals from the file when every corner has one, else computed
// per smoothing group.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <sstream>

#include "io/read_file.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"

namespace velocity {

namespace {

// Material names may hold spaces ("01 - Default", 3ds Max's default name), which
// tinyobjloader cuts at the first space in `usemtl` (but not in `newmtl`), so a face's
// material is lost. Before parsing, the spaces in both are replaced by kNameSpace, and
// put back in the names afterwards. Trailing white space (a '\r') is not part of a name.
constexpr char kNameSpace = '\x1f';

std::string protect_material_names(std::string text) {
  size_t line = 0;
  while (line < text.size()) {
    size_t end = text.find('\n', line);
    if (end == std::string::npos) end = text.size();
    size_t at = text.find_first_not_of(" \t", line);
    if (at < end && (text.compare(at, 7, "usemtl ") == 0 || text.compare(at, 7, "newmtl ") == 0 ||
                     text.compare(at, 7, "usemtl\t") == 0 || text.compare(at, 7, "newmtl\t") == 0)) {
      size_t first = text.find_first_not_of(" \t", at + 7), last = end;
      while (last > first && (text[last - 1] == ' ' || text[last - 1] == '\t' || text[last - 1] == '\r')) --last;
      for (size_t i = first; i < last; ++i)
        if (text[i] == ' ' || text[i] == '\t') text[i] = kNameSpace;
    }
    line = end + 1;
  }
  return text;
}

std::string restore_spaces(std::string name) {
  std::replace(name.begin(), name.end(), kNameSpace, ' ');
  return name;
}

// An MTL texture's -o (offset) and -s (scale) as a UvTransform in the engine's uvs: MTL
// applies u' = s u + o to OBJ's uvs (v up); with v = 1 - v_obj on both sides, the v
// offset becomes 1 - s - o.
UvTransform uv_transform(const tinyobj::texture_option_t& t) {
  UvTransform uv;
  uv.scale = {t.scale[0], t.scale[1]};
  uv.offset = {t.origin_offset[0], 1 - t.scale[1] - t.origin_offset[1]};
  if (!std::isfinite(uv.scale.x) || !std::isfinite(uv.scale.y) || !std::isfinite(uv.offset.x) ||
      !std::isfinite(uv.offset.y))
    return {};
  return uv;
}

// MTL as Velocity's material: Kd, map_Kd (with -s, -o, -clamp), Ks and Ns as the Phong
// highlight, d (or 1 - Tr) and map_d as alpha; and, for Shading::Pbr on request, the
// PBR parameters (docs/appearance.md): Pm metallic, Pr roughness (else from Ns), Ke
// emissive, map_Bump / bump / norm the normal map (-bm its scale).
Material material_from(const tinyobj::material_t& m) {
  Material mat;
  mat.name = restore_spaces(m.name);
  mat.color = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
  mat.texture_file = m.diffuse_texname;  // map_Kd
  mat.texture_uv = uv_transform(m.diffuse_texopt);
  if (m.diffuse_texopt.clamp) mat.wrap = Wrap::Clamp;
  float ks = std::max({m.specular[0], m.specular[1], m.specular[2]});
  if (ks > 0) {
    mat.specular = ks;
    mat.shininess = m.shininess > 0 ? m.shininess : 32.0f;
    mat.shading = Shading::Phong;
  }
  if (std::isfinite(m.dissolve) && m.dissolve < 1) {
    mat.alpha = std::max(0.0f, float(m.dissolve));
    mat.alpha_mode = AlphaMode::Blend;
  }
  mat.alpha_file = m.alpha_texname;  // map_d
  if (!mat.alpha_file.empty()) mat.alpha_mode = AlphaMode::Blend;
  auto unit = [](float x, float fallback) { return std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : fallback; };
  mat.pbr.metallic = unit(m.metallic, 0);
  // Blinn-Phong's exponent n and GGX's alpha = roughness^2 match at alpha^2 = 2 / (n + 2).
  const float ns = std::isfinite(m.shininess) ? std::max(0.0f, float(m.shininess)) : 0.0f;
  mat.pbr.roughness = m.roughness > 0 ? unit(m.roughness, 1) : std::sqrt(std::sqrt(2 / (ns + 2)));
  mat.pbr.emissive = {unit(m.emission[0], 0), unit(m.emission[1], 0), unit(m.emission[2], 0)};
  const bool norm = !m.normal_texname.empty();
  const tinyobj::texture_option_t& normal_opt = norm ? m.normal_texopt : m.bump_texopt;
  mat.pbr.normal.file = norm ? m.normal_texname : m.bump_texname;  // norm, else map_Bump / bump
  mat.pbr.normal.uv = uv_transform(normal_opt);
  if (std::isfinite(normal_opt.bump_multiplier)) mat.pbr.normal_scale = normal_opt.bump_multiplier;
  mat.pbr.emissive_map.file = m.emissive_texname;  // map_Ke
  mat.pbr.emissive_map.uv = uv_transform(m.emissive_texopt);
  return mat;
}

// The material libraries an OBJ names ("mtllib x.mtl", relative to the OBJ's folder) are
// untrusted paths too: each is read whole through read_file, so a name such as
// /dev/zero, a FIFO or a directory is refused instead of read without end, and all of
// them together stay within the memory limit. One that cannot be read is a warning in
// tinyobjloader's sense (the faces keep no material), as before.
class BoundedMaterialReader : public tinyobj::MaterialReader {
 public:
  BoundedMaterialReader(std::string dir, size_t budget) : dir_(std::move(dir)), budget_(budget) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* map, std::string* warn, std::string* err) override {
    std::string text;
    try {
      text = detail::read_file(dir_ + name, budget_);
    } catch (const Error& e) {
      if (warn) *warn += std::string(e.what()) + "\n";
      return false;
    }
    budget_ -= text.size();
    std::istringstream in(protect_material_names(std::move(text)));
    tinyobj::LoadMtl(map, materials, &in, warn, err);
    return true;
  }

 private:
  std::string dir_;
  size_t budget_;
};

// One Velocity vertex per distinct (position, normal, uv) index triple of the file.
struct CornerKey {
  int v, n, t;
  bool operator==(const CornerKey&) const = default;
};
struct CornerHash {
  size_t operator()(const CornerKey& k) const {
    return size_t(uint32_t(k.v)) * 0x9E3779B97F4A7C15ull ^ size_t(uint32_t(k.n)) * 0xC2B2AE3D27D4EB4Full ^
           size_t(uint32_t(k.t));
  }
};

}  // namespace

Model load_obj(const std::string& path, const LoadOptions& options) {
  // Read through read_file (a missing file, a directory, a device or a file over the
  // memory limit gets a clear error), then parse from memory.
  std::string text = detail::read_file(path, options.max_memory);
  size_t slash = path.find_last_of('/');
  BoundedMaterialReader mtl_reader(slash == std::string::npos ? "" : path.substr(0, slash + 1),
                                   options.max_memory - text.size());
  std::istringstream in(protect_material_names(std::move(text)));
  tinyobj::attrib_t at;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> obj_materials;
  std::string warnings, why;
  if (!tinyobj::LoadObj(&at, &shapes, &obj_materials, &warnings, &why, &in, &mtl_reader, /*triangulate=*/true,
                        /*default_vcols_fallback=*/true)) {
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw Error(path + ": cannot read OBJ: " + (why.empty() ? "unknown error" : why));
  }
  size_t bytes = at.vertices.size() * 4 + at.normals.size() * 4 + at.texcoords.size() * 4;
  if (bytes > options.max_memory) throw Error(path + ": OBJ needs more memory than the limit allows");

  std::vector<Material> materials;
  for (const auto& m : obj_materials) materials.push_back(material_from(m));

  Model model;
  model.path = path;
  const bool has_colors = !at.colors.empty() && at.colors.size() == at.vertices.size();
  for (const tinyobj::shape_t& shape : shapes) {
    const auto& idx = shape.mesh.indices;
    if (idx.empty()) continue;
    auto mesh = std::make_shared<Mesh>();
    mesh->name = shape.name;
    // One Velocity vertex per distinct (position, normal, uv) triple.
    std::unordered_map<CornerKey, uint32_t, CornerHash> remap;
    remap.reserve(std::min(idx.size(), at.vertices.size() / 3 * 2 + 16));
    bool all_normals = true, any_uv = false;
    for (const auto& i : idx) all_normals &= i.normal_index >= 0, any_uv |= i.texcoord_index >= 0;
    auto fetch = [&](const std::vector<float>& a, int i, int n, int k) -> float {
      size_t at_i = size_t(i) * n + k;
      if (i < 0 || at_i >= a.size()) throw Error(path + ": index out of range in group '" + shape.name + "'");
      return a[at_i];
    };
    for (size_t f = 0; f + 2 < idx.size(); f += 3) {
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        const auto& i = idx[f + k];
        CornerKey key{i.vertex_index, all_normals ? i.normal_index : -1, any_uv ? i.texcoord_index : -1};
        auto [it, inserted] = remap.try_emplace(key, uint32_t(mesh->positions.size()));
        if (inserted) {
          mesh->positions.push_back({fetch(at.vertices, i.vertex_index, 3, 0), fetch(at.vertices, i.vertex_index, 3, 1),
                                     fetch(at.vertices, i.vertex_index, 3, 2)});
          if (all_normals)
            mesh->normals.push_back(normalize({fetch(at.normals, i.normal_index, 3, 0),
                                               fetch(at.normals, i.normal_index, 3, 1),
                                               fetch(at.normals, i.normal_index, 3, 2)}));
          // OBJ's `vt` has v = 0 at the image's bottom row, the engine's at the top: the
          // one place OBJ's uvs are converted (v' = 1 - v).
          if (any_uv)
            mesh->uvs.push_back(i.texcoord_index >= 0 ? Vec2{fetch(at.texcoords, i.texcoord_index, 2, 0),
                                                             1 - fetch(at.texcoords, i.texcoord_index, 2, 1)}
                                                      : Vec2{0, 1});
          if (has_colors)
            mesh->colors.push_back({fetch(at.colors, i.vertex_index, 3, 0), fetch(at.colors, i.vertex_index, 3, 1),
                                    fetch(at.colors, i.vertex_index, 3, 2)});
        }
        t.v[k] = it->second;
      }
      mesh->triangles.push_back(t);
    }
    // Materials: the shape's per-face ids, -1 meaning none.
    const auto& ids = shape.mesh.material_ids;
    bool any_material = std::any_of(ids.begin(), ids.end(), [](int m) { return m >= 0; });
    if (any_material && !materials.empty()) {
      mesh->materials = materials;
      mesh->materials.push_back(Material{});  // for faces without one
      uint32_t none = uint32_t(materials.size());
      for (size_t f = 0; f < mesh->triangles.size(); ++f) {
        int m = f < ids.size() ? ids[f] : -1;
        mesh->face_materials.push_back(m >= 0 && size_t(m) < materials.size() ? uint32_t(m) : none);
      }
    }
    // Smoothing groups (`s N`, per face) when the file has no normals.
    if (!all_normals) {
      const auto& sg = shape.mesh.smoothing_group_ids;
      bool any_group = std::any_of(sg.begin(), sg.end(), [](unsigned g) { return g != 0; });
      if (any_group && sg.size() == mesh->triangles.size())
        for (unsigned g : sg) mesh->smoothing_groups.push_back(g == 0 ? 0u : (1u << ((g - 1) % 32)));
      compute_normals(*mesh);
    }
    mesh->validate();
    model.nodes.push_back({shape.name, std::move(mesh), Mat4::identity(), -1});
  }
  if (model.nodes.empty()) throw Error(path + ": OBJ file has no faces");
  return model;
}

}  // namespace velocity
