// Every other common model format through Assimp (Debian's libassimp-dev 5.2): glTF 2.0
// (.gltf, .glb), 3D Studio (.3ds), PLY and STL (ASCII and binary both).
//
// Why Assimp for glTF too, not tinygltf (libtinygltf-dev 2.7) beside it:
//  * One adapter, from one scene structure (aiScene), is less code to write, test and
//    keep than two; 3DS, PLY and STL need Assimp anyway. With tinygltf, Velocity would
//    decode accessors itself (component types, strides, normalisation, sparse storage,
//    strip and fan modes): several hundred lines more, each a place for a bug.
//  * Assimp 5.2's glTF 2.0 importer has what Velocity draws: the node hierarchy (TRS or
//    matrix), base-colour factor and texture, COLOR_0, perspective and orthographic
//    cameras, .glb and embedded buffers; it rejects the broken files of its own test
//    suite with a clear message, checks accessors against their buffers, and came
//    through thousands of truncated and byte-mutated .gltf and .glb files.
//  * Its weak points are known and bounded here: two structural attacks on its JSON
//    handling are stopped by io/gltf_check.hpp (a check tinygltf would have needed
//    too, for the node trees), and its camera quirks are undone below.
//  * Build weight: Debian ships Assimp as a shared library (with zlib, minizip and
//    draco), so the build costs its headers only; tinygltf would add a second JSON and
//    image-decoding stack for one format.
//
// What this file does around Assimp, because Assimp 5.2.5 does not:
//  * PLY files are checked whole before Assimp sees them (io/ply_check.hpp: its reader
//    hangs, over-allocates or crashes on damaged files).
//  * glTF JSON is checked first too, and Assimp reads a copy without skins, animations
//    and morph targets (io/gltf_check.hpp: Assimp's parser overflows the stack on deep
//    nesting, a node shared by two parents is copied once per path, which grows
//    exponentially, and some damaged or unusual files crash it).
//  * ASCII STL files are parsed whole first (io/stl_check.hpp: Assimp reads a damaged
//    or truncated one as far as it can, silently, and leaks memory on some).
//  * 3D Studio files' chunks are walked first (io/tds_check.hpp: Assimp allocates
//    whatever a damaged keyframe count asks for).
//  * Faces are checked before triangulation (aiProcess_Triangulate aborts the process
//    on a face with no corners), so ReadFile runs without it and it is applied after.
//  * LoadOptions::max_memory bounds the bytes of every file Assimp opens (a .gltf's .bin
//    buffers included) and the size of the meshes built from them.
//  * 3D Studio cameras are left out: Assimp loses their target (see convert_scene).
//
// Mapping to Velocity: one ModelNode per aiNode, the root included (3D Studio puts its
// Z-up to Y-up turn there), in depth-first order so parents come first; a node's
// aiMeshes (a glTF mesh's primitives, one material each) are merged into one Mesh with
// per-face materials, shared between nodes that use the same aiMeshes. Normals come from
// the file when every one is usable, else compute_normals(); uvs from channels 0 and 1
// (see engine_uv), tangents with glTF's handedness; colours and alphas from colour set
// 0 (as the file has them: a glTF material's base colour is not multiplied in). A glTF
// file's materials and lights are read from its JSON (io/gltf_appearance.hpp), the
// other formats' materials from Assimp's. Points (point clouds) become triangles with one
// corner three times under a Shading::Points material; lines are dropped.
// Assimp and Velocity both take counter-clockwise triangles as front; under a node
// whose world matrix mirrors (negative determinant) the winding is reversed, as glTF
// specifies.
#include <assimp/DefaultIOSystem.h>
#include <assimp/IOStream.hpp>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/gltf_appearance.hpp"
#include "io/gltf_check.hpp"
#include "io/ply_check.hpp"
#include "io/read_file.hpp"
#include "io/stl_check.hpp"
#include "io/tds_check.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"

namespace velocity {

namespace {

// --- reading -------------------------------------------------------------------------

// A file Assimp reads from memory: the checked and trimmed glTF (see gltf_check.hpp).
class MemoryStream : public Assimp::IOStream {
 public:
  explicit MemoryStream(std::shared_ptr<const std::string> data) : data_(std::move(data)) {}
  size_t Read(void* out, size_t size, size_t count) override {
    if (size == 0) return 0;
    size_t n = std::min(count, (data_->size() - pos_) / size);
    std::memcpy(out, data_->data() + pos_, n * size);
    pos_ += n * size;
    return n;
  }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  // Offsets from the current position may be negative (wrapped round, as fseek's
  // long); from the end, Assimp's own streams count backwards either way.
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const int64_t size = int64_t(data_->size()), delta = int64_t(offset);
    int64_t target = origin == aiOrigin_SET ? delta
                     : origin == aiOrigin_CUR ? int64_t(pos_) + delta
                                              : size - (delta < 0 ? -delta : delta);
    if (origin == aiOrigin_SET && offset > data_->size()) return aiReturn_FAILURE;
    if (target < 0 || target > size) return aiReturn_FAILURE;
    pos_ = size_t(target);
    return aiReturn_SUCCESS;
  }
  size_t Tell() const override { return pos_; }
  size_t FileSize() const override { return data_->size(); }
  void Flush() override {}

