// glTF node animations: read from the file (Model::animations), sampled with LINEAR
// (slerp for rotations) and STEP interpolation, and posed into a scene; morph target
// weights, morphing the node's mesh.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "gltf_animated.hpp"
#include "velocity/animation.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/view_setup.hpp"

namespace velocity {
namespace {

namespace fs = std::filesystem;
constexpr float kPi = 3.14159265358979f;

void expect_matrix_near(const Mat4& a, const Mat4& b, float tol = 1e-5f) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << "element " << i << "," << j;
}

Quat about_y(float angle) { return {0, std::sin(angle / 2), 0, std::cos(angle / 2)}; }

TEST(Animation, LinearStepAndSlerp) {
  Keys<Vec3> move{{1, 3}, {{0, 0, 0}, {4, -2, 8}}, Interpolation::Linear};
  EXPECT_EQ(sample(move, 0.0f, {}), (Vec3{0, 0, 0}));  // before the first key: the first
  EXPECT_EQ(sample(move, 2.0f, {}), (Vec3{2, -1, 4}));
  EXPECT_EQ(sample(move, 9.0f, {}), (Vec3{4, -2, 8}));  // after the last: the last
  EXPECT_EQ(sample(Keys<Vec3>{}, 2.0f, {7, 7, 7}), (Vec3{7, 7, 7}));  // no keys: the rest value
  Keys<Vec3> step{{0, 1, 2}, {{1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, Interpolation::Step};
  EXPECT_EQ(sample(step, 0.99f, {}), (Vec3{1, 1, 1}));
  EXPECT_EQ(sample(step, 1.0f, {}), (Vec3{2, 2, 2}));
  EXPECT_EQ(sample(step, 1.7f, {}), (Vec3{2, 2, 2}));
  // A quarter turn about Y, a quarter of the way: 22.5 degrees (slerp: the angle goes
  // evenly, which a straight lerp of the quaternions would not).
  Keys<Quat> turn{{0, 1}, {Quat{}, about_y(kPi / 2)}, Interpolation::Linear};
  Quat q = sample(turn, 0.25f, {});
  EXPECT_NEAR(2 * std::atan2(q.y, q.w), kPi / 8, 1e-5f);
  EXPECT_NEAR(q.x, 0, 1e-6f);
  // The short way round: from 350 to 10 degrees goes through 0.
  Quat a = about_y(-kPi / 18), b = about_y(kPi / 18);
  b = {-b.x, -b.y, -b.z, -b.w};  // the same rotation, the other sign
  Quat mid = slerp(a, b, 0.5f);
  expect_matrix_near(rotation_matrix(mid), Mat4::identity());
}

class AnimationFile : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& bytes) {
    dir_ = fs::temp_directory_path() / ("velocity_animation_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return (dir_ / name).string();
  }
  // What loading the file says: its error, or "(loaded)".
  static std::string message(const std::string& path) {
    try {
      load_model(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The file's animation, on the node it names, at the interpolated pose.
TEST_F(AnimationFile, ReadFromGltfAndPosedAtTheInterpolatedTime) {
  Model m = load_model(write("moving.gltf", test::animated_box_gltf(true)));
  ASSERT_EQ(m.animations.size(), 1u);
  const Animation& a = m.animations[0];
  EXPECT_EQ(a.name, "move");
  EXPECT_FLOAT_EQ(a.duration, 2.0f);
  ASSERT_EQ(a.nodes.size(), 1u);
  ASSERT_LT(a.nodes[0].node, m.nodes.size());
  EXPECT_EQ(m.nodes[a.nodes[0].node].name, "mover") << "the node's own name, not the loader's tag";
  EXPECT_EQ(a.nodes[0].rotation.interpolation, Interpolation::Linear);
  EXPECT_EQ(a.nodes[0].scale.interpolation, Interpolation::Step);
  // 0.5 s: a quarter of the way along and round, the scale still 1.
  expect_matrix_near(pose(a.nodes[0], 0.5f), translate({0.5f, 0, 0}) * rotate_y(kPi / 8) * scale({1, 1, 1}));
  // 1.5 s: three quarters; the scale stepped to 2 at 0.8 s.
  expect_matrix_near(pose(a.nodes[0], 1.5f), translate({1.5f, 0, 0}) * rotate_y(3 * kPi / 8) * scale({2, 2, 2}));
  // Posed in a scene: the node's world matrix is its parent's times the pose.
  Scene scene;
  add_to_scene(scene, m);
  Animation in_scene = a;  // add_to_scene keeps the node order: node i is object i
  apply(in_scene, 1.5f, scene);
  const ObjectId id = *scene.find("mover");
  expect_matrix_near(scene.world_matrices()[id],
                     translate({0, 1, 0}) * translate({1.5f, 0, 0}) * rotate_y(3 * kPi / 8) * scale({2, 2, 2}));
  // At rest (no animation applied) it is the file's pose, time 0.
  Model still = load_model(write("still.gltf", test::animated_box_gltf(false)));
  EXPECT_TRUE(still.animations.empty());
}

// Bad keys are refused with the animation and channel named.
TEST_F(AnimationFile, BadKeysAreRefusedWithTheChannelNamed) {
  auto with = [&](auto change) {
    nlohmann::json j = nlohmann::json::parse(test::animated_box_gltf(true));
    change(j);
    return write("bad.gltf", j.dump());
  };
  // Key times that are not times (a VEC3 accessor).
  std::string m = message(with([](nlohmann::json& j) { j["animations"][0]["samplers"][0]["input"] = 4; }));
  EXPECT_NE(m.find("animation 0: channel 0: input: accessor type \"VEC3\", expected SCALAR"), std::string::npos) << m;
  // A node that does not exist.
  m = message(with([](nlohmann::json& j) { j["animations"][0]["channels"][1]["target"]["node"] = 9; }));
  EXPECT_NE(m.find("target node is 9, expected an index below 2"), std::string::npos) << m;
  // An unknown interpolation.
  m = message(with([](nlohmann::json& j) { j["animations"][0]["samplers"][2]["interpolation"] = "SMOOTH"; }));
  EXPECT_NE(m.find("interpolation \"SMOOTH\""), std::string::npos) << m;
}

// Khronos's AnimatedMorphCube (Debian's assimp-testmodels): one mesh, two targets
// ("thin", "angle") that lift the top of the cube, weights LINEAR over 127 keys. The
// expected values are worked out from the file's accessors by hand (a Python reading of
// the .bin): vertex 5 is (-0.01, -0.01, -0.01) at rest, target 0 moves it by
// (0, 0.018932529, 0) and target 1 by (0, 0.019890836, 0).
TEST(MorphFile, MorphCubeWeightsMoveTheTargetsVertices) {
  const std::string file =
      "/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (Debian package assimp-testmodels)";
  Model m = load_model(file);
  ASSERT_EQ(m.animations.size(), 1u);
  const Animation& a = m.animations[0];
  EXPECT_EQ(a.name, "Square");
  EXPECT_NEAR(a.duration, 4.2f, 1e-4f);
  ASSERT_EQ(a.morphs.size(), 1u);
  const MorphAnimation& morph_keys = a.morphs[0];
  EXPECT_EQ(m.nodes[morph_keys.node].name, "AnimatedMorphCube");
  ASSERT_TRUE(morph_keys.targets);
  ASSERT_EQ(morph_keys.targets->positions.size(), 2u);
  ASSERT_EQ(morph_keys.targets->normals.size(), 2u);
  ASSERT_EQ(morph_keys.weights.times.size(), 127u);
  const Mesh& rest = *m.nodes[morph_keys.node].mesh;
  ASSERT_EQ(rest.positions.size(), 24u);
  EXPECT_NEAR(rest.positions[5].y, -0.01f, 1e-6f);

  // 1.05 s: halfway between keys 31 (1.0333 s, weights 0.712547, 0) and 32 (1.0667 s,
  // 0.740741, 0): weight 0.726644 on "thin" alone.
  std::vector<float> w = sample(morph_keys.weights, 1.05f, morph_keys.targets->rest_weights);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0], 0.726644f, 1e-5f);
  EXPECT_NEAR(w[1], 0.0f, 1e-6f);
  Mesh at = morph(*morph_keys.targets, w);
  EXPECT_NEAR(at.positions[5].y, 0.0037572f, 1e-6f);
  EXPECT_NEAR(at.positions[5].x, -0.01f, 1e-6f);
  EXPECT_NEAR(at.positions[0].y, rest.positions[0].y, 1e-7f) << "vertex 0 is in neither target";
  // 3.0 s: just past key 90 (2.99999857 s): weights 0.122667 and 0.877333, both targets.
  Scene scene;
  add_to_scene(scene, m);
  apply(a, 3.0f, scene);
  const Mesh& morphed = *scene.objects()[morph_keys.node].mesh;
  EXPECT_NEAR(morphed.positions[5].y, -0.01f + 0.122667f * 0.0189325f + 0.877333f * 0.0198908f, 2e-6f);
  EXPECT_NEAR(morphed.positions[2].y, -0.01f + 0.122667f * 0.0189325f, 2e-6f) << "vertex 2: target 0 alone";
  for (const Vec3& n : morphed.normals) EXPECT_NEAR(length(n), 1.0f, 1e-5f);
  // Back at rest: the file's own mesh again.
  velocity::rest(a, scene);
  EXPECT_NEAR(scene.objects()[morph_keys.node].mesh->positions[5].y, -0.01f, 1e-6f);
}

// The glTF tutorial's SimpleSkin (Debian's assimp-testmodels: simple_skin.gltf): a strip
// of 10 vertices, two joints at (0, 1, 0) (the second, a child of the first, turns about
// Z: from none at 0 s to 45.03 degrees at 0.5 s), both inverse bind matrices a
// translation by (-0.5, -1, 0), so the rest pose stands half a unit left of the bind
// pose. Expected values worked out by hand from the file (a Python reading of its data
// URIs): at 0.25 s the second joint has turned 22.514 degrees.
TEST(SkinFile, SimpleSkinVerticesFollowTheirJointsByWeight) {
  const std::string file = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (Debian package assimp-testmodels)";
  Model m = load_model(file);
  ASSERT_EQ(m.skins.size(), 1u);
  const Skin& sk = m.skins[0];
  ASSERT_EQ(sk.joints.size(), 2u);
  ASSERT_EQ(sk.vertex_weights.size(), 10u);
  EXPECT_EQ(m.nodes[sk.joints[1]].parent, int(sk.joints[0])) << "the second joint is the first's child";
  EXPECT_FLOAT_EQ(sk.vertex_weights[2][0], 0.75f);
  EXPECT_FLOAT_EQ(sk.vertex_weights[2][1], 0.25f);
  ASSERT_EQ(m.animations.size(), 1u);
  Scene scene;
  add_to_scene(scene, m);
  // At rest: every vertex half a unit left (both joints where they were bound, less 0.5 in x).
  skin(m.skins, scene);
  const Mesh* mesh = scene.objects()[sk.node].mesh.get();
  EXPECT_NEAR(mesh->positions[9].x, 0.5f, 1e-6f);
  EXPECT_NEAR(mesh->positions[9].y, 2.0f, 1e-6f);
  // 0.25 s: vertex 9 (1, 2, 0) on the second joint alone, vertex 5 (1, 1, 0) half and
  // half, vertex 2 (0, 0.5, 0) three quarters on the first.
  apply(m.animations[0], 0.25f, scene);
  skin(m.skins, scene);
  mesh = scene.objects()[sk.node].mesh.get();
  EXPECT_NEAR(mesh->positions[9].x, 0.0789816f, 1e-4f);
  EXPECT_NEAR(mesh->positions[9].y, 2.1152407f, 1e-4f);
  EXPECT_NEAR(mesh->positions[5].x, 0.4809463f, 1e-4f);
  EXPECT_NEAR(mesh->positions[5].y, 1.0957277f, 1e-4f);
  EXPECT_NEAR(mesh->positions[2].x, -0.4426093f, 1e-4f);
  EXPECT_NEAR(mesh->positions[2].y, 0.4616630f, 1e-4f);
  EXPECT_NEAR(mesh->positions[2].z, 0.0f, 1e-6f);
  for (const Vec3& n : mesh->normals) EXPECT_NEAR(length(n), 1.0f, 1e-4f);
}

// `velocity render --time`: the file opened as the viewer opens it (scene_from_model),
// then posed at a time. Vertex 9 (bind (1, 2, 0)) follows the second joint alone:
// rotate((1, 2) - (0.5, 1)) about Z by the joint's angle, plus (0, 1). At 0.25 s the
// angle is 22.514 degrees (the values above); at 1.0 s a key of 90 degrees: (-1, 1.5);
// past the end (5.5 s) the last key, 0 degrees: the rest pose (0.5, 2).
TEST(SkinFile, SceneFromModelPosedAtATime) {
  const std::string file = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (Debian package assimp-testmodels)";
  std::vector<Animation> animations;
  std::vector<Skin> skins;
  Scene scene = scene_from_model(file, LoadOptions{}, false, 4.0f / 3.0f, &animations, &skins);
  ASSERT_EQ(animations.size(), 1u);
  ASSERT_EQ(skins.size(), 1u);
  const size_t node = skins[0].node;
  pose_at(animations, 0, 0.25f, skins, scene);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].x, 0.0789816f, 1e-4f);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].y, 2.1152407f, 1e-4f);
  pose_at(animations, 0, 1.0f, skins, scene);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].x, -1.0f, 1e-4f);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].y, 1.5f, 1e-4f);
  pose_at(animations, 0, 99.0f, skins, scene);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].x, 0.5f, 1e-5f);
  EXPECT_NEAR(scene.objects()[node].mesh->positions[9].y, 2.0f, 1e-5f);
  // No such animation, a negative or NaN time: errors that say what there is.
  auto message = [&](size_t index, float time) {
    try {
      pose_at(animations, index, time, skins, scene);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(posed)");
  };
  EXPECT_EQ(message(1, 0), "animation 1: the file has 1 animation (0..0)");
  EXPECT_EQ(message(0, -1), "animation time must be 0 or more seconds, got -1.000000");
  EXPECT_NE(message(0, std::nanf("")).find("animation time must be 0 or more seconds"), std::string::npos);
  EXPECT_EQ(message(0, 0.5f), "(posed)");
}

