// The glTF check (see gltf_check.hpp for why it exists), on nlohmann::json (Debian's
// nlohmann-json3-dev, header-only): measure the nesting depth with a scan (so that no
// parser ever recurses deeply), parse, validate the node graph and the images' media
// types, drop skins, animations and morph targets, and write the file out again.
#include "io/gltf_check.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include "velocity/error.hpp"

namespace velocity::detail {

namespace {

using nlohmann::json;

constexpr int kMaxDepth = 64;  // real files nest about 8 deep ("extensions" included)

uint32_t read_u32(std::string_view b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}

// The JSON text: the whole of a .gltf, the first chunk of a .glb (12-byte header
// "glTF", version, length; then chunk length, type "JSON", data).
std::string_view json_text(std::string_view bytes, const std::string& path) {
  if (bytes.size() < 4 || bytes.substr(0, 4) != "glTF") return bytes;
  if (bytes.size() < 20) throw Error(path + ": GLB file is " + std::to_string(bytes.size()) + " bytes, too short");
  if (read_u32(bytes, 4) != 2)
    throw Error(path + ": GLB version " + std::to_string(read_u32(bytes, 4)) + " (expected 2)");
  uint32_t length = read_u32(bytes, 12);
  if (bytes.substr(16, 4) != "JSON") throw Error(path + ": GLB's first chunk is not JSON");
  if (length > bytes.size() - 20)
    throw Error(path + ": GLB's JSON chunk of " + std::to_string(length) + " bytes runs past the end of the file");
  return bytes.substr(20, length);
}

void check_depth(std::string_view text, const std::string& path) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;  // skip the escaped character
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDepth)
        throw Error(path + ": glTF JSON nests deeper than " + std::to_string(kMaxDepth) + " levels (at byte " +
                    std::to_string(i) + ")");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// An index into an array of `size`, or an error saying what `what` should have been.
size_t index_of(const json& v, size_t size, const std::string& what, const std::string& path) {
  if (!v.is_number_integer() || v.get<int64_t>() < 0 || uint64_t(v.get<int64_t>()) >= size)
    throw Error(path + ": " + what + " is " + v.dump() + ", expected a node index below " + std::to_string(size));
  return size_t(v.get<int64_t>());
}

const json* member(const json& object, const char* key, json::value_t type, const std::string& where,
                   const std::string& path) {
  auto it = object.find(key);
  if (it == object.end()) return nullptr;
  if (it->type() != type)
    throw Error(path + ": " + where + "\"" + key + "\" is " + it->type_name() + ", expected " +
                json(type).type_name());
  return &*it;
}

// Element `i` of the array `list`, which must be an object; `where` begins the message.
const json& object_at(const json& list, size_t i, const std::string& where, const std::string& path) {
  const json& item = list[i];
  if (!item.is_object()) throw Error(path + ": " + where + "is " + item.type_name() + ", expected an object");
  return item;
}

void check_nodes(const json& root, const std::string& path) {
  std::vector<int64_t> parent;
  std::vector<std::vector<size_t>> children;
  if (const json* nodes = member(root, "nodes", json::value_t::array, "", path)) {
    const size_t n = nodes->size();
    parent.assign(n, -1);
    children.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const std::string where = "node " + std::to_string(i) + ": ";
      const json& node = object_at(*nodes, i, where, path);
      const json* list = member(node, "children", json::value_t::array, where, path);
      if (!list) continue;
      for (const json& c : *list) {
        size_t child = index_of(c, n, "a child of node " + std::to_string(i), path);
        if (child == i) throw Error(path + ": node " + std::to_string(i) + " lists itself as a child");
        if (parent[child] >= 0)
          throw Error(path + ": node " + std::to_string(child) + " is a child of both node " +
                      std::to_string(parent[child]) + " and node " + std::to_string(i) +
                      " (glTF nodes must form trees)");
        parent[child] = int64_t(i);
        children[i].push_back(child);
      }
    }
    // Every node has at most one parent now; walking down from the roots reaches every
    // node unless some are on a cycle.
    std::vector<size_t> stack;
    for (size_t i = 0; i < n; ++i)
      if (parent[i] < 0) stack.push_back(i);
    size_t reached = 0;
    while (!stack.empty()) {
      size_t i = stack.back();
      stack.pop_back();
      ++reached;
      stack.insert(stack.end(), children[i].begin(), children[i].end());
    }
    if (reached != n) throw Error(path + ": the nodes' children form a cycle (glTF nodes must form trees)");
  }
  if (const json* scenes = member(root, "scenes", json::value_t::array, "", path)) {
    for (size_t s = 0; s < scenes->size(); ++s) {
      const std::string where = "scene " + std::to_string(s) + ": ";
      const json& scene = object_at(*scenes, s, where, path);
      const json* list = member(scene, "nodes", json::value_t::array, where, path);
      if (!list) continue;
      std::vector<bool> listed(parent.size(), false);
      for (const json& v : *list) {
        size_t node = index_of(v, parent.size(), "a node of scene " + std::to_string(s), path);
        if (parent[node] >= 0)
          throw Error(path + ": scene " + std::to_string(s) + " lists node " + std::to_string(node) +
                      ", which is a child of node " + std::to_string(parent[node]) + " (scenes list root nodes)");
        if (listed[node])
          throw Error(path + ": scene " + std::to_string(s) + " lists node " + std::to_string(node) + " twice");
        listed[node] = true;
      }
    }
  }
}

