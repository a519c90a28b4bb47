// The 3D Studio ASC reader: every quirk of the real files, the axis conversion,
// smoothing groups, lights and cameras, error messages, truncated and damaged input.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>

#include "loader_test_util.hpp"
#include "velocity/load.hpp"

#if __has_include("velocity/renderer.hpp")
#include "velocity/renderer.hpp"
#define VELOCITY_HAVE_RENDERER 1
#endif

namespace velocity {
namespace {

using test::loads_or_throws_error;
using test::read_bytes;
using test::shared_data;
using test::test_data;

// A tiny one-triangle file in 3D Studio's own spelling.
const char* kTriangle =
    "Ambient light color: Red=0.3 Green=0.3 Blue=0.3\r\n"
    "\r\n"
    "Named object: \"Tri\"\r\n"
    "Tri-mesh, Vertices: 3     Faces: 1\r\n"
    "Vertex list:\r\n"
    "Vertex 0:  X: 0     Y: 0     Z: 0\r\n"
    "Vertex 1:  X: 1     Y: 0     Z: 0\r\n"
    "Vertex 2:  X: 0     Y: 1     Z: 0\r\n"
    "Face list:\r\n"
    "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\r\n"
    "Material:\"RED\"\r\n"
    "Smoothing:  1\r\n";

LoadOptions no_swap() {
  LoadOptions o;
  o.swap_yz = false;
  return o;
}

Mesh only_mesh(const Model& m) {  // a copy: the model may be a temporary
  EXPECT_EQ(m.nodes.size(), 1u);
  return *m.nodes.at(0).mesh;
}

std::string error_of(std::string_view text, LoadOptions options = {}) {
  try {
    parse_asc(text, "t.asc", options);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// Cube [0,1]^3 as an ASC mesh: 8 vertices, 12 faces counter-clockwise seen from
// outside, face pair k (one side) in smoothing group `group(k)`.
std::string cube_asc(const std::string& smoothing_for_side_k /* "%d" -> k+1, or fixed */) {
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  std::string s = "Named object: \"Cube\"\nTri-mesh, Vertices: 8     Faces: 12\nVertex list:\n";
  for (int i = 0; i < 8; ++i)
    s += "Vertex " + std::to_string(i) + ":  X: " + std::to_string(i & 1) + "  Y: " + std::to_string((i >> 1) & 1) +
         "  Z: " + std::to_string((i >> 2) & 1) + "\n";
  s += "Face list:\n";
  int f = 0;
  for (int k = 0; k < 6; ++k) {
    const int* q = quads[k];
    int tris[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
    for (auto& t : tris) {
      s += "Face " + std::to_string(f++) + ":    A:" + std::to_string(t[0]) + " B:" + std::to_string(t[1]) +
           " C:" + std::to_string(t[2]) + " AB:1 BC:1 CA:1\n";
      std::string g = smoothing_for_side_k == "%d" ? std::to_string(k + 1) : smoothing_for_side_k;
      s += "Smoothing:  " + g + "\n";
    }
  }
  return s;
}

// ---- the format's quirks ----------------------------------------------------------------

TEST(Asc, ParsesOneTriangleWithAmbientMaterialAndSmoothing) {
  Model m = parse_asc(kTriangle, "tri.asc", no_swap());
  const Mesh& mesh = only_mesh(m);
  EXPECT_EQ(m.nodes[0].name, "Tri");
  EXPECT_EQ(mesh.name, "Tri");
  EXPECT_EQ(mesh.positions.size(), 3u);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0].v[1], 1u);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].name, "RED");
  ASSERT_EQ(mesh.normals.size(), 3u);
  EXPECT_NEAR(mesh.normals[0].z, 1.0f, 1e-6f);
  ASSERT_EQ(m.lights.size(), 1u);
  EXPECT_EQ(m.lights[0].type, LightType::Ambient);
  EXPECT_FLOAT_EQ(m.lights[0].color.y, 0.3f);
  EXPECT_EQ(m.path, "tri.asc");
  EXPECT_NO_THROW(mesh.validate());
}

TEST(Asc, LineEndingsLfCrlfCrMixedAndNoFinalNewline) {
  std::string crlf = kTriangle;
  std::string lf, cr, mixed;
  for (size_t i = 0; i < crlf.size(); ++i) {
    if (crlf[i] == '\r') continue;
    lf += crlf[i];
  }
  for (char c : lf) cr += c == '\n' ? '\r' : c;
  bool flip = false;
  for (char c : lf) {
    if (c == '\n') mixed += (flip = !flip) ? "\r\n" : "\n";
    else mixed += c;
  }
  std::string no_final = lf.substr(0, lf.size() - 1);
  for (const std::string& text : {crlf, lf, cr, mixed, no_final}) {
    Model m = parse_asc(text, "t.asc", no_swap());
    const Mesh& mesh = only_mesh(m);
    EXPECT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.triangles.size(), 1u);
    ASSERT_EQ(mesh.smoothing_groups.size(), 0u);  // one group on every face: stored as "all smooth"
    EXPECT_EQ(mesh.materials.at(0).name, "RED");
  }
}