 private:
  std::shared_ptr<const std::string> data_;
  size_t pos_ = 0;
};

// Assimp's default file access, counting the bytes of every distinct file opened (the
// model, a glTF's buffers) against the memory limit, and serving the model file itself
// from memory when it was rewritten before import. Assimp opens a file several times
// (to detect the format, then to read it); each is counted once.
class LimitedIOSystem : public Assimp::DefaultIOSystem {
 public:
  LimitedIOSystem(size_t limit, const std::string& model, std::shared_ptr<const std::string> replacement)
      : limit_(limit), model_(canonical(model)), replacement_(std::move(replacement)) {}

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    Assimp::IOStream* stream = nullptr;
    size_t size = 0;
    if (replacement_ && canonical(file) == model_) {
      stream = new MemoryStream(replacement_);
      std::error_code ec;  // counted as the larger of the file and what replaces it
      uintmax_t on_disk = std::filesystem::file_size(file, ec);
      size = std::max<size_t>(replacement_->size(), ec ? 0 : size_t(on_disk));
    } else {
      stream = DefaultIOSystem::Open(file, mode);
      if (stream) size = stream->FileSize();
    }
    if (!stream) return nullptr;
    size_t& counted = sizes_[file];
    if (size > counted) {
      if (size - counted > limit_ - used_) {
        Close(stream);
        refused_ = std::string(file) + " (" + std::to_string(size) + " bytes)";
        return nullptr;
      }
      used_ += size - counted;
      counted = size;
    }
    return stream;
  }

  // The file refused for the limit, if any.
  const std::string& refused() const { return refused_; }

 private:
  static std::string canonical(const std::string& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : p.string();
  }

  size_t limit_, used_ = 0;
  std::string model_;
  std::shared_ptr<const std::string> replacement_;
  std::map<std::string, size_t> sizes_;
  std::string refused_;
};