// Assimp takes an embedded image's file extension from after the '/' of its media type
// ("image/png") without checking that there is one, and crashes when there is not
// (mimeType "imagepng", or a data URI "data:imagepng;base64,...").
void check_images(const json& root, const std::string& path) {
  const json* images = member(root, "images", json::value_t::array, "", path);
  if (!images) return;
  for (size_t i = 0; i < images->size(); ++i) {
    const std::string where = "image " + std::to_string(i) + ": ";
    const json& image = object_at(*images, i, where, path);
    std::string type;
    if (const json* mime = member(image, "mimeType", json::value_t::string, where, path)) type = mime->get<std::string>();
    if (const json* uri = member(image, "uri", json::value_t::string, where, path)) {
      const std::string& u = uri->get_ref<const std::string&>();
      // "data:image/png;base64,...": the media type runs to the first ';' or ','.
      if (u.rfind("data:", 0) == 0) type = u.substr(5, std::min(u.find_first_of(";,"), u.size()) - 5);
    }
    if (!type.empty() && type.find('/') == std::string::npos)
      throw Error(path + ": " + where + "media type '" + type + "' is not TYPE/SUBTYPE (such as image/png)");
  }
}

// The extensions Assimp is let read: those that change what Velocity draws. Any other
// is removed (a damaged KHR_texture_transform aborts Assimp: it reads the numbers
// without checking that they are numbers).
bool kept_extension(const std::string& name) {
  return name == "KHR_materials_unlit" || name == "KHR_materials_pbrSpecularGlossiness" ||
         name == "KHR_mesh_quantization" || name == "KHR_draco_mesh_compression";
}

// The extensions Velocity reads from the JSON itself (io/gltf_appearance.hpp), which
// Assimp's copy goes without.
bool read_by_velocity(const std::string& name) {
  return name == "KHR_texture_transform" || name == "KHR_lights_punctual" || name == "KHR_materials_emissive_strength";
}

// Removes "extras" (free-form application data) and the extensions not kept, and
// checks that every array holds values of one type, as every array of the glTF schema
// does: Debian builds Assimp's JSON library with its assertions on, so reading a
// string where a number should be aborts the process. `where` is a JSON pointer for
// the message. Recursion is bounded by check_depth().
void trim_and_check(json& v, const std::string& where, const std::string& path) {
  if (v.is_object()) {
    v.erase("extras");
    if (auto it = v.find("extensions"); it != v.end() && it->is_object())
      for (auto e = it->begin(); e != it->end();) e = kept_extension(e.key()) ? std::next(e) : it->erase(e);
    for (auto& [key, child] : v.items()) trim_and_check(child, where + "/" + key, path);
  } else if (v.is_array()) {
    for (size_t i = 0; i < v.size(); ++i) {
      const bool same = v[i].type() == v[0].type() || (v[i].is_number() && v[0].is_number());
      if (!same)
        throw Error(path + ": " + where + "/" + std::to_string(i) + " is " + v[i].type_name() + " in an array of " +
                    v[0].type_name() + "s");
      trim_and_check(v[i], where + "/" + std::to_string(i), path);
    }
  }
}

void check_required_extensions(const json& root, const std::string& path) {
  const json* required = member(root, "extensionsRequired", json::value_t::array, "", path);
  if (!required) return;
  for (const json& name : *required)
    if (!name.is_string() || !(kept_extension(name.get<std::string>()) || read_by_velocity(name.get<std::string>())))
      throw Error(path + ": the file requires glTF extension " + name.dump() + ", which Velocity does not read");
}