TEST(Asc, PageHeadersAnywhereAreSkipped) {
  const char* text =
      "\r\n"  // a leading blank line, no Ambient line (the pinball files)
      "Named object: \"P\"\r\n"
      "Tri-mesh, Vertices: 3     Faces: 1\r\n"
      "Vertex list:\r\n"
      "Vertex 0:  X: 0     Y: 0     Z: 0\r\n"
      "\r\n"
      "                                    Page 2\r\n"
      "\r\n\r\n"
      "Vertex 1:  X: 1     Y: 0     Z: 0\r\n"
      "Vertex 2:  X: 0     Y: 1     Z: 0\r\n"
      "Face list:\r\n"
      "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\r\n"
      "                                     Page 3\r\n"
      "Material:\"M\"\r\n"
      "Smoothing:  1\r\n"
      "\r\n" "                                     Page 4\r\n";
  Model m = parse_asc(text, "t.asc");
  EXPECT_EQ(only_mesh(m).positions.size(), 3u);
  EXPECT_EQ(only_mesh(m).materials.at(0).name, "M");
}

TEST(Asc, HeaderVariantsOfOtherWriters) {
  // Single spaces, no colons on the list lines, a Mapped line, tabs before U: and AB:,
  // trailing spaces, "Material: " with a space (the pinball and JeGX/PLIB dialects).
  const char* text =
      "\n"
      "Named object: \"rzr\"\n"
      "\n"
      "Tri-mesh, Vertices: 3 Faces: 1\n"
      "Mapped\n"
      "Vertex list\n"
      "Vertex 0: X: -12.88 Y: 2.40688 Z: -33.8284 \t U: 0.25 V: -0.4271 \n"
      "Vertex 1: X: 2.86 Y: 2.40688 Z: -32.3287 \t U: 10.0 V: 1 \n"
      "Vertex 2: X: 2.86 Y: 2.55533 Z: -32.477 \t U: 0.0 V: 0.0 \n"
      "Face list\n"
      "Face 0: A:0 B:1 C:2 \t AB:1 BC:1 CA:1 \n"
      "Material: \"r255g255b255a255\"\n"
      "Smoothing:1\n";
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc", no_swap()));
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_FLOAT_EQ(mesh.uvs[0].x, 0.25f);
  EXPECT_FLOAT_EQ(mesh.uvs[0].y, 1.4271f);  // V up in the file: 1 - V in the engine's uvs
  EXPECT_FLOAT_EQ(mesh.uvs[1].x, 10.0f);
  EXPECT_FLOAT_EQ(mesh.uvs[1].y, 0.0f);
  EXPECT_FLOAT_EQ(mesh.positions[0].z, -33.8284f);
  EXPECT_EQ(mesh.materials.at(0).color, (Vec3{1, 1, 1}));
}

TEST(Asc, NumberFormats) {
  const char* text =
      "Named object: \"N\"\n"
      "Tri-mesh, Vertices: 3     Faces: 1\n"
      "Vertex list:\n"
      "Vertex 0:  X:-2500     Y:-0     Z:-0.000000\n"       // integers, negative zeros, no space
      "Vertex 1:  X:\t1.5\tY:  +2     Z:1e2\n"               // tabs, '+', an exponent
      "Vertex 2:  X: .5     Y: 3.     Z: -0\n"
      "Face list:\n"
      "Face 0:    A:0 B:1 C:2\n";                             // no edge flags
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc", no_swap()));
  EXPECT_EQ(mesh.positions[0].x, -2500.0f);
  EXPECT_EQ(mesh.positions[0].y, 0.0f);
  EXPECT_EQ(mesh.positions[1].x, 1.5f);
  EXPECT_EQ(mesh.positions[1].y, 2.0f);
  EXPECT_EQ(mesh.positions[1].z, 100.0f);
  EXPECT_EQ(mesh.positions[2].x, 0.5f);
  EXPECT_EQ(mesh.positions[2].y, 3.0f);
}

