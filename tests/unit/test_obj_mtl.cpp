// OBJ/MTL materials as people write them: names with spaces, texture options (-s, -o,
// -bm, -clamp), normal maps (map_Bump, bump, norm), alpha (d, Tr, map_d), and the PBR
// parameters filled for --shading pbr (Pm, Pr, Ke, Ns); on files the tests write.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "velocity/load.hpp"
#include "velocity/log.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;

class ObjMtl : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("velocity_obj_mtl_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    old_ = set_warning_handler([this](std::string_view m) { warnings_.emplace_back(m); });
  }
  void TearDown() override {
    set_warning_handler(old_);
    fs::remove_all(dir_);
  }
  std::string write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return (dir_ / name).string();
  }
  void write_image(const std::string& name, int w, int h, uint32_t rgba) {
    write_png((dir_ / name).string(), Image(w, h, rgba));
  }
  fs::path dir_;
  std::vector<std::string> warnings_;
  WarningHandler old_;
};

const Material& material_of_face(const Mesh& mesh, size_t face) {
  return mesh.materials.at(mesh.face_materials.empty() ? 0 : mesh.face_materials.at(face));
}

TEST_F(ObjMtl, MaterialNamesWithSpaces) {
  // 3ds Max's default material name, a tab inside a name, and CRLF line ends.
  write("two.mtl", "newmtl 01 - Default\r\nKd 1 0 0\r\nnewmtl other\tmaterial  \r\nKd 0 1 0\r\n");
  Model m = load_model(write("two.obj",
                             "mtllib two.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 0\r\n"
                             "usemtl 01 - Default\r\nf 1 2 3\r\nusemtl other\tmaterial\r\nf 2 4 3\r\n"));
  const Mesh& mesh = *m.nodes.at(0).mesh;
  ASSERT_EQ(mesh.triangle_count(), 2u);
  EXPECT_EQ(material_of_face(mesh, 0).name, "01 - Default");
  EXPECT_EQ(material_of_face(mesh, 0).color, (Vec3{1, 0, 0}));
  EXPECT_EQ(material_of_face(mesh, 1).name, "other material");
  EXPECT_EQ(material_of_face(mesh, 1).color, (Vec3{0, 1, 0}));
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
}

TEST_F(ObjMtl, AssimpSpaceInMaterialName) {
  const std::string file = "/usr/share/assimp/models/OBJ/space_in_material_name.obj";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (assimp-testmodels)";
  // Every face uses "Hard Shiny Plastic White" (Kd 0.141176 0.184314 0.411765).
  Model m = load_model(file);
  size_t faces = 0;
  for (const ModelNode& n : m.nodes)
    if (n.mesh)
      for (size_t f = 0; f < n.mesh->triangle_count(); ++f, ++faces) {
        EXPECT_EQ(material_of_face(*n.mesh, f).name, "Hard Shiny Plastic White");
        EXPECT_EQ(material_of_face(*n.mesh, f).color, (Vec3{0.141176f, 0.184314f, 0.411765f}));
      }
  EXPECT_GT(faces, 0u);
  for (const std::string& w : warnings_) EXPECT_EQ(w.find("not found in .mtl"), std::string::npos) << w;
}