// A non-negative integer member of `object` (`fallback` when absent and optional), at
// most 2^53 (JSON's exact integers), so that the sums and products below cannot wrap.
uint64_t size_member(const json& object, const char* key, std::optional<uint64_t> fallback, const std::string& where,
                     const std::string& path) {
  auto it = object.find(key);
  if (it == object.end()) {
    if (fallback) return *fallback;
    throw Error(path + ": " + where + "has no \"" + key + "\"");
  }
  if (!it->is_number_integer() || it->get<int64_t>() < 0 || it->get<uint64_t>() > (uint64_t(1) << 53))
    throw Error(path + ": " + where + "\"" + key + "\" is " + it->dump() + ", expected a whole number from 0 to 2^53");
  return it->get<uint64_t>();
}

// Bytes base64 text of `chars` characters (its '=' padding included) decodes to.
uint64_t base64_bytes(std::string_view text) {
  uint64_t n = text.size() / 4 * 3;
  if (!text.empty() && text.back() == '=') --n;
  if (text.size() > 1 && text[text.size() - 2] == '=') --n;
  return n;
}

// What the binary data must hold for the accessors to be read: every buffer's length
// fits the bytes it has (a .glb's BIN chunk, a data URI; files named by URI are checked
// by Assimp against their size, which LoadOptions::max_memory bounds), every buffer
// view lies inside its buffer, every accessor's elements inside its view. An accessor
// with no view, or a sparse one, is count × element size bytes that Assimp allocates
// and fills before reading anything else: a 2 KB file claiming four billion VEC4s
// asked for 68 GB. Those must fit `max_memory` / 4 (Assimp copies them twice more into
// its own mesh arrays). Returns each accessor's count.
std::vector<uint64_t> check_accessors(const json& root, std::string_view bin_chunk, bool glb, size_t max_memory,
                                      const std::string& path) {
  std::vector<uint64_t> buffer_size;
  if (const json* buffers = member(root, "buffers", json::value_t::array, "", path)) {
    for (size_t i = 0; i < buffers->size(); ++i) {
      const std::string where = "buffer " + std::to_string(i) + ": ";
      const json& buffer = object_at(*buffers, i, where, path);
      const uint64_t length = size_member(buffer, "byteLength", std::nullopt, where, path);
      const json* uri = member(buffer, "uri", json::value_t::string, where, path);
      if (!uri) {
        if (!glb || i != 0) throw Error(path + ": " + where + "has no \"uri\" (only a .glb's first buffer may have none)");
        if (length > bin_chunk.size())
          throw Error(path + ": " + where + "byteLength " + std::to_string(length) + " is more than the " +
                      std::to_string(bin_chunk.size()) + " bytes of the GLB's binary chunk");
      } else if (const std::string& u = uri->get_ref<const std::string&>(); u.rfind("data:", 0) == 0) {
        const size_t comma = u.find(',');
        const uint64_t have = comma == std::string::npos ? 0 : base64_bytes(std::string_view(u).substr(comma + 1));
        if (length > have)
          throw Error(path + ": " + where + "byteLength " + std::to_string(length) + " is more than the " +
                      std::to_string(have) + " bytes of its data URI");
      }
      buffer_size.push_back(length);
    }
  }
  struct View {
    uint64_t length, stride;
  };
  std::vector<View> views;
  if (const json* list = member(root, "bufferViews", json::value_t::array, "", path)) {
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string where = "bufferView " + std::to_string(i) + ": ";
      const json& view = object_at(*list, i, where, path);
      const uint64_t buffer = size_member(view, "buffer", std::nullopt, where, path);
      if (buffer >= buffer_size.size())
        throw Error(path + ": " + where + "buffer " + std::to_string(buffer) + " does not exist (the file has " +
                    std::to_string(buffer_size.size()) + ")");
      const uint64_t offset = size_member(view, "byteOffset", 0, where, path);
      const uint64_t length = size_member(view, "byteLength", std::nullopt, where, path);
      if (offset + length > buffer_size[buffer])
        throw Error(path + ": " + where + "bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                    " run past the end of buffer " + std::to_string(buffer) + " (" +
                    std::to_string(buffer_size[buffer]) + " bytes)");
      const uint64_t stride = size_member(view, "byteStride", 0, where, path);
      if (stride != 0 && (stride < 4 || stride > 252 || stride % 4 != 0))
        throw Error(path + ": " + where + "byteStride " + std::to_string(stride) +
                    " is not a multiple of 4 from 4 to 252");
      views.push_back({length, stride});
    }
  }
  std::vector<uint64_t> counts;
  const json* accessors = member(root, "accessors", json::value_t::array, "", path);
  if (!accessors) return counts;
  // Checks that `count` elements of `element` bytes from `offset` fit view `index`.
  auto check_fits = [&](const json& index, uint64_t offset, uint64_t count, uint64_t element, bool strided,
                        const std::string& where) {
    if (!index.is_number_integer() || index.get<int64_t>() < 0 || index.get<uint64_t>() >= views.size())
      throw Error(path + ": " + where + "bufferView is " + index.dump() + ", expected one of the file's " +
                  std::to_string(views.size()) + " buffer views");
    const View& view = views[index.get<size_t>()];
    const uint64_t stride = strided && view.stride ? view.stride : element;
    const uint64_t end = count == 0 ? offset : offset + stride * (count - 1) + element;
    if (end > view.length)
      throw Error(path + ": " + where + std::to_string(count) + " elements of " + std::to_string(element) +
                  " bytes from byte " + std::to_string(offset) + " run past the end of bufferView " + index.dump() +
                  " (" + std::to_string(view.length) + " bytes)");
  };
  for (size_t i = 0; i < accessors->size(); ++i) {
    const std::string where = "accessor " + std::to_string(i) + ": ";
    const json& accessor = object_at(*accessors, i, where, path);
    const uint64_t component = size_member(accessor, "componentType", std::nullopt, where, path);
    uint64_t component_bytes = 0;
    switch (component) {
      case 5120: case 5121: component_bytes = 1; break;  // (UNSIGNED_)BYTE
      case 5122: case 5123: component_bytes = 2; break;  // (UNSIGNED_)SHORT
      case 5125: case 5126: component_bytes = 4; break;  // UNSIGNED_INT, FLOAT
      default:
        throw Error(path + ": " + where + "componentType " + std::to_string(component) +
                    " is not one of glTF's (5120-5123, 5125, 5126)");
    }
    const json* type = member(accessor, "type", json::value_t::string, where, path);
    static const std::pair<const char*, uint64_t> kTypes[] = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                              {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    uint64_t components = 0;
    for (const auto& [name, n] : kTypes)
      if (type && *type == name) components = n;
    if (!components)
      throw Error(path + ": " + where + "type is " + (type ? type->dump() : std::string("missing")) +
                  ", expected SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
    const uint64_t element = component_bytes * components;
    const uint64_t count = size_member(accessor, "count", std::nullopt, where, path);
    if (count == 0) throw Error(path + ": " + where + "\"count\" is 0, expected at least 1");
    counts.push_back(count);
    const uint64_t offset = size_member(accessor, "byteOffset", 0, where, path);
    const json* sparse = member(accessor, "sparse", json::value_t::object, where, path);
    if (auto view = accessor.find("bufferView"); view != accessor.end()) {
      check_fits(*view, offset, count, element, true, where);
    }
    const bool allocated = sparse || accessor.find("bufferView") == accessor.end();
    if (allocated && count > max_memory / 4 / element)
      throw Error(path + ": " + where + std::to_string(count) + " elements of " + std::to_string(element) +
                  " bytes " + (sparse ? "in a sparse accessor" : "with no bufferView") + ": Assimp would allocate " +
                  std::to_string(count * element) + " bytes, more than a quarter of the limit of " +
                  std::to_string(max_memory) + " bytes (LoadOptions::max_memory)");
    if (!sparse) continue;
    const std::string in = where + "sparse: ";
    const uint64_t changed = size_member(*sparse, "count", std::nullopt, in, path);
    if (changed > count)
      throw Error(path + ": " + in + "count " + std::to_string(changed) + " is more than the accessor's " +
                  std::to_string(count));
    const json* indices = member(*sparse, "indices", json::value_t::object, in, path);
    const json* values = member(*sparse, "values", json::value_t::object, in, path);
    if (!indices || !values) throw Error(path + ": " + in + "needs both \"indices\" and \"values\"");
    const uint64_t index_type = size_member(*indices, "componentType", std::nullopt, in + "indices: ", path);
    const uint64_t index_bytes = index_type == 5121 ? 1 : index_type == 5123 ? 2 : index_type == 5125 ? 4 : 0;
    if (!index_bytes)
      throw Error(path + ": " + in + "indices: componentType " + std::to_string(index_type) +
                  " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT (5121, 5123, 5125)");
    for (const auto& [part, bytes] : {std::pair{indices, index_bytes}, std::pair{values, element}}) {
      const std::string at = in + (part == indices ? "indices: " : "values: ");
      auto view = part->find("bufferView");
      if (view == part->end()) throw Error(path + ": " + at + "has no \"bufferView\"");
      check_fits(*view, size_member(*part, "byteOffset", 0, at, path), changed, bytes, false, at);
    }
  }
  return counts;
}

// Every primitive has positions and enough vertices for its mode. Assimp 5.2.5 makes
// count - 2 faces of a triangle strip or fan and count - 1 of a line strip, in unsigned
// arithmetic: a strip of 1 vertex, or one with no POSITION (count 0), asks for 2^32 or
// 2^64 faces. glTF lets a primitive go without positions (to be skipped); Velocity,
// which would draw nothing of it, refuses the file instead.
void check_primitives(const json& root, const std::vector<uint64_t>& accessor_count, const std::string& path) {
  const json* meshes = member(root, "meshes", json::value_t::array, "", path);
  if (!meshes) return;
  static const char* const kModes[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                       "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  static const uint64_t kMinimum[] = {1, 2, 2, 2, 3, 3, 3};
  auto count_of = [&](const json& index, const std::string& what) {
    if (!index.is_number_integer() || index.get<int64_t>() < 0 || index.get<uint64_t>() >= accessor_count.size())
      throw Error(path + ": " + what + " is " + index.dump() + ", expected one of the file's " +
                  std::to_string(accessor_count.size()) + " accessors");
    return accessor_count[index.get<size_t>()];
  };
  for (size_t m = 0; m < meshes->size(); ++m) {
    const std::string in = "mesh " + std::to_string(m) + ": ";
    const json& mesh = object_at(*meshes, m, in, path);
    const json* primitives = member(mesh, "primitives", json::value_t::array, in, path);
    if (!primitives) continue;
    for (size_t p = 0; p < primitives->size(); ++p) {
      const std::string where = "mesh " + std::to_string(m) + ", primitive " + std::to_string(p) + ": ";
      const json& primitive = object_at(*primitives, p, where, path);
      const uint64_t mode = size_member(primitive, "mode", 4, where, path);
      if (mode > 6) throw Error(path + ": " + where + "mode " + std::to_string(mode) + " is not a glTF mode (0-6)");
      const json* attributes = member(primitive, "attributes", json::value_t::object, where, path);
      if (!attributes || !attributes->contains("POSITION"))
        throw Error(path + ": " + where + "has no POSITION attribute (nothing to draw)");
      for (const auto& [name, index] : attributes->items()) count_of(index, where + "attribute " + name);
      uint64_t vertices = count_of((*attributes)["POSITION"], where + "attribute POSITION");
      if (auto indices = primitive.find("indices"); indices != primitive.end())
        vertices = count_of(*indices, where + "indices");
      if (vertices < kMinimum[mode])
        throw Error(path + ": " + where + "a " + kModes[mode] + " needs at least " + std::to_string(kMinimum[mode]) +
                    " vertices, it has " + std::to_string(vertices));
    }
  }
}

// Assimp gets no skins, animations or morph targets: those parts go (see gltf_check.hpp;
// Velocity reads animations and morph targets from the JSON itself). Nor does it
// draw lines from model files, and Assimp 5.2.5 crashes (a null pointer) on a LINE_LOOP
// primitive (mode 2) whose first index is out of range, while it drops such indices in
// a LINE_STRIP (mode 3): line loops are given to it as line strips.
//
// Assimp 5.2.5 numbers a glTF file's materials in the order primitives first use them,
// not the file's: each material is named by its index in the file instead
// (kMaterialTag + index), so that the adapter finds the material Velocity read from the
// JSON (io/gltf_appearance.hpp).
void remove_what_velocity_does_not_draw(json& root) {
  if (root.contains("materials") && root["materials"].is_array())
    for (size_t i = 0; i < root["materials"].size(); ++i)
      if (root["materials"][i].is_object()) root["materials"][i]["name"] = kMaterialTag + std::to_string(i);
  // Animations and skins are read by Velocity (io/gltf_appearance.hpp); the nodes they
  // move, the skins' joints and the skinned nodes are tagged with their index (kNodeTag)
  // for the adapter.
  const bool has_nodes = root.contains("nodes") && root["nodes"].is_array();
  auto tag = [&](const json* node) {
    if (!has_nodes || !node || !node->is_number_unsigned() || node->get<uint64_t>() >= root["nodes"].size()) return;
    json& n = root["nodes"][node->get<size_t>()];
    if (!n.is_object()) return;
    const std::string name = n.contains("name") && n["name"].is_string() ? n["name"].get<std::string>() : "";
    if (name.rfind(kNodeTag, 0) != 0) n["name"] = kNodeTag + std::to_string(node->get<size_t>()) + ":" + name;
  };
  if (root.contains("animations") && root["animations"].is_array())
    for (const json& anim : root["animations"]) {
      if (!anim.is_object() || !anim.contains("channels") || !anim["channels"].is_array()) continue;
      for (const json& channel : anim["channels"])
        tag(channel.is_object() && channel.contains("target") && channel["target"].is_object() &&
                    channel["target"].contains("node")
                ? &channel["target"]["node"]
                : nullptr);
    }
  if (root.contains("skins") && root["skins"].is_array())
    for (const json& skin : root["skins"])
      if (skin.is_object() && skin.contains("joints") && skin["joints"].is_array())
        for (const json& joint : skin["joints"]) tag(&joint);
  if (has_nodes)
    for (size_t i = 0; i < root["nodes"].size(); ++i)
      if (const json& n = root["nodes"][i]; n.is_object() && n.contains("skin")) {
        const json index = i;
        tag(&index);
      }
  root.erase("skins");
  root.erase("animations");
  if (json* nodes = root.contains("nodes") ? &root["nodes"] : nullptr)
    for (json& node : *nodes) node.erase("skin"), node.erase("weights");
  if (root.contains("meshes") && root["meshes"].is_array())
    for (json& mesh : root["meshes"]) {
      if (!mesh.is_object()) continue;
      mesh.erase("weights");
      if (mesh.contains("primitives") && mesh["primitives"].is_array())
        for (json& primitive : mesh["primitives"]) {
          if (!primitive.is_object()) continue;
          primitive.erase("targets");
          if (auto mode = primitive.find("mode"); mode != primitive.end() && *mode == 2) *mode = 3;
        }
    }
}

void put_u32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
}

// A .glb's binary chunk (after the JSON chunk: length, type "BIN\0", data), or nothing.
std::string_view bin_chunk(std::string_view bytes, std::string_view json_chunk) {
  const size_t at = size_t(json_chunk.data() + json_chunk.size() - bytes.data());
  if (bytes.size() - at < 8 || bytes.substr(at + 4, 4) != std::string_view("BIN\0", 4)) return {};
  return bytes.substr(at + 8, std::min<size_t>(read_u32(bytes, at), bytes.size() - at - 8));
}

}  // namespace

std::string prepare_gltf(std::string_view bytes, const std::string& path, size_t max_memory) {
  std::string_view text = json_text(bytes, path);
  const bool is_glb = text.data() != bytes.data();
  check_depth(text, path);
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 3, ...": keep from "parse error".
    const char* what = e.what();
    const char* start = std::strchr(what, ']');
    throw Error(path + ": invalid glTF JSON:" + std::string(start ? start + 1 : what));
  }
  if (!root.is_object()) throw Error(path + ": glTF JSON is " + std::string(root.type_name()) + ", expected an object");
  const json* asset = member(root, "asset", json::value_t::object, "", path);
  const json* version = asset ? member(*asset, "version", json::value_t::string, "asset: ", path) : nullptr;
  if (!version) throw Error(path + ": glTF file has no \"asset\": {\"version\": ...}");
  const std::string v = version->get<std::string>();
  if (v.rfind("2.", 0) != 0) throw Error(path + ": glTF version " + v + " is not supported (2.x only)");
  check_required_extensions(root, path);
  trim_and_check(root, "", path);
  check_nodes(root, path);
  check_images(root, path);

  const std::string_view bin = is_glb ? bin_chunk(bytes, text) : std::string_view();
  check_primitives(root, check_accessors(root, bin, is_glb, max_memory, path), path);

  remove_what_velocity_does_not_draw(root);
  std::string out = root.dump();
  if (!is_glb) return out;
  // A .glb: header, the new JSON chunk padded with spaces to 4 bytes, the other chunks.
  out.resize((out.size() + 3) / 4 * 4, ' ');
  const std::string_view rest = bytes.substr(20 + text.size());
  std::string glb = "glTF";
  put_u32(glb, 2);
  put_u32(glb, uint32_t(12 + 8 + out.size() + rest.size()));
  put_u32(glb, uint32_t(out.size()));
  glb += "JSON";
  glb += out;
  glb += rest;
  return glb;
}

}  // namespace velocity::detail
