// glTF 2.0 materials, images and lights from the file's JSON (see gltf_appearance.hpp
// for why not through Assimp), as the glTF 2.0 specification and its KHR_ extensions
// define them.
#include "io/gltf_appearance.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <optional>

#include "io/read_file.hpp"
#include "velocity/error.hpp"
#include "velocity/log.hpp"
#include "velocity/texture.hpp"

namespace velocity::detail {

namespace {

using nlohmann::json;

constexpr float kPi = 3.14159265358979f;

uint32_t read_u32(std::string_view b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;  // '-' and '_': the URL-safe alphabet
  if (c == '/' || c == '_') return 63;
  return -1;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

class Reader {
 public:
  Reader(const json& root, std::string_view bin, const std::string& path, const LoadOptions& options)
      : root_(root), bin_(bin), path_(path), options_(options), budget_(options.max_memory) {}

  Material material(size_t i) {
    const std::string where = "material " + std::to_string(i) + ": ";
    const json& m = at(list("materials"), i, where);
    Material out = default_material();
    if (const json* name = member(m, "name", json::value_t::string, where)) out.name = name->get<std::string>();
    if (const json* pbr = member(m, "pbrMetallicRoughness", json::value_t::object, where)) {
      const std::string w = where + "pbrMetallicRoughness: ";
      const std::vector<float> base = numbers(*pbr, "baseColorFactor", {1, 1, 1, 1}, 0, 1, w);
      out.color = {base[0], base[1], base[2]};
      out.alpha = base[3];
      out.pbr.metallic = number(*pbr, "metallicFactor", 1, 0, 1, w);
      out.pbr.roughness = number(*pbr, "roughnessFactor", 1, 0, 1, w);
      if (const json* t = member(*pbr, "baseColorTexture", json::value_t::object, w)) {
        TextureRef ref = texture(*t, w + "baseColorTexture: ", &out);
        out.texture = ref.texture;
        out.texture_uv = ref.uv;
      }
      if (const json* t = member(*pbr, "metallicRoughnessTexture", json::value_t::object, w))
        out.pbr.metallic_roughness = texture(*t, w + "metallicRoughnessTexture: ", nullptr);
    }
    if (const json* t = member(m, "normalTexture", json::value_t::object, where)) {
      out.pbr.normal = texture(*t, where + "normalTexture: ", nullptr);
      out.pbr.normal_scale = number(*t, "scale", 1, -1e6f, 1e6f, where + "normalTexture: ");
    }
    if (const json* t = member(m, "occlusionTexture", json::value_t::object, where)) {
      out.pbr.occlusion = texture(*t, where + "occlusionTexture: ", nullptr);
      out.pbr.occlusion_strength = number(*t, "strength", 1, 0, 1, where + "occlusionTexture: ");
    }
    if (const json* t = member(m, "emissiveTexture", json::value_t::object, where))
      out.pbr.emissive_map = texture(*t, where + "emissiveTexture: ", nullptr);
    const std::vector<float> emissive = numbers(m, "emissiveFactor", {0, 0, 0}, 0, 1, where);
    out.pbr.emissive = {emissive[0], emissive[1], emissive[2]};
    if (const json* mode = member(m, "alphaMode", json::value_t::string, where)) {
      const std::string& s = mode->get_ref<const std::string&>();
      if (s == "OPAQUE") out.alpha_mode = AlphaMode::Opaque;
      else if (s == "MASK") out.alpha_mode = AlphaMode::Mask;
      else if (s == "BLEND") out.alpha_mode = AlphaMode::Blend;
      else fail(where + "alphaMode is \"" + s + "\", expected OPAQUE, MASK or BLEND");
    }
    out.alpha_cutoff = number(m, "alphaCutoff", 0.5f, 0, 1e6f, where);
    if (const json* two = member(m, "doubleSided", json::value_t::boolean, where)) out.two_sided = two->get<bool>();
    if (const json* ext = member(m, "extensions", json::value_t::object, where)) {
      out.pbr.unlit = ext->contains("KHR_materials_unlit");
      // KHR_materials_emissive_strength: a factor on the emissive colour (HDR emission).
      if (const json* s = member(*ext, "KHR_materials_emissive_strength", json::value_t::object, where))
        out.pbr.emissive = out.pbr.emissive * number(*s, "emissiveStrength", 1, 0, 1e6f, where + "emissive strength: ");
    }
    return out;
  }

  // The spec's default material (a primitive without one): white, fully metallic and rough.
  static Material default_material() {
    Material out;
    out.shading = Shading::Pbr;
    out.color_space = ColorSpace::Linear;
    out.color = {1, 1, 1};
    out.pbr.metallic = out.pbr.roughness = 1;
    return out;
  }

  // The file's animations: each channel's keys (float accessors), grouped by the node
  // they move, with the node's rest translation, rotation and scale; morph target
  // weights with the targets of the node's mesh. Channels of other component types are
  // left out with a warning.
  std::vector<Animation> animations() {
    std::vector<Animation> out;
    const json& anims = list("animations");
    const json& nodes = list("nodes");
    bool warned = false;
    auto skip = [&](const std::string& why) {
      if (!warned) warn(path_ + ": " + why + " (Velocity plays node translation, rotation and scale)");
      warned = true;
    };
    for (size_t a = 0; a < anims.size(); ++a) {
      const std::string where = "animation " + std::to_string(a) + ": ";
      const json& anim = at(anims, a, where);
      Animation result;
      if (const json* name = member(anim, "name", json::value_t::string, where)) result.name = name->get<std::string>();
      const json* channels = member(anim, "channels", json::value_t::array, where);
      const json* samplers = member(anim, "samplers", json::value_t::array, where);
      if (!channels || !samplers) fail(where + "expected \"channels\" and \"samplers\"");
      std::map<size_t, NodeAnimation> by_node;
      for (size_t c = 0; c < channels->size(); ++c) {
        const std::string w = where + "channel " + std::to_string(c) + ": ";
        const json& channel = at(*channels, c, w);
        const json* target = member(channel, "target", json::value_t::object, w);
        const json* path = target ? member(*target, "path", json::value_t::string, w + "target: ") : nullptr;
        if (!path) fail(w + "expected a \"target\" with a \"path\"");
        const std::string what = path->get<std::string>();
        if (what != "translation" && what != "rotation" && what != "scale" && what != "weights")
          fail(w + "target path \"" + what + "\", expected translation, rotation, scale or weights");
        if (!target->contains("node")) continue;  // the spec allows it (an extension's target)
        const size_t n = index((*target)["node"], nodes.size(), w + "target node");
        const json& sampler = at(*samplers, index(channel.value("sampler", json(-1)), samplers->size(), w + "sampler"),
                                 w + "sampler: ");
        const std::string mode = sampler.value("interpolation", std::string("LINEAR"));
        if (mode != "LINEAR" && mode != "STEP" && mode != "CUBICSPLINE")
          fail(w + "interpolation \"" + mode + "\", expected LINEAR, STEP or CUBICSPLINE");
        std::shared_ptr<MorphTargets> targets;
        if (what == "weights") {
          const json& node = at(nodes, n, w + "target node: ");
          if (!node.contains("mesh")) fail(w + "weights of node " + std::to_string(n) + ", which has no mesh");
          targets = morph_targets(node, w + "target node: ");
          if (!targets) continue;
        }
        // Weights: one scalar per target a key.
        const size_t width = what == "rotation" ? 4 : targets ? targets->positions.size() : 3;
        std::vector<float> times, values;
        if (!floats(sampler.value("input", json(-1)), 1, times, w + "input") ||
            !floats(sampler.value("output", json(-1)), targets ? 1 : width, values, w + "output")) {
          skip(w + "keys that are not 32-bit floats in a buffer view are not read");
          continue;
        }
        const size_t per_key = mode == "CUBICSPLINE" ? 3 : 1;  // in-tangent, value, out-tangent
        if (values.size() != times.size() * width * per_key)
          fail(w + std::to_string(times.size()) + " key times but " + std::to_string(values.size() / width) +
               " values (expected " + std::to_string(times.size() * per_key) + ")");
        for (size_t k = 0; k < times.size(); ++k)
          if (!std::isfinite(times[k]) || times[k] < 0 || (k && times[k] <= times[k - 1]))
            fail(w + "key time " + std::to_string(k) + " is " + std::to_string(times[k]) +
                 ", expected a finite time after the one before");
        const Interpolation mode_of_keys = mode == "STEP" ? Interpolation::Step : Interpolation::Linear;
        if (targets) {
          MorphAnimation morph{n, {times, {}, mode_of_keys}, targets};
          for (size_t k = 0; k < times.size(); ++k) {
            const float* key = &values[(k * per_key + (per_key == 3)) * width];
            morph.weights.values.emplace_back(key, key + width);
          }
          if (!times.empty()) result.duration = std::max(result.duration, times.back());
          result.morphs.push_back(std::move(morph));
          continue;
        }
        auto [it, first] = by_node.try_emplace(n);
        NodeAnimation& node = it->second;
        if (first) rest_pose(at(nodes, n, w + "target node: "), node, w + "target node: ");
        node.node = n;
        const Interpolation interp = mode == "STEP" ? Interpolation::Step : Interpolation::Linear;
        auto value = [&](size_t k, size_t i) { return values[(k * per_key + (per_key == 3)) * width + i]; };
        if (what == "rotation") {
          node.rotation = {times, {}, interp};
          for (size_t k = 0; k < times.size(); ++k)
            node.rotation.values.push_back({value(k, 0), value(k, 1), value(k, 2), value(k, 3)});
        } else {
          Keys<Vec3>& keys = what == "translation" ? node.translation : node.scale;
          keys = {times, {}, interp};
          for (size_t k = 0; k < times.size(); ++k) keys.values.push_back({value(k, 0), value(k, 1), value(k, 2)});
        }
        if (!times.empty()) result.duration = std::max(result.duration, times.back());
      }
      for (auto& [n, node] : by_node) result.nodes.push_back(std::move(node));
      if (!result.nodes.empty() || !result.morphs.empty()) out.push_back(std::move(result));
    }
    return out;
  }

  std::vector<Light> lights() {
    std::vector<Light> out;
    const json* ext = member(root_, "extensions", json::value_t::object, "");
    const json* punctual = ext ? member(*ext, "KHR_lights_punctual", json::value_t::object, "") : nullptr;
    const json* defs = punctual ? member(*punctual, "lights", json::value_t::array, "KHR_lights_punctual: ") : nullptr;
    if (!defs || defs->empty()) return out;
    const json& nodes = list("nodes");
    // The nodes of the scene shown ("scene", else the first), depth first with their
    // world matrices (gltf_check made sure they form trees).
    std::vector<std::pair<size_t, Mat4>> stack;
    const json& scenes = list("scenes");
    if (!scenes.empty()) {
      size_t s = 0;
      if (const json* chosen = member(root_, "scene", json::value_t::number_unsigned, ""))
        s = std::min<size_t>(chosen->get<size_t>(), scenes.size() - 1);
      if (const json* roots = member(at(scenes, s, "scene: "), "nodes", json::value_t::array, "scene: "))
        for (const json& r : *roots) stack.push_back({index(r, nodes.size(), "scene: node"), Mat4::identity()});
    }
    while (!stack.empty()) {
      auto [n, parent] = stack.back();
      stack.pop_back();
      const std::string where = "node " + std::to_string(n) + ": ";
      const json& node = at(nodes, n, where);
      const Mat4 world = parent * local_matrix(node, where);
      if (const json* children = member(node, "children", json::value_t::array, where))
        for (const json& c : *children) stack.push_back({index(c, nodes.size(), where + "child"), world});
      const json* next = member(node, "extensions", json::value_t::object, where);
      const json* use = next ? member(*next, "KHR_lights_punctual", json::value_t::object, where) : nullptr;
      if (!use || !use->contains("light")) continue;
      const size_t l = index((*use)["light"], defs->size(), where + "KHR_lights_punctual light");
      out.push_back(light(at(*defs, l, "light " + std::to_string(l) + ": "), world, "light " + std::to_string(l) + ": "));
    }
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw Error(path_ + ": " + what); }

  const json& list(const char* key) const {
    static const json empty = json::array();
    const json* l = member(root_, key, json::value_t::array, "");
    return l ? *l : empty;
  }

  const json& at(const json& array, size_t i, const std::string& where) const {
    if (i >= array.size() || !array[i].is_object()) fail(where + "expected an object");
    return array[i];
  }

  // A member of the type asked for, nullptr when absent (unsigned also takes a
  // non-negative integer, which nlohmann may store as either).
  const json* member(const json& object, const char* key, json::value_t type, const std::string& where) const {
    auto it = object.find(key);
    if (it == object.end()) return nullptr;
    const bool ok = it->type() == type || (type == json::value_t::number_unsigned && it->is_number_integer() &&
                                          it->get<int64_t>() >= 0);
    if (!ok) fail(where + "\"" + key + "\" is " + it->dump() + ", expected " + json(type).type_name());
    return &*it;
  }

  size_t index(const json& v, size_t size, const std::string& what) const {
    if (!v.is_number_integer() || v.get<int64_t>() < 0 || uint64_t(v.get<int64_t>()) >= size)
      fail(what + " is " + v.dump() + ", expected an index below " + std::to_string(size));
    return size_t(v.get<int64_t>());
  }

  uint64_t whole(const json& object, const char* key, uint64_t fallback, const std::string& where) const {
    auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_integer() || it->get<int64_t>() < 0)
      fail(where + "\"" + key + "\" is " + it->dump() + ", expected a whole number");
    return it->get<uint64_t>();
  }

  float number(const json& object, const char* key, float fallback, float lo, float hi,
               const std::string& where) const {
    auto it = object.find(key);
    if (it == object.end()) return fallback;
    const double v = it->is_number() ? it->get<double>() : NAN;
    if (!(v >= lo && v <= hi))
      fail(where + "\"" + key + "\" is " + it->dump() + ", expected a number from " + json(lo).dump() + " to " +
           json(hi).dump());
    return float(v);
  }

  // An array of fallback.size() numbers in [lo, hi].
  std::vector<float> numbers(const json& object, const char* key, std::vector<float> fallback, float lo, float hi,
                             const std::string& where) const {
    auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_array() || it->size() != fallback.size())
      fail(where + "\"" + key + "\" is " + it->dump() + ", expected " + std::to_string(fallback.size()) + " numbers");
    for (size_t k = 0; k < fallback.size(); ++k) {
      const double v = (*it)[k].is_number() ? (*it)[k].get<double>() : NAN;
      if (!(v >= lo && v <= hi))
        fail(where + "\"" + key + "\"[" + std::to_string(k) + "] is " + (*it)[k].dump() + ", expected a number from " +
             json(lo).dump() + " to " + json(hi).dump());
      fallback[k] = float(v);
    }
    return fallback;
  }

