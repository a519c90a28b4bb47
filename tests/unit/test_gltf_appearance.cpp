// glTF 2.0 appearance as the file says it: metallic-roughness materials, texture uv sets
// and KHR_texture_transform, TEXCOORD_1, TANGENT, COLOR_0's alpha, KHR_lights_punctual,
// and images inside the file (a .glb's buffer, data URIs), on files the tests write.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gltf_test_util.hpp"
#include "io/gltf_appearance.hpp"
#include "loader_test_util.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;
using test::GltfBuilder;

class GltfAppearanceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("velocity_gltf_appearance_" + std::to_string(::getpid()) + "_" +
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
  fs::path dir_;
  std::vector<std::string> warnings_;
  WarningHandler old_;
};

// A 2x2 PNG, each texel its own colour: top row red, green; bottom row blue, white.
std::string four_colour_png(const fs::path& dir) {
  Image img(2, 2);
  const uint8_t c[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  for (int i = 0; i < 4; ++i) {
    uint8_t* p = img.pixel(i % 2, i / 2);
    p[0] = c[i][0], p[1] = c[i][1], p[2] = c[i][2], p[3] = 255;
  }
  const std::string file = (dir / "four.png").string();
  write_png(file, img);
  return test::read_bytes(file);
}

// A quad from (-1, -1) to (1, 1) facing +Z with glTF's uvs (v = 0 at the image's top
// row, so at y = +1), TEXCOORD_1 mirrored in u, tangents (w -1 on the last two
// vertices) and COLOR_0 with alpha; `materials` primitives over it, one per entry (-1:
// none).
void add_quad(GltfBuilder& b, const std::vector<int>& materials) {
  const int pos = b.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int nrm = b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int uv0 = b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  const int uv1 = b.floats({1, 1, 0, 1, 0, 0, 1, 0}, "VEC2", 2);
  const int tan = b.floats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1, 1, 0, 0, -1}, "VEC4", 4);
  const int col = b.floats({1, 0, 0, 1, 0, 1, 0, 0.5f, 0, 0, 1, 0.25f, 1, 1, 1, 0}, "VEC4", 4);
  const int idx = b.indices({0, 1, 2, 0, 2, 3});
  nlohmann::json prims = nlohmann::json::array();
  for (int m : materials) {
    nlohmann::json p = {{"attributes",
                         {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1},
                          {"TANGENT", tan}, {"COLOR_0", col}}},
                        {"indices", idx}};
    if (m >= 0) p["material"] = m;
    prims.push_back(p);
  }
  b.json["meshes"].push_back({{"primitives", prims}});
  b.json["nodes"].push_back({{"name", "quad"}, {"mesh", 0}});
  b.json["scenes"] = {{{"nodes", {0}}}};
  b.json["scene"] = 0;
}

// The quad's mesh (Assimp makes a single root node the model's root).
Mesh& quad_mesh(Model& m) {
  for (ModelNode& n : m.nodes)
    if (n.mesh) return *n.mesh;
  throw Error("no mesh");
}

const Material* find_material(const Mesh& mesh, const std::string& name) {
  for (const Material& m : mesh.materials)
    if (m.name == name) return &m;
  return nullptr;
}

