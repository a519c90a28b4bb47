// Fuzz target: the formats read through Assimp (load_with_assimp: glTF 2.0 text and
// binary, 3D Studio, PLY, STL), with Velocity's own checks in front of Assimp. The
// first byte picks the extension, the rest is the file; it goes through a file, as
// load_with_assimp takes a path. Assimp itself (Debian's libassimp) is not instrumented:
// what this finds is a crash, a hang, an allocation beyond the limit, or a report in
// Velocity's checks and adapter.
// Property: it loads or throws velocity::Error; what loads is a consistent model.
#include "fuzz_util.hpp"
#include "velocity/error.hpp"
#include "velocity/log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  if (size == 0) return 0;
  static const char* const kNames[] = {"fuzz.gltf", "fuzz.glb", "fuzz.3ds", "fuzz.ply", "fuzz.stl"};
  static const bool quiet = [] { return set_warning_handler({}), true; }();  // dropped points, lines
  (void)quiet;
  std::string path = fuzz::TempDir::get().write(kNames[data[0] % 5], {reinterpret_cast<const char*>(data + 1), size - 1});
  Model model;
  try {
    model = load_with_assimp(path, fuzz::fuzz_load_options());
  } catch (const Error&) {
    return 0;
  }
  fuzz::check_model(model);  // a velocity::Error here is a bug: it escapes
  return 0;
}