  // A textureInfo: the texture (decoded when textures are loaded), its uv set and its
  // KHR_texture_transform. `base` (the base-colour texture) also takes the sampler's
  // wrap and filter modes and the file name.
  TextureRef texture(const json& info, const std::string& where, Material* base) {
    TextureRef ref;
    const json& textures = list("textures");
    if (!info.contains("index")) fail(where + "no \"index\"");
    const size_t t = index(info["index"], textures.size(), where + "index");
    const json& texture = at(textures, t, where + "texture " + std::to_string(t) + ": ");
    ref.uv.uv_set = int(number(info, "texCoord", 0, 0, 1e6f, where));
    const json* ext = member(info, "extensions", json::value_t::object, where);
    if (const json* tt = ext ? member(*ext, "KHR_texture_transform", json::value_t::object, where) : nullptr) {
      const std::string w = where + "KHR_texture_transform: ";
      const std::vector<float> offset = numbers(*tt, "offset", {0, 0}, -1e6f, 1e6f, w);
      const std::vector<float> scale = numbers(*tt, "scale", {1, 1}, -1e6f, 1e6f, w);
      ref.uv.offset = {offset[0], offset[1]};
      ref.uv.scale = {scale[0], scale[1]};
      ref.uv.rotation = number(*tt, "rotation", 0, -1e6f, 1e6f, w);
      ref.uv.uv_set = int(number(*tt, "texCoord", float(ref.uv.uv_set), 0, 1e6f, w));
    }
    if (ref.uv.uv_set > 1) {
      warn(path_ + ": " + where + "uses TEXCOORD_" + std::to_string(ref.uv.uv_set) +
           "; Velocity reads TEXCOORD_0 and TEXCOORD_1 only, so TEXCOORD_0 addresses it");
      ref.uv.uv_set = 0;
    }
    if (base) {
      const json* s = member(texture, "sampler", json::value_t::number_unsigned, where);
      if (s) sampler(at(list("samplers"), index(*s, list("samplers").size(), where + "sampler"), where), *base);
    }
    const json* source = member(texture, "source", json::value_t::number_unsigned, where);
    if (!source) return ref;  // an extension's image format (KTX2, WebP): not read
    const size_t image = index(*source, list("images").size(), where + "source");
    const json& im = at(list("images"), image, "image " + std::to_string(image) + ": ");
    const json* uri = member(im, "uri", json::value_t::string, "image: ");
    const bool external = uri && uri->get_ref<const std::string&>().rfind("data:", 0) != 0;
    if (options_.load_textures) ref.texture = decoded(image);
    if (base && external && (ref.texture || !options_.load_textures)) base->texture_file = uri->get<std::string>();
    return ref;
  }