// A joint that does not exist, and joints of a vertex past the skin's, are refused.
TEST_F(AnimationFile, BadSkinsAreRefusedWithThePlaceNamed) {
  const std::string file = "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "skipped: " << file << " is missing (Debian package assimp-testmodels)";
  std::ifstream in(file);
  const nlohmann::json good = nlohmann::json::parse(in);
  auto message = [&](auto change) {
    nlohmann::json j = good;
    change(j);
    try {
      load_model(write("bad.gltf", j.dump()));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
  };
  std::string m = message([](nlohmann::json& j) { j["skins"][0]["joints"][1] = 7; });
  EXPECT_NE(m.find("skin 0: joint is 7, expected an index below 3"), std::string::npos) << m;
  // One joint only: the vertices' second joint (index 1) is past it.
  m = message([](nlohmann::json& j) {
    j["skins"][0]["joints"] = {1};
    j["skins"][0].erase("inverseBindMatrices");
  });
  EXPECT_NE(m.find("JOINTS_0 of vertex 2 is 1.000000, expected a joint below 1"), std::string::npos) << m;
  // Inverse bind matrices that are not MAT4.
  m = message([](nlohmann::json& j) { j["skins"][0]["inverseBindMatrices"] = 1; });
  EXPECT_NE(m.find("skin 0: inverseBindMatrices: accessor type \"VEC3\", expected MAT4"), std::string::npos) << m;
}

// Morph weights on a node without a mesh, and targets that do not fit their primitive,
// are refused naming the channel or primitive.
TEST_F(AnimationFile, BadMorphTargetsAreRefusedWithThePlaceNamed) {
  auto with = [&](auto change) {
    nlohmann::json j = nlohmann::json::parse(test::animated_box_gltf(true));
    // One target: the box's own positions as offsets (8 VEC3), weights 0 then 1 over 2 s.
    j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
    j["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", 1}, {"path", "weights"}}}});
    change(j);
    return write("bad.gltf", j.dump());
  };
  // The weights sampler is the translation's (VEC3): weights must be scalars.
  std::string m = message(with([](nlohmann::json&) {}));
  EXPECT_NE(m.find("channel 3: output: accessor type \"VEC3\", expected SCALAR"), std::string::npos) << m;
  // Weights of node 0, which has no mesh.
  m = message(with([](nlohmann::json& j) { j["animations"][0]["channels"][3]["target"]["node"] = 0; }));
  EXPECT_NE(m.find("channel 3: weights of node 0, which has no mesh"), std::string::npos) << m;
  // A target of the index accessor: 36 scalars, not VEC3 offsets.
  m = message(with([](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = 1; }));
  EXPECT_NE(m.find("primitive 0: target 0 POSITION: accessor type \"SCALAR\", expected VEC3"), std::string::npos) << m;
}

}  // namespace
}  // namespace velocity