std::string format_name(const std::string& path) {
  std::string ext = detail::lower_extension(path);
  if (ext == "gltf" || ext == "glb") return "glTF";
  if (ext == "3ds") return "3D Studio";
  if (ext == "ply") return "PLY";
  if (ext == "stl") return "STL";
  for (char& c : ext) c = (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
  return ext.empty() ? std::string("model") : ext;
}

// The checks before Assimp: existence, type and size (detail::read_file, with clearer
// messages than Assimp's "Unable to open file"), then the format checks, which need
// the bytes (Assimp reads the whole file anyway, so reading it once more is cheap).
// Returns what Assimp is to read instead of the file, if anything (a glTF file), and a
// glTF file's materials and lights (read from the JSON: io/gltf_appearance.hpp).
// A PLY file's header declares no faces (or zero): a point cloud.
bool ply_without_faces(std::string_view bytes) {
  const size_t end = bytes.find("end_header");
  const std::string_view header = bytes.substr(0, end == std::string_view::npos ? 0 : end);
  const size_t at = header.find("\nelement face ");
  if (at == std::string_view::npos) return true;
  const size_t digit = header.find_first_not_of(' ', at + 14);
  return digit < header.size() && header[digit] == '0' &&
         (digit + 1 >= header.size() || header[digit + 1] < '0' || header[digit + 1] > '9');
}

std::shared_ptr<const std::string> check_file(const std::string& path, const LoadOptions& options,
                                              std::optional<detail::GltfAppearance>& appearance, bool& point_cloud) {
  const size_t max_memory = options.max_memory;
  const std::string bytes = detail::read_file(path, max_memory);
  const std::string ext = detail::lower_extension(path);
  if (detail::looks_like_ply(bytes)) {
    detail::check_ply(bytes, path);
    point_cloud = ply_without_faces(bytes);
  }
  if (ext == "stl" && detail::is_ascii_stl(bytes)) detail::check_ascii_stl(bytes, path);
  if (ext == "3ds") detail::check_3ds(bytes, path);
  if (ext == "gltf" || ext == "glb") {
    auto prepared = std::make_shared<const std::string>(detail::prepare_gltf(bytes, path, max_memory));
    appearance = detail::read_gltf_appearance(bytes, path, options);
    return prepared;
  }
  return nullptr;
}

// Checks what the importer built before anything trusts it: array pointers, index
// ranges, node mesh references, faces with corners (Triangulate aborts on one without),
// and the memory the Velocity meshes will take.
void check_scene(const aiScene& scene, const std::string& path, size_t max_memory) {
  if (!scene.mRootNode) throw Error(path + ": the file has no scene (no root node)");
  if (scene.mNumMeshes && !scene.mMeshes) throw Error(path + ": the importer returned no mesh array");
  // Position, normal, uv and colour per vertex; corners and a material per triangle.
  constexpr size_t kVertexBytes = sizeof(Vec3) * 3 + sizeof(Vec2);
  constexpr size_t kFaceBytes = sizeof(Triangle) + sizeof(uint32_t);
  size_t bytes = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (!mesh || (mesh->mNumVertices && !mesh->mVertices) || (mesh->mNumFaces && !mesh->mFaces))
      throw Error(path + ": mesh " + std::to_string(m) + " is incomplete");
    if (mesh->mMaterialIndex >= scene.mNumMaterials)
      throw Error(path + ": mesh " + std::to_string(m) + " uses material " + std::to_string(mesh->mMaterialIndex) +
                  ", but there are only " + std::to_string(scene.mNumMaterials));
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices == 0 || !face.mIndices)
        throw Error(path + ": face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                    " has no corners (file truncated?)");
      for (unsigned k = 0; k < face.mNumIndices; ++k)
        if (face.mIndices[k] >= mesh->mNumVertices)
          throw Error(path + ": face " + std::to_string(f) + " of mesh " + std::to_string(m) + " uses vertex " +
                      std::to_string(face.mIndices[k]) + ", but there are only " + std::to_string(mesh->mNumVertices));
      // A polygon of n corners becomes n - 2 triangles.
      bytes += kFaceBytes * std::max<size_t>(1, face.mNumIndices - (face.mNumIndices > 2 ? 2 : 0));
    }
    bytes += kVertexBytes * mesh->mNumVertices;
    if (mesh->mNumFaces == 0) bytes += kFaceBytes * mesh->mNumVertices;  // a point cloud's points
    if (bytes > max_memory)
      throw Error(path + ": the meshes need more than the limit of " + std::to_string(max_memory) +
                  " bytes (LoadOptions::max_memory)");
  }
  std::vector<const aiNode*> stack{scene.mRootNode};
  while (!stack.empty()) {
    const aiNode* node = stack.back();
    stack.pop_back();
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      if (node->mMeshes[i] >= scene.mNumMeshes)
        throw Error(path + ": node '" + node->mName.C_Str() + "' uses mesh " + std::to_string(node->mMeshes[i]) +
                    ", but there are only " + std::to_string(scene.mNumMeshes));
    for (unsigned i = 0; i < node->mNumChildren; ++i)
      if (node->mChildren[i]) stack.push_back(node->mChildren[i]);
  }
}

// --- conversion ----------------------------------------------------------------------

// aiMatrix4x4 is row-major with the translation in a4, b4, c4: Velocity's layout.
Mat4 to_mat4(const aiMatrix4x4& a) {
  Mat4 m;
  const float* src = &a.a1;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m.m[r][c] = src[r * 4 + c];
  return m;
}