  // glTF's sampler: wrap modes (GL enums) and whether it filters.
  void sampler(const json& s, Material& m) const {
    auto wrap = [&](const char* key) {
      const float v = number(s, key, 10497, 0, 1e6f, "sampler: ");
      return v == 33071 ? Wrap::Clamp : v == 33648 ? Wrap::MirroredRepeat : Wrap::Repeat;
    };
    // Velocity has one wrap mode for both axes. When the file's differ, the repeating
    // one wins over a clamp: an axis is clamped mostly where its uvs stay inside [0, 1],
    // where repeating draws the same, while a repeating axis' uvs leave it (BoxTextured:
    // u from 3 to 4, mirrored, v from 0 to 1, clamped).
    const Wrap s_wrap = wrap("wrapS"), t_wrap = wrap("wrapT");
    m.wrap = s_wrap == t_wrap ? s_wrap : s_wrap == Wrap::Clamp ? t_wrap : s_wrap;
    const float mag = number(s, "magFilter", 9729, 0, 1e6f, "sampler: ");
    const float min = number(s, "minFilter", 9987, 0, 1e6f, "sampler: ");
    if (mag == 9728 && (min == 9728 || min == 9984)) m.filter = Filter::Nearest;  // NEAREST
    else if (min == 9728 || min == 9729) m.filter = Filter::Bilinear;              // no mip-maps
  }

