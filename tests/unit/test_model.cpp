// load_model's dispatch and file errors, Model's counts, and add_to_scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "loader_test_util.hpp"
#include "velocity/load.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;

// A scratch folder for the test's files, removed afterwards.
class ModelFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("velocity_model_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string error_of(const std::string& path, LoadOptions options = {}) {
    try {
      load_model(path, options);
    } catch (const Error& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

const char* kAsc =
    "Named object: \"T\"\nTri-mesh, Vertices: 3 Faces: 1\n"
    "Vertex 0: X: 0 Y: 0 Z: 0\nVertex 1: X: 1 Y: 0 Z: 0\nVertex 2: X: 0 Y: 1 Z: 0\nFace 0: A:0 B:1 C:2\n";
const char* kPlg = "tri 3 1\n0 0 0\n1 0 0\n0 1 0\n0x109f 3 0 1 2\n";

TEST_F(ModelFiles, DispatchesByExtensionCaseInsensitively) {
  EXPECT_EQ(load_model(write("a.ASC", kAsc)).triangle_count(), 1u);
  EXPECT_EQ(load_model(write("b.asc", kAsc)).nodes.at(0).name, "T");
  EXPECT_EQ(load_model(write("c.PLG", kPlg)).nodes.at(0).name, "tri");
  // .plx is read as the Tricks dialect: 0x109f is then two-sided.
  EXPECT_TRUE(load_model(write("d.plx", kPlg)).nodes.at(0).mesh->materials.at(0).two_sided);
  Model obj = load_model(write("e.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_EQ(obj.triangle_count(), 1u);
}

TEST_F(ModelFiles, RefusesImagesAndUnknownExtensions) {
  std::string pcx = write("t.pcx", "x");
  EXPECT_EQ(error_of(pcx), pcx + ": a PCX file is an image, not a model (read it with read_pcx)");
  std::string txt = write("t.txt", "x");
  EXPECT_EQ(error_of(txt), txt + ": unknown model extension 'txt' (expected .asc, .plg, .plx, .obj, .gltf, .glb, .3ds, .ply or .stl)");
  std::string none = write("noext", "x");
  EXPECT_EQ(error_of(none), none + ": unknown model extension '' (expected .asc, .plg, .plx, .obj, .gltf, .glb, .3ds, .ply or .stl)");
}

TEST_F(ModelFiles, MissingFileDirectoryAndSizeLimit) {
  std::string missing = (dir_ / "missing.asc").string();
  EXPECT_EQ(error_of(missing), missing + ": no such file");
  fs::create_directories(dir_ / "folder.asc");
  std::string folder = (dir_ / "folder.asc").string();
  EXPECT_EQ(error_of(folder), folder + ": is a directory, expected a file");
  std::string path = write("big.asc", kAsc);
  LoadOptions tiny;
  tiny.max_memory = 16;
  EXPECT_EQ(error_of(path, tiny), path + ": file is " + std::to_string(std::string(kAsc).size()) +
                                      " bytes, more than the limit of 16 (LoadOptions::max_memory)");
}

TEST_F(ModelFiles, ParseErrorsNameTheFile) {
  std::string path = write("bad.asc", "Named object: \"T\"\nTri-mesh, Vertices: 3 Faces: 1\n");
  EXPECT_EQ(error_of(path), path + ":2: expected 3 vertices in mesh 'T' (its Tri-mesh header), got 0");
}

Model two_level_model() {
  Model m;
  m.path = "made.asc";
  auto mesh = std::make_shared<Mesh>(make_cube());
  m.nodes.push_back({"body", mesh, translate({1, 0, 0}), -1});
  m.nodes.push_back({"wheel", mesh, translate({0, 2, 0}), 0});
  m.nodes.push_back({"pivot", nullptr, scale({2, 2, 2}), -1});
  m.lights.push_back(Light::ambient({0.2f, 0.2f, 0.2f}));
  m.lights.push_back(Light::point({0, 5, 0}, {1, 1, 1}));
  return m;
}

TEST(Model, CountsSumOverNodesWithMeshes) {
  Model m = two_level_model();
  EXPECT_EQ(m.vertex_count(), 2 * make_cube().vertex_count());
  EXPECT_EQ(m.triangle_count(), 24u);
  EXPECT_EQ(Model{}.vertex_count(), 0u);
}

TEST(Model, AddToSceneKeepsNamesHierarchyMatricesAndLights) {
  Scene scene;
  scene.lights.push_back(Light::directional({0, 1, 0}, {1, 1, 1}));
  ObjectId holder = scene.add_object("holder", nullptr);
  Model m = two_level_model();
  std::vector<ObjectId> roots = add_to_scene(scene, m, holder);
  ASSERT_EQ(scene.objects().size(), 4u);
  ASSERT_EQ(roots.size(), 2u);
  const Object& body = scene.object(roots[0]);
  EXPECT_EQ(body.name, "body");
  EXPECT_EQ(body.parent, holder);
  EXPECT_EQ(body.base, translate({1, 0, 0}));
  EXPECT_EQ(body.mesh, m.nodes[0].mesh);
  ObjectId wheel = *scene.find("wheel");
  EXPECT_EQ(scene.object(wheel).parent, roots[0]);
  EXPECT_EQ(scene.object(wheel).base, translate({0, 2, 0}));
  EXPECT_EQ(scene.object(roots[1]).name, "pivot");
  EXPECT_EQ(scene.object(roots[1]).mesh, nullptr);
  // The wheel sits at body (1, 0, 0) + its own (0, 2, 0).
  Vec3 at = scene.world_matrices()[wheel].transform_point({0, 0, 0});
  EXPECT_EQ(at, (Vec3{1, 2, 0}));
  ASSERT_EQ(scene.lights.size(), 3u);  // the scene's own light is kept, the model's appended
  EXPECT_EQ(scene.lights[1].type, LightType::Ambient);
  EXPECT_EQ(scene.lights[2].type, LightType::Point);
}

TEST(Model, AddToSceneRefusesABrokenHierarchyAndAddsNothing) {
  Scene scene;
  Model m = two_level_model();
  m.nodes[0].parent = 1;  // a child before its parent
  EXPECT_THROW(add_to_scene(scene, m), Error);
  EXPECT_TRUE(scene.objects().empty());
  EXPECT_TRUE(scene.lights.empty());
}

TEST(Model, RealFileIntoAScene) {
  Scene scene;
  Model m = load_model(test::test_data("models/UUSALKU.ASC"));
  std::vector<ObjectId> roots = add_to_scene(scene, m);
  EXPECT_EQ(roots.size(), 2u);
  EXPECT_TRUE(scene.find("s01").has_value());
  EXPECT_EQ(scene.lights.size(), 2u);  // ambient + Light01
  EXPECT_GT(scene.bounds().radius, 0.0f);
}

}  // namespace
}  // namespace velocity