TEST_F(GltfAppearanceTest, MetallicRoughnessMaterialsAsAuthored) {
  GltfBuilder b;
  const int tex = b.texture(b.image_in_buffer(four_colour_png(dir_)));
  add_quad(b, {1, 0, -1});
  b.json["materials"] = nlohmann::json::parse(R"([
    {"name": "plain", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 0.5]}, "alphaMode": "BLEND"},
    {"name": "full",
     "pbrMetallicRoughness": {
       "baseColorTexture": {"index": 0, "texCoord": 1, "extensions": {"KHR_texture_transform":
         {"offset": [0.5, 0.25], "rotation": 0.5, "scale": [2, 3]}}},
       "metallicFactor": 0.25, "roughnessFactor": 0.75,
       "metallicRoughnessTexture": {"index": 0}},
     "normalTexture": {"index": 0, "scale": 0.5},
     "occlusionTexture": {"index": 0, "strength": 0.3, "extensions": {"KHR_texture_transform": {"texCoord": 1}}},
     "emissiveTexture": {"index": 0},
     "emissiveFactor": [1, 0.5, 0],
     "alphaMode": "MASK", "alphaCutoff": 0.25, "doubleSided": true,
     "extensions": {"KHR_materials_unlit": {}}}])");
  (void)tex;
  b.json["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_unlit"};
  Model m = load_model(write("quad.glb", b.glb()));
  const Mesh& mesh = quad_mesh(m);
  ASSERT_EQ(mesh.materials.size(), 3u);
  // One primitive per material, in the file's order: full, plain, the default.
  ASSERT_EQ(mesh.face_materials.size(), 6u);
  EXPECT_EQ(mesh.materials[mesh.face_materials[0]].name, "full");
  EXPECT_EQ(mesh.materials[mesh.face_materials[2]].name, "plain");
  const Material& def = mesh.materials[mesh.face_materials[4]];

  const Material* plain = find_material(mesh, "plain");
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->shading, Shading::Pbr);
  EXPECT_EQ(plain->color_space, ColorSpace::Linear);
  EXPECT_EQ(plain->color, (Vec3{0.2f, 0.4f, 0.6f}));
  EXPECT_EQ(plain->alpha, 0.5f);
  EXPECT_EQ(plain->alpha_mode, AlphaMode::Blend);
  EXPECT_FALSE(plain->two_sided);
  EXPECT_EQ(plain->pbr.metallic, 1.0f);  // the spec's defaults
  EXPECT_EQ(plain->pbr.roughness, 1.0f);
  EXPECT_FALSE(plain->texture);
  EXPECT_FALSE(plain->pbr.unlit);

  const Material* full = find_material(mesh, "full");
  ASSERT_TRUE(full);
  EXPECT_EQ(full->shading, Shading::Pbr);
  EXPECT_EQ(full->color, (Vec3{1, 1, 1}));
  EXPECT_EQ(full->pbr.metallic, 0.25f);
  EXPECT_EQ(full->pbr.roughness, 0.75f);
  ASSERT_TRUE(full->texture);
  EXPECT_EQ(full->texture->width(), 2);
  EXPECT_EQ(full->texture->levels()[0].texels[0], 0xff0000ffu);  // red, the image's top-left texel
  EXPECT_EQ(full->texture_file, "");                             // embedded
  EXPECT_EQ(full->texture_uv.uv_set, 1);
  EXPECT_EQ(full->texture_uv.offset, (Vec2{0.5f, 0.25f}));
  EXPECT_EQ(full->texture_uv.rotation, 0.5f);
  EXPECT_EQ(full->texture_uv.scale, (Vec2{2, 3}));
  EXPECT_EQ(full->pbr.metallic_roughness.texture, full->texture);  // one image, decoded once
  EXPECT_TRUE(full->pbr.metallic_roughness.uv.identity());
  EXPECT_TRUE(full->pbr.normal);
  EXPECT_EQ(full->pbr.normal_scale, 0.5f);
  EXPECT_TRUE(full->pbr.occlusion);
  EXPECT_EQ(full->pbr.occlusion.uv.uv_set, 1);  // the transform's texCoord overrides
  EXPECT_FLOAT_EQ(full->pbr.occlusion_strength, 0.3f);
  EXPECT_TRUE(full->pbr.emissive_map);
  EXPECT_EQ(full->pbr.emissive, (Vec3{1, 0.5f, 0}));
  EXPECT_EQ(full->alpha_mode, AlphaMode::Mask);
  EXPECT_EQ(full->alpha_cutoff, 0.25f);
  EXPECT_TRUE(full->two_sided);
  EXPECT_TRUE(full->pbr.unlit);

  // The spec's default material: white, metallic 1, roughness 1.
  EXPECT_EQ(def.shading, Shading::Pbr);
  EXPECT_EQ(def.color, (Vec3{1, 1, 1}));
  EXPECT_EQ(def.pbr.metallic, 1.0f);
  EXPECT_EQ(def.pbr.roughness, 1.0f);
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
}

