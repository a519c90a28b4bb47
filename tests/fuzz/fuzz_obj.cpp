// Fuzz target: the OBJ adapter (load_obj: tinyobjloader, then Velocity's meshes,
// materials and normals). load_obj takes a path, so the input goes through a file.
// An input may carry a material library after a line "%%mtl%%": it is written beside
// the OBJ as fuzz.mtl, which the OBJ can name ("mtllib fuzz.mtl").
// Property: it loads or throws velocity::Error; what loads is a consistent model.
#include "fuzz_util.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  std::string_view input(reinterpret_cast<const char*>(data), size), mtl;
  static constexpr std::string_view kSeparator = "\n%%mtl%%\n";
  if (size_t at = input.find(kSeparator); at != std::string_view::npos) {
    mtl = input.substr(at + kSeparator.size());
    input = input.substr(0, at);
  }
  fuzz::TempDir& dir = fuzz::TempDir::get();
  dir.write("fuzz.mtl", mtl);
  std::string path = dir.write("fuzz.obj", input);
  Model model;
  try {
    model = load_obj(path, fuzz::fuzz_load_options());
  } catch (const Error&) {
    return 0;
  }
  fuzz_check(model.path == path);
  fuzz::check_model(model);  // a velocity::Error here is a bug: it escapes
  return 0;
}
