// glTF 2.0, 3D Studio, PLY and STL through Assimp (load_with_assimp), and texture file
// lookup (resolve_texture_path).
//
// The real files are Debian's assimp-testmodels (/usr/share/assimp/models, installed by
// scripts/deps.sh), read in place. The expected counts were not taken from Assimp: they
// were computed once with a short Python script from the files themselves (glTF: the
// JSON's accessor counts over the scene's node instances; PLY: the header's element
// counts and the face lists, a polygon of n corners giving n - 2 triangles; binary STL:
// the header's triangle count, ASCII STL: the "facet normal" lines; 3D Studio: the
// FACE_ARRAY chunks, 0x4120). Assimp gives each STL triangle and each 3D Studio face
// its own three vertices, and keeps glTF's and PLY's indexing, so the vertex counts
// follow from those.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "io/ply_check.hpp"
#include "loader_test_util.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;
using test::loads_or_throws_error;
using test::read_bytes;

const std::string kModels = "/usr/share/assimp/models";

std::string model(const std::string& relative) { return kModels + "/" + relative; }

#define REQUIRE_TEST_MODELS()                                                                          \
  do {                                                                                                 \
    if (!fs::is_directory(kModels))                                                                    \
      GTEST_SKIP() << "skipped: " << kModels << " is missing (Debian package assimp-testmodels; "      \
                   << "scripts/deps.sh installs it)";                                                  \
  } while (0)

// A fresh folder under the system's temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("velocity_formats_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string error_of(const std::string& path, const LoadOptions& options = {}) {
  try {
    load_with_assimp(path, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Silences load warnings (dropped points) for the length of a test.
struct QuietWarnings {
  WarningHandler old = set_warning_handler({});
  ~QuietWarnings() { set_warning_handler(old); }
};

const ModelNode* find_node(const Model& m, const std::string& name) {
  for (const ModelNode& n : m.nodes)
    if (n.name == name) return &n;
  return nullptr;
}

Mat4 world_of(const Model& m, const ModelNode* node) {
  Mat4 w = node->local;
  for (int p = node->parent; p >= 0; p = m.nodes[size_t(p)].parent) w = m.nodes[size_t(p)].local * w;
  return w;
}

void expect_near(Vec3 a, Vec3 b, float tolerance, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tolerance) << what;
  EXPECT_NEAR(a.y, b.y, tolerance) << what;
  EXPECT_NEAR(a.z, b.z, tolerance) << what;
}

// Every node's parent comes before it, as ModelNode requires.
void expect_parents_first(const Model& m) {
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    EXPECT_LT(m.nodes[i].parent, int(i)) << m.nodes[i].name;
    EXPECT_GE(m.nodes[i].parent, -1) << m.nodes[i].name;
  }
}

// The world-space corners of every triangle of every node, in file order.
std::vector<Vec3> world_corners(const Model& m) {
  std::vector<Vec3> out;
  for (const ModelNode& n : m.nodes) {
    if (!n.mesh) continue;
    Mat4 w = world_of(m, &n);
    for (const Triangle& t : n.mesh->triangles)
      for (uint32_t v : t.v) out.push_back(w.transform_point(n.mesh->positions[v]));
  }
  return out;
}

// ------------------------------------------------------------------------------ glTF