float determinant3(const Mat4& a) {
  const auto& m = a.m;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
float clamp01(float x) { return x > 0 ? (x < 1 ? x : 1) : 0; }  // NaN -> 0
Vec3 to_vec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

Material convert_material(const aiMaterial& in) {
  Material m;
  aiString name;
  if (in.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
  // glTF's base colour (Assimp copies it to the diffuse colour too); else the diffuse.
  aiColor4D color;
  if (in.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS || in.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS)
    m.color = {clamp01(color.r), clamp01(color.g), clamp01(color.b)};
  // A highlight needs an exponent: a specular colour alone (Assimp's PLY and STL default
  // material has white) is not one.
  float shininess = 0, strength = 1;
  aiColor4D specular(0, 0, 0, 0);
  in.Get(AI_MATKEY_SHININESS_STRENGTH, strength);
  if (in.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0 &&
      in.Get(AI_MATKEY_COLOR_SPECULAR, specular) == AI_SUCCESS) {
    float ks = std::max({specular.r, specular.g, specular.b}) * strength;
    if (ks > 0 && std::isfinite(ks)) {
      m.specular = std::min(ks, 1.0f);
      m.shininess = std::min(shininess, 1024.0f);
    }
  }
  int model = 0;
  in.Get(AI_MATKEY_SHADING_MODEL, model);
  if (model == aiShadingMode_Flat) m.shading = Shading::Flat;
  else if (model == aiShadingMode_NoShading) m.shading = Shading::Unlit;  // glTF KHR_materials_unlit
  else if (model == aiShadingMode_Phong || model == aiShadingMode_Blinn || m.specular > 0) m.shading = Shading::Phong;
  int two_sided = 0;
  if (in.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) m.two_sided = two_sided != 0;
  // For --shading pbr (docs/appearance.md): a dielectric whose roughness matches the
  // Phong exponent (GGX alpha = roughness^2, alpha^2 = 2 / (n + 2)), the emissive colour.
  m.pbr.metallic = 0;
  m.pbr.roughness = std::sqrt(std::sqrt(2 / (std::max(0.0f, std::isfinite(shininess) ? shininess : 0.0f) + 2)));
  aiColor4D emissive(0, 0, 0, 0);
  if (in.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS)
    m.pbr.emissive = {clamp01(emissive.r), clamp01(emissive.g), clamp01(emissive.b)};
  // The base-colour texture's file name; load_model resolves and loads it. A "*N" name
  // is an image embedded in aiScene::mTextures, not read yet (resolve_texture_path
  // gives "" for it, so it is reported as not found).
  aiString texture;
  if (in.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
      in.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS)
    m.texture_file = texture.C_Str();
  return m;
}

// The vertex arrays a node's merged mesh has: each filled for every part when one part
// has it (tangents only when every part has them: there is no default tangent).
struct Channels {
  bool uvs = false, uvs1 = false, colors = false, alphas = false, tangents = true;
};

// Texture coordinates: Assimp gives every format's with v = 0 at the image's bottom row
// (OpenGL's convention: it flips glTF's, whose v = 0 is the top row; 3D Studio's and
// PLY's are v up already). The engine's v = 0 is the top row (Mesh::uvs), so this is
// the one place that turns them for glTF, 3D Studio and PLY: v' = 1 - v.
Vec2 engine_uv(const aiVector3D& t) {
  return {std::isfinite(t.x) ? t.x : 0.0f, std::isfinite(t.y) ? 1.0f - t.y : 0.0f};
}

// One aiMesh as a Velocity mesh: its triangles, its vertices, normals computed when the
// file's are missing or unusable. `with`: the arrays to fill even when this part has
// none, because a sibling part of the same node has them.
Mesh convert_part(const aiMesh& in, const Material& material, const Channels& with, const std::string& path) {
  Mesh part;
  part.name = in.mName.C_Str();
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices == 3) part.triangles.push_back({{face.mIndices[0], face.mIndices[1], face.mIndices[2]}});
    // A point (a point cloud: PLY without faces, glTF POINTS) is a triangle with one
    // corner three times, drawn by Shading::Points.
    if (face.mNumIndices == 1) part.triangles.push_back({{face.mIndices[0], face.mIndices[0], face.mIndices[0]}});
  }
  if (in.mNumFaces == 0)  // a PLY point cloud: every vertex a point
    for (uint32_t v = 0; v < in.mNumVertices; ++v) part.triangles.push_back({{v, v, v}});
  const unsigned nv = in.mNumVertices;
  part.positions.resize(nv);
  for (unsigned v = 0; v < nv; ++v) {
    part.positions[v] = to_vec3(in.mVertices[v]);
    if (!finite(part.positions[v]))
      throw Error(path + ": vertex " + std::to_string(v) + " of mesh '" + part.name + "' has a coordinate that is " +
                  "not a finite number");
  }
  bool normals_ok = in.mNormals != nullptr;
  for (unsigned v = 0; normals_ok && v < nv; ++v) {
    Vec3 n = to_vec3(in.mNormals[v]);
    normals_ok = finite(n) && dot(n, n) > 1e-12f;
  }
  if (normals_ok) {
    part.normals.resize(nv);
    for (unsigned v = 0; v < nv; ++v) part.normals[v] = normalize(to_vec3(in.mNormals[v]));
  }
  if (with.uvs) {
    part.uvs.resize(nv);
    if (in.mTextureCoords[0])
      for (unsigned v = 0; v < nv; ++v) part.uvs[v] = engine_uv(in.mTextureCoords[0][v]);
  }
  if (with.uvs1) {
    part.uvs1.resize(nv);
    if (in.mTextureCoords[1])
      for (unsigned v = 0; v < nv; ++v) part.uvs1[v] = engine_uv(in.mTextureCoords[1][v]);
  }
  if (with.colors) {
    part.colors.assign(nv, material.color);
    if (in.mColors[0])
      for (unsigned v = 0; v < nv; ++v) {
        const aiColor4D& c = in.mColors[0][v];
        part.colors[v] = {clamp01(c.r), clamp01(c.g), clamp01(c.b)};
      }
  }
  if (with.alphas) {
    part.alphas.assign(nv, 1.0f);
    if (in.mColors[0])
      for (unsigned v = 0; v < nv; ++v) part.alphas[v] = std::isnan(in.mColors[0][v].a) ? 1.0f : clamp01(in.mColors[0][v].a);
  }
  if (with.tangents && normals_ok) {
    // glTF's TANGENT is xyz and a handedness w; Assimp keeps xyz and makes the
    // bitangent (N x T) w, so w is the sign of B . (N x T).
    part.tangents.resize(nv);
    for (unsigned v = 0; v < nv; ++v) {
      const Vec3 n = part.normals[v], t = to_vec3(in.mTangents[v]);
      const Vec3 b = in.mBitangents ? to_vec3(in.mBitangents[v]) : cross(n, t);
      const Vec3 tn = finite(t) && dot(t, t) > 1e-12f ? normalize(t) : Vec3{1, 0, 0};
      part.tangents[v] = {tn.x, tn.y, tn.z, dot(b, cross(n, t)) < 0 ? -1.0f : 1.0f};
    }
  }
  if (!normals_ok) compute_normals(part);
  return part;
}