  // Image `i` as a texture, decoded once; nullptr (with a warning) when it cannot be.
  std::shared_ptr<const Texture> decoded(size_t i) {
    auto [it, fresh] = images_.try_emplace(i);
    if (!fresh) return it->second;
    const std::string name = path_ + " image " + std::to_string(i);
    try {
      const json& image = at(list("images"), i, "image " + std::to_string(i) + ": ");
      std::shared_ptr<const Texture> texture;
      if (const json* uri = member(image, "uri", json::value_t::string, "image: ")) {
        const std::string& u = uri->get_ref<const std::string&>();
        if (u.rfind("data:", 0) == 0) {
          texture = std::make_shared<const Texture>(decode_image(decode_data_uri(u, name), name));
        } else {
          const std::string file = resolve_texture_path(path_, u);
          if (file.empty()) throw Error(path_ + ": texture '" + u + "' not found next to the model");
          texture = load_texture(file);
        }
      } else if (const json* view = member(image, "bufferView", json::value_t::number_unsigned, "image: ")) {
        texture = std::make_shared<const Texture>(decode_image(buffer_view(view->get<size_t>(), name), name));
      } else {
        throw Error(name + ": neither \"uri\" nor \"bufferView\"");
      }
      if (texture->memory_bytes() > budget_)
        throw Error(name + ": textures exceed the memory limit of " + std::to_string(options_.max_memory) +
                    " bytes (LoadOptions::max_memory)");
      budget_ -= texture->memory_bytes();
      it->second = texture;
    } catch (const Error& e) {
      warn(std::string(e.what()) + " (texture of " + path_ + ")");
    }
    return it->second;
  }

  // The bytes of buffer view `v` (gltf_check made sure it lies inside its buffer; it
  // is checked again here against the bytes actually found).
  std::string_view buffer_view(size_t v, const std::string& name) {
    const json& views = list("bufferViews");
    if (v >= views.size() || !views[v].is_object()) throw Error(name + ": buffer view " + std::to_string(v) + " does not exist");
    const json& view = views[v];
    const size_t b = index(view.value("buffer", json(-1)), list("buffers").size(), name + ": buffer");
    const uint64_t offset = whole(view, "byteOffset", 0, name + ": ");
    const uint64_t length = whole(view, "byteLength", 0, name + ": ");
    std::string_view data = buffer(b, name);
    if (offset > data.size() || length > data.size() - offset)
      throw Error(name + ": buffer view " + std::to_string(v) + " runs past the end of buffer " + std::to_string(b));
    return data.substr(size_t(offset), size_t(length));
  }

