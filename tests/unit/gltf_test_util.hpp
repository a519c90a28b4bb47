// Writing small glTF 2.0 files in the tests: a binary buffer of float and index
// accessors, the JSON around it, as .gltf (buffer as a data URI) or .glb.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace velocity::test {

inline std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += k[(v >> s) & 63];
  }
  if (i < bytes.size()) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16 | (i + 1 < bytes.size() ? uint32_t(uint8_t(bytes[i + 1])) << 8 : 0);
    out += k[(v >> 18) & 63], out += k[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

class GltfBuilder {
 public:
  nlohmann::json json = {{"asset", {{"version", "2.0"}}}};

  // Appends `floats` (count elements of `type`, "VEC2", "VEC3", "VEC4") as an accessor.
  int floats(const std::vector<float>& values, const char* type, int components) {
    const size_t offset = add(values.data(), values.size() * 4);
    nlohmann::json a = {{"bufferView", view(offset, values.size() * 4)},
                        {"componentType", 5126},
                        {"count", values.size() / size_t(components)},
                        {"type", type}};
    if (components == 3) {  // POSITION needs min and max
      std::vector<float> lo(3, 1e30f), hi(3, -1e30f);
      for (size_t i = 0; i < values.size(); ++i) lo[i % 3] = std::min(lo[i % 3], values[i]), hi[i % 3] = std::max(hi[i % 3], values[i]);
      a["min"] = lo, a["max"] = hi;
    }
    json["accessors"].push_back(a);
    return int(json["accessors"].size() - 1);
  }
  int indices(const std::vector<uint16_t>& values) {
    const size_t offset = add(values.data(), values.size() * 2);
    json["accessors"].push_back(
        {{"bufferView", view(offset, values.size() * 2)}, {"componentType", 5123}, {"count", values.size()}, {"type", "SCALAR"}});
    return int(json["accessors"].size() - 1);
  }
  // An image in the buffer (a .glb's way, or any .gltf's).
  int image_in_buffer(const std::string& png) {
    const size_t offset = add(png.data(), png.size());
    json["images"].push_back({{"bufferView", view(offset, png.size())}, {"mimeType", "image/png"}});
    return int(json["images"].size() - 1);
  }
  int image_uri(const std::string& uri) {
    json["images"].push_back({{"uri", uri}});
    return int(json["images"].size() - 1);
  }
  int texture(int image) {
    json["textures"].push_back({{"source", image}});
    return int(json["textures"].size() - 1);
  }

  // The .gltf text, its buffer a data URI.
  std::string gltf() const {
    nlohmann::json j = json;
    j["buffers"] = {{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}};
    return j.dump();
  }
  // The .glb bytes.
  std::string glb() const {
    nlohmann::json j = json;
    j["buffers"] = {{{"byteLength", bin_.size()}}};
    std::string text = j.dump();
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::string bin = bin_;
    bin.resize((bin.size() + 3) / 4 * 4, '\0');
    std::string out = "glTF";
    put(out, 2), put(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    put(out, uint32_t(text.size())), out += "JSON", out += text;
    put(out, uint32_t(bin.size())), out += std::string("BIN\0", 4), out += bin;
    return out;
  }

 private:
  static void put(std::string& out, uint32_t v) {
    for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
  }
  size_t add(const void* data, size_t n) {
    bin_.resize((bin_.size() + 3) / 4 * 4, '\0');
    const size_t at = bin_.size();
    bin_.append(static_cast<const char*>(data), n);
    return at;
  }
  int view(size_t offset, size_t length) {
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    return int(json["bufferViews"].size() - 1);
  }
  std::string bin_;
};

}  // namespace velocity::test
