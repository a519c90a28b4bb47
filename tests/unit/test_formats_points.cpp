// Point clouds: files with points and no faces (PLY with only vertices, OBJ with only
// `v` or `p`, glTF POINTS) load as points and draw as squares RenderOptions::point_size
// pixels a side.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gltf_test_util.hpp"
#include "velocity/load.hpp"
#include "velocity/renderer.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;

class FormatsPoints : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("velocity_formats_points_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

// The model's points drawn from (0, 0, 3) at 64x64 with `size`; how many pixels are
// not the clear colour.
int lit_pixels(const Model& m, float size, Image* out = nullptr) {
  Scene scene;
  add_to_scene(scene, m);
  scene.camera.position = {0, 0, 3};
  Renderer r(64, 64);
  r.options.point_size = size;
  r.render(scene);
  Image img = r.color_image();
  int n = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 4) n += img.pixels[i] > 100 || img.pixels[i + 1] > 100;
  if (out) *out = img;
  return n;
}

void expect_one_point(const Model& m) {
  ASSERT_EQ(m.vertex_count(), 1u);
  ASSERT_EQ(m.triangle_count(), 1u);
  for (const ModelNode& n : m.nodes)
    if (n.mesh) {
      EXPECT_EQ(n.mesh->materials.at(0).shading, Shading::Points) << m.path;
    }
  EXPECT_EQ(lit_pixels(m, 1), 1) << m.path;
  Image img;
  EXPECT_EQ(lit_pixels(m, 5, &img), 25) << m.path;
  EXPECT_GT(img.pixel(32, 32)[0], 100) << m.path;  // a 5x5 square about the centre
  EXPECT_GT(img.pixel(30, 30)[0], 100) << m.path;
}

TEST_F(FormatsPoints, PlyOnlyVertices) {
  expect_one_point(load_model(write("p.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                    "property float z\nend_header\n0 0 0\n")));
}

TEST_F(FormatsPoints, ObjOnlyVerticesOrPoints) {
  expect_one_point(load_model(write("v.obj", "v 0 0 0\n")));
  expect_one_point(load_model(write("p.obj", "v 0 0 0\np 1\n")));
}

TEST_F(FormatsPoints, GltfPoints) {
  test::GltfBuilder b;
  const int pos = b.floats({0, 0, 0}, "VEC3", 3);
  nlohmann::json primitive = {{"attributes", {{"POSITION", pos}}}, {"mode", 0}};
  b.json["meshes"] = nlohmann::json::array({{{"primitives", nlohmann::json::array({primitive})}}});
  b.json["nodes"] = {{{"mesh", 0}}};
  b.json["scenes"] = {{{"nodes", {0}}}};
  expect_one_point(load_model(write("p.gltf", b.gltf())));
}

TEST_F(FormatsPoints, AssimpModels) {
  const std::string file = "/usr/share/assimp/models/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (assimp-testmodels)";
  Model m = load_model(file);
  EXPECT_GT(m.vertex_count(), 0u);
  EXPECT_EQ(m.triangle_count(), m.vertex_count());
}

}  // namespace
}  // namespace velocity