  std::string_view buffer(size_t b, const std::string& name) {
    const json& buf = at(list("buffers"), b, name + ": buffer: ");
    const json* uri = member(buf, "uri", json::value_t::string, name + ": buffer: ");
    if (!uri) {
      if (b != 0 || bin_.data() == nullptr) throw Error(name + ": buffer " + std::to_string(b) + " has no data");
      return bin_;
    }
    auto [it, fresh] = buffers_.try_emplace(b);
    if (fresh) {
      const std::string& u = uri->get_ref<const std::string&>();
      if (u.rfind("data:", 0) == 0) {
        it->second = decode_data_uri(u, name);
      } else {
        const std::string file = resolve_texture_path(path_, u);
        if (file.empty()) throw Error(name + ": buffer file '" + u + "' not found next to the model");
        it->second = read_file(file, budget_);
      }
      budget_ -= std::min(budget_, it->second.size());
    }
    return it->second;
  }

  // Accessor `v` of `type` (`width` components) as floats, whatever its component type:
  // floats as they are, unsigned bytes and shorts as their value, or divided by their
  // largest when "normalized". False for a sparse accessor or one without a buffer view.
  bool elements(const json& v, const char* type, size_t width, std::vector<float>& out, const std::string& where) {
    const json& acc = at(list("accessors"), index(v, list("accessors").size(), where + " accessor"), where + ": ");
    if (acc.value("type", std::string()) != type)
      fail(where + ": accessor type " + acc.value("type", json()).dump() + ", expected " + type);
    const int component = acc.value("componentType", 0);
    const size_t size = component == 5126 ? 4 : component == 5123 ? 2 : component == 5121 ? 1 : 0;
    if (size == 0) fail(where + ": component type " + std::to_string(component) + ", expected 5121, 5123 or 5126");
    if (!acc.contains("bufferView") || acc.contains("sparse")) return false;
    const bool normalized = acc.value("normalized", false);
    const uint64_t count = whole(acc, "count", 0, where + ": ");
    const size_t view_index = index(acc["bufferView"], list("bufferViews").size(), where + ": bufferView");
    const std::string_view bytes = buffer_view(view_index, path_);
    const uint64_t offset = whole(acc, "byteOffset", 0, where + ": ");
    const uint64_t stride =
        whole(at(list("bufferViews"), view_index, where + ": "), "byteStride", width * size, where + ": ");
    out.clear();
    if (count == 0) return true;
    if (stride < width * size || offset > bytes.size() || (count - 1) > (bytes.size() - offset) / stride ||
        offset + (count - 1) * stride + width * size > bytes.size())
      fail(where + ": accessor runs past the end of its buffer view");
    out.resize(size_t(count) * width);
    for (size_t k = 0; k < count; ++k)
      for (size_t c = 0; c < width; ++c) {
        const char* at_byte = bytes.data() + offset + k * stride + c * size;
        float& to = out[k * width + c];
        if (size == 4) {
          std::memcpy(&to, at_byte, 4);  // glTF is little-endian, as we are
        } else if (size == 2) {
          uint16_t u;
          std::memcpy(&u, at_byte, 2);
          to = normalized ? float(u) / 65535.0f : float(u);
        } else {
          const uint8_t u = uint8_t(*at_byte);
          to = normalized ? float(u) / 255.0f : float(u);
        }
      }
    return true;
  }

  // Accessor `v` as floats, `width` a element (SCALAR 1, VEC3 3, VEC4 4): false when it
  // is not plain 32-bit floats in a buffer view (gltf_check made sure it lies inside it).
  bool floats(const json& v, size_t width, std::vector<float>& out, const std::string& where) {
    const json& acc = at(list("accessors"), index(v, list("accessors").size(), where + " accessor"), where + ": ");
    static const char* kTypes[] = {"", "SCALAR", "", "VEC3", "VEC4"};
    if (acc.value("type", std::string()) != kTypes[width])
      fail(where + ": accessor type " + acc.value("type", json()).dump() + ", expected " + kTypes[width]);
    if (acc.value("componentType", 0) != 5126 || !acc.contains("bufferView") || acc.contains("sparse")) return false;
    const uint64_t count = whole(acc, "count", 0, where + ": ");
    const size_t view_index = index(acc["bufferView"], list("bufferViews").size(), where + ": bufferView");
    const std::string_view bytes = buffer_view(view_index, path_);
    const uint64_t offset = whole(acc, "byteOffset", 0, where + ": ");
    const uint64_t stride = whole(at(list("bufferViews"), view_index, where + ": "), "byteStride", width * 4, where + ": ");
    if (count == 0) return true;
    if (stride < width * 4 || offset > bytes.size() || (count - 1) > (bytes.size() - offset) / stride ||
        offset + (count - 1) * stride + width * 4 > bytes.size())
      fail(where + ": accessor runs past the end of its buffer view");
    out.resize(size_t(count) * width);
    for (size_t k = 0; k < count; ++k)
      std::memcpy(&out[k * width], bytes.data() + offset + k * stride, width * 4);  // glTF is little-endian, as we are
    return true;
  }