TEST_F(GltfAppearanceTest, SecondUvSetTangentsAndVertexAlpha) {
  GltfBuilder b;
  add_quad(b, {-1});
  Model m = load_model(write("quad.gltf", b.gltf()));
  const Mesh& mesh = quad_mesh(m);
  ASSERT_EQ(mesh.vertex_count(), 4u);
  // Vertex 0 is (-1, -1): glTF's TEXCOORD_0 (0, 1), TEXCOORD_1 (1, 1) -- the same
  // numbers in the engine's convention (v = 0 at the top row, as glTF's).
  ASSERT_EQ(mesh.uvs.size(), 4u);
  ASSERT_EQ(mesh.uvs1.size(), 4u);
  for (size_t v = 0; v < 4; ++v) {
    const Vec3 p = mesh.positions[v];
    EXPECT_EQ(mesh.uvs[v], (Vec2{p.x > 0 ? 1.0f : 0.0f, p.y > 0 ? 0.0f : 1.0f})) << v;
    EXPECT_EQ(mesh.uvs1[v], (Vec2{p.x > 0 ? 0.0f : 1.0f, p.y > 0 ? 0.0f : 1.0f})) << v;
  }
  ASSERT_EQ(mesh.tangents.size(), 4u);
  ASSERT_EQ(mesh.alphas.size(), 4u);
  ASSERT_EQ(mesh.colors.size(), 4u);
  for (size_t v = 0; v < 4; ++v) {
    const Vec3 p = mesh.positions[v];
    const size_t file_index = p.x < 0 ? (p.y < 0 ? 0 : 3) : (p.y < 0 ? 1 : 2);
    EXPECT_EQ(mesh.tangents[v].x, 1.0f);
    EXPECT_EQ(mesh.tangents[v].w, file_index >= 2 ? -1.0f : 1.0f) << v;
    const float alpha[4] = {1, 0.5f, 0.25f, 0};
    EXPECT_EQ(mesh.alphas[v], alpha[file_index]) << v;
  }
}

