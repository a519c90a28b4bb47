// Matrices, transforms and projection.
#include <gtest/gtest.h>

#include "velocity/math.hpp"
#include "velocity/scene.hpp"

using namespace velocity;

namespace {

void expect_near(Vec3 a, Vec3 b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(Math, RotationsAreRightHanded) {
  expect_near(rotate_z(radians(90)).transform_vector({1, 0, 0}), {0, 1, 0});
  expect_near(rotate_x(radians(90)).transform_vector({0, 1, 0}), {0, 0, 1});
  expect_near(rotate_y(radians(90)).transform_vector({0, 0, 1}), {1, 0, 0});
  expect_near(rotate(radians(90), {0, 0, 2}).transform_vector({1, 0, 0}), {0, 1, 0});
}

TEST(Math, ComposedTransformScalesThenRotatesThenTranslates) {
  Transform t;
  t.scale = {2, 2, 2};
  t.rotation = {0, radians(90), 0};
  t.translation = {10, 0, 0};
  // (1,0,0) -> scale (2,0,0) -> yaw 90 (0,0,-2) -> translate (10,0,-2)
  expect_near(t.matrix().transform_point({1, 0, 0}), {10, 0, -2});
}

TEST(Math, InverseUndoesMatrix) {
  Mat4 m = translate({1, 2, 3}) * rotate(0.7f, {1, 1, 0}) * scale({2, 3, 4});
  Mat4 inv;
  ASSERT_TRUE(invert(m, inv));
  Mat4 id = m * inv;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(id.m[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
  Mat4 singular = scale({1, 0, 1});
  EXPECT_FALSE(invert(singular, inv));
}

TEST(Math, NormalMatrixKeepsNormalsPerpendicularUnderNonUniformScale) {
  Mat4 m = scale({4, 1, 1});
  Vec3 tangent = m.transform_vector(normalize({1, -1, 0}));  // along the surface x + y = 1
  Vec3 n = normal_matrix(m).transform_vector(normalize({1, 1, 0}));
  EXPECT_NEAR(dot(tangent, n), 0.0f, 1e-6f);
}

TEST(Math, PerspectiveMapsNearAndFarToClipBounds) {
  Mat4 p = perspective(radians(45), 16.0f / 9.0f, 0.1f, 100.0f);
  Vec4 n = p * Vec4{0, 0, -0.1f, 1}, f = p * Vec4{0, 0, -100, 1};
  EXPECT_NEAR(n.z / n.w, -1.0f, 1e-5f);
  EXPECT_NEAR(f.z / f.w, 1.0f, 1e-4f);
  // The top of the view at distance d is d * tan(22.5 degrees).
  Vec4 top = p * Vec4{0, std::tan(radians(22.5f)) * 5, -5, 1};
  EXPECT_NEAR(top.y / top.w, 1.0f, 1e-5f);
  Vec4 right = p * Vec4{std::tan(radians(22.5f)) * 5 * 16.0f / 9.0f, 0, -5, 1};
  EXPECT_NEAR(right.x / right.w, 1.0f, 1e-5f);
}

TEST(Math, OrthographicIsAffine) {
  Mat4 o = orthographic(-2, 2, -1, 1, 1, 11);
  Vec4 a = o * Vec4{2, 1, -1, 1}, b = o * Vec4{-2, -1, -11, 1};
  EXPECT_FLOAT_EQ(a.w, 1.0f);
  expect_near(a.xyz(), {1, 1, -1});
  expect_near(b.xyz(), {-1, -1, 1});
}

TEST(Math, CameraViewIsTheInverseOfItsPlacement) {
  Camera cam;
  cam.position = {1, 2, 3};
  cam.yaw = 0.3f, cam.pitch = -0.2f, cam.roll = 0.1f;
  Mat4 placement = translate(cam.position) * rotate_y(cam.yaw) * rotate_x(cam.pitch) * rotate_z(cam.roll);
  Mat4 id = cam.view() * placement;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(id.m[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
}

TEST(Math, CameraLookAtPointsDownItsMinusZ) {
  Camera cam;
  cam.position = {3, 4, 5};
  cam.look_at({-1, 0, 2});
  Vec3 target_in_eye = cam.view().transform_point({-1, 0, 2});
  EXPECT_NEAR(target_in_eye.x, 0.0f, 1e-4f);
  EXPECT_NEAR(target_in_eye.y, 0.0f, 1e-4f);
  EXPECT_LT(target_in_eye.z, 0.0f);
}

TEST(Math, FocalLengthGivesFieldOfView) {
  // A 24 mm high film behind a 12 mm lens sees 90 degrees.
  EXPECT_NEAR(Camera::fov_from_focal_length(12.0f), radians(90), 1e-5f);
}

TEST(Scene, ChildFollowsParentAndTurnsOnItsOwn) {
  Scene scene;
  ObjectId car = scene.add_object("car", nullptr);
  ObjectId wheel = scene.add_object("wheel", nullptr, car);
  scene.object(wheel).transform.translation = {1, 0, 0};
  scene.object(car).transform.translation = {0, 0, -5};
  scene.object(car).transform.rotation = {0, radians(90), 0};
  auto world = scene.world_matrices();
  expect_near(world[wheel].transform_point({0, 0, 0}), {0, 0, -6});
  // Spinning the wheel moves a point on its rim, not the wheel's centre.
  scene.object(wheel).transform.rotation = {0, 0, radians(90)};
  world = scene.world_matrices();
  expect_near(world[wheel].transform_point({0, 0, 0}), {0, 0, -6});
  // Rim point (0,1,0) turns to (-1,0,0) about the wheel axle; the car puts that at -5.
  expect_near(world[wheel].transform_point({0, 1, 0}), {0, 0, -5}, 1e-5f);
  EXPECT_THROW(scene.add_object("orphan", nullptr, 42), std::exception);
}

TEST(Scene, TransformsNeverTouchTheMesh) {
  auto mesh = std::make_shared<Mesh>(make_cube(1.0f));
  std::vector<Vec3> before = mesh->positions;
  Scene scene;
  ObjectId id = scene.add_object("cube", mesh);
  scene.object(id).transform.scale = {3, 3, 3};
  scene.object(id).transform.translation = {5, 5, 5};
  (void)scene.world_matrices();
  (void)scene.bounds();
  EXPECT_EQ(mesh->positions, before);
}