  // The morph targets of `node`'s mesh: each target's POSITION and NORMAL offsets, its
  // primitives' one after another (the order the adapter merges them in; MorphTargets::base
  // is left to it), and the node's or mesh's weights at rest. Null, with a warning, when
  // an offset is not plain floats (a sparse accessor, say); null without targets.
  std::shared_ptr<MorphTargets> morph_targets(const json& node, const std::string& where) {
    const size_t m = index(node["mesh"], list("meshes").size(), where + "mesh");
    auto& cached = morphs_[m];
    if (cached.first) return cached.second;
    cached.first = true;
    const std::string w = where + "mesh " + std::to_string(m) + ": ";
    const json& mesh = at(list("meshes"), m, w);
    const json* prims = member(mesh, "primitives", json::value_t::array, w);
    size_t count = 0;
    for (size_t p = 0; prims && p < prims->size(); ++p)
      if (const json* t = member(at(*prims, p, w), "targets", json::value_t::array, w)) count = std::max(count, t->size());
    if (count == 0) return nullptr;
    auto out = std::make_shared<MorphTargets>();
    out->positions.resize(count), out->normals.resize(count);
    bool any_normals = false;
    for (size_t p = 0; p < prims->size(); ++p) {
      const std::string wp = w + "primitive " + std::to_string(p) + ": ";
      const json& prim = at(*prims, p, wp);
      const json* attrs = member(prim, "attributes", json::value_t::object, wp);
      if (!attrs || !attrs->contains("POSITION")) fail(wp + "expected a POSITION attribute");
      const json& accessors = list("accessors");
      const uint64_t vertices = whole(at(accessors, index((*attrs)["POSITION"], accessors.size(), wp + "POSITION"), wp),
                                      "count", 0, wp);
      // Every target holds an offset of each vertex, given or not: within the memory limit.
      const uint64_t per_target = vertices * 2 * sizeof(Vec3);  // vertices <= the buffer's size
      if (vertices > budget_ || (per_target && count > budget_ / per_target))
        fail(wp + std::to_string(count) + " morph targets of " + std::to_string(vertices) +
             " vertices need more than the memory limit");
      budget_ -= size_t(count * per_target);
      const json* targets = member(prim, "targets", json::value_t::array, wp);
      for (size_t k = 0; k < count; ++k) {
        const json* target = targets && k < targets->size() ? &at(*targets, k, wp + "target: ") : nullptr;
        for (const char* attr : {"POSITION", "NORMAL"}) {
          std::vector<float> v(size_t(vertices) * 3, 0.0f);
          if (target && target->contains(attr)) {
            const std::string wt = wp + "target " + std::to_string(k) + " " + attr;
            if (!floats((*target)[attr], 3, v, wt)) {
              warn(path_ + ": " + wt + ": offsets that are not 32-bit floats in a buffer view are not read "
                                       "(the mesh is not morphed)");
              return cached.second = nullptr;
            }
            if (v.size() != vertices * 3)
              fail(wt + ": " + std::to_string(v.size() / 3) + " offsets for " + std::to_string(vertices) + " vertices");
            any_normals |= attr == std::string_view("NORMAL");
          }
          std::vector<Vec3>& to = attr == std::string_view("POSITION") ? out->positions[k] : out->normals[k];
          for (size_t i = 0; i + 2 < v.size(); i += 3) to.push_back({v[i], v[i + 1], v[i + 2]});
        }
      }
    }
    if (!any_normals) out->normals.clear();
    // The rest weights: the node's, else the mesh's, else zeros.
    const std::vector<float> zeros(count, 0.0f);
    out->rest_weights = numbers(mesh, "weights", zeros, -1e30f, 1e30f, w);
    out->rest_weights = numbers(node, "weights", out->rest_weights, -1e30f, 1e30f, where);
    return cached.second = out;
  }