TEST(Asc, MaterialAppliesToTheFaceBeforeItAndIsNotSticky) {
  const char* text =
      "Named object: \"M\"\n"
      "Tri-mesh, Vertices: 3     Faces: 3\n"
      "Vertex list:\n"
      "Vertex 0:  X: 0 Y: 0 Z: 0\nVertex 1:  X: 1 Y: 0 Z: 0\nVertex 2:  X: 0 Y: 1 Z: 0\n"
      "Face list:\n"
      "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\n"
      "Material:\"YELLOW PLASTIC\"\n"
      "Face 1:    A:0 B:2 C:1 AB:1 BC:1 CA:1\n"  // no Material: not the one before
      "Face 2:    A:0 B:1 C:2 AB:1 BC:1 CA:1\n"
      "Material:\"r133g169b191a0\"\n";
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc"));
  ASSERT_EQ(mesh.face_materials.size(), 3u);
  ASSERT_EQ(mesh.materials.size(), 3u);
  EXPECT_EQ(mesh.materials[mesh.face_materials[0]].name, "YELLOW PLASTIC");
  EXPECT_EQ(mesh.materials[mesh.face_materials[1]].name, "");  // the unnamed default
  EXPECT_EQ(mesh.materials[mesh.face_materials[1]].color, Material{}.color);
  const Material& coded = mesh.materials[mesh.face_materials[2]];
  EXPECT_EQ(coded.name, "r133g169b191a0");
  EXPECT_NEAR(coded.color.x, 133 / 255.0f, 1e-6f);
  EXPECT_NEAR(coded.color.y, 169 / 255.0f, 1e-6f);
  EXPECT_NEAR(coded.color.z, 191 / 255.0f, 1e-6f);
}

TEST(Asc, MaterialNamesEmptyTexturesAndSharedEntries) {
  const char* text =
      "Named object: \"M\"\n"
      "Tri-mesh, Vertices: 3     Faces: 3\n"
      "Vertex 0:  X: 0 Y: 0 Z: 0\nVertex 1:  X: 1 Y: 0 Z: 0\nVertex 2:  X: 0 Y: 1 Z: 0\n"
      "Face 0:    A:0 B:1 C:2\nMaterial: \"floor2.png\"\n"
      "Face 1:    A:0 B:1 C:2\nMaterial: \"\"\n"
      "Face 2:    A:0 B:1 C:2\nMaterial: \"floor2.png\"\n";
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc"));
  ASSERT_EQ(mesh.materials.size(), 2u);  // one entry per distinct name
  EXPECT_EQ(mesh.materials[mesh.face_materials[0]].name, "floor2.png");
  EXPECT_EQ(mesh.materials[mesh.face_materials[1]].name, "");
  EXPECT_EQ(mesh.face_materials[0], mesh.face_materials[2]);
}

TEST(Asc, NoMaterialLinesMeansNoMaterials) {
  std::string text = kTriangle;
  text.erase(text.find("Material:"), std::string("Material:\"RED\"\r\n").size());
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc"));
  EXPECT_TRUE(mesh.materials.empty());
  EXPECT_TRUE(mesh.face_materials.empty());
}

TEST(Asc, SmoothingGroupListsBecomeBitMasks) {
  const char* text =
      "Named object: \"S\"\n"
      "Tri-mesh, Vertices: 4     Faces: 5\n"
      "Vertex 0:  X: 0 Y: 0 Z: 0\nVertex 1:  X: 1 Y: 0 Z: 0\nVertex 2:  X: 0 Y: 1 Z: 0\nVertex 3:  X: 0 Y: 0 Z: 1\n"
      "Face 0:    A:0 B:1 C:2\nSmoothing:  1, 2\n"
      "Face 1:    A:0 B:3 C:1\nSmoothing:  17\n"
      "Face 2:    A:0 B:2 C:3\nSmoothing:1\n"
      "Face 3:    A:1 B:3 C:2\n"  // no Smoothing line: group 0, faceted
      "Face 4:    A:1 B:3 C:2\nSmoothing:  32, 1, \n";
  const Mesh& mesh = only_mesh(parse_asc(text, "t.asc"));
  ASSERT_EQ(mesh.smoothing_groups.size(), 5u);
  EXPECT_EQ(mesh.smoothing_groups[0], 0b11u);
  EXPECT_EQ(mesh.smoothing_groups[1], 1u << 16);
  EXPECT_EQ(mesh.smoothing_groups[2], 1u);
  EXPECT_EQ(mesh.smoothing_groups[3], 0u);
  EXPECT_EQ(mesh.smoothing_groups[4], (1u << 31) | 1u);
}

TEST(Asc, SmoothingGroupsOutsideOneToThirtyTwoAreErrors) {
  std::string base = "Named object: \"S\"\nTri-mesh, Vertices: 3 Faces: 1\n"
                     "Vertex 0: X: 0 Y: 0 Z: 0\nVertex 1: X: 1 Y: 0 Z: 0\nVertex 2: X: 0 Y: 1 Z: 0\n"
                     "Face 0: A:0 B:1 C:2\n";
  EXPECT_NE(error_of(base + "Smoothing:  0\n").find("t.asc:7: expected smoothing group numbers from 1 to 32"),
            std::string::npos);
  EXPECT_NE(error_of(base + "Smoothing:  33\n").find("t.asc:7:"), std::string::npos);
  EXPECT_NE(error_of(base + "Smoothing:  1 x\n").find("got 'x'"), std::string::npos);
}