void append(Mesh& to, const Mesh& part, uint32_t material) {
  const uint32_t base = uint32_t(to.positions.size());
  to.positions.insert(to.positions.end(), part.positions.begin(), part.positions.end());
  to.normals.insert(to.normals.end(), part.normals.begin(), part.normals.end());
  to.uvs.insert(to.uvs.end(), part.uvs.begin(), part.uvs.end());
  to.uvs1.insert(to.uvs1.end(), part.uvs1.begin(), part.uvs1.end());
  to.tangents.insert(to.tangents.end(), part.tangents.begin(), part.tangents.end());
  to.colors.insert(to.colors.end(), part.colors.begin(), part.colors.end());
  to.alphas.insert(to.alphas.end(), part.alphas.begin(), part.alphas.end());
  for (Triangle t : part.triangles) {
    for (uint32_t& v : t.v) v += base;
    to.triangles.push_back(t);
    to.face_materials.push_back(material);
  }
}

// The Velocity mesh of a node: its aiMeshes merged, each with its own material.
std::shared_ptr<Mesh> convert_node_meshes(const aiScene& scene, const aiNode& node, bool mirrored,
                                          const std::vector<Material>& materials, const std::string& path) {
  auto has_triangles = [](const aiMesh& m) {
    if (m.mNumFaces == 0) return m.mNumVertices > 0;  // a point cloud
    for (unsigned f = 0; f < m.mNumFaces; ++f)
      if (m.mFaces[f].mNumIndices == 3 || m.mFaces[f].mNumIndices == 1) return true;
    return false;
  };
  auto only_points = [](const aiMesh& m) {
    for (unsigned f = 0; f < m.mNumFaces; ++f)
      if (m.mFaces[f].mNumIndices != 1) return false;
    return true;
  };
  std::vector<const aiMesh*> parts;
  Channels with;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh* m = scene.mMeshes[node.mMeshes[i]];
    if (!has_triangles(*m)) continue;
    parts.push_back(m);
    with.uvs |= m->mTextureCoords[0] != nullptr;
    with.uvs1 |= m->mTextureCoords[1] != nullptr;
    with.colors |= m->mColors[0] != nullptr;
    with.tangents &= m->mTangents != nullptr;
    for (unsigned v = 0; m->mColors[0] && v < m->mNumVertices && !with.alphas; ++v) with.alphas = m->mColors[0][v].a < 1;
  }
  if (parts.empty()) return nullptr;

  auto mesh = std::make_shared<Mesh>();
  mesh->name = parts.size() == 1 && parts[0]->mName.length ? parts[0]->mName.C_Str() : node.mName.C_Str();
  // (aiMaterial index, a point cloud) -> index in mesh->materials
  std::map<std::pair<unsigned, bool>, uint32_t> slot_of;
  for (const aiMesh* m : parts) {
    const bool points = only_points(*m);
    auto [it, added] = slot_of.try_emplace({m->mMaterialIndex, points}, uint32_t(mesh->materials.size()));
    if (added) {
      mesh->materials.push_back(materials[m->mMaterialIndex]);
      if (points) mesh->materials.back().shading = Shading::Points;
    }
    Mesh part = convert_part(*m, mesh->materials[it->second], with, path);
    // Normals are all from the file or all computed per part: compute_normals may have
    // split vertices, so the arrays are appended as they are now.
    append(*mesh, part, it->second);
  }
  // A part whose normals were computed has no tangents (the file's would not fit them).
  if (mesh->tangents.size() != mesh->positions.size()) mesh->tangents.clear();
  if (mesh->materials.size() == 1) mesh->face_materials.clear();
  if (mirrored)
    for (Triangle& t : mesh->triangles) std::swap(t.v[1], t.v[2]);
  mesh->validate();
  return mesh;
}

