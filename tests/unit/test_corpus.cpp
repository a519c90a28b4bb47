// The corpus: every real file under ../shared/data/models loads, with the counts its own
// headers declare (found here by a separate, simpler scan); every file under an
// invalid/ folder is refused. Skipped, saying so, when the shared folder is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "loader_test_util.hpp"
#include "velocity/load.hpp"

#if __has_include("velocity/renderer.hpp")
#include "velocity/renderer.hpp"
#define VELOCITY_HAVE_RENDERER 1
#endif

namespace velocity {
namespace {

namespace fs = std::filesystem;
using test::read_bytes;
using test::shared_data;

std::string models_dir() { return shared_data("models"); }

#define REQUIRE_CORPUS()                                                                                   \
  do {                                                                                                     \
    if (!fs::is_directory(models_dir()))                                                                   \
      GTEST_SKIP() << "skipped: the shared corpus " << models_dir() << " is missing (it lives beside the " \
                   << "repository in ../shared/data; see SOURCES.md), so no real file was checked";        \
  } while (0)

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Every file under models/, sorted; `invalid` selects the files under an invalid/ folder.
std::vector<fs::path> corpus_files(bool invalid) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(models_dir())) {
    if (!e.is_regular_file()) continue;
    bool in_invalid = e.path().parent_path().filename() == "invalid";
    if (in_invalid == invalid) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Expected {
  size_t vertices = 0, triangles = 0, meshes = 0;
  // ASC: each mesh's name and header counts, in file order.
  std::vector<std::tuple<std::string, size_t, size_t>> per_mesh;
};

// ASC: every "Tri-mesh, Vertices: N Faces: M" header and the "Named object" before it
// (split on whitespace, no code shared with the reader), and their sums.
Expected scan_asc(const std::string& text) {
  Expected e;
  std::istringstream in(text);
  std::string line, name;
  while (std::getline(in, line)) {
    if (line.rfind("Named object:", 0) == 0) {
      size_t open = line.find('"'), close = line.rfind('"');
      name = line.substr(open + 1, close - open - 1);
    }
    if (line.rfind("Tri-mesh,", 0) != 0) continue;
    std::istringstream words(line);
    std::string w;
    size_t v = 0, f = 0;
    while (words >> w) {
      if (w == "Vertices:") words >> w, v = std::stoul(w);
      if (w == "Faces:") words >> w, f = std::stoul(w);
    }
    e.per_mesh.emplace_back(name, v, f);
    e.vertices += v, e.triangles += f, ++e.meshes;
  }
  return e;
}

// PLG: the header's vertex count, and sum(n - 2) over the polygons with n >= 3.
Expected scan_plg(const std::string& text) {
  Expected e;
  std::istringstream in(text);
  std::string line;
  std::vector<std::vector<std::string>> records;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find_first_of(";#"));
    std::istringstream words(line);
    std::vector<std::string> tokens;
    for (std::string w; words >> w;) tokens.push_back(w);
    if (!tokens.empty()) records.push_back(tokens);
  }
  if (records.empty()) return e;
  e.vertices = std::stoul(records[0][1]);
  size_t polygons = std::stoul(records[0][2]);
  for (size_t i = 0; i < polygons; ++i) {
    size_t n = std::stoul(records.at(1 + e.vertices + i).at(1));
    if (n >= 3) e.triangles += n - 2;
  }
  e.meshes = 1;
  return e;
}

// Totals from shared/data/SOURCES.md, written by hand: a second, independent check.
const std::map<std::string, std::pair<size_t, size_t>> kSourcesTotals = {
    {"CITY.ASC", {610, 796}},   {"UUSALKU.ASC", {180, 324}},     {"TESTI.ASC", {13, 9}},
    {"car01.asc", {561, 573}},  {"cube01.asc", {8, 12}},          {"hammer02.asc", {460, 784}},
    {"hammer03.asc", {460, 784}}, {"sphere01.asc", {482, 960}},   {"duck.asc", {304, 564}},
    {"cube.asc", {8, 12}},      {"fork.asc", {48, 72}},           {"rails.asc", {992, 1620}},
    {"floor.asc", {225, 392}},  {"house-3d.asc", {196, 184}},     {"plunger.asc", {4, 2}},
    {"floor-walls-side.asc", {378, 434}}, {"bumper.asc", {16, 22}},
};

