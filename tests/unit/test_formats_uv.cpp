// Texture coordinates per format: each loader turns its format's convention into the
// engine's (v = 0 at the image's top row). One quad per format, written by the test in
// that format with the format's own uvs, textured with a 2x2 image of four colours (top
// row red, green; bottom row blue, white), drawn, and the four quarters' pixels checked:
// red must be at the top left whatever the format (docs/appearance.md).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gltf_test_util.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;

class FormatsUv : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("velocity_formats_uv_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    Image img(2, 2);
    const uint8_t c[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int i = 0; i < 4; ++i) {
      uint8_t* p = img.pixel(i % 2, i / 2);
      p[0] = c[i][0], p[1] = c[i][1], p[2] = c[i][2], p[3] = 255;
    }
    write_png((dir_ / "four.png").string(), img);
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

  // Draws the model's quad (facing +Z, from -1 to 1) with the four-colour texture
  // (loaded here for formats that cannot name one), unlit, nearest texel, both sides;
  // returns the colours at the quarters' centres as "TL TR BL BR", each as three bits.
  std::string quarters(Model& m) {
    auto four = load_texture((dir_ / "four.png").string());
    for (ModelNode& n : m.nodes)
      if (n.mesh) {
        n.mesh->colors.clear();
        if (n.mesh->materials.empty()) n.mesh->materials.push_back({});
        for (Material& mat : n.mesh->materials) {
          if (!mat.texture) mat.texture = four;
          mat.shading = Shading::Unlit;
          mat.filter = Filter::Nearest;
          mat.two_sided = true;
          mat.color = {1, 1, 1};
        }
      }
    Scene scene;
    add_to_scene(scene, m);
    scene.camera.position = {0, 0, 3};
    Renderer r(64, 64);
    r.render(scene);
    Image img = r.color_image();
    std::string out;
    for (auto [x, y] : {std::pair{24, 24}, {40, 24}, {24, 40}, {40, 40}}) {
      const uint8_t* p = img.pixel(x, y);
      out += (out.empty() ? "" : " ") + std::to_string(p[0] > 128) + std::to_string(p[1] > 128) +
             std::to_string(p[2] > 128);
    }
    return out;
  }

  fs::path dir_;
  std::vector<std::string> warnings_;
  WarningHandler old_;
};

// Red, green / blue, white: the image as it is, the right way up and round.
const char* kUpright = "100 010 001 111";

TEST_F(FormatsUv, ObjVIsUp) {
  // OBJ: v = 1 at the image's top, so the quad's top corners have v = 1.
  write("quad.mtl", "newmtl four\nKd 1 1 1\nmap_Kd four.png\n");
  Model m = load_model(write("quad.obj",
                             "mtllib quad.mtl\n"
                             "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                             "usemtl four\nf 1/1 2/2 3/3 4/4\n"));
  ASSERT_TRUE(m.nodes.at(0).mesh->materials.at(0).texture);
  EXPECT_EQ(quarters(m), kUpright);
  EXPECT_TRUE(warnings_.empty());
}

TEST_F(FormatsUv, AscVIsUp) {
  // ASC (3D Studio, Z up; the loader stands it up): the quad in the file's XZ plane,
  // seen from the front (-Y), V = 1 at its top (z = 1); the material names the image.
  Model m = load_model(write("quad.asc",
                             "Named object: \"quad\"\nTri-mesh, Vertices: 4     Faces: 2\nMapped\nVertex list:\n"
                             "Vertex 0:  X: -1 Y: 0 Z: -1  U: 0 V: 0\nVertex 1:  X: 1 Y: 0 Z: -1  U: 1 V: 0\n"
                             "Vertex 2:  X: 1 Y: 0 Z: 1  U: 1 V: 1\nVertex 3:  X: -1 Y: 0 Z: 1  U: 0 V: 1\n"
                             "Face list:\n"
                             "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\nMaterial:\"four.png\"\n"
                             "Face 1:    A:0 B:2 C:3 AB:1 BC:1 CA:1\nMaterial:\"four.png\"\n"));
  ASSERT_TRUE(m.nodes.at(0).mesh->materials.at(0).texture);
  EXPECT_EQ(quarters(m), kUpright);
}

TEST_F(FormatsUv, PlyVIsUp) {
  // PLY's s, t: t = 1 at the image's top (PLY has no texture reference: the test's
  // texture is applied).
  Model m = load_model(write("quad.ply",
                             "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nproperty float s\nproperty float t\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n"
                             "-1 -1 0 0 0\n1 -1 0 1 0\n1 1 0 1 1\n-1 1 0 0 1\n4 0 1 2 3\n"));
  EXPECT_EQ(quarters(m), kUpright);
}

// A 3D Studio file: MAIN > EDITOR > OBJECT "quad" > TRIANGLES > VERTICES, FACES, UVS.
std::string tds_quad() {
  auto chunk = [](uint16_t id, const std::string& body) {
    std::string c(6, '\0');
    const uint32_t size = uint32_t(6 + body.size());
    std::memcpy(&c[0], &id, 2), std::memcpy(&c[2], &size, 4);
    return c + body;
  };
  auto bytes = [](const void* p, size_t n) { return std::string(static_cast<const char*>(p), n); };
  // Z up: the quad in the XZ plane, facing -Y (3D Studio's front view), V = 1 at z = 1.
  const uint16_t nv = 4, nf = 2;
  const float xyz[12] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  const float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  const uint16_t faces[8] = {0, 1, 2, 0, 0, 2, 3, 0};
  std::string mesh = chunk(0x4110, bytes(&nv, 2) + bytes(xyz, sizeof xyz)) +
                     chunk(0x4120, bytes(&nf, 2) + bytes(faces, sizeof faces)) +
                     chunk(0x4140, bytes(&nv, 2) + bytes(uv, sizeof uv));
  return chunk(0x4D4D, chunk(0x3D3D, chunk(0x4000, std::string("quad", 5) + chunk(0x4100, mesh))));
}

TEST_F(FormatsUv, ThreeDsVIsUp) {
  Model m = load_model(write("quad.3ds", tds_quad()));
  EXPECT_EQ(quarters(m), kUpright);
}

TEST_F(FormatsUv, GltfVIsDown) {
  // glTF: v = 0 at the image's top, so the quad's top corners have v = 0.
  test::GltfBuilder b;
  const int pos = b.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int uv = b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  const int idx = b.indices({0, 1, 2, 0, 2, 3});
  nlohmann::json primitive = {{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"indices", idx}};
  b.json["meshes"] = nlohmann::json::array({{{"primitives", nlohmann::json::array({primitive})}}});
  b.json["nodes"] = {{{"mesh", 0}}};
  b.json["scenes"] = {{{"nodes", {0}}}};
  Model m = load_model(write("quad.gltf", b.gltf()));
  EXPECT_EQ(quarters(m), kUpright);
}

TEST_F(FormatsUv, PlgAndStlHaveNone) {
  Model plg = load_model(write("tri.plg", "tri 3 1\n0 0 0\n1 0 0\n0 1 0\n0x10ff 3 0 1 2\n"));
  Model stl = load_model(write("tri.stl",
                               "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                               "endloop\nendfacet\nendsolid t\n"));
  for (Model* m : {&plg, &stl})
    for (const ModelNode& n : m->nodes)
      if (n.mesh) EXPECT_TRUE(n.mesh->uvs.empty()) << m->path;
}

}  // namespace
}  // namespace velocity