TEST(Asc, CubeWithOneGroupPerSideHasHardEdges) {
  Model m = parse_asc(cube_asc("%d"), "cube.asc", no_swap());
  const Mesh& mesh = only_mesh(m);
  // Every corner gets one normal per side that meets there: 8 corners x 3 sides = 24
  // distinct (position, normal) pairs. (compute_normals() may store a pair more than
  // once: it does not yet reuse a copy it made for an earlier face.)
  EXPECT_GE(mesh.vertex_count(), 24u);
  std::set<std::tuple<float, float, float, float, float, float>> distinct;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    Vec3 p = mesh.positions[v], n = mesh.normals[v];
    distinct.insert({p.x, p.y, p.z, n.x, n.y, n.z});
  }
  EXPECT_EQ(distinct.size(), 24u);
  // Each vertex normal is its face's normal, which points out of the cube.
  for (const Triangle& t : mesh.triangles) {
    Vec3 fn = face_normal(mesh, t);
    Vec3 centroid = (mesh.positions[t.v[0]] + mesh.positions[t.v[1]] + mesh.positions[t.v[2]]) / 3.0f;
    EXPECT_GT(dot(fn, centroid - Vec3{0.5f, 0.5f, 0.5f}), 0.0f);
    for (uint32_t v : t.v) EXPECT_NEAR(dot(mesh.normals[v], fn), 1.0f, 1e-5f);
  }
}

TEST(Asc, CubeWithOneGroupEverywhereIsSmooth) {
  const Mesh& mesh = only_mesh(parse_asc(cube_asc("1"), "cube.asc", no_swap()));
  EXPECT_EQ(mesh.vertex_count(), 8u);
  // A smooth cube's corner normals point along the diagonals.
  for (size_t v = 0; v < 8; ++v) {
    Vec3 diagonal = normalize(mesh.positions[v] - Vec3{0.5f, 0.5f, 0.5f});
    EXPECT_GT(dot(mesh.normals[v], diagonal), 0.9f);
  }
}

TEST(Asc, SphereWithOneGroupIsSmooth) {
  Mesh sphere = make_sphere(32);
  std::string s = "Named object: \"Sphere\"\nTri-mesh, Vertices: " + std::to_string(sphere.vertex_count()) +
                  "     Faces: " + std::to_string(sphere.triangle_count()) + "\nVertex list:\n";
  char line[160];
  for (size_t i = 0; i < sphere.vertex_count(); ++i) {
    Vec3 p = sphere.positions[i];
    std::snprintf(line, sizeof line, "Vertex %zu:  X:%f     Y:%f     Z:%f\n", i, p.x, p.y, p.z);
    s += line;
  }
  s += "Face list:\n";
  for (size_t f = 0; f < sphere.triangle_count(); ++f) {
    const Triangle& t = sphere.triangles[f];
    std::snprintf(line, sizeof line, "Face %zu:    A:%u B:%u C:%u AB:1 BC:1 CA:1\nSmoothing:  1\n", f, t.v[0], t.v[1],
                  t.v[2]);
    s += line;
  }
  const Mesh& mesh = only_mesh(parse_asc(s, "sphere.asc", no_swap()));
  EXPECT_EQ(mesh.vertex_count(), sphere.vertex_count());  // nothing split
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    EXPECT_GT(dot(mesh.normals[v], normalize(mesh.positions[v])), 0.99f) << "vertex " << v;
}

// ---- axes ---------------------------------------------------------------------------------

