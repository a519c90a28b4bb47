// glTF node animations: read from the file (Model::animations), sampled with LINEAR
// (slerp for rotations) and STEP interpolation, and posed into a scene.
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
  auto message = [&](const std::string& path) {
    try {
      load_model(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
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

}  // namespace
}  // namespace velocity