TEST(Corpus, EveryModelLoadsWithItsHeaderCounts) {
  REQUIRE_CORPUS();
  size_t checked = 0;
  for (const fs::path& path : corpus_files(false)) {
    SCOPED_TRACE(path.string());
    std::string ext = lower(path.extension().string());
    std::string text = read_bytes(path.string());
    Expected want = ext == ".asc" ? scan_asc(text) : scan_plg(text);
    Model m;
    try {
      m = load_model(path.string());
    } catch (const Error& e) {
      ADD_FAILURE() << "failed to load: " << e.what();
      continue;
    }
    EXPECT_EQ(m.nodes.size(), want.meshes);
    EXPECT_EQ(m.triangle_count(), want.triangles);
    if (ext == ".asc") {
      // Per object: the name, the faces, and at least the header's vertices
      // (compute_normals() adds copies along hard edges, after the file's own).
      for (size_t i = 0; i < std::min(m.nodes.size(), want.per_mesh.size()); ++i) {
        const auto& [name, v, f] = want.per_mesh[i];
        EXPECT_EQ(m.nodes[i].name, name);
        EXPECT_EQ(m.nodes[i].mesh->triangle_count(), f) << name;
        EXPECT_GE(m.nodes[i].mesh->vertex_count(), v) << name;
      }
      EXPECT_GE(m.vertex_count(), want.vertices);
      auto totals = kSourcesTotals.find(path.filename().string());
      if (totals != kSourcesTotals.end()) {
        EXPECT_EQ(totals->second.first, want.vertices);
        EXPECT_EQ(totals->second.second, want.triangles);
      }
    } else {
      EXPECT_EQ(m.vertex_count(), want.vertices);
    }
    for (const ModelNode& n : m.nodes) {
      ASSERT_TRUE(n.mesh);
      EXPECT_NO_THROW(n.mesh->validate()) << n.name;
      EXPECT_EQ(n.mesh->normals.size(), n.mesh->positions.size()) << n.name;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 18u + 36u);  // SOURCES.md: 18 ASC files; 16 Black Art and 20 Tricks PLG files
}

TEST(Corpus, InvalidFilesAreRefused) {
  REQUIRE_CORPUS();
  std::vector<fs::path> files = corpus_files(true);
  ASSERT_FALSE(files.empty());
  for (const fs::path& path : files) {
    try {
      load_model(path.string());
      ADD_FAILURE() << path << " loaded, but it is not a model";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(path.string() + ":"), std::string::npos) << e.what();
    }
  }
}

// A closed, outward-facing mesh encloses a positive volume (the divergence theorem over
// its triangles); a reader that got a dialect's winding backwards makes it negative. A
// few files contradict their own book's back-face rule; they are listed, so that a
// change in the reader shows up here either way.
TEST(Corpus, PlgWindingGivesPositiveVolume) {
  REQUIRE_CORPUS();
  const std::map<std::string, const char*> reversed = {
      // One-sided in Black Art's engine, yet every face is listed the other way round:
      // the book's own renderer shows their insides (convex, so it goes unnoticed).
      {"PYRAMID.PLG", "all 5 faces against Black Art's rule"},
      {"DIAMOND.PLG", "all 8 faces against Black Art's rule"},
      {"TELE.PLG", "half of its faces against Black Art's rule"},
      // Two-sided (0xdfff), so the order never mattered in Tricks' engine; the corrected
      // tank2/tank3 and tower1 files list the same faces the other way.
      {"tank1.plg", "two-sided, reversed"},
      {"tower_t3d.plg", "two-sided, reversed"},
  };
  for (const fs::path& path : corpus_files(false)) {
    if (lower(path.extension().string()) != ".plg") continue;
    std::string name = path.filename().string();
    if (name == "DART.PLG") continue;  // three open fins: no volume
    Model m = load_model(path.string());
    const Mesh& mesh = *m.nodes.at(0).mesh;
    double volume = 0;
    for (const Triangle& t : mesh.triangles) {
      Vec3 a = mesh.positions[t.v[0]], b = mesh.positions[t.v[1]], c = mesh.positions[t.v[2]];
      volume += double(dot(a, cross(b, c))) / 6.0;
    }
    if (reversed.count(name))
      EXPECT_LT(volume, 0.0) << name << ": " << reversed.at(name);
    else
      EXPECT_GT(volume, 0.0) << name;
  }
}