TEST(FormatsGltf, BoxTexturedTextAndBinaryAgree) {
  REQUIRE_TEST_MODELS();
  Model text = load_with_assimp(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
  Model binary = load_with_assimp(model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  for (const Model* m : {&text, &binary}) {
    SCOPED_TRACE(m->path);
    // The JSON: one mesh of 24 vertices and 36 indices, under a node with a Z-up to
    // Y-up matrix [1,0,0,0, 0,0,-1,0, 0,1,0,0, 0,0,0,1] (column-major).
    EXPECT_EQ(m->vertex_count(), 24u);
    EXPECT_EQ(m->triangle_count(), 12u);
    ASSERT_EQ(m->nodes.size(), 2u);
    EXPECT_EQ(m->nodes[1].parent, 0);
    const Mat4& up = m->nodes[0].local;
    EXPECT_EQ(up.m[1][2], 1.0f);
    EXPECT_EQ(up.m[2][1], -1.0f);
    EXPECT_EQ(up.m[1][1], 0.0f);
    const Mesh& mesh = *m->nodes[1].mesh;
    EXPECT_EQ(mesh.normals.size(), 24u);  // from the file
    EXPECT_EQ(mesh.uvs.size(), 24u);
    EXPECT_TRUE(mesh.colors.empty());
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "Texture");
    expect_near(mesh.materials[0].color, {1, 1, 1}, 0, "no baseColorFactor: white");
  }
  EXPECT_EQ(text.nodes[1].mesh->positions.size(), binary.nodes[1].mesh->positions.size());
  for (size_t i = 0; i < text.nodes[1].mesh->positions.size(); ++i)
    EXPECT_EQ(text.nodes[1].mesh->positions[i], binary.nodes[1].mesh->positions[i]) << i;
}

TEST(FormatsGltf, NestedNodeHierarchyAndTransforms) {
  REQUIRE_TEST_MODELS();
  Model m = load_with_assimp(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
  // 82 nodes in the scene under two roots, so Assimp adds a "ROOT" above them; the
  // nodes' meshes instanced over the scene hold 84657 vertices and 121496 triangles.
  EXPECT_EQ(m.nodes.size(), 83u);
  EXPECT_EQ(m.vertex_count(), 84657u);
  EXPECT_EQ(m.triangle_count(), 121496u);
  expect_parents_first(m);
  EXPECT_EQ(m.nodes[0].name, "ROOT");

  // Node 55 sits four levels down: 55 <- 43 <- 14 <- 13 <- 0 (Assimp names unnamed glTF
  // nodes "nodes[i]").
  const ModelNode* n55 = find_node(m, "nodes[55]");
  ASSERT_NE(n55, nullptr);
  std::vector<std::string> chain;
  for (int p = n55->parent; p >= 0; p = m.nodes[size_t(p)].parent) chain.push_back(m.nodes[size_t(p)].name);
  EXPECT_EQ(chain, (std::vector<std::string>{"nodes[43]", "nodes[14]", "nodes[13]", "nodes[0]", "ROOT"}));
  ASSERT_TRUE(n55->mesh);

  // Its "matrix" in the file (column-major there, rows here).
  const float local55[3][4] = {{-0.9999850392341614f, 0.004973156377673149f, -0.0022700002882629633f, 48.794708251953125f},
                               {-0.004973169881850481f, -0.9999876618385315f, 3.554153522600245e-07f, 768.6771850585938f},
                               {-0.0022699704859405756f, 1.164450713986298e-05f, 0.9999974370002747f, -20.402503967285156f}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(n55->local.m[r][c], local55[r][c]) << r << "," << c;
  // The product of the chain's matrices, computed in double precision from the file.
  const float world55[3][4] = {{0.0049734129326578095f, 0.9999876606296972f, -5.984693536875273e-07f, -803.939028924307f},
                               {-3.3323773860130523e-07f, 6.001334927567752e-07f, 1.0000000293447693f, -79.5001502406959f},
                               {0.9999876303340893f, -0.004973413127241347f, 3.361101682582829e-07f, -14.018017251396422f}};
  Mat4 w = world_of(m, n55);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(w.m[r][c], world55[r][c], c == 3 ? 2e-3 : 1e-5) << r << "," << c;

  // The same hierarchy in a Scene gives the same world matrix.
  Scene scene;
  add_to_scene(scene, m);
  auto id = scene.find("nodes[55]");
  ASSERT_TRUE(id);
  Mat4 sw = scene.world_matrices()[*id];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(sw.m[r][c], world55[r][c], c == 3 ? 2e-3 : 1e-5) << r << "," << c;

  // Materials: the file's baseColorFactors (the Python script's set of them).
  std::set<std::vector<float>> colors;
  for (const ModelNode& n : m.nodes)
    if (n.mesh)
      for (const Material& mat : n.mesh->materials)
        colors.insert({std::round(mat.color.x * 1000) / 1000, std::round(mat.color.y * 1000) / 1000,
                       std::round(mat.color.z * 1000) / 1000});
  std::set<std::vector<float>> expected{{0, 0, 0},        {0, 0, 0.85f},        {0, 0.425f, 0.425f}, {0, 0.561f, 0.85f},
                                        {0.85f, 0, 0}, {0.85f, 0.561f, 0}, {0.85f, 0.85f, 0.85f}};
  EXPECT_EQ(colors, expected);
}

TEST(FormatsGltf, MeshesUsedByManyNodesAreShared) {
  REQUIRE_TEST_MODELS();
  Model m = load_with_assimp(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
  // The file's 29 meshes are used by 67 nodes: the Velocity meshes are shared too.
  std::set<const Mesh*> distinct;
  size_t with_mesh = 0;
  for (const ModelNode& n : m.nodes)
    if (n.mesh) distinct.insert(n.mesh.get()), ++with_mesh;
  EXPECT_LT(distinct.size(), with_mesh);
  // Node 78's mesh (28) has two primitives with materials 32 and 33: one Velocity mesh,
  // two materials, one per face.
  const ModelNode* n78 = find_node(m, "nodes[78]");
  ASSERT_TRUE(n78 && n78->mesh);
  EXPECT_EQ(n78->mesh->materials.size(), 2u);
  EXPECT_EQ(n78->mesh->face_materials.size(), n78->mesh->triangles.size());
  EXPECT_NO_THROW(n78->mesh->validate());
}

TEST(FormatsGltf, Cameras) {
  REQUIRE_TEST_MODELS();
  // Cameras.gltf: node 1 at (0.5, 0.5, 3) with a perspective camera (yfov 0.7, znear
  // 0.01, zfar 100), node 2 at the same place with an orthographic one (ymag 1).
  Model m = load_with_assimp(model("glTF2/cameras/Cameras.gltf"));
  ASSERT_EQ(m.cameras.size(), 2u);
  const Camera& p = m.cameras[0].camera;
  EXPECT_EQ(p.projection, Projection::Perspective);
  EXPECT_FLOAT_EQ(p.fov_y, 0.7f);
  EXPECT_FLOAT_EQ(p.near, 0.01f);
  EXPECT_FLOAT_EQ(p.far, 100.0f);
  expect_near(p.position, {0.5f, 0.5f, 3}, 1e-6f, "perspective camera position (once, not twice)");
  EXPECT_NEAR(p.yaw, 0, 1e-6);
  EXPECT_NEAR(p.pitch, 0, 1e-6);
  EXPECT_NEAR(p.roll, 0, 1e-6);
  const Camera& o = m.cameras[1].camera;
  EXPECT_EQ(o.projection, Projection::Orthographic);
  EXPECT_FLOAT_EQ(o.ortho_height, 2.0f);
  expect_near(o.position, {0.5f, 0.5f, 3}, 1e-6f, "orthographic camera position");

  // 2CylinderEngine: one perspective camera (yfov 0.3143463730812073, znear 0.05, zfar
  // 1e6) on a node with a full rotation matrix. Its view must take the node's -Z axis
  // to -Z and its +Y axis to +Y: that checks yaw, pitch and roll together.
  Model e = load_with_assimp(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
  ASSERT_EQ(e.cameras.size(), 1u);
  const Camera& c = e.cameras[0].camera;
  EXPECT_FLOAT_EQ(c.fov_y, 0.3143463730812073f);
  EXPECT_FLOAT_EQ(c.near, 0.05f);
  EXPECT_FLOAT_EQ(c.far, 1e6f);
  expect_near(c.position, {1005.9874267578125f, 766.3170776367188f, 953.3455810546875f}, 1e-3f, "engine camera");
  Vec3 node_z{0.6246951818466187f, 0.4685211479663849f, 0.6246950030326843f};
  Vec3 node_y{-0.33129435777664185f, 0.883452296257019f, -0.33129459619522095f};
  expect_near(c.view().transform_vector(-node_z), {0, 0, -1}, 1e-5f, "view direction");
  expect_near(c.view().transform_vector(node_y), {0, 1, 0}, 1e-5f, "up");
}

TEST(FormatsGltf, StripsAndFansBecomeTrianglesPointsAndLinesAreRefused) {
  REQUIRE_TEST_MODELS();
  QuietWarnings quiet;
  // glTF-Asset-Generator's Mesh_PrimitiveMode: a quad as a strip (mode 5: files 04 and,
  // indexed, 11), a fan (mode 6: 05, 12) and triangles (mode 4: 06, 13); 4 corners
  // (6 for 06), two triangles, both facing the same way.
  for (const char* n : {"04", "05", "06", "11", "12", "13"}) {
    SCOPED_TRACE(n);
    Model m = load_with_assimp(model("glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" +
                                     std::string(n) + ".gltf"));
    ASSERT_EQ(m.triangle_count(), 2u);
    std::vector<Vec3> c = world_corners(m);
    Vec3 n0 = cross(c[1] - c[0], c[2] - c[0]), n1 = cross(c[4] - c[3], c[5] - c[3]);
    EXPECT_GT(dot(n0, n1), 0) << "a strip's second triangle must keep the first one's winding";
  }
  // Lines only (mode 1): nothing to draw (points, mode 0, are a point cloud:
  // test_formats_points.cpp).
  for (const char* n : {"01"}) {
    std::string e = error_of(model("glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" +
                                   std::string(n) + ".gltf"));
    EXPECT_NE(e.find("the file has no triangles (only"), std::string::npos) << e;
  }
}

// A one-triangle glTF written by the test: COLOR_0, a base colour, and the same mesh
// under a mirroring node (scale -1 in x) and a plain one. `nodes` and `scenes` replace
// the node graph.
const char* kTriangleNodes = R"([{"name": "mirror", "scale": [-1, 1, 1], "children": [1]},
            {"name": "tri", "mesh": 0},
            {"name": "plain", "mesh": 0, "translation": [3, 0, 0]}])";
std::string write_triangle_gltf(const TempDir& dir, const std::string& nodes = kTriangleNodes,
                                const std::string& scenes = R"([{"nodes": [0, 2]}])") {
  struct {
    float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    float colors[12] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};
    uint16_t indices[4] = {0, 1, 2, 0};
  } buffer;
  static_assert(sizeof buffer == 92);
  write_bytes(dir / "tri.bin", std::string(reinterpret_cast<const char*>(&buffer), sizeof buffer));
  std::string json = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": )" + scenes + R"(,
  "nodes": )" + nodes + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}, "indices": 2, "material": 0}]}],
  "materials": [{"name": "red", "doubleSided": true,
                 "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}}],
  "buffers": [{"uri": "tri.bin", "byteLength": 92}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 84},
                  {"buffer": 0, "byteOffset": 84, "byteLength": 6}],
  "accessors": [
    {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC4"},
    {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
  write_bytes(dir / "tri.gltf", json);
  return dir / "tri.gltf";
}

TEST(FormatsGltf, VertexColorsMaterialAndMirroredWinding) {
  TempDir dir;
  Model m = load_with_assimp(write_triangle_gltf(dir));
  const ModelNode* tri = find_node(m, "tri");
  const ModelNode* plain = find_node(m, "plain");
  ASSERT_TRUE(tri && plain && tri->mesh && plain->mesh);
  EXPECT_EQ(m.nodes[size_t(tri->parent)].name, "mirror");
  for (const ModelNode* n : {tri, plain}) {
    const Mesh& mesh = *n->mesh;
    ASSERT_EQ(mesh.colors.size(), 3u);
    expect_near(mesh.colors[0], {1, 0, 0}, 0, "COLOR_0[0]");
    expect_near(mesh.colors[1], {0, 1, 0}, 0, "COLOR_0[1]");
    expect_near(mesh.colors[2], {0, 0, 1}, 0, "COLOR_0[2]");
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "red");
    expect_near(mesh.materials[0].color, {1, 0, 0}, 0, "baseColorFactor");
    EXPECT_TRUE(mesh.materials[0].two_sided);
    EXPECT_EQ(mesh.normals.size(), 3u);  // computed: the file has none
  }
  // The mirrored instance is its own mesh with the winding reversed, so that in the
  // world both triangles face +Z (counter-clockwise seen from +Z), as glTF specifies.
  EXPECT_NE(tri->mesh, plain->mesh);
  for (const ModelNode* n : {tri, plain}) {
    Mat4 w = world_of(m, n);
    const Triangle& t = n->mesh->triangles.at(0);
    Vec3 a = w.transform_point(n->mesh->positions[t.v[0]]);
    Vec3 b = w.transform_point(n->mesh->positions[t.v[1]]);
    Vec3 c = w.transform_point(n->mesh->positions[t.v[2]]);
    EXPECT_GT(cross(b - a, c - a).z, 0) << n->name;
  }
}

// --------------------------------------------------------------------------- 3D Studio

TEST(Formats3ds, CountsHierarchyAndAxes) {
  REQUIRE_TEST_MODELS();
  // fels.3ds: one object, 768 faces.
  Model fels = load_with_assimp(model("3DS/fels.3ds"));
  EXPECT_EQ(fels.triangle_count(), 768u);
  EXPECT_EQ(fels.vertex_count(), 3u * 768u);
  // test1.3ds: nine boxes (Box01..Box10 without Box03) of 12 faces each.
  Model boxes = load_with_assimp(model("3DS/test1.3ds"));
  EXPECT_EQ(boxes.triangle_count(), 108u);
  EXPECT_EQ(boxes.vertex_count(), 324u);
  expect_parents_first(boxes);
  for (const char* name : {"Box01", "Box02", "Box04", "Box05", "Box06", "Box07", "Box08", "Box09", "Box10"}) {
    const ModelNode* n = find_node(boxes, name);
    ASSERT_NE(n, nullptr) << name;
    EXPECT_EQ(n->parent, 0) << name;
    ASSERT_TRUE(n->mesh) << name;
    EXPECT_EQ(n->mesh->triangle_count(), 12u) << name;
  }
  // 3D Studio is Z up; the root turns it to Velocity's Y up: (x, y, z) -> (x, z, -y).
  const Mat4& root = boxes.nodes[0].local;
  expect_near(root.transform_vector({0, 0, 1}), {0, 1, 0}, 0, "3DS up is +Y");
  expect_near(root.transform_vector({0, 1, 0}), {0, 0, -1}, 0, "3DS +Y is -Z");
  // Materials by name, with the file's diffuse colour (150/255).
  const Mesh& box = *find_node(boxes, "Box01")->mesh;
  ASSERT_EQ(box.materials.size(), 1u);
  EXPECT_EQ(box.materials[0].name, "2 - Default");
  EXPECT_NEAR(box.materials[0].color.x, 150 / 255.0f, 1e-6);
  // Filled for --shading pbr: a dielectric, its roughness from the Phong exponent.
  EXPECT_EQ(box.materials[0].shading, Shading::Gouraud);  // its own shading stays the default
  EXPECT_EQ(box.materials[0].pbr.metallic, 0.0f);
  EXPECT_GT(box.materials[0].pbr.roughness, 0.0f);
  EXPECT_LE(box.materials[0].pbr.roughness, 1.0f);
}

TEST(Formats3ds, CamerasAreNotConvertedButSaidSo) {
  REQUIRE_TEST_MODELS();
  std::vector<std::string> warnings;
  WarningHandler old = set_warning_handler([&](std::string_view w) { warnings.emplace_back(w); });
  Model m = load_with_assimp(model("3DS/CameraRollAnim.3ds"));
  set_warning_handler(old);
  EXPECT_EQ(m.triangle_count(), 12u);
  EXPECT_TRUE(m.cameras.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("camera"), std::string::npos) << warnings[0];
}

// -------------------------------------------------------------------------------- PLY

Vec3 sum_area_normals(const Mesh& m) {
  Vec3 s;
  for (const Triangle& t : m.triangles)
    s += cross(m.positions[t.v[1]] - m.positions[t.v[0]], m.positions[t.v[2]] - m.positions[t.v[0]]);
  return s;
}

float surface_area(const Mesh& m) {
  float a = 0;
  for (const Triangle& t : m.triangles)
    a += 0.5f * length(cross(m.positions[t.v[1]] - m.positions[t.v[0]], m.positions[t.v[2]] - m.positions[t.v[0]]));
  return a;
}

TEST(FormatsPly, AsciiQuadsAndBinaryTrianglesGiveTheSameCube) {
  REQUIRE_TEST_MODELS();
  // cube.ply: ASCII, 8 vertices, 6 quads; cube_binary.ply: little-endian, the same 8
  // vertices, 12 triangles.
  Model ascii = load_with_assimp(model("PLY/cube.ply"));
  Model binary = load_with_assimp(model("PLY/cube_binary.ply"));
  for (const Model* m : {&ascii, &binary}) {
    SCOPED_TRACE(m->path);
    EXPECT_EQ(m->vertex_count(), 8u);
    EXPECT_EQ(m->triangle_count(), 12u);
    std::vector<const Mesh*> meshes;
    for (const ModelNode& n : m->nodes)
      if (n.mesh) meshes.push_back(n.mesh.get());
    ASSERT_EQ(meshes.size(), 1u);
    EXPECT_EQ(meshes[0]->normals.size(), 8u);  // computed: the files have none
    EXPECT_NEAR(surface_area(*meshes[0]), 6.0f, 1e-5);
    expect_near(sum_area_normals(*meshes[0]), {0, 0, 0}, 1e-5f, "closed surface");
  }
  const Mesh& a = *ascii.nodes[0].mesh;
  const Mesh& b = *binary.nodes[0].mesh;
  for (size_t i = 0; i < 8; ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << i;
}

TEST(FormatsPly, NormalsUvsAndVertexColorsFromTheFile) {
  REQUIRE_TEST_MODELS();
  // Wuson.ply: 11184 vertices with normals and uvs (s, t), 3732 triangles.
  Model wuson = load_with_assimp(model("PLY/Wuson.ply"));
  EXPECT_EQ(wuson.vertex_count(), 11184u);
  EXPECT_EQ(wuson.triangle_count(), 3732u);
  const Mesh& w = *wuson.nodes[0].mesh;
  EXPECT_EQ(w.normals.size(), 11184u);
  EXPECT_EQ(w.uvs.size(), 11184u);
  // float-color.ply: three vertices coloured (0, 0, 1) (float red, green, blue).
  Model colored = load_with_assimp(model("PLY/float-color.ply"));
  ASSERT_EQ(colored.vertex_count(), 3u);
  const Mesh& c = *colored.nodes[0].mesh;
  ASSERT_EQ(c.colors.size(), 3u);
  for (Vec3 color : c.colors) expect_near(color, {0, 0, 1}, 0, "float-color.ply");
  expect_near(c.positions[2], {200, 200, 0}, 0, "float-color.ply vertex 2");
}

// The same coloured mesh (a quad and a triangle, uchar colours) as ASCII, binary
// little-endian and binary big-endian PLY.
std::string ply_file(const std::string& format) {
  const float xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5f, 0.25f}};
  const uint8_t rgb[5][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {51, 102, 204}};
  const std::vector<std::vector<int32_t>> faces = {{0, 1, 2, 3}, {1, 4, 2}};
  std::string s = "ply\nformat " + format + " 1.0\ncomment written by test_formats\nelement vertex 5\n"
                  "property float x\nproperty float y\nproperty float z\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                  "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const bool big = format == "binary_big_endian";
  auto put = [&](const void* p, size_t n) {
    std::string bytes(static_cast<const char*>(p), n);
    if (big) std::reverse(bytes.begin(), bytes.end());  // the test machine is little-endian
    s += bytes;
  };
  for (int v = 0; v < 5; ++v) {
    if (format == "ascii") {
      char line[128];
      std::snprintf(line, sizeof line, "%g %g %g %d %d %d\n", xyz[v][0], xyz[v][1], xyz[v][2], rgb[v][0], rgb[v][1],
                    rgb[v][2]);
      s += line;
    } else {
      for (float f : xyz[v]) put(&f, 4);
      for (uint8_t c : rgb[v]) put(&c, 1);
    }
  }
  for (const auto& f : faces) {
    if (format == "ascii") {
      s += std::to_string(f.size());
      for (int32_t i : f) s += " " + std::to_string(i);
      s += "\n";
    } else {
      uint8_t n = uint8_t(f.size());
      put(&n, 1);
      for (int32_t i : f) put(&i, 4);
    }
  }
  return s;
}

TEST(FormatsPly, AsciiLittleAndBigEndianWithColorsAgree) {
  TempDir dir;
  std::vector<Mesh> meshes;
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    std::string path = dir / (std::string(format) + ".ply");
    write_bytes(path, ply_file(format));
    Model m = load_with_assimp(path);
    ASSERT_EQ(m.nodes.size(), 1u) << format;
    meshes.push_back(*m.nodes[0].mesh);
  }
  const Mesh& a = meshes[0];
  EXPECT_EQ(a.vertex_count(), 5u);
  EXPECT_EQ(a.triangle_count(), 3u);  // the quad fanned into two, and the triangle
  ASSERT_EQ(a.colors.size(), 5u);
  expect_near(a.colors[4], {51 / 255.0f, 102 / 255.0f, 204 / 255.0f}, 1e-6f, "uchar colour / 255");
  expect_near(a.positions[4], {2, 0.5f, 0.25f}, 0, "vertex 4");
  for (size_t k = 1; k < meshes.size(); ++k) {
    const Mesh& b = meshes[k];
    ASSERT_EQ(b.vertex_count(), a.vertex_count()) << k;
    ASSERT_EQ(b.triangle_count(), a.triangle_count()) << k;
    for (size_t i = 0; i < a.vertex_count(); ++i) {
      EXPECT_EQ(b.positions[i], a.positions[i]) << k << " " << i;
      EXPECT_EQ(b.colors[i], a.colors[i]) << k << " " << i;
    }
    for (size_t t = 0; t < a.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(b.triangles[t].v[c], a.triangles[t].v[c]) << k << " " << t;
  }
}

TEST(FormatsPly, PointCloudsArePoints) {
  REQUIRE_TEST_MODELS();
  // points.ply: four coloured points, no faces: four points, one (v, v, v) each.
  Model m = load_with_assimp(model("PLY/points.ply"));
  ASSERT_EQ(m.vertex_count(), 4u);
  ASSERT_EQ(m.triangle_count(), 4u);
  for (const ModelNode& n : m.nodes)
    if (n.mesh) {
      EXPECT_EQ(n.mesh->materials.at(0).shading, Shading::Points);
      for (const Triangle& t : n.mesh->triangles) EXPECT_TRUE(t.v[0] == t.v[1] && t.v[1] == t.v[2]);
    }
}

// -------------------------------------------------------------------------------- STL

TEST(FormatsStl, AsciiAndBinaryGiveTheSameMesh) {
  REQUIRE_TEST_MODELS();
  // Spider: 1368 facets in both files, the same corners to 5e-7 (the ASCII file's
  // decimals), coordinates up to 4.
  Model ascii = load_with_assimp(model("STL/Spider_ascii.stl"));
  Model binary = load_with_assimp(model("STL/Spider_binary.stl"));
  EXPECT_EQ(ascii.triangle_count(), 1368u);
  EXPECT_EQ(binary.triangle_count(), 1368u);
  EXPECT_EQ(ascii.vertex_count(), 3u * 1368u);
  EXPECT_EQ(binary.vertex_count(), 3u * 1368u);
  std::vector<Vec3> a = world_corners(ascii), b = world_corners(binary);
  ASSERT_EQ(a.size(), b.size());
  float worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, length(a[i] - b[i]));
  EXPECT_LT(worst, 2e-6f);
  // Normals come from the facets: every vertex has one.
  for (const ModelNode& n : binary.nodes) {
    if (n.mesh) {
      EXPECT_EQ(n.mesh->normals.size(), n.mesh->vertex_count());
    }
  }
}

TEST(FormatsStl, MoreFiles) {
  REQUIRE_TEST_MODELS();
  EXPECT_EQ(load_with_assimp(model("STL/Wuson.stl")).triangle_count(), 3732u);         // binary header
  EXPECT_EQ(load_with_assimp(model("STL/sphereWithHole.stl")).triangle_count(), 285u);  // ASCII facets
  // Two "solid" blocks: two nodes under the root, one triangle each.
  Model two = load_with_assimp(model("STL/triangle_with_two_solids.stl"));
  EXPECT_EQ(two.triangle_count(), 2u);
  size_t with_mesh = 0;
  for (const ModelNode& n : two.nodes) with_mesh += n.mesh != nullptr;
  EXPECT_EQ(with_mesh, 2u);
}

// ---------------------------------------------------------------------- texture paths

TEST(FormatsTexturePath, ExactCaseInsensitiveAndMissing) {
  TempDir dir;
  fs::create_directories(dir.path() / "Tex");
  write_bytes(dir / "Tex/Wood.PNG", "x");
  write_bytes(dir / "image1.jpg", "x");
  write_bytes(dir / "my tex.png", "x");
  const std::string m = dir / "car.gltf";
  EXPECT_EQ(resolve_texture_path(m, "Tex/Wood.PNG"), dir / "Tex/Wood.PNG");        // exact
  EXPECT_EQ(resolve_texture_path(m, "tex/wood.png"), dir / "Tex/Wood.PNG");        // case, per component
  EXPECT_EQ(resolve_texture_path(m, "TEX\\WOOD.PNG"), dir / "Tex/Wood.PNG");       // Windows separators
  EXPECT_EQ(resolve_texture_path(m, "./IMAGE1.JPG"), dir / "image1.jpg");          // 3D Studio's upper case
  EXPECT_EQ(resolve_texture_path(m, "C:\\maps\\Image1.jpg"), dir / "image1.jpg");  // the writer's machine
  EXPECT_EQ(resolve_texture_path(m, "my%20tex.png"), dir / "my tex.png");          // glTF URI
  EXPECT_EQ(resolve_texture_path(m, dir / "image1.jpg"), dir / "image1.jpg");      // absolute, present
  EXPECT_EQ(resolve_texture_path(m, "missing.png"), "");
  EXPECT_EQ(resolve_texture_path(m, "Tex"), "");  // a folder is not a texture
  EXPECT_EQ(resolve_texture_path(m, ""), "");
  EXPECT_EQ(resolve_texture_path(m, "*0"), "");  // embedded in a .glb
}

TEST(FormatsTexturePath, RealThreeDsNames) {
  REQUIRE_TEST_MODELS();
  // test1.3ds and cube_with_diffuse_texture.3DS name IMAGE1.JPG, CWALL02.JPG and
  // TEST.PNG (their material chunks, seen with `strings`); the files beside them are
  // IMAGE1.jpg, CWALL02.jpg and test.png.
  EXPECT_EQ(resolve_texture_path(model("3DS/test1.3ds"), "IMAGE1.JPG"), model("3DS/IMAGE1.jpg"));
  EXPECT_EQ(resolve_texture_path(model("3DS/test1.3ds"), "CWALL02.JPG"), model("3DS/CWALL02.jpg"));
  EXPECT_EQ(resolve_texture_path(model("3DS/cube_with_diffuse_texture.3DS"), "TEST.PNG"), model("3DS/test.png"));
  EXPECT_EQ(resolve_texture_path(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"), "CesiumLogoFlat.png"),
            model("glTF2/BoxTextured-glTF/CesiumLogoFlat.png"));
}

// ----------------------------------------------------------------------------- errors

TEST(FormatsErrors, MissingFilesAndBrokenFilesFromAssimpsSuite) {
  EXPECT_NE(error_of("/nonexistent/car.glb").find("/nonexistent/car.glb: no such file"), std::string::npos);
  TempDir dir;
  fs::create_directories(dir.path() / "folder.glb");
  EXPECT_NE(error_of(dir / "folder.glb").find("is a directory"), std::string::npos);
  EXPECT_NE(error_of(dir / "car.fbx").find("car.fbx: 'fbx' is not a format read through Assimp"), std::string::npos);
  REQUIRE_TEST_MODELS();
  QuietWarnings quiet;
  for (const char* bad : {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "glTF2/MissingBin/BoxTextured.gltf",
                          "glTF2/TestNoRootNode/NoScene.gltf", "glTF2/TestNoRootNode/SceneWithoutNodes.gltf",
                          "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "glTF2/wrongTypes/badArray.gltf",
                          "glTF2/wrongTypes/badNumber.gltf", "glTF2/wrongTypes/badString.gltf",
                          "glTF2/SchemaFailures/sceneWrongType.gltf", "glTF2/issue_3269/texcoord_crash.gltf",
                          "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
                          "invalid/empty.3ds", "invalid/empty.ply"}) {
    std::string e = error_of(model(bad));
    EXPECT_EQ(e.rfind(model(bad) + ": ", 0), 0u) << bad << ": " << e;  // names the file first
  }
  std::string e = error_of(model("glTF2/MissingBin/BoxTextured.gltf"));
  EXPECT_NE(e.find("BoxTextured0.bin"), std::string::npos) << e;
  // Buffer views running past their buffer: Assimp loads the meshes that fit; Velocity,
  // which makes no partial models, refuses the file.
  e = error_of(model("glTF2/IncorrectVertexArrays/Cube.gltf"));
  EXPECT_NE(e.find("Cube.gltf: bufferView 2: bytes 504 to 936 run past the end of buffer 0 (514 bytes)"),
            std::string::npos)
      << e;
}

// Copies `source` (and, for a .gltf, its neighbours) to `dir` cut to `length` bytes.
std::string truncated_copy(const TempDir& dir, const std::string& source, size_t length) {
  std::string bytes = read_bytes(source);
  std::string path = dir / fs::path(source).filename().string();
  write_bytes(path, bytes.substr(0, std::min(length, bytes.size())));
  return path;
}

TEST(FormatsErrors, TruncatedFilesThrow) {
  REQUIRE_TEST_MODELS();
  TempDir dir;
  // Cut points that certainly lose data: nothing, the first bytes, half, all but the
  // last byte of a binary file (whose sizes are all declared up front).
  struct Case {
    const char* file;
    bool binary;
  };
  for (Case c : {Case{"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", true}, Case{"3DS/test1.3ds", true},
                 Case{"PLY/cube.ply", false}, Case{"PLY/cube_binary.ply", true}, Case{"PLY/Wuson.ply", false},
                 Case{"STL/Spider_binary.stl", true}, Case{"STL/Spider_ascii.stl", false}}) {
    const size_t n = fs::file_size(model(c.file));
    std::vector<size_t> cuts{0, 16, n / 2};
    if (c.binary) cuts.push_back(n - 1);
    for (size_t cut : cuts) {
      std::string path = truncated_copy(dir, model(c.file), cut);
      std::string e = error_of(path);
      EXPECT_EQ(e.rfind(path + ":", 0), 0u) << c.file << " cut to " << cut << ": " << e;
    }
  }
}

TEST(FormatsErrors, TruncationSweepNeverCrashesOrHangs) {
  REQUIRE_TEST_MODELS();
  TempDir dir;
  QuietWarnings quiet;
  for (const char* file : {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "3DS/test1.3ds", "PLY/cube.ply",
                           "PLY/cube_binary.ply", "PLY/float-color.ply", "STL/triangle.stl", "STL/Spider_binary.stl"}) {
    const size_t n = fs::file_size(model(file));
    for (size_t i = 0; i < 48; ++i) {
      std::string path = truncated_copy(dir, model(file), n * i / 48);
      loads_or_throws_error([&] { load_with_assimp(path); }, std::string(file) + " cut to " + std::to_string(n * i / 48));
    }
  }
}

TEST(FormatsErrors, MutatedFilesLoadOrThrow) {
  REQUIRE_TEST_MODELS();
  TempDir dir;
  QuietWarnings quiet;
  test::Rng rng;
  // Assimp 5.2.5 alone hangs, aborts or crashes on about one in ten of these PLY
  // mutations; the PLY check must stop every one.
  for (const char* file : {"PLY/cube.ply", "PLY/cube_binary.ply", "PLY/float-color.ply", "PLY/cube_uv.ply",
                           "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "3DS/test1.3ds", "STL/triangle.stl",
                           "STL/Spider_binary.stl"}) {
    const std::string original = read_bytes(model(file));
    const std::string path = dir / fs::path(file).filename().string();
    for (int trial = 0; trial < 150; ++trial) {
      std::string bytes = original;
      int flips = 1 + int(rng.next() % 8);
      for (int k = 0; k < flips; ++k) bytes[rng.next() % bytes.size()] = char(rng.next() & 0xff);
      write_bytes(path, bytes);
      loads_or_throws_error([&] { load_with_assimp(path); }, std::string(file) + " trial " + std::to_string(trial));
    }
  }
}

TEST(FormatsErrors, PlyHeadersAssimpWouldHangOrAllocateOn) {
  TempDir dir;
  // No end_header: Assimp 5.2.5 loops forever on these.
  write_bytes(dir / "cut.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float32 x\n");
  std::string e = error_of(dir / "cut.ply");
  EXPECT_NE(e.find("cut.ply: PLY header has no 'end_header' line"), std::string::npos) << e;
  write_bytes(dir / "cut.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float32 x\nproperty float");
  e = error_of(dir / "cut.ply");
  EXPECT_NE(e.find("cut.ply:5: expected 'property TYPE NAME'"), std::string::npos) << e;
  // 300 million vertices claimed in 4 bytes: Assimp allocates 3.5 GB before failing.
  write_bytes(dir / "liar.ply",
              "ply\nformat binary_little_endian 1.0\nelement vertex 300000000\nproperty float x\n"
              "property float y\nproperty float z\nend_header\n0000");
  e = error_of(dir / "liar.ply");
  EXPECT_NE(e.find("ends inside element 'vertex' #0"), std::string::npos) << e;
  // A face list cut short (Assimp makes a face with no corners and aborts).
  write_bytes(dir / "short.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  e = error_of(dir / "short.ply");
  EXPECT_NE(e.find("ends before element 'face' #0"), std::string::npos) << e;
  // A face naming a vertex that is not there.
  write_bytes(dir / "index.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  e = error_of(dir / "index.ply");
  EXPECT_NE(e.find("index.ply:13: element 'face' #0 uses vertex 7, but there are only 3"), std::string::npos) << e;
  // An unknown type, and a list longer than its line.
  write_bytes(dir / "type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty floaty x\nend_header\n0\n");
  e = error_of(dir / "type.ply");
  EXPECT_NE(e.find("type.ply:4: expected a PLY type"), std::string::npos) << e;
  write_bytes(dir / "list.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n9 0 1 2\n");
  e = error_of(dir / "list.ply");
  EXPECT_NE(e.find("has length 9 but only 3 values follow"), std::string::npos) << e;
  // Found by fuzzing: a typo ends an element's property list for Assimp, which then
  // skips the properties after it; the binary data is read in another layout, and a
  // list length of -128 made Assimp ask for 34 GB.
  write_bytes(dir / "typo.ply",
              "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\npropertp float y\n"
              "property float z\nend_header\n");
  e = error_of(dir / "typo.ply");
  EXPECT_NE(e.find("typo.ply:6: 'property' after line 5 ('propertp float y'), which ends the element's property "
                   "list for Assimp"),
            std::string::npos)
      << e;
  // Assimp takes "PLY" in any case, and by content whatever the extension: so does
  // the check (this one has no end_header either).
  write_bytes(dir / "upper.ply", "plY\nformat binary_li");
  e = error_of(dir / "upper.ply");
  EXPECT_NE(e.find("upper.ply:1: not a PLY file"), std::string::npos) << e;
  // The check accepts what the writers write.
  EXPECT_TRUE(detail::looks_like_ply(ply_file("ascii")));
  EXPECT_NO_THROW(detail::check_ply(ply_file("ascii"), "a.ply"));
  EXPECT_NO_THROW(detail::check_ply(ply_file("binary_little_endian"), "l.ply"));
  EXPECT_NO_THROW(detail::check_ply(ply_file("binary_big_endian"), "b.ply"));
}

TEST(FormatsErrors, GltfFilesAssimpWouldCrashOrBlowUpOn) {
  TempDir dir;
  EXPECT_NO_THROW(load_with_assimp(write_triangle_gltf(dir)));
  // A node listed as a child by two nodes: Assimp copies it once per path (here 2^40).
  std::string dag = "[";
  for (int i = 0; i < 40; ++i) dag += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
  dag += "{\"mesh\": 0}]";
  std::string e = error_of(write_triangle_gltf(dir, dag, R"([{"nodes": [0]}])"));
  EXPECT_NE(e.find("tri.gltf: node 1 is a child of both node 0 and node 0"), std::string::npos) << e;
  e = error_of(write_triangle_gltf(dir, R"([{"children": [1]}, {"children": [2]}, {"children": [1], "mesh": 0}])",
                                   R"([{"nodes": [0]}])"));
  EXPECT_NE(e.find("node 1 is a child of both node 0 and node 2"), std::string::npos) << e;
  e = error_of(write_triangle_gltf(dir, R"([{"children": [1]}, {"children": [0], "mesh": 0}])", R"([{"nodes": []}])"));
  EXPECT_NE(e.find("form a cycle"), std::string::npos) << e;
  e = error_of(write_triangle_gltf(dir, R"([{"children": [1]}, {"mesh": 0}])", R"([{"nodes": [0, 1]}])"));
  EXPECT_NE(e.find("scene 0 lists node 1, which is a child of node 0"), std::string::npos) << e;
  e = error_of(write_triangle_gltf(dir, R"([{"children": [7]}])", R"([{"nodes": [0]}])"));
  EXPECT_NE(e.find("a child of node 0 is 7, expected a node index below 1"), std::string::npos) << e;
  // 200,000 brackets deep: Assimp's recursive JSON parser overflows the stack.
  std::string deep = std::string(200000, '[') + std::string(200000, ']');
  e = error_of(write_triangle_gltf(dir, kTriangleNodes, deep));
  EXPECT_NE(e.find("tri.gltf: glTF JSON nests deeper than 64 levels"), std::string::npos) << e;
  // The same in a .glb's JSON chunk.
  std::string json = "{\"asset\": {\"version\": \"2.0\"}, \"x\": " + deep + "}";
  json.resize((json.size() + 3) / 4 * 4, ' ');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  write_bytes(dir / "deep.glb",
              "glTF" + u32(2) + u32(uint32_t(20 + json.size())) + u32(uint32_t(json.size())) + "JSON" + json);
  e = error_of(dir / "deep.glb");
  EXPECT_NE(e.find("deep.glb: glTF JSON nests deeper"), std::string::npos) << e;
  // Broken JSON, and glTF 1.0 (Assimp's older importer; not taken).
  write_bytes(dir / "cut.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
  e = error_of(dir / "cut.gltf");
  EXPECT_NE(e.find("cut.gltf: invalid glTF JSON: parse error at line 1"), std::string::npos) << e;
  // An image media type without '/': Assimp takes the extension from after the '/'.
  std::string images = R"([{"nodes": [0, 2]}], "images": [{"uri": "data:imagepng;base64,AAAA"}])";
  e = error_of(write_triangle_gltf(dir, kTriangleNodes, images));
  EXPECT_NE(e.find("image 0: media type 'imagepng' is not TYPE/SUBTYPE"), std::string::npos) << e;
  // A string among numbers: Debian's Assimp asserts (aborts) reading some of them.
  e = error_of(write_triangle_gltf(dir, R"([{"mesh": 0, "translation": [1, "x", 0]}])", R"([{"nodes": [0]}])"));
  EXPECT_NE(e.find("tri.gltf: /nodes/0/translation/1 is string in an array of numbers"), std::string::npos) << e;
  // Extensions Velocity does not use are not read at all: strings for numbers in
  // KHR_texture_transform (which aborts Assimp) and an unknown extension do no harm.
  std::string extensions = R"([{"nodes": [0, 2]}], "extensionsUsed": ["KHR_texture_transform", "EXT_whatever"],
    "textures": [{"source": 0, "extensions": {"KHR_texture_transform": {"scale": ["a", "b"]}}}],
    "extras": {"anything": [1, "two", {"three": 3}]})";
  EXPECT_NO_THROW(load_with_assimp(write_triangle_gltf(dir, kTriangleNodes, extensions)));
  const std::string required = R"([{"nodes": [0, 2]}], "extensionsRequired": ["EXT_meshopt_compression"])";
  e = error_of(write_triangle_gltf(dir, kTriangleNodes, required));
  EXPECT_NE(e.find("requires glTF extension \"EXT_meshopt_compression\", which Velocity does not read"),
            std::string::npos)
      << e;
  REQUIRE_TEST_MODELS();
  e = error_of(model("glTF/BoxTextured-glTF/BoxTextured.gltf"));
  EXPECT_NE(e.find("glTF version 1.0 is not supported"), std::string::npos) << e;
  // simple_skin.gltf without its (optional) inverseBindMatrices: Assimp 5.2.5 crashes
  // on the skin; Velocity, which does not skin, removes skins first and loads it.
  std::string skin = read_bytes(model("glTF2/simple_skin/simple_skin.gltf"));
  const std::string ibm = "\"inverseBindMatrices\" : 4,";
  ASSERT_NE(skin.find(ibm), std::string::npos);
  write_bytes(dir / "skin.gltf", skin.replace(skin.find(ibm), ibm.size(), ""));
  Model skinned = load_with_assimp(dir / "skin.gltf");
  EXPECT_EQ(skinned.triangle_count(), 8u);  // 10 vertices, 24 indices
}

// The binary data must hold what the accessors claim. Found by fuzzing: a 2 KB glTF
// whose sparse accessor claimed 2^32 - 1 VEC4s made Assimp allocate 68 GB.
TEST(FormatsErrors, GltfAccessorsMustFitTheirBuffers) {
  TempDir dir;
  const std::string good = read_bytes(write_triangle_gltf(dir));
  // The triangle's file with `from` replaced by `to`: its error, or "" when it loads.
  auto edited = [&](const std::string& from, const std::string& to, size_t max_memory = LoadOptions{}.max_memory) {
    std::string json = good;
    EXPECT_NE(json.find(from), std::string::npos) << from;
    if (json.find(from) != std::string::npos) json.replace(json.find(from), from.size(), to);
    write_bytes(dir / "edited.gltf", json);
    LoadOptions options;
    options.max_memory = max_memory;
    try {
      load_with_assimp(dir / "edited.gltf", options);
      return std::string();
    } catch (const Error& e) {
      return std::string(e.what());
    }
  };
  const std::string positions = R"("componentType": 5126, "count": 3, "type": "VEC3")";
  const std::string buffers = R"("buffers": [{"uri": "tri.bin", "byteLength": 92}])";
  // A sparse accessor with no bufferView: zeros, then the listed elements replaced. This
  // one moves vertex 2 from (0, 1, 0) to (0, 2, 0) and loads.
  const std::string sparse = R"("sparse": {"count": 1,
      "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 2, "byteOffset": 4}})";
  const std::string two_buffers = R"("buffers": [{"uri": "tri.bin", "byteLength": 92},
      {"uri": "data:application/octet-stream;base64,AgAAAAAAAAAAAABAAAAAAA==", "byteLength": 16}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 84}, {"buffer": 0, "byteOffset": 84, "byteLength": 6},
                    {"buffer": 1, "byteLength": 16}])";
  std::string json = good;
  json.replace(json.find(buffers), json.find("\"accessors\"") - json.find(buffers), two_buffers + ",\n  ");
  json.replace(json.find(R"("bufferView": 0, "byteOffset": 0, )" + positions),
               (R"("bufferView": 0, "byteOffset": 0, )" + positions).size(),
               R"("bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3", )" + sparse);
  write_bytes(dir / "sparse.gltf", json);
  Model m = load_with_assimp(dir / "sparse.gltf");
  ASSERT_EQ(m.triangle_count(), 2u);  // two instances of the triangle
  const Mesh& mesh = *find_node(m, "plain")->mesh;
  expect_near(mesh.positions.at(2), {0, 2, 0}, 0, "the sparse value");

  // The finding: four billion elements Assimp would allocate itself.
  std::string e = edited(R"("bufferView": 0, "byteOffset": 0, )" + positions + ",",
                         R"("componentType": 5126, "count": 4294967295, "type": "VEC4", )" + sparse + ",");
  EXPECT_NE(e.find("edited.gltf: accessor 0: 4294967295 elements of 16 bytes in a sparse accessor: Assimp would allocate "
                   "68719476720 bytes, more than a quarter of the limit of 2147483648 bytes (LoadOptions::max_memory)"),
            std::string::npos)
      << e;
  e = edited(R"("bufferView": 0, "byteOffset": 0, )" + positions, R"("componentType": 5126, "count": 1000, "type": "VEC3")",
             10000);
  EXPECT_NE(e.find("accessor 0: 1000 elements of 12 bytes with no bufferView: Assimp would allocate 12000 bytes, more "
                   "than a quarter of the limit of 10000 bytes"),
            std::string::npos)
      << e;
  // Accessors, views and buffers one element or byte too long.
  e = edited(R"("byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC4")",
             R"("byteOffset": 36, "componentType": 5126, "count": 4, "type": "VEC4")");
  EXPECT_NE(e.find("accessor 1: 4 elements of 16 bytes from byte 36 run past the end of bufferView 0 (84 bytes)"),
            std::string::npos)
      << e;
  e = edited(R"("byteOffset": 84, "byteLength": 6)", R"("byteOffset": 84, "byteLength": 9)");
  EXPECT_NE(e.find("bufferView 1: bytes 84 to 93 run past the end of buffer 0 (92 bytes)"), std::string::npos) << e;
  e = edited(buffers, R"("buffers": [{"uri": "data:application/octet-stream;base64,AAAA", "byteLength": 92}])");
  EXPECT_NE(e.find("buffer 0: byteLength 92 is more than the 3 bytes of its data URI"), std::string::npos) << e;
  e = edited(buffers, R"("buffers": [{"byteLength": 92}])");
  EXPECT_NE(e.find("buffer 0: has no \"uri\" (only a .glb's first buffer may have none)"), std::string::npos) << e;
  // Strides, component types, element types and counts glTF does not have.
  e = edited(R"("byteOffset": 0, "byteLength": 84})", R"("byteOffset": 0, "byteLength": 84, "byteStride": 6})");
  EXPECT_NE(e.find("bufferView 0: byteStride 6 is not a multiple of 4 from 4 to 252"), std::string::npos) << e;
  e = edited(positions, R"("componentType": 5124, "count": 3, "type": "VEC3")");
  EXPECT_NE(e.find("accessor 0: componentType 5124 is not one of glTF's"), std::string::npos) << e;
  e = edited(positions, R"("componentType": 5126, "count": 3, "type": "VEC5")");
  EXPECT_NE(e.find("accessor 0: type is \"VEC5\", expected SCALAR, VEC2"), std::string::npos) << e;
  e = edited(positions, R"("componentType": 5126, "count": -3, "type": "VEC3")");
  EXPECT_NE(e.find("accessor 0: \"count\" is -3, expected a whole number from 0 to 2^53"), std::string::npos) << e;
  e = edited(R"("bufferView": 1,)", R"("bufferView": 7,)");
  EXPECT_NE(e.find("accessor 2: bufferView is 7, expected one of the file's 2 buffer views"), std::string::npos) << e;
  // Primitives: positions, a mode, and enough vertices for it. Found by fuzzing: a line
  // strip with no POSITION made Assimp ask for 2^32 - 1 faces (count - 1, unsigned).
  e = edited(R"("attributes": {"POSITION": 0, "COLOR_0": 1})", R"("attributes": {"COLOR_0": 1}, "mode": 3)");
  EXPECT_NE(e.find("mesh 0, primitive 0: has no POSITION attribute"), std::string::npos) << e;
  e = edited(R"("indices": 2, "material": 0)", R"("indices": 2, "material": 0, "mode": 9)");
  EXPECT_NE(e.find("mesh 0, primitive 0: mode 9 is not a glTF mode (0-6)"), std::string::npos) << e;
  e = edited(R"("count": 3, "type": "SCALAR")", R"("count": 2, "type": "SCALAR")");
  EXPECT_NE(e.find("mesh 0, primitive 0: a TRIANGLES needs at least 3 vertices, it has 2"), std::string::npos) << e;
  e = edited(R"("indices": 2, "material": 0)", R"("indices": 5, "material": 0)");
  EXPECT_NE(e.find("mesh 0, primitive 0: indices is 5, expected one of the file's 3 accessors"), std::string::npos)
      << e;
  // A .glb whose buffer claims more than its binary chunk.
  std::string glb_json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 64}]})";
  glb_json.resize((glb_json.size() + 3) / 4 * 4, ' ');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  write_bytes(dir / "short.glb", "glTF" + u32(2) + u32(uint32_t(28 + glb_json.size() + 8)) +
                                     u32(uint32_t(glb_json.size())) + "JSON" + glb_json + u32(8) +
                                     std::string("BIN\0", 4) + std::string(8, '\0'));
  e = error_of(dir / "short.glb");
  EXPECT_NE(e.find("short.glb: buffer 0: byteLength 64 is more than the 8 bytes of the GLB's binary chunk"),
            std::string::npos)
      << e;
}