TEST(Asc, SwapYzStandsZUpModelsUprightAndKeepsFrontFaces) {
  // In 3D Studio this triangle lies flat on the ground (z = 0) and faces up (+Z): its
  // vertices run counter-clockwise seen from above.
  Model swapped = parse_asc(kTriangle, "t.asc");  // swap_yz is on by default
  const Mesh& m = only_mesh(swapped);
  // (x, y, z) -> (x, z, -y): a rotation, not a mirror.
  EXPECT_EQ(m.positions[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(m.positions[2], (Vec3{0, 0, -1}));
  // Up in 3D Studio is up in Velocity, and the face still turns its front (counter-
  // clockwise side) upwards: seen from above it is drawn, from below it is culled.
  Vec3 n = face_normal(m, m.triangles[0]);
  EXPECT_NEAR(n.y, 1.0f, 1e-6f);
  EXPECT_NEAR(m.normals[0].y, 1.0f, 1e-6f);

  // A point 3D Studio puts behind the origin (+Y, away from its front view) ends up
  // behind it in Velocity too (-Z, away from the default camera on +Z).
  const char* point =
      "Named object: \"P\"\nTri-mesh, Vertices: 3 Faces: 0\n"
      "Vertex 0: X: 1 Y: 2 Z: 3\nVertex 1: X: 0 Y: 0 Z: 0\nVertex 2: X: 0 Y: 0 Z: 0\n";
  EXPECT_EQ(only_mesh(parse_asc(point, "p.asc")).positions[0], (Vec3{1, 3, -2}));
  EXPECT_EQ(only_mesh(parse_asc(point, "p.asc", no_swap())).positions[0], (Vec3{1, 2, 3}));
}

#ifdef VELOCITY_HAVE_RENDERER
// The same triangle, drawn: seen from above it covers pixels, seen from below it is a
// back face and culled.
TEST(Asc, SwappedGroundTriangleIsDrawnFromAboveAndCulledFromBelow) {
  Scene scene;
  add_to_scene(scene, parse_asc(kTriangle, "t.asc"));
  scene.lights.clear();
  Renderer r(32, 32);
  auto covered = [&](Vec3 eye) {
    scene.camera.position = eye;
    scene.camera.look_at({0.3f, 0, -0.3f});
    r.render(scene);
    return r.stats().triangles_rasterized;
  };
  EXPECT_EQ(covered({0.3f, 3, -0.2f}), 1u);
  EXPECT_EQ(covered({0.3f, -3, -0.2f}), 0u);
}
#endif

// ---- objects, lights, cameras ---------------------------------------------------------------

const char* kScene =
    "Ambient light color: Red=0.039216 Green=0.039216 Blue=0.039216\n"
    "\n"
    "Named object: \"Light01\"\n"
    "Direct light\n"
    "Position:  X:0 Y:-100 Z:50\n"
    "Light color: Red=0.705882 Green=0.5 Blue=1\n"
    "\n"
    "Named object: \"Spot\"\n"
    "Direct light\n"
    "Position: X:1\tY:2\tZ:3\n"
    "Spotlight to: X:0\tY:0\tZ:0\n"
    "Hotspot size: 44 degrees\n"
    "Falloff size: 45 degrees\n"
    "Light color: Red=1\tGreen=1\tBlue=1\n"
    "\n"
    "Named object: \"Camera01\"\n"
    "Camera (50.000004mm)\n"
    "Position:  X:0 Y:-10 Z:0\n"
    "Target:  X:0 Y:0 Z:0\n"
    "Bank angle: 30 degrees\n"
    "Near 0 Far 1000\n"
    "\n"
    "Named object: \"A\"\n"
    "Tri-mesh, Vertices: 3     Faces: 1\n"
    "Vertex list:\n"
    "Vertex 0:  X: -1 Y: 0 Z: 0\nVertex 1:  X: 1 Y: 0 Z: 0\nVertex 2:  X: 0 Y: 0 Z: 1\n"
    "Face list:\n"
    "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\n"
    "\n"
    "Named object: \"B two\"\n"
    "Tri-mesh, Vertices: 3     Faces: 1\n"
    "Vertex list:\n"
    "Vertex 0:  X: 0 Y: 0 Z: 0\nVertex 1:  X: 1 Y: 0 Z: 0\nVertex 2:  X: 0 Y: 1 Z: 0\n"
    "Face list:\n"
    "Face 0:    A:0 B:1 C:2 AB:1 BC:1 CA:1\n";

TEST(Asc, SeveralNamedObjectsBecomeNodesInFileOrder) {
  Model m = parse_asc(kScene, "scene.asc");
  ASSERT_EQ(m.nodes.size(), 2u);  // lights and cameras are not nodes
  EXPECT_EQ(m.nodes[0].name, "A");
  EXPECT_EQ(m.nodes[1].name, "B two");
  for (const ModelNode& n : m.nodes) {
    EXPECT_EQ(n.parent, -1);
    EXPECT_EQ(n.local, Mat4::identity());  // ASC vertices are already in world space
  }
  EXPECT_EQ(m.vertex_count(), 6u);
  EXPECT_EQ(m.triangle_count(), 2u);
}

TEST(Asc, DirectLightsBecomePointLightsAndAmbientStaysAmbient) {
  Model m = parse_asc(kScene, "scene.asc");
  ASSERT_EQ(m.lights.size(), 3u);
  EXPECT_EQ(m.lights[0].type, LightType::Ambient);
  EXPECT_FLOAT_EQ(m.lights[0].color.x, 0.039216f);
  EXPECT_EQ(m.lights[1].type, LightType::Point);
  EXPECT_EQ(m.lights[1].position, (Vec3{0, 50, 100}));  // swapped like the vertices
  EXPECT_EQ(m.lights[1].color, (Vec3{0.705882f, 0.5f, 1}));
  EXPECT_EQ(m.lights[1].linear, 0.0f);  // 3D Studio lights do not fall off by default
  EXPECT_EQ(m.lights[1].quadratic, 0.0f);
  EXPECT_EQ(m.lights[2].type, LightType::Point);  // a spotlight: a point light at its position
  EXPECT_EQ(m.lights[2].position, (Vec3{1, 3, -2}));
}

TEST(Asc, CameraFromFocalLengthTargetAndBank) {
  Model m = parse_asc(kScene, "scene.asc");
  ASSERT_EQ(m.cameras.size(), 1u);
  const NamedCamera& c = m.cameras[0];
  EXPECT_EQ(c.name, "Camera01");
  EXPECT_EQ(c.camera.position, (Vec3{0, 0, 10}));  // 3D Studio (0, -10, 0): in front
  EXPECT_NEAR(c.camera.fov_y, Camera::fov_from_focal_length(50.000004f), 1e-6f);
  // Looking at the origin from +Z is Velocity's rest orientation.
  EXPECT_NEAR(c.camera.yaw, 0.0f, 1e-6f);
  EXPECT_NEAR(c.camera.pitch, 0.0f, 1e-6f);
  EXPECT_NEAR(c.camera.roll, radians(30.0f), 1e-6f);
  // Clip planes fitted around the meshes (3D Studio's Near/Far are fog ranges).
  // The meshes lie within 1.3 of (0, 0.5, -0.5), 10.5 from the camera.
  EXPECT_GT(c.camera.near, 9.0f);
  EXPECT_LT(c.camera.near, 9.5f);
  EXPECT_GT(c.camera.far, 11.5f);
  EXPECT_LT(c.camera.far, 12.0f);
}

TEST(Asc, CameraLookingDownFromAbove) {
  const char* text =
      "Named object: \"C\"\nCamera (35mm)\nPosition:  X:0 Y:0 Z:100\nTarget:  X:0 Y:0 Z:0\n"
      "Named object: \"T\"\nTri-mesh, Vertices: 3 Faces: 1\n"
      "Vertex 0: X: 0 Y: 0 Z: 0\nVertex 1: X: 1 Y: 0 Z: 0\nVertex 2: X: 0 Y: 1 Z: 0\nFace 0: A:0 B:1 C:2\n";
  Model m = parse_asc(text, "t.asc");
  const Camera& cam = m.cameras.at(0).camera;
  EXPECT_EQ(cam.position, (Vec3{0, 100, 0}));
  EXPECT_NEAR(cam.pitch, -std::numbers::pi_v<float> / 2, 1e-5f);  // straight down
  EXPECT_NEAR(cam.fov_y, 2 * std::atan(12.0f / 35.0f), 1e-6f);
}

// ---- errors -----------------------------------------------------------------------------------

TEST(Asc, CountMismatchNamesFileLineAndExpectation) {
  std::string text = kTriangle;
  text.replace(text.find("Vertices: 3"), 11, "Vertices: 4");
  EXPECT_EQ(error_of(text), "t.asc:4: expected 4 vertices in mesh 'Tri' (its Tri-mesh header), got 3");
  text = kTriangle;
  text.replace(text.find("Faces: 1"), 8, "Faces: 2");
  EXPECT_EQ(error_of(text), "t.asc:4: expected 2 faces in mesh 'Tri' (its Tri-mesh header), got 1");
  text = kTriangle;
  text.replace(text.find("Vertices: 3"), 11, "Vertices: 2");
  EXPECT_NE(error_of(text).find("t.asc:8: expected at most 2 vertices in mesh 'Tri'"), std::string::npos);
}

TEST(Asc, FaceIndexOutOfRangeIsAnError) {
  std::string text = kTriangle;
  text.replace(text.find("C:2"), 3, "C:3");
  EXPECT_EQ(error_of(text), "t.asc:10: expected vertex numbers below 3 (mesh 'Tri'), got '3'");
}

TEST(Asc, BadNumbersAreErrors) {
  for (const char* bad : {"X: nan", "X: inf", "X: -inf", "X: 1e99", "X: abc", "X: 1.2.3", "X: --1"}) {
    std::string text = kTriangle;
    text.replace(text.find("X: 1 "), 4, bad);
    std::string e = error_of(text);
    EXPECT_NE(e.find("t.asc:7: expected"), std::string::npos) << bad << ": " << e;
  }
}

TEST(Asc, OutOfOrderRecordsAndStrayLinesAreErrors) {
  std::string text = kTriangle;
  text.replace(text.find("Vertex 1:"), 9, "Vertex 5:");
  EXPECT_EQ(error_of(text), "t.asc:7: expected 'Vertex 1:', got 'Vertex 5:  X: 1     Y: 0     Z: 0'");

  text = kTriangle;
  text.insert(text.find("Face list"), "Hello there\r\n");
  EXPECT_EQ(error_of(text),
            "t.asc:9: expected a Vertex, Face, Material or Smoothing line in mesh 'Tri', got 'Hello there'");

  EXPECT_NE(error_of("Vertex 0: X: 0 Y: 0 Z: 0\n").find("t.asc:1: expected a 'Tri-mesh' line"), std::string::npos);
  EXPECT_NE(error_of("Named object: \"x\"\nTri-mesh, Vertices: 0 Faces: 0\nMaterial:\"A\"\n")
                .find("t.asc:3: expected a Face line before this Material line"),
            std::string::npos);
  EXPECT_NE(error_of("Named object: \"x\"\nTri-mesh, Vertices: three Faces: 0\n")
                .find("t.asc:2: expected 'Tri-mesh, Vertices: N Faces: M'"),
            std::string::npos);
  EXPECT_NE(error_of("Named object: \"c\"\nCamera (0mm)\n").find("t.asc:2: expected 'Camera (F mm)'"),
            std::string::npos);
  EXPECT_NE(error_of("Named object: \"c\"\nCamera (35mm)\nPosition: X:0 Y:0 Z:0\n")
                .find("t.asc:1: expected 'Position:' and 'Target:' lines for camera 'c', got no Target"),
            std::string::npos);
  EXPECT_NE(error_of("Named object: \"l\"\nDirect light\n").find("t.asc:1: expected a 'Position:' line for light 'l'"),
            std::string::npos);
}

TEST(Asc, TextWithoutNamedObjectsIsNotAnAscFile) {
  EXPECT_EQ(error_of(""), "t.asc:1: expected at least one 'Named object:' (is this a 3D Studio ASCII file?), got none");
  EXPECT_NE(error_of("<html>\n<body>\n").find("t.asc:2: expected at least one 'Named object:'"), std::string::npos);
}

TEST(Asc, HugeHeaderCountsAllocateNothingAndFail) {
  // Claims four billion vertices in a 100-byte file: refused by the memory limit ...
  std::string e = error_of("Named object: \"x\"\nTri-mesh, Vertices: 4000000000 Faces: 4000000000\n");
  EXPECT_NE(e.find("more than LoadOptions::max_memory allows"), std::string::npos) << e;
  // ... and, under a generous limit, by the count check, after reserving only what the
  // few remaining bytes could hold.
  LoadOptions big;
  big.max_memory = SIZE_MAX;
  e = error_of("Named object: \"x\"\nTri-mesh, Vertices: 4000000000 Faces: 1\nVertex 0: X: 0 Y: 0 Z: 0\n", big);
  EXPECT_EQ(e, "t.asc:2: expected 4000000000 vertices in mesh 'x' (its Tri-mesh header), got 1");
}

// ---- real files -----------------------------------------------------------------------------

TEST(Asc, LoadsSecondRealityCity) {
  Model m = load_asc(test_data("models/CITY.ASC"));
  EXPECT_EQ(m.nodes.size(), 25u);
  EXPECT_EQ(m.triangle_count(), 796u);
  EXPECT_GE(m.vertex_count(), 610u);  // plus the copies hard edges need
  ASSERT_EQ(m.cameras.size(), 1u);
  EXPECT_EQ(m.lights.size(), 2u);  // ambient + Light02
  for (const ModelNode& n : m.nodes) EXPECT_NO_THROW(n.mesh->validate()) << n.name;
}

TEST(Asc, LoadsForkWithLfEndingsAndThreeLights) {
  Model m = load_asc(test_data("models/fork.asc"));
  ASSERT_EQ(m.nodes.size(), 1u);
  EXPECT_EQ(m.nodes[0].name, "fork");
  EXPECT_EQ(m.triangle_count(), 72u);
  EXPECT_EQ(m.lights.size(), 4u);
  EXPECT_EQ(m.nodes[0].mesh->materials.at(0).name, "CHROME GIFMAP");
}

TEST(Asc, LoadsDuckWithCameraAndSpacedMaterialNames) {
  Model m = load_asc(test_data("models/duck.asc"));
  EXPECT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.triangle_count(), 516u + 24u + 24u);
  ASSERT_EQ(m.cameras.size(), 1u);
  EXPECT_NEAR(m.cameras[0].camera.fov_y, Camera::fov_from_focal_length(30.219599f), 1e-6f);
  bool yellow = false;
  for (const Material& mat : m.nodes[0].mesh->materials) yellow |= mat.name == "YELLOW PLASTIC";
  EXPECT_TRUE(yellow);
}

TEST(Asc, LoadsTestiWithFewSmoothingLinesAndBlankLinesBeforeTheLastPage) {
  Model m = load_asc(test_data("models/TESTI.ASC"));
  EXPECT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.triangle_count(), 9u);
}