 public:
  // The file's skins, one per node with a "skin" and a "mesh": the joints and inverse
  // bind matrices, and each vertex's JOINTS_0 and WEIGHTS_0, its primitives' one after
  // another (a primitive without them: weights zero, its vertices stay put). Skins whose
  // accessors are sparse are left out with a warning.
  std::vector<Skin> skins() {
    std::vector<Skin> out;
    const json& nodes = list("nodes");
    const json& skins = list("skins");
    const json& accessors = list("accessors");
    for (size_t n = 0; n < nodes.size(); ++n) {
      const std::string where = "node " + std::to_string(n) + ": ";
      const json& node = at(nodes, n, where);
      if (!node.contains("skin") || !node.contains("mesh")) continue;
      const size_t si = index(node["skin"], skins.size(), where + "skin");
      const std::string w = "skin " + std::to_string(si) + ": ";
      const json& def = at(skins, si, w);
      const json* joints = member(def, "joints", json::value_t::array, w);
      if (!joints || joints->empty()) fail(w + "expected \"joints\", a list of nodes");
      Skin skin;
      skin.node = n;
      for (const json& j : *joints) skin.joints.push_back(index(j, nodes.size(), w + "joint"));
      skin.inverse_bind.assign(joints->size(), Mat4::identity());
      if (def.contains("inverseBindMatrices")) {
        std::vector<float> m;
        if (!elements(def["inverseBindMatrices"], "MAT4", 16, m, w + "inverseBindMatrices")) {
          warn(path_ + ": " + w + "inverse bind matrices that are not 32-bit floats are not read (not skinned)");
          continue;
        }
        if (m.size() != joints->size() * 16)
          fail(w + std::to_string(m.size() / 16) + " inverse bind matrices for " + std::to_string(joints->size()) +
               " joints");
        for (size_t j = 0; j < joints->size(); ++j)
          for (int k = 0; k < 16; ++k) skin.inverse_bind[j].m[k % 4][k / 4] = m[j * 16 + size_t(k)];  // column-major
      }
      const size_t mi = index(node["mesh"], list("meshes").size(), where + "mesh");
      const json* prims = member(at(list("meshes"), mi, where + "mesh: "), "primitives", json::value_t::array, where);
      bool read = true;
      for (size_t p = 0; prims && p < prims->size() && read; ++p) {
        const std::string wp = where + "mesh " + std::to_string(mi) + ": primitive " + std::to_string(p) + ": ";
        const json* attrs = member(at(*prims, p, wp), "attributes", json::value_t::object, wp);
        if (!attrs || !attrs->contains("POSITION")) fail(wp + "expected a POSITION attribute");
        const uint64_t vertices =
            whole(at(accessors, index((*attrs)["POSITION"], accessors.size(), wp + "POSITION"), wp), "count", 0, wp);
        // (Each skinned node holds its own copy: within the memory limit.)
        constexpr size_t kBytesPerVertex = 2 * 4 * sizeof(float) + sizeof(std::array<uint16_t, 4>) + sizeof(std::array<float, 4>);
        if (vertices > budget_ / kBytesPerVertex)
          fail(wp + "skinning " + std::to_string(vertices) + " vertices needs more than the memory limit");
        budget_ -= size_t(vertices) * kBytesPerVertex;
        std::vector<float> j(size_t(vertices) * 4, 0.0f), wt(size_t(vertices) * 4, 0.0f);
        if (attrs->contains("JOINTS_0") && attrs->contains("WEIGHTS_0")) {
          read = elements((*attrs)["JOINTS_0"], "VEC4", 4, j, wp + "JOINTS_0") &&
                 elements((*attrs)["WEIGHTS_0"], "VEC4", 4, wt, wp + "WEIGHTS_0");
          if (!read) {
            warn(path_ + ": " + wp + "sparse joints or weights are not read (not skinned)");
            break;
          }
          if (j.size() != vertices * 4 || wt.size() != vertices * 4)
            fail(wp + "JOINTS_0 and WEIGHTS_0 need one element per vertex (" + std::to_string(vertices) + ")");
        }
        for (size_t v = 0; v < vertices; ++v) {
          std::array<uint16_t, 4> js{};
          std::array<float, 4> ws{};
          for (size_t k = 0; k < 4; ++k) {
            const float index_value = j[v * 4 + k];
            if (wt[v * 4 + k] != 0 && !(index_value >= 0 && index_value < float(joints->size())))
              fail(wp + "JOINTS_0 of vertex " + std::to_string(v) + " is " + std::to_string(index_value) +
                   ", expected a joint below " + std::to_string(joints->size()));
            js[k] = uint16_t(index_value >= 0 && index_value < float(joints->size()) ? index_value : 0);
            ws[k] = wt[v * 4 + k];
          }
          skin.vertex_joints.push_back(js);
          skin.vertex_weights.push_back(ws);
        }
      }
      if (read) out.push_back(std::move(skin));
    }
    return out;
  }

 private:
  // An animated node's rest translation, rotation and scale (an animated node has no
  // "matrix", says the spec; one that has is decomposed no further: identity rest).
  void rest_pose(const json& node, NodeAnimation& out, const std::string& where) const {
    const std::vector<float> t = numbers(node, "translation", {0, 0, 0}, -1e30f, 1e30f, where);
    const std::vector<float> q = numbers(node, "rotation", {0, 0, 0, 1}, -1, 1, where);
    const std::vector<float> s = numbers(node, "scale", {1, 1, 1}, -1e30f, 1e30f, where);
    out.rest_translation = {t[0], t[1], t[2]};
    out.rest_rotation = {q[0], q[1], q[2], q[3]};
    out.rest_scale = {s[0], s[1], s[2]};
  }

  // A node's matrix: "matrix" (column-major) or translation * rotation * scale.
  Mat4 local_matrix(const json& node, const std::string& where) const {
    Mat4 m;
    if (node.contains("matrix")) {
      const std::vector<float> v(16, 0);
      const std::vector<float> a = numbers(node, "matrix", v, -1e30f, 1e30f, where);
      for (int k = 0; k < 16; ++k) m.m[k % 4][k / 4] = a[size_t(k)];
      return m;
    }
    const std::vector<float> t = numbers(node, "translation", {0, 0, 0}, -1e30f, 1e30f, where);
    const std::vector<float> q = numbers(node, "rotation", {0, 0, 0, 1}, -1, 1, where);
    const std::vector<float> s = numbers(node, "scale", {1, 1, 1}, -1e30f, 1e30f, where);
    const float x = q[0], y = q[1], z = q[2], w = q[3];
    Mat4 r;  // the unit quaternion's rotation matrix
    r.m[0][0] = 1 - 2 * (y * y + z * z), r.m[0][1] = 2 * (x * y - z * w), r.m[0][2] = 2 * (x * z + y * w);
    r.m[1][0] = 2 * (x * y + z * w), r.m[1][1] = 1 - 2 * (x * x + z * z), r.m[1][2] = 2 * (y * z - x * w);
    r.m[2][0] = 2 * (x * z - y * w), r.m[2][1] = 2 * (y * z + x * w), r.m[2][2] = 1 - 2 * (x * x + y * y);
    return translate({t[0], t[1], t[2]}) * r * scale({s[0], s[1], s[2]});
  }