TEST_F(ObjMtl, TextureOptionsNormalMapsAlphaAndPbr) {
  write_image("wood.png", 4, 4, 0xff336699u);
  write_image("n.png", 4, 4, 0xffff8080u);
  write_image("glow.png", 4, 4, 0xff00ffffu);
  // The alpha map: a grey level of 0x40 everywhere, at half the base texture's size.
  write_image("cut.png", 2, 2, 0xff404040u);
  write("m.mtl",
        "newmtl a\nKd 0.5 0.25 1\nKs 0.5 0.5 0.5\nNs 98\nd 0.75\n"
        "map_Kd -s 2 4 1 -o 0.5 0.25 0 -clamp on wood.png\n"
        "map_Bump -bm 0.4 n.png\nmap_d cut.png\n"
        "newmtl b\nKd 1 1 1\nPm 0.8\nPr 0.3\nKe 0.1 0.2 0.3\nmap_Ke glow.png\nnorm n.png\nTr 0.25\n"
        "newmtl c\nKd 1 1 1\nbump n.png\n");
  Model m = load_model(write("m.obj",
                             "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                             "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 2/2\nusemtl c\nf 1/1 2/2 3/3\n"));
  const Mesh& mesh = *m.nodes.at(0).mesh;
  const Material& a = material_of_face(mesh, 0);
  const Material& b = material_of_face(mesh, 1);
  const Material& c = material_of_face(mesh, 2);
  ASSERT_EQ(a.name, "a");
  EXPECT_EQ(a.shading, Shading::Phong);  // the seed's shading stays the default
  EXPECT_EQ(a.color_space, ColorSpace::Srgb);
  // -s 2 4, -o 0.5 0.25 in OBJ's v-up uvs: in the engine's (v flipped) the offset's v is
  // 1 - 4 - 0.25.
  EXPECT_EQ(a.texture_uv.scale, (Vec2{2, 4}));
  EXPECT_EQ(a.texture_uv.offset, (Vec2{0.5f, -3.25f}));
  EXPECT_EQ(a.wrap, Wrap::Clamp);
  EXPECT_EQ(a.alpha, 0.75f);
  EXPECT_EQ(a.alpha_mode, AlphaMode::Blend);
  // map_d: the base texture's alpha is the map's grey level (0x40), its colour kept.
  ASSERT_TRUE(a.texture);
  EXPECT_EQ(a.texture->width(), 4);
  for (uint32_t t : a.texture->levels()[0].texels) EXPECT_EQ(t, 0x40336699u);
  ASSERT_TRUE(a.pbr.normal);
  EXPECT_EQ(a.pbr.normal.file, "n.png");
  EXPECT_FLOAT_EQ(a.pbr.normal_scale, 0.4f);
  EXPECT_EQ(a.pbr.metallic, 0.0f);
  EXPECT_NEAR(a.pbr.roughness, std::pow(2.0 / 100, 0.25), 1e-6);  // from Ns 98

  EXPECT_EQ(b.pbr.metallic, 0.8f);
  EXPECT_FLOAT_EQ(b.pbr.roughness, 0.3f);
  EXPECT_EQ(b.pbr.emissive, (Vec3{0.1f, 0.2f, 0.3f}));
  ASSERT_TRUE(b.pbr.emissive_map);
  EXPECT_EQ(b.pbr.emissive_map.texture->levels()[0].texels[0], 0xff00ffffu);
  ASSERT_TRUE(b.pbr.normal);  // norm
  EXPECT_EQ(b.pbr.normal.texture, a.pbr.normal.texture);  // one file, loaded once
  EXPECT_FLOAT_EQ(b.alpha, 0.75f);                        // Tr 0.25
  EXPECT_FALSE(b.texture);
  EXPECT_TRUE(c.pbr.normal);  // bump
  EXPECT_EQ(c.alpha_mode, AlphaMode::Opaque);
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
}

TEST_F(ObjMtl, AlphaMapWithoutABaseTexture) {
  Image cut(2, 1);
  cut.pixel(0, 0)[3] = 255, cut.pixel(1, 0)[3] = 0;  // an alpha channel: it is the map
  write_png((dir_ / "cut.png").string(), cut);
  write("m.mtl", "newmtl a\nKd 1 0 0\nmap_d cut.png\n");
  Model m = load_model(write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"));
  const Material& a = m.nodes.at(0).mesh->materials.at(0);
  ASSERT_TRUE(a.texture);
  EXPECT_EQ(a.texture->levels()[0].texels, (std::vector<uint32_t>{0xffffffffu, 0x00ffffffu}));
  EXPECT_EQ(a.color, (Vec3{1, 0, 0}));
}

}  // namespace
}  // namespace velocity