// Found by fuzzing: Assimp 5.2.5 dereferences a null pointer on a LINE_LOOP whose
// indices are out of range. Velocity draws no lines; it reads loops as strips, on which
// Assimp drops such indices, and the file is refused with a message, not a crash.
TEST(FormatsErrors, GltfLineLoopWithIndicesOutOfRange) {
  TempDir dir;
  std::string json = read_bytes(write_triangle_gltf(dir));
  auto replace = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(json.find(from), std::string::npos) << from;
    json.replace(json.find(from), from.size(), to);
  };
  // Indices: the last two colour components, 1.0f, read as 32-bit integers: 1065353216.
  replace(R"("bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 3)",
          R"("bufferView": 0, "byteOffset": 76, "componentType": 5125, "count": 2)");
  replace(R"("indices": 2, "material": 0)", R"("indices": 2, "material": 0, "mode": 2)");
  write_bytes(dir / "loop.gltf", json);
  std::string e = error_of(dir / "loop.gltf");
  EXPECT_NE(e.find("loop.gltf: cannot read glTF file: Mesh"), std::string::npos) << e;
  EXPECT_NE(e.find("has no faces"), std::string::npos) << e;
  // In range, the loop is read (as a strip) and refused for having no triangles.
  replace(R"("bufferView": 0, "byteOffset": 76, "componentType": 5125, "count": 2)",
          R"("bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 3)");
  write_bytes(dir / "loop.gltf", json);
  e = error_of(dir / "loop.gltf");
  EXPECT_NE(e.find("loop.gltf: the file has no triangles (only"), std::string::npos) << e;
}