  // A KHR_lights_punctual light at a node: it shines along the node's -Z, from the
  // node's origin; intensity (lux, or candela) times colour is the Light's colour.
  Light light(const json& def, const Mat4& world, const std::string& where) const {
    const std::vector<float> color = numbers(def, "color", {1, 1, 1}, 0, 1e6f, where);
    const float intensity = number(def, "intensity", 1, 0, 1e12f, where);
    const Vec3 c = Vec3{color[0], color[1], color[2]} * intensity;
    Vec3 towards = world.transform_vector({0, 0, 1});
    if (!(dot(towards, towards) > 0)) towards = {0, 0, 1};
    const Vec3 position = world.transform_point({0, 0, 0});
    const json* type = member(def, "type", json::value_t::string, where);
    const std::string kind = type ? type->get<std::string>() : "";
    Light l;
    if (kind == "directional") {
      l = Light::directional(towards, c);
    } else if (kind == "point") {
      l = Light::point(position, c);
    } else if (kind == "spot") {
      const json* spot = member(def, "spot", json::value_t::object, where);
      const json none = json::object();
      const float inner = number(spot ? *spot : none, "innerConeAngle", 0, 0, kPi / 2, where + "spot: ");
      const float outer = number(spot ? *spot : none, "outerConeAngle", kPi / 4, 0, kPi / 2, where + "spot: ");
      if (!(inner < outer)) fail(where + "spot: innerConeAngle " + json(inner).dump() + " is not below outerConeAngle " + json(outer).dump());
      l = Light::spot(position, towards, c, inner, outer);
    } else {
      fail(where + "type is " + (type ? type->dump() : std::string("missing")) + ", expected \"directional\", \"point\" or \"spot\"");
    }
    if (kind != "directional") {
      l.falloff = Falloff::InverseSquare;
      l.range = number(def, "range", 0, 0, 1e30f, where);
    }
    return l;
  }

  const json& root_;
  std::string_view bin_;
  const std::string& path_;
  const LoadOptions& options_;
  size_t budget_;
  std::map<size_t, std::pair<bool, std::shared_ptr<MorphTargets>>> morphs_;  // by mesh: read yet, the targets
  std::map<size_t, std::shared_ptr<const Texture>> images_;
  std::map<size_t, std::string> buffers_;
};

}  // namespace

std::string decode_data_uri(std::string_view uri, const std::string& where) {
  if (uri.substr(0, 5) != "data:") throw Error(where + ": not a data URI");
  const size_t comma = uri.find(',');
  if (comma == std::string_view::npos) throw Error(where + ": data URI has no ',' before its data");
  const std::string_view header = uri.substr(5, comma - 5), data = uri.substr(comma + 1);
  std::string out;
  if (header.size() >= 7 && header.substr(header.size() - 7) == ";base64") {
    out.reserve(data.size() / 4 * 3);
    uint32_t acc = 0;
    int bits = 0;
    size_t i = 0;
    for (; i < data.size() && data[i] != '='; ++i) {
      const int v = base64_value(data[i]);
      if (v < 0)
        throw Error(where + ": data URI has '" + std::string(1, data[i]) + "' at character " + std::to_string(comma + 1 + i) +
                    " of its base64");
      acc = (acc << 6) | uint32_t(v), bits += 6;
      if (bits >= 8) bits -= 8, out += char((acc >> bits) & 0xff);
    }
    for (; i < data.size(); ++i)
      if (data[i] != '=') throw Error(where + ": data URI has base64 after its '=' padding");
    return out;
  }
  // Percent-encoded text.
  out.reserve(data.size());
  for (size_t i = 0; i < data.size(); ++i) {
    if (data[i] == '%' && i + 2 < data.size() + 0 && hex_value(data[i + 1]) >= 0 && hex_value(data[i + 2]) >= 0) {
      out += char(hex_value(data[i + 1]) * 16 + hex_value(data[i + 2]));
      i += 2;
    } else {
      out += data[i];
    }
  }
  return out;
}

GltfAppearance read_gltf_appearance(std::string_view bytes, const std::string& path, const LoadOptions& options) {
  // The JSON (a .glb's first chunk) and a .glb's binary chunk; prepare_gltf checked the
  // header, the nesting depth and that the JSON parses.
  std::string_view text = bytes, bin;
  if (bytes.size() >= 20 && bytes.substr(0, 4) == "glTF") {
    const size_t length = std::min<size_t>(read_u32(bytes, 12), bytes.size() - 20);
    text = bytes.substr(20, length);
    const size_t at = 20 + length;
    if (bytes.size() - at >= 8 && bytes.substr(at + 4, 4) == std::string_view("BIN\0", 4))
      bin = bytes.substr(at + 8, std::min<size_t>(read_u32(bytes, at), bytes.size() - at - 8));
  }
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    throw Error(path + ": invalid glTF JSON: " + e.what());
  }
  Reader reader(root, bin, path, options);
  GltfAppearance out;
  if (auto it = root.find("materials"); it != root.end() && it->is_array())
    for (size_t i = 0; i < it->size(); ++i) out.materials.push_back(reader.material(i));
  out.materials.push_back(Reader::default_material());
  out.lights = reader.lights();
  out.animations = reader.animations();
  out.skins = reader.skins();
  return out;
}

}  // namespace velocity::detail