// Yaw, pitch and roll of a camera whose placement turns -Z to `forward` and +Y to `up`
// (Camera's placement is Ry(yaw) Rx(pitch) Rz(roll)). With Z = -forward, Y = up made
// orthogonal and X = Y x Z as the columns of R:
//   R[0][2] = sin(yaw) cos(pitch), R[1][2] = -sin(pitch), R[2][2] = cos(yaw) cos(pitch),
//   R[1][0] = cos(pitch) sin(roll), R[1][1] = cos(pitch) cos(roll).
void set_orientation(Camera& cam, Vec3 forward, Vec3 up) {
  Vec3 z = -normalize(forward);
  if (dot(z, z) == 0) z = {0, 0, 1};
  Vec3 y = up - z * dot(up, z);
  if (dot(y, y) < 1e-12f) y = std::abs(z.y) < 0.9f ? Vec3{0, 1, 0} - z * z.y : Vec3{0, 0, -1} - z * (-z.z);
  y = normalize(y);
  Vec3 x = cross(y, z);
  cam.pitch = std::asin(std::clamp(-z.y, -1.0f, 1.0f));
  cam.yaw = std::atan2(z.x, z.z);
  cam.roll = std::atan2(x.y, y.y);
}

NamedCamera convert_camera(const aiCamera& in, const aiNode* node, const Mat4& world, bool gltf) {
  NamedCamera out;
  out.name = in.mName.C_Str();
  Camera& cam = out.camera;
  Vec3 position = to_vec3(in.mPosition);
  if (node) {
    // Assimp 5.2.5's glTF 2.0 importer (and its 3DS one) puts the camera node's
    // translation in mPosition as well as in the node (Cameras.gltf: node at
    // (0.5, 0.5, 3), mPosition (0.5, 0.5, 3)); applying both would count it twice.
    const aiMatrix4x4& t = node->mTransformation;
    Vec3 d = position - Vec3{t.a4, t.b4, t.c4};
    if (dot(position, position) > 0 && dot(d, d) <= 1e-10f * std::max(1.0f, dot(position, position)))
      position = {};
  }
  cam.position = world.transform_point(position);
  set_orientation(cam, world.transform_vector(to_vec3(in.mLookAt)), world.transform_vector(to_vec3(in.mUp)));

  const float aspect = in.mAspect > 0 && std::isfinite(in.mAspect) ? in.mAspect : 1.0f;
  if (in.mHorizontalFOV == 0 && in.mOrthographicWidth > 0) {
    // mOrthographicWidth is half the view's width (glTF's xmag).
    cam.projection = Projection::Orthographic;
    cam.ortho_height = 2 * in.mOrthographicWidth / aspect;
  } else {
    // glTF stores the vertical field of view; Assimp 5.2 reports yfov * aspect as the
    // horizontal one (not the 2 atan(aspect tan(yfov / 2)) it is), so divide back. The
    // other formats give a true horizontal angle.
    float fov = gltf ? in.mHorizontalFOV / aspect : 2 * std::atan(std::tan(in.mHorizontalFOV / 2) / aspect);
    if (std::isfinite(fov) && fov > 0 && fov < 3.1f) cam.fov_y = fov;
  }
  if (in.mClipPlaneNear > 0 && std::isfinite(in.mClipPlaneNear)) cam.near = in.mClipPlaneNear;
  if (in.mClipPlaneFar > cam.near && std::isfinite(in.mClipPlaneFar))
    cam.far = in.mClipPlaneFar;
  else
    cam.far = std::max(cam.far, cam.near * 1000);
  return out;
}

