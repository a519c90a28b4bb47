// Helpers shared by the fuzz targets (tests/fuzz/fuzz_*.cpp). Each target defines
// LLVMFuzzerTestOneInput; it is linked either with libFuzzer (VELOCITY_FUZZ, clang) or
// with replay_main.cpp, which runs it over the corpus and the regressions in ctest.
//
// The property every target checks: an input either works or throws velocity::Error.
// Any other exception escapes the target (libFuzzer and the replay driver report it as
// a crash), and so does a sanitizer report, a hang or a broken invariant (fuzz_check).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "velocity/image.hpp"
#include "velocity/load.hpp"
#include "velocity/scene.hpp"
#include "velocity/texture.hpp"

namespace velocity::fuzz {

// A broken invariant: print it and abort, so that libFuzzer saves the input.
#define fuzz_check(cond)                                                                  \
  do {                                                                                    \
    if (!(cond)) {                                                                        \
      std::fprintf(stderr, "fuzz_check failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
      std::abort();                                                                       \
    }                                                                                     \
  } while (0)

// Readers that take a path get the input through a file in a private folder, made once
// per process under $TMPDIR (or /tmp) and removed at exit.
class TempDir {
 public:
  static TempDir& get() {
    static TempDir dir;
    return dir;
  }
  // Writes `bytes` to NAME in the folder and returns its path.
  std::string write(const std::string& name, std::string_view bytes) {
    std::string path = path_ + "/" + name;
    FILE* f = std::fopen(path.c_str(), "wb");
    fuzz_check(f != nullptr);
    fuzz_check(bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
    fuzz_check(std::fclose(f) == 0);
    written_ += name + "\n";
    return path;
  }
  const std::string& path() const { return path_; }

 private:
  TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string tmpl = std::string(base && *base ? base : "/tmp") + "/velocity-fuzz-XXXXXX";
    fuzz_check(mkdtemp(tmpl.data()) != nullptr);
    path_ = tmpl;
  }
  ~TempDir() {
    size_t start = 0;
    for (size_t end; (end = written_.find('\n', start)) != std::string::npos; start = end + 1)
      ::unlink((path_ + "/" + written_.substr(start, end - start)).c_str());
    ::rmdir(path_.c_str());
  }
  std::string path_, written_;
};

// What every successful model load must satisfy: add_to_scene accepts it (consistent
// arrays, indices in range, parents first), and the counts add up.
inline void check_model(const Model& model) {
  Scene scene;
  std::vector<ObjectId> roots = add_to_scene(scene, model);  // throws velocity::Error if inconsistent
  fuzz_check(scene.objects().size() == model.nodes.size());
  fuzz_check(roots.size() <= model.nodes.size());
  size_t vertices = 0, triangles = 0;
  for (const Object& o : scene.objects())
    if (o.mesh) vertices += o.mesh->vertex_count(), triangles += o.mesh->triangle_count();
  fuzz_check(vertices == model.vertex_count() && triangles == model.triangle_count());
  // Its animations play (poses, morphs and skins) at the start, middle and end, and rest
  // again: the morphed and skinned meshes keep their vertex counts.
  skin(model.skins, scene);
  for (const Animation& a : model.animations) {
    for (float t : {0.0f, a.duration / 2, a.duration}) apply(a, t, scene), skin(model.skins, scene);
    rest(a, scene);
  }
  size_t after = 0;
  for (const Object& o : scene.objects())
    if (o.mesh) after += o.mesh->vertex_count();
  fuzz_check(after == vertices);
}

// What every decoded image must satisfy.
inline void check_image(const Image& image) {
  fuzz_check(image.width >= 1 && image.height >= 1);
  fuzz_check(image.pixels.size() == size_t(image.width) * size_t(image.height) * 4);
}

// A decoded image is consistent and makes a texture (its whole mip chain) of its size.
inline void check_decoded_image(const Image& image) {
  check_image(image);
  Texture texture(image);
  fuzz_check(texture.width() == image.width && texture.height() == image.height);
}

// The loaders get a small memory limit so that the fuzzer's own limit (-rss_limit_mb)
// only trips on real bugs.
inline LoadOptions fuzz_load_options() {
  LoadOptions options;
  options.max_memory = size_t(64) << 20;
  return options;
}

}  // namespace velocity::fuzz