// ---- truncated and damaged input --------------------------------------------------------------

void check_every_prefix(const std::string& bytes, const std::string& what) {
  size_t loaded = 0;
  for (size_t n = 0; n <= bytes.size(); ++n)
    loaded += loads_or_throws_error([&] { parse_asc(std::string_view(bytes).substr(0, n), what); },
                                    what + " cut at " + std::to_string(n));
  EXPECT_GT(loaded, 0u) << what;  // at least the whole file loads
}

TEST(Asc, EveryPrefixOfForkLoadsOrThrows) {
  std::string bytes = read_bytes(test_data("models/fork.asc"));
  ASSERT_EQ(bytes.size(), 9000u);
  check_every_prefix(bytes, "fork.asc");
}

TEST(Asc, EveryPrefixOfTestiLoadsOrThrows) { check_every_prefix(read_bytes(test_data("models/TESTI.ASC")), "TESTI.ASC"); }

TEST(Asc, EveryPrefixOfCube01LoadsOrThrows) {
  std::string path = shared_data("models/asc/cube01.asc");
  VELOCITY_REQUIRE_SHARED(path);
  check_every_prefix(read_bytes(path), "cube01.asc");
}

TEST(Asc, DamagedBytesLoadOrThrow) {
  std::string original = read_bytes(test_data("models/fork.asc"));
  test::Rng rng;
  const char alphabet[] = "0123456789 :-.\"\r\n\tXYZABCVFaceVertexPage\xff";
  for (int i = 0; i < 3000; ++i) {
    std::string bytes = original;
    int edits = 1 + int(rng.next() % 4);
    for (int e = 0; e < edits; ++e) {
      size_t at = rng.next() % bytes.size();
      switch (rng.next() % 3) {
        case 0: bytes[at] = alphabet[rng.next() % (sizeof alphabet - 1)]; break;
        case 1: bytes.erase(at, 1 + rng.next() % 8); break;
        case 2: bytes.insert(at, 1, alphabet[rng.next() % (sizeof alphabet - 1)]); break;
      }
      if (bytes.empty()) bytes.assign(1, 'x');
    }
    loads_or_throws_error([&] { parse_asc(bytes, "damaged.asc"); }, "mutation " + std::to_string(i));
  }
}