Model convert_scene(const aiScene& scene, const std::string& path, const detail::GltfAppearance* gltf_appearance) {
  Model model;
  model.path = path;
  std::vector<Material> materials;
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    if (gltf_appearance) {
      // The material Velocity read, by the index prepare_gltf put in its name (Assimp's
      // order is its own); Assimp's default material has no such name.
      const auto& own = gltf_appearance->materials;
      const std::string name = scene.mMaterials[i] ? scene.mMaterials[i]->GetName().C_Str() : "";
      const std::string_view tag = detail::kMaterialTag;
      size_t index = own.size() - 1;
      if (name.size() > tag.size() && name.compare(0, tag.size(), tag) == 0)
        index = std::min<size_t>(std::strtoull(name.c_str() + tag.size(), nullptr, 10), own.size() - 1);
      materials.push_back(own[index]);
    } else {
      materials.push_back(scene.mMaterials[i] ? convert_material(*scene.mMaterials[i]) : Material{});
    }
  }
  if (gltf_appearance) model.lights = gltf_appearance->lights;

  // Depth first, parents before children; world matrices for the winding and cameras.
  struct Pending {
    const aiNode* node;
    int parent;
  };
  std::vector<Pending> stack{{scene.mRootNode, -1}};
  std::vector<Mat4> world;
  std::map<const aiNode*, size_t> index_of;
  std::map<std::pair<std::vector<unsigned>, bool>, std::shared_ptr<Mesh>> built;  // shared instances
  size_t dropped = 0;
  std::map<size_t, size_t> model_node_of_gltf;  // animated nodes
  while (!stack.empty()) {
    auto [node, parent] = stack.back();
    stack.pop_back();
    ModelNode out;
    out.name = node->mName.C_Str();
    // A node an animation moves: its glTF index and its own name (prepare_gltf's tag).
    if (const std::string_view tag = detail::kNodeTag;
        gltf_appearance && out.name.size() > tag.size() && out.name.compare(0, tag.size(), tag) == 0) {
      char* end = nullptr;
      const size_t gltf_index = std::strtoull(out.name.c_str() + tag.size(), &end, 10);
      if (end && *end == ':') {
        model_node_of_gltf[gltf_index] = model.nodes.size();
        out.name = end + 1;
        if (out.name.empty()) out.name = "node " + std::to_string(gltf_index);
      }
    }
    out.local = to_mat4(node->mTransformation);
    out.parent = parent;
    world.push_back(parent < 0 ? out.local : world[size_t(parent)] * out.local);
    if (node->mNumMeshes) {
      bool mirrored = determinant3(world.back()) < 0;
      std::vector<unsigned> key(node->mMeshes, node->mMeshes + node->mNumMeshes);
      auto& mesh = built[{key, mirrored}];
      if (!mesh) mesh = convert_node_meshes(scene, *node, mirrored, materials, path);
      out.mesh = mesh;
      for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        const aiMesh* m = scene.mMeshes[node->mMeshes[i]];
        for (unsigned f = 0; f < m->mNumFaces; ++f) dropped += m->mFaces[f].mNumIndices == 2;
      }
    }
    index_of[node] = model.nodes.size();
    model.nodes.push_back(std::move(out));
    const int me = int(model.nodes.size() - 1);
    for (unsigned i = node->mNumChildren; i-- > 0;)  // reversed: children pop in file order
      if (node->mChildren[i]) stack.push_back({node->mChildren[i], me});
  }
  if (model.triangle_count() == 0)
    throw Error(path + ": the file has no triangles" +
                (dropped ? " (only " + std::to_string(dropped) + " lines, which Velocity does not draw)"
                         : std::string()));
  if (dropped)
    warn(path + ": " + std::to_string(dropped) + " lines dropped (Velocity draws triangles and points only)");

  // Animations, moving Model nodes (a node outside the scene shown is not moved). Morph
  // targets get the node's mesh as their base: its vertices are the primitives' in order,
  // so a count that differs (a primitive of lines left out) means they do not fit.
  std::map<const MorphTargets*, std::shared_ptr<const MorphTargets>> based;
  if (gltf_appearance)
    for (Animation a : gltf_appearance->animations) {
      std::erase_if(a.nodes, [&](NodeAnimation& n) {
        auto it = model_node_of_gltf.find(n.node);
        if (it == model_node_of_gltf.end()) return true;
        n.node = it->second;
        return false;
      });
      std::erase_if(a.morphs, [&](MorphAnimation& m) {
        auto it = model_node_of_gltf.find(m.node);
        if (it == model_node_of_gltf.end() || !m.targets) return true;
        m.node = it->second;
        const std::shared_ptr<Mesh>& mesh = model.nodes[m.node].mesh;
        auto [at, fresh] = based.try_emplace(m.targets.get());
        std::shared_ptr<const MorphTargets>& with_base = at->second;
        if (fresh && mesh) {
          auto t = std::make_shared<MorphTargets>(*m.targets);
          t->base = mesh;
          bool fits = true;
          for (const auto& offsets : t->positions) fits &= offsets.size() == mesh->positions.size();
          if (fits) with_base = std::move(t);
          else warn(path + ": node \"" + model.nodes[m.node].name + "\": its morph targets do not match its mesh's " +
                    std::to_string(mesh->positions.size()) + " vertices (not morphed)");
        }
        if (!with_base) return true;
        m.targets = with_base;
        return false;
      });
      if (!a.nodes.empty() || !a.morphs.empty()) model.animations.push_back(std::move(a));
    }
  // Skins: the skinned node's mesh is the bind pose (its vertices the primitives' in order).
  if (gltf_appearance)
    for (Skin skin : gltf_appearance->skins) {
      auto it = model_node_of_gltf.find(skin.node);
      if (it == model_node_of_gltf.end() || !model.nodes[it->second].mesh) continue;
      skin.node = it->second;
      skin.base = model.nodes[skin.node].mesh;
      bool found = true;
      for (size_t& j : skin.joints) {
        auto joint = model_node_of_gltf.find(j);
        found &= joint != model_node_of_gltf.end();
        if (found) j = joint->second;
      }
      if (!found) continue;  // a joint outside the scene shown
      if (skin.vertex_joints.size() != skin.base->positions.size()) {
        warn(path + ": node \"" + model.nodes[skin.node].name + "\": its skin does not match its mesh's " +
             std::to_string(skin.base->positions.size()) + " vertices (not skinned)");
        continue;
      }
      model.skins.push_back(std::move(skin));
    }

  const std::string ext = detail::lower_extension(path);
  const bool gltf = ext == "gltf" || ext == "glb";
  // Assimp 5.2.5's 3DS reader loses a camera's target (every camera looks along its
  // node's +Z, straight up once the root turns Z up to Y up) and takes the lens in mm
  // for an angle in degrees: such a camera would mislead, so none is made.
  if (ext == "3ds" && scene.mNumCameras) {
    warn(path + ": " + std::to_string(scene.mNumCameras) +
         " 3D Studio camera(s) not converted (Assimp 5.2 loses their target)");
    return model;
  }
  for (unsigned i = 0; i < scene.mNumCameras; ++i) {
    if (!scene.mCameras[i]) continue;
    const aiNode* node = scene.mRootNode->FindNode(scene.mCameras[i]->mName);
    auto it = node ? index_of.find(node) : index_of.end();
    Mat4 m = it == index_of.end() ? Mat4::identity() : world[it->second];
    model.cameras.push_back(convert_camera(*scene.mCameras[i], node, m, gltf));
  }
  return model;
}

}  // namespace