TEST_F(GltfAppearanceTest, PunctualLightsPlacedByTheirNodes) {
  GltfBuilder b;
  add_quad(b, {-1});
  b.json["extensionsUsed"] = {"KHR_lights_punctual"};
  b.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::parse(R"([
    {"type": "point", "color": [1, 0.5, 0.25], "intensity": 4, "range": 10},
    {"type": "directional", "intensity": 2},
    {"type": "spot", "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}}])");
  // Node 1 at (1, 2, 3) holds the point light; its child node 2, one unit along -Z, the
  // spot; node 3, turned -90 degrees about X (its -Z points down), the directional.
  b.json["nodes"].push_back({{"translation", {1, 2, 3}}, {"children", {2}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.json["nodes"].push_back({{"translation", {0, 0, -1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  b.json["nodes"].push_back({{"rotation", {-std::sqrt(0.5), 0, 0, std::sqrt(0.5)}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  b.json["scenes"][0]["nodes"] = {0, 1, 3};
  Model m = load_model(write("lights.gltf", b.gltf()));
  ASSERT_EQ(m.lights.size(), 3u);
  auto near = [](Vec3 a, Vec3 e) { return length(a - e) < 1e-5f; };
  const Light* point = nullptr, *spot = nullptr, *sun = nullptr;
  for (const Light& l : m.lights)
    (l.type == LightType::Point ? point : l.type == LightType::Spot ? spot : sun) = &l;
  ASSERT_TRUE(point && spot && sun);
  EXPECT_TRUE(near(point->position, {1, 2, 3}));
  EXPECT_TRUE(near(point->color, {4, 2, 1}));  // colour times intensity
  EXPECT_EQ(point->falloff, Falloff::InverseSquare);
  EXPECT_EQ(point->range, 10.0f);
  EXPECT_TRUE(near(spot->position, {1, 2, 2}));
  EXPECT_TRUE(near(spot->direction, {0, 0, 1}));  // towards the light: it shines along -Z
  EXPECT_FLOAT_EQ(spot->inner_cone, 0.2f);
  EXPECT_FLOAT_EQ(spot->outer_cone, 0.4f);
  EXPECT_EQ(spot->range, 0.0f);  // none: infinite
  EXPECT_EQ(spot->falloff, Falloff::InverseSquare);
  EXPECT_TRUE(near(sun->direction, {0, 1, 0})) << sun->direction.x << " " << sun->direction.y << " " << sun->direction.z;
  EXPECT_TRUE(near(sun->color, {2, 2, 2}));
}

TEST_F(GltfAppearanceTest, BadValuesAreClearErrors) {
  struct Case {
    const char* materials;
    const char* expect;
  } cases[] = {
      {R"([{"alphaMode": "SOMETIMES"}])", "alphaMode is \"SOMETIMES\""},
      {R"([{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1]}}])", "expected 4 numbers"},
      {R"([{"pbrMetallicRoughness": {"metallicFactor": 2}}])", "\"metallicFactor\" is 2"},
      {R"([{"normalTexture": {"index": 7}}])", "normalTexture: index is 7"},
      {R"([{"emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": ["x", 1]}}}}])",
       "KHR_texture_transform"},
  };
  for (const Case& c : cases) {
    GltfBuilder b;
    b.texture(b.image_uri("four.png"));
    add_quad(b, {0});
    b.json["materials"] = nlohmann::json::parse(c.materials);
    const std::string file = write("bad.gltf", b.gltf());
    try {
      load_model(file);
      ADD_FAILURE() << c.materials << ": loaded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("bad.gltf: material 0: "), std::string::npos) << e.what();
    }
  }
  GltfBuilder b;
  add_quad(b, {-1});
  b.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::parse(
      R"([{"type": "spot", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.4}}])");
  b.json["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  try {
    load_model(write("spot.gltf", b.gltf()));
    ADD_FAILURE() << "a spot light whose inner cone is wider than its outer one loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("light 0: spot: innerConeAngle 0.5 is not below outerConeAngle"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(GltfAppearanceTest, DataUris) {
  EXPECT_EQ(detail::decode_data_uri("data:text/plain;base64,SGVsbG8=", "t"), "Hello");
  EXPECT_EQ(detail::decode_data_uri("data:text/plain;base64,SGVsbG8h", "t"), "Hello!");
  EXPECT_EQ(detail::decode_data_uri("data:,a%20b%2", "t"), "a b%2");
  EXPECT_THROW(detail::decode_data_uri("data:;base64,SGV*bG8=", "t"), Error);
  EXPECT_THROW(detail::decode_data_uri("data:;base64,SG=Vs", "t"), Error);
  EXPECT_THROW(detail::decode_data_uri("data:text/plain;base64", "t"), Error);
}

// The image inside the file is drawn, the right way up: the 2x2 image's red texel at
// the quad's top left, green top right, blue bottom left, white bottom right; as a .glb
// (image in the binary chunk) and as a .gltf (image as a data URI).
TEST_F(GltfAppearanceTest, EmbeddedImagesAreDrawnTheRightWayUp) {
  const std::string png = four_colour_png(dir_);
  for (bool binary : {true, false}) {
    GltfBuilder b;
    b.texture(binary ? b.image_in_buffer(png) : b.image_uri("data:image/png;base64," + test::base64(png)));
    add_quad(b, {0});
    b.json["materials"] = nlohmann::json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    Model m = load_model(write(binary ? "quad.glb" : "quad.gltf", binary ? b.glb() : b.gltf()));
    Mesh& mesh = quad_mesh(m);
    ASSERT_TRUE(mesh.materials.at(0).texture) << binary;
    // Drawn unlit (the texture as it is) and without the vertex colours, so that the
    // pixels are the texels, whatever the lighting model does.
    mesh.materials[0].shading = Shading::Unlit;
    mesh.materials[0].filter = Filter::Nearest;
    mesh.colors.clear();
    Scene scene;
    add_to_scene(scene, m);
    scene.frame_camera(1.0f);
    Renderer r(64, 64);
    r.render(scene);
    Image img = r.color_image();
    auto rgb = [&](int x, int y) {
      const uint8_t* p = img.pixel(x, y);
      return std::to_string(p[0] > 128) + std::to_string(p[1] > 128) + std::to_string(p[2] > 128);
    };
    EXPECT_EQ(rgb(26, 26), "100") << binary << " top left: red";
    EXPECT_EQ(rgb(38, 26), "010") << binary << " top right: green";
    EXPECT_EQ(rgb(26, 38), "001") << binary << " bottom left: blue";
    EXPECT_EQ(rgb(38, 38), "111") << binary << " bottom right: white";
  }
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
}

TEST_F(GltfAppearanceTest, BrokenEmbeddedImageIsAWarning) {
  GltfBuilder b;
  b.texture(b.image_in_buffer("\x89PNG\r\n\x1a\n not really"));
  add_quad(b, {0});
  b.json["materials"] = nlohmann::json::parse(R"([{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
  Model m = load_model(write("broken.glb", b.glb()));
  EXPECT_FALSE(quad_mesh(m).materials.at(0).texture);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_NE(warnings_[0].find("broken.glb image 0: cannot read image"), std::string::npos) << warnings_[0];
}

}  // namespace
}  // namespace velocity

namespace velocity {
namespace {

// assimp-testmodels' BoxTextured in its three forms (image file, data URIs, .glb):
// each draws the Cesium logo on the front face (the file's -Y face, +Z once its root
// node stands it up) upright -- sky blue above, grass green below. The file's uvs run
// u from 4 at the left to 3 at the right: with the .gltf's sampler (wrapS
// MIRRORED_REPEAT, wrapT CLAMP_TO_EDGE, whose v stays in [0, 1]) the logo reads the
// right way round, the white sun on the right; the other two forms' sampler repeats, so
// there the logo is mirrored as authored, the sun on the left.
TEST(GltfBoxTextured, ImagesInAllThreeFormsDrawUpright) {
  const std::string models = "/usr/share/assimp/models/glTF2/";
  if (!fs::is_directory(models)) GTEST_SKIP() << "skipped: " << models << " is missing (assimp-testmodels)";
  for (const char* file : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Embedded/BoxTextured.gltf",
                           "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
    Model m = load_model(models + file);
    bool mirrored_repeat = false;
    for (ModelNode& n : m.nodes)
      if (n.mesh)
        for (Material& mat : n.mesh->materials) {
          ASSERT_TRUE(mat.texture) << file;
          EXPECT_EQ(mat.texture->width(), 211) << file;
          mat.shading = Shading::Unlit;  // the texels as they are
          mirrored_repeat = mat.wrap == Wrap::MirroredRepeat;
        }
    Scene scene;
    add_to_scene(scene, m);
    scene.camera.position = {0, 0, 2.5f};
    Renderer r(128, 128);
    r.render(scene);
    Image img = r.color_image();
    auto is = [&](int x, int y, const char* what) {
      const uint8_t* p = img.pixel(x, y);
      const int red = p[0], green = p[1], blue = p[2];
      if (std::string(what) == "sky") return blue > 180 && blue > red + 60;
      if (std::string(what) == "grass") return green > 100 && green > blue + 40 && green > red + 20;
      return red > 220 && green > 220 && blue > 220;  // the sun
    };
    EXPECT_TRUE(is(64, 40, "sky")) << file;
    EXPECT_TRUE(is(64, 88, "grass")) << file;
    EXPECT_EQ(mirrored_repeat, std::string(file) == "BoxTextured-glTF/BoxTextured.gltf");
    EXPECT_TRUE(is(mirrored_repeat ? 77 : 51, 48, "sun")) << file;
    EXPECT_TRUE(is(mirrored_repeat ? 51 : 77, 48, "sky")) << file;
  }
}

}  // namespace
}  // namespace velocity

namespace velocity {
namespace {

// KHR_texture_transform and texCoord 1 as drawn: the quad's quarters for a transform
// (as JSON) on the base-colour texture of the four-colour image.
class GltfTextureTransform : public GltfAppearanceTest {
 protected:
  std::string quarters(const char* texture_info) {
    GltfBuilder b;
    b.texture(b.image_in_buffer(four_colour_png(dir_)));
    add_quad(b, {0});
    b.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", nlohmann::json::parse(texture_info)}}}}};
    Model m = load_model(write("t.glb", b.glb()));
    Mesh& mesh = quad_mesh(m);
    mesh.materials.at(0).shading = Shading::Unlit;
    mesh.materials[0].filter = Filter::Nearest;
    mesh.colors.clear();
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
};

TEST_F(GltfTextureTransform, OffsetScaleRotationAndUvSet) {
  // Red, green / blue, white as the image is.
  EXPECT_EQ(quarters(R"({"index": 0})"), "100 010 001 111");
  // u' = 0.5 u + 0.5: the image's right column over the whole quad.
  EXPECT_EQ(quarters(R"({"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [0.5, 1]}}})"),
            "010 010 111 111");
  // A quarter turn: u' = v, v' = 1 - u (offset [0, 1]).
  EXPECT_EQ(quarters(R"({"index": 0, "extensions": {"KHR_texture_transform": {"rotation": 1.5707963, "offset": [0, 1]}}})"),
            "001 100 111 010");
  // TEXCOORD_1 is TEXCOORD_0 mirrored in u.
  EXPECT_EQ(quarters(R"({"index": 0, "texCoord": 1})"), "010 100 111 001");
}

}  // namespace
// KHR_lights_punctual lights cast shadows when the frame asks for them: a directional
// light turned 30 degrees about Y shines past a small quad floating over a large one, and
// the large one shows the small one's shadow beside it; shadows off, it does not.
TEST_F(GltfAppearanceTest, PunctualLightsCastShadows) {
  GltfBuilder b;
  add_quad(b, {0});
  b.json["materials"] = nlohmann::json::parse(R"([{"pbrMetallicRoughness": {"metallicFactor": 0}}])");
  b.json["nodes"][0]["scale"] = {4, 4, 1};
  b.json["nodes"].push_back({{"mesh", 0}, {"translation", {0, 0, 1}}, {"scale", {0.5, 0.5, 1}}});
  b.json["extensionsUsed"] = {"KHR_lights_punctual"};
  b.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::parse(R"([{"type": "directional", "intensity": 3}])");
  b.json["nodes"].push_back({{"rotation", {0, std::sin(radians(15.0f)), 0, std::cos(radians(15.0f))}},
                             {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  b.json["scenes"][0]["nodes"] = {0, 1, 2};
  Model m = load_model(write("shadow.gltf", b.gltf()));
  ASSERT_EQ(m.lights.size(), 1u);
  EXPECT_TRUE(m.lights[0].cast_shadows);
  Scene scene;
  add_to_scene(scene, m);
  scene.frame_camera(1.0f);
  auto draw = [&](bool shadows) {
    Renderer r(96, 96);
    r.options.shadows = shadows;
    r.options.shadow_map_size = 512;
    r.render(scene);
    return r.color_image();
  };
  const Image on = draw(true), off = draw(false);
  int darker = 0, brighter = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      darker += on.pixel(x, y)[1] + 8 < off.pixel(x, y)[1];
      brighter += on.pixel(x, y)[1] > off.pixel(x, y)[1];
    }
  EXPECT_GT(darker, 20);  // the strip of shadow beside the small quad (32 pixels here)
  EXPECT_EQ(brighter, 0);
}

}  // namespace velocity