// ---- speed ------------------------------------------------------------------------------------

// A generated grid of about a million triangles, written as 3D Studio writes (CRLF, a
// Material and a Smoothing line per face, Page headers). `bands` > 0 puts the faces in
// alternating smoothing groups, bands of that many columns, so compute_normals() has
// hard edges to split; 0 puts every face in group 1. Prints the load time.
void million_triangle_bench(int bands) {
  const int n = 709;  // (n - 1)^2 * 2 = 1,002,528 triangles
  std::string s = "Ambient light color: Red=0.3 Green=0.3 Blue=0.3\r\n\r\nNamed object: \"Grid\"\r\n";
  s += "Tri-mesh, Vertices: " + std::to_string(n * n) + "     Faces: " + std::to_string(2 * (n - 1) * (n - 1)) +
       "\r\nVertex list:\r\n";
  char line[200];
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      std::snprintf(line, sizeof line, "Vertex %d:  X:%f     Y:%f     Z:%f\r\n", y * n + x, x * 0.01, y * 0.01,
                    0.1 * std::sin(x * 0.05) * std::cos(y * 0.05));
      s += line;
    }
  s += "Face list:\r\n";
  int f = 0;
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      int a = y * n + x, b = a + 1, c = a + n, d = c + 1;
      int group = bands > 0 ? 1 + (x / bands) % 2 : 1;
      const char* fmt = "Face %d:    A:%d B:%d C:%d AB:1 BC:1 CA:0\r\nMaterial:\"r133g169b191a0\"\r\nSmoothing:  %d\r\n";
      std::snprintf(line, sizeof line, fmt, f++, a, b, d, group);
      s += line;
      std::snprintf(line, sizeof line, fmt, f++, a, d, c, group);
      s += line;
      if (f % 20 == 0) s += "\r\n                                    Page 1\r\n\r\n";
    }
  auto start = std::chrono::steady_clock::now();
  Model m = parse_asc(s, "grid.asc");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(m.triangle_count(), size_t(2 * (n - 1) * (n - 1)));
  // The share of that spent in compute_normals(), timed again on a copy.
  Mesh copy = *m.nodes[0].mesh;
  start = std::chrono::steady_clock::now();
  compute_normals(copy);
  double normals = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ bench    ] %zu triangles, %zu vertices, %.1f MB of text: %.3f s (%.1f M triangles/s), "
              "of which compute_normals %.3f s\n",
              m.triangle_count(), m.vertex_count(), s.size() / 1e6, seconds, m.triangle_count() / seconds / 1e6,
              normals);
}

// Run with --gtest_also_run_disabled_tests.
TEST(AscBench, DISABLED_MillionTriangles) { million_triangle_bench(0); }
TEST(AscBench, DISABLED_MillionTrianglesWithSmoothingGroups) { million_triangle_bench(50); }

}  // namespace
}  // namespace velocity