Model load_with_assimp(const std::string& path, const LoadOptions& options) {
  // Only the formats tested here (tests/unit/test_formats.cpp, truncated and mutated
  // files included): Assimp's other readers have not been through that.
  const std::string ext = detail::lower_extension(path);
  if (ext != "gltf" && ext != "glb" && ext != "3ds" && ext != "ply" && ext != "stl")
    throw Error(path + ": '" + ext + "' is not a format read through Assimp (expected .gltf, .glb, .3ds, .ply or .stl)");
  std::optional<detail::GltfAppearance> appearance;
  bool point_cloud = false;
  std::shared_ptr<const std::string> replacement = check_file(path, options, appearance, point_cloud);
  const std::string format = format_name(path);
  try {
    Assimp::Importer importer;
    auto* io = new LimitedIOSystem(options.max_memory, path, replacement);
    importer.SetIOHandler(io);  // the importer owns and deletes it
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    // A PLY point cloud's mesh has no faces, which Assimp's validation refuses; the file
    // was checked whole (check_ply) and check_scene checks what Assimp built.
    const aiScene* scene = importer.ReadFile(path, point_cloud ? 0u : unsigned(aiProcess_ValidateDataStructure));
    if (!scene) {
      if (!io->refused().empty())
        throw Error(path + ": " + io->refused() + " would take the files read past the limit of " +
                    std::to_string(options.max_memory) + " bytes (LoadOptions::max_memory)");
      std::string why = importer.GetErrorString();
      while (!why.empty() && (why.back() == '\n' || why.back() == '\r' || why.back() == ' ')) why.pop_back();
      throw Error(path + ": cannot read " + format + " file: " + (why.empty() ? "unknown error" : why));
    }
    check_scene(*scene, path, options.max_memory);
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
    if (!scene) throw Error(path + ": cannot triangulate: " + std::string(importer.GetErrorString()));
    return convert_scene(*scene, path, appearance ? &*appearance : nullptr);
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw Error(path + ": out of memory reading the " + format + " file");
  } catch (const std::exception& e) {
    throw Error(path + ": cannot read " + format + " file: " + e.what());
  }
}

}  // namespace velocity
