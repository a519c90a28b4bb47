// velocity_fuzz_glb_seed: turns a .gltf whose buffers are files beside it into one
// input for the assimp fuzz target (fuzz_assimp.cpp): the byte 1 (".glb"), then a GLB
// with those buffers merged into its binary chunk.
//
//   velocity_fuzz_glb_seed IN.gltf OUT
//
// The fuzz target writes its input to one file, so a .gltf seed that names a .bin is
// refused by Assimp before any mesh is read ("could not open referenced file"): most
// of assimp-testmodels' glTF files, Draco-compressed ones included. As GLBs they reach
// the accessors, the index conversion and the Draco decoder. Buffers are placed one after
// another (each at a multiple of 4), their buffer views moved to buffer 0 at the new
// offset; images keep their URIs (a missing texture is only a warning). Exits 1, saying
// why, when the file is not such a glTF (a data URI buffer, a missing .bin, no buffers).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool read_whole(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out.assign(std::istreambuf_iterator<char>(in), {});
  return true;
}

void put_u32(std::string& out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
}

int fail(const std::string& why) {
  std::fprintf(stderr, "velocity_fuzz_glb_seed: %s\n", why.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using nlohmann::json;
  if (argc != 3) return fail("usage: velocity_fuzz_glb_seed IN.gltf OUT");
  const std::string in = argv[1];
  const std::string dir = in.find('/') == std::string::npos ? "" : in.substr(0, in.rfind('/') + 1);
  std::string text;
  if (!read_whole(in, text)) return fail(in + ": cannot read");
  json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!root.is_object() || !root.contains("buffers") || !root["buffers"].is_array() || root["buffers"].empty())
    return fail(in + ": no buffers");

  std::string bin;
  std::vector<uint64_t> base;  // where each buffer starts in `bin`
  for (json& buffer : root["buffers"]) {
    if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string())
      return fail(in + ": a buffer without a file URI");
    const std::string uri = buffer["uri"];
    if (uri.rfind("data:", 0) == 0) return fail(in + ": a data URI buffer");
    std::string bytes;
    if (!read_whole(dir + uri, bytes)) return fail(in + ": cannot read " + dir + uri);
    bin.resize((bin.size() + 3) / 4 * 4, '\0');
    base.push_back(bin.size());
    bin += bytes;
  }
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  if (root.contains("bufferViews") && root["bufferViews"].is_array())
    for (json& view : root["bufferViews"]) {
      if (!view.is_object() || !view.contains("buffer") || !view["buffer"].is_number_unsigned() ||
          view["buffer"].get<uint64_t>() >= base.size())
        return fail(in + ": a buffer view with no valid buffer");
      const uint64_t offset = view.value("byteOffset", uint64_t(0));
      view["byteOffset"] = base[view["buffer"].get<size_t>()] + offset;
      view["buffer"] = 0;
    }
  root["buffers"] = json::array({{{"byteLength", bin.size()}}});

  std::string chunk = root.dump();
  chunk.resize((chunk.size() + 3) / 4 * 4, ' ');
  std::string out(1, '\x01');  // fuzz_assimp.cpp: 1 = .glb
  out += "glTF";
  put_u32(out, 2);
  put_u32(out, uint32_t(12 + 8 + chunk.size() + 8 + bin.size()));
  put_u32(out, uint32_t(chunk.size()));
  out += "JSON" + chunk;
  put_u32(out, uint32_t(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  std::ofstream(argv[2], std::ios::binary) << out;
  return 0;
}