#ifdef VELOCITY_HAVE_RENDERER
// Pixels of `image` that differ from the background an empty scene renders to.
size_t drawn_pixels(const Image& image, const Image& empty) {
  size_t n = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4)
    n += std::memcmp(&image.pixels[i], &empty.pixels[i], 3) != 0;
  return n;
}

// Every model draws something. Seen from a corner (flat models such as floor.asc are
// edge-on from straight ahead) and without back-face culling (single-sided sheets such
// as plunger.asc may face away).
TEST(Corpus, EveryModelRendersANonEmptyImage) {
  REQUIRE_CORPUS();
  Renderer renderer(96, 72);
  renderer.options.cull_back_faces = false;
  Scene empty_scene;
  renderer.render(empty_scene);
  Image empty = renderer.color_image();
  for (const fs::path& path : corpus_files(false)) {
    Scene scene;
    add_to_scene(scene, load_model(path.string()));
    scene.frame_camera(96.0f / 72.0f);
    Sphere s = scene.bounds();
    float d = length(scene.camera.position - s.center);
    scene.camera.position = s.center + normalize(Vec3{1.0f, 0.8f, 1.2f}) * d;
    scene.camera.look_at(s.center);
    renderer.render(scene);
    EXPECT_GT(drawn_pixels(renderer.color_image(), empty), 50u) << path.filename();
  }
}

// The cameras stored in the files look at their scenes: a wrong axis conversion or
// look-at would point them into the void.
TEST(Corpus, FileCamerasSeeTheirScenes) {
  REQUIRE_CORPUS();
  Renderer renderer(96, 72);
  Scene empty_scene;
  renderer.render(empty_scene);
  Image empty = renderer.color_image();
  size_t cameras = 0;
  for (const fs::path& path : corpus_files(false)) {
    Model m = load_model(path.string());
    for (const NamedCamera& c : m.cameras) {
      // Second Reality's opening camera starts inside the first object's height range,
      // looking away from everything: the demo animates it from there.
      if (path.filename() == "UUSALKU.ASC") continue;
      Scene scene;
      add_to_scene(scene, m);
      scene.camera = c.camera;
      renderer.render(scene);
      EXPECT_GT(drawn_pixels(renderer.color_image(), empty), 200u) << path.filename() << " camera " << c.name;
      ++cameras;
    }
  }
  EXPECT_EQ(cameras, 3u);  // CITY.ASC, duck.asc, duck_redscripts.asc
}
#endif

// The copies in tests/data/models are byte-for-byte the shared originals.
TEST(Corpus, ProjectCopiesMatchTheOriginals) {
  REQUIRE_CORPUS();
  for (const char* name : {"CITY.ASC", "UUSALKU.ASC", "TESTI.ASC", "fork.asc", "duck.asc"})
    EXPECT_EQ(read_bytes(test::test_data(std::string("models/") + name)),
              read_bytes(shared_data(std::string("models/asc/") + name)))
        << name;
}

}  // namespace
}  // namespace velocity
