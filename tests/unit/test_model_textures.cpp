// Textures named by model files are found next to the model and loaded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

using namespace velocity;
namespace fs = std::filesystem;

namespace {

class ModelTextures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("velocity_model_textures_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    write_png((dir_ / "checker.png").string(), make_checkerboard(64, 8));
    old_ = set_warning_handler([this](std::string_view m) { warnings_.emplace_back(m); });
  }
  void TearDown() override {
    set_warning_handler(old_);
    fs::remove_all(dir_);
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
  std::vector<std::string> warnings_;
  WarningHandler old_;
};

const char* kQuadObj =
    "mtllib quad.mtl\n"
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl checked\n"
    "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

}  // namespace

TEST_F(ModelTextures, ObjMapKdIsFoundIgnoringCase) {
  write("quad.mtl", "newmtl checked\nKd 1 1 1\nmap_Kd CHECKER.PNG\n");
  Model m = load_model(write("quad.obj", kQuadObj));
  ASSERT_EQ(m.nodes.size(), 1u);
  const Material& mat = m.nodes[0].mesh->materials.at(0);
  EXPECT_EQ(mat.texture_file, "CHECKER.PNG");
  ASSERT_TRUE(mat.texture);
  EXPECT_EQ(mat.texture->width(), 64);
  EXPECT_TRUE(warnings_.empty());

  // And it is drawn: the quad shows both checker colours.
  Scene scene;
  add_to_scene(scene, m);
  scene.frame_camera(1.0f);
  Renderer r(64, 64);
  r.render(scene);
  Image img = r.color_image();
  bool dark = false, light = false;
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    dark |= img.pixels[i + 2] > 100 && img.pixels[i] < 60;   // (40, 60, 160), lit
    light |= img.pixels[i] > 150 && img.pixels[i + 2] < 90;  // (230, 200, 80), lit
  }
  EXPECT_TRUE(dark && light);
}

TEST_F(ModelTextures, AscMaterialNamingAnImageFile) {
  std::string asc = write("quad.asc",
                          "Named object: \"quad\"\nTri-mesh, Vertices: 3     Faces: 1\nVertex list:\n"
                          "Vertex 0:  X: 0 Y: 0 Z: 0  U: 0 V: 0\nVertex 1:  X: 1 Y: 0 Z: 0  U: 1 V: 0\n"
                          "Vertex 2:  X: 0 Y: 1 Z: 0  U: 0 V: 1\nFace list:\n"
                          "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\nMaterial:\"Checker.png\"\n");
  Model m = load_model(asc);
  const Material& mat = m.nodes.at(0).mesh->materials.at(0);
  EXPECT_EQ(mat.texture_file, "Checker.png");
  ASSERT_TRUE(mat.texture);
  EXPECT_EQ(mat.texture->height(), 64);
}

TEST_F(ModelTextures, MissingTextureIsAWarningNotAnError) {
  write("quad.mtl", "newmtl checked\nKd 1 0 0\nmap_Kd nowhere.png\n");
  Model m = load_model(write("quad.obj", kQuadObj));
  const Material& mat = m.nodes[0].mesh->materials.at(0);
  EXPECT_FALSE(mat.texture);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_NE(warnings_[0].find("nowhere.png"), std::string::npos);
  LoadOptions no_textures;
  no_textures.load_textures = false;
  warnings_.clear();
  load_model((dir_ / "quad.obj").string(), no_textures);
  EXPECT_TRUE(warnings_.empty());
}