TEST(FormatsErrors, AsciiStlAssimpWouldMisread) {
  TempDir dir;
  const std::string facet =
      "  facet normal 0 0 1\n    outer loop\n      vertex 1 1 0\n      vertex -1 1 0\n      vertex 0 -1 0\n"
      "    endloop\n  endfacet\n";
  write_bytes(dir / "good.stl", "solid good\n" + facet + facet + "endsolid good\n");
  EXPECT_EQ(load_with_assimp(dir / "good.stl").triangle_count(), 2u);
  // Assimp loads each of these without a word (and leaks memory on some).
  std::string number = "solid t\n" + facet + facet + "endsolid\n";
  number.replace(number.find("vertex -1 1 0"), 13, "vertex -1k 1 0");
  write_bytes(dir / "number.stl", number);
  std::string e = error_of(dir / "number.stl");
  EXPECT_NE(e.find("number.stl:5: expected a finite number (the vertex), got '-1k'"), std::string::npos) << e;
  write_bytes(dir / "cut.stl", "solid t\n" + facet + facet.substr(0, 40));
  e = error_of(dir / "cut.stl");
  EXPECT_NE(e.find("cut.stl:11: the file ends where 'vertex' should be (file truncated?)"), std::string::npos) << e;
  write_bytes(dir / "noend.stl", "solid t\n" + facet);
  e = error_of(dir / "noend.stl");
  EXPECT_NE(e.find("the file ends where 'facet' or 'endsolid' should be"), std::string::npos) << e;
  std::string keyword = "solid t\n" + facet + "endsolid\n";
  keyword.replace(keyword.find("endloop"), 7, "endlopp");
  write_bytes(dir / "keyword.stl", keyword);
  e = error_of(dir / "keyword.stl");
  EXPECT_NE(e.find("keyword.stl:7: expected 'endloop', got 'endlopp'"), std::string::npos) << e;
  // A normal broken over two lines: Assimp reads it wrong (and leaks memory).
  std::string broken = "solid t\n" + facet + "endsolid\n";
  broken.replace(broken.find("0 0 1"), 5, "0 0\n1");
  write_bytes(dir / "broken.stl", broken);
  e = error_of(dir / "broken.stl");
  EXPECT_NE(e.find("broken.stl:3: the facet normal should be on line 2"), std::string::npos) << e;
  // A binary file may start with "solid" too: its size tells.
  std::string binary = "solid but binary";
  binary.resize(80, ' ');
  const uint32_t one = 1;
  const float corners[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary += std::string(reinterpret_cast<const char*>(&one), 4) +
            std::string(reinterpret_cast<const char*>(corners), sizeof corners) + std::string(2, '\0');
  write_bytes(dir / "binary.stl", binary);
  EXPECT_EQ(load_with_assimp(dir / "binary.stl").triangle_count(), 1u);
}

// A 3D Studio chunk: id, length (header included), data; little-endian.
std::string chunk_3ds(uint16_t id, const std::string& data) {
  uint32_t length = uint32_t(6 + data.size());
  std::string c(6, '\0');
  std::memcpy(&c[0], &id, 2);
  std::memcpy(&c[2], &length, 4);
  return c + data;
}

TEST(FormatsErrors, ThreeDsCountsAssimpWouldTrust) {
  TempDir dir;
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  // A keyframe track (0xb020, in an object node tag 0xb002) claiming 2^30 keys in 4
  // bytes: Assimp reserves for all of them.
  std::string track = std::string(10, '\0') + u32(1u << 30) + std::string(4, '\0');
  write_bytes(dir / "keys.3ds", chunk_3ds(0x4d4d, chunk_3ds(0xb000, chunk_3ds(0xb002, chunk_3ds(0xb020, track)))));
  std::string e = error_of(dir / "keys.3ds");
  EXPECT_NE(e.find("keys.3ds: byte 38: chunk 0xb020 claims 1073741824 keys"), std::string::npos) << e;
  // A vertex list claiming 65535 vertices in 24 bytes.
  std::string vertices = std::string("\xff\xff", 2) + std::string(24, '\0');
  std::string object = std::string("box", 4) + chunk_3ds(0x4100, chunk_3ds(0x4110, vertices));
  write_bytes(dir / "vertices.3ds", chunk_3ds(0x4d4d, chunk_3ds(0x3d3d, chunk_3ds(0x4000, object))));
  e = error_of(dir / "vertices.3ds");
  EXPECT_NE(e.find("chunk 0x4110 claims 65535 vertices (786420 bytes), but holds 24"), std::string::npos) << e;
  // A chunk longer than its parent.
  std::string main = chunk_3ds(0x4d4d, chunk_3ds(0x3d3d, "abc"));
  main[8] = 100;  // the editor chunk's length
  write_bytes(dir / "long.3ds", main);
  e = error_of(dir / "long.3ds");
  EXPECT_NE(e.find("long.3ds: byte 6: chunk 0x3d3d has length 100, but its parent has 9 bytes left"), std::string::npos)
      << e;
}

TEST(FormatsErrors, MemoryLimit) {
  REQUIRE_TEST_MODELS();
  LoadOptions tiny;
  tiny.max_memory = 1000;  // below the file's 68484 bytes
  std::string e = error_of(model("STL/Spider_binary.stl"), tiny);
  EXPECT_NE(e.find("LoadOptions::max_memory"), std::string::npos) << e;
  LoadOptions small;
  small.max_memory = 80000;  // the file fits; its 4104 vertices and 1368 triangles do not
  e = error_of(model("STL/Spider_binary.stl"), small);
  EXPECT_NE(e.find("the meshes need more"), std::string::npos) << e;
  // A .gltf of 3695 bytes whose buffer (BoxTextured0.bin, 840 bytes) is read too.
  LoadOptions text_only;
  text_only.max_memory = 4000;
  e = error_of(model("glTF2/BoxTextured-glTF/BoxTextured.gltf"), text_only);
  EXPECT_NE(e.find("BoxTextured0.bin"), std::string::npos) << e;
  EXPECT_NE(e.find("LoadOptions::max_memory"), std::string::npos) << e;
}

TEST(FormatsDispatch, LoadModelTakesTheNewExtensions) {
  REQUIRE_TEST_MODELS();
  EXPECT_EQ(load_model(model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb")).triangle_count(), 12u);
  EXPECT_EQ(load_model(model("glTF2/BoxTextured-glTF/BoxTextured.gltf")).triangle_count(), 12u);
  EXPECT_EQ(load_model(model("3DS/cube_with_diffuse_texture.3DS")).triangle_count(), 12u);  // upper case
  EXPECT_EQ(load_model(model("PLY/cube.ply")).triangle_count(), 12u);
  EXPECT_EQ(load_model(model("STL/triangle.stl")).triangle_count(), 1u);
}

// ----------------------------------------------------------------------------- render

int pixels_unlike_background(const Image& image, Vec3 background) {
  int n = 0;
  const int br = int(std::lround(background.x * 255)), bg = int(std::lround(background.y * 255)),
            bb = int(std::lround(background.z * 255));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      n += std::abs(p[0] - br) + std::abs(p[1] - bg) + std::abs(p[2] - bb) > 6;
    }
  return n;
}

TEST(FormatsRender, EngineThroughItsOwnCameraAndFramed) {
  REQUIRE_TEST_MODELS();
  Model m = load_with_assimp(model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"));
  Scene scene;
  add_to_scene(scene, m);
  Renderer renderer(96, 72);
  // Framed from +Z.
  scene.frame_camera(96.0f / 72.0f);
  const FrameStats& framed = renderer.render(scene);
  EXPECT_GT(framed.triangles_rasterized, 1000u);
  int covered = pixels_unlike_background(renderer.color_image(), scene.background);
  EXPECT_GT(covered, 96 * 72 / 10) << "the engine should cover a good part of the frame";
  // Through the file's own camera, which looks at the engine.
  scene.camera = m.cameras.at(0).camera;
  const FrameStats& own = renderer.render(scene);
  EXPECT_GT(own.triangles_rasterized, 1000u);
  EXPECT_GT(pixels_unlike_background(renderer.color_image(), scene.background), 96 * 72 / 20);
}

}  // namespace
}  // namespace velocity
