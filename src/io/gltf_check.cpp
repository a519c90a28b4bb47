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

void check_nodes(const json& root, const std::string& path) {
  std::vector<int64_t> parent;
  std::vector<std::vector<size_t>> children;
  if (const json* nodes = member(root, "nodes", json::value_t::array, "", path)) {
    const size_t n = nodes->size();
    parent.assign(n, -1);
    children.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const json& node = (*nodes)[i];
      const std::string where = "node " + std::to_string(i) + ": ";
      if (!node.is_object()) throw Error(path + ": " + where + "is " + node.type_name() + ", expected an object");
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
      const json& scene = (*scenes)[s];
      const std::string where = "scene " + std::to_string(s) + ": ";
      if (!scene.is_object()) throw Error(path + ": " + where + "is " + scene.type_name() + ", expected an object");
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
    const json& image = (*images)[i];
    const std::string where = "image " + std::to_string(i) + ": ";
    if (!image.is_object()) throw Error(path + ": " + where + "is " + image.type_name() + ", expected an object");
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
    if (!name.is_string() || !kept_extension(name.get<std::string>()))
      throw Error(path + ": the file requires glTF extension " + name.dump() + ", which Velocity does not read");
}

// Velocity neither skins nor animates: those parts go (see gltf_check.hpp).
void remove_animation(json& root) {
  root.erase("skins");
  root.erase("animations");
  if (json* nodes = root.contains("nodes") ? &root["nodes"] : nullptr)
    for (json& node : *nodes) node.erase("skin"), node.erase("weights");
  if (root.contains("meshes") && root["meshes"].is_array())
    for (json& mesh : root["meshes"]) {
      if (!mesh.is_object()) continue;
      mesh.erase("weights");
      if (mesh.contains("primitives") && mesh["primitives"].is_array())
        for (json& primitive : mesh["primitives"])
          if (primitive.is_object()) primitive.erase("targets");
    }
}

void put_u32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
}

}  // namespace

std::string prepare_gltf(std::string_view bytes, const std::string& path) {
  std::string_view text = json_text(bytes, path);
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

  remove_animation(root);
  std::string out = root.dump();
  if (text.data() == bytes.data()) return out;  // a .gltf
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
