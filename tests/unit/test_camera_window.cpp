// Camera::window: off-centre view volumes (a pinhole camera's principal point) for
// perspective and orthographic cameras, checked against the projection's definition
// and against rendered pixels and depth.
#include <gtest/gtest.h>

#include <cmath>

#include "velocity/error.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;

namespace {

// Window coordinates (x right from the left edge, y down from the top, in pixels) of an
// eye-space point under `p` for a width x height image, as the rasterizer maps them.
Vec3 to_image(const Mat4& p, Vec3 eye, int width, int height) {
  Vec4 c = p * Vec4{eye.x, eye.y, eye.z, 1};
  float x = c.x / c.w, y = c.y / c.w;
  return {(x * 0.5f + 0.5f) * float(width), (0.5f - y * 0.5f) * float(height), c.z / c.w};
}

// A small square facing the camera, centred on `at` (eye space = world space here).
Mesh square_at(Vec3 at, float half) {
  Mesh m;
  m.positions = {{at.x - half, at.y - half, at.z},
                 {at.x + half, at.y - half, at.z},
                 {at.x + half, at.y + half, at.z},
                 {at.x - half, at.y + half, at.z}};
  m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  return m;
}

}  // namespace

TEST(CameraWindow, CentredWindowIsTheFieldOfView) {
  Camera c;
  c.fov_y = radians(50);
  float aspect = 1.5f;
  Mat4 expected = c.projection_matrix(aspect);
  float t = std::tan(c.fov_y / 2);
  c.window = ViewWindow{-t * aspect, t * aspect, -t, t};
  Mat4 got = c.projection_matrix(7.0f);  // the aspect is the window's now
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(got.m[i][j], expected.m[i][j], 1e-6f) << i << "," << j;
}

TEST(CameraWindow, OrthographicWindowIsTheBox) {
  Camera c;
  c.projection = Projection::Orthographic;
  c.near = 1, c.far = 9;
  c.window = ViewWindow{-1, 3, -0.5f, 1.5f};
  Mat4 p = c.projection_matrix(1);
  Vec3 a = to_image(p, {-1, 1.5f, -5}, 400, 200);  // top-left corner of the box
  EXPECT_NEAR(a.x, 0, 1e-4f);
  EXPECT_NEAR(a.y, 0, 1e-4f);
  Vec3 b = to_image(p, {3, -0.5f, -5}, 400, 200);  // bottom-right
  EXPECT_NEAR(b.x, 400, 1e-3f);
  EXPECT_NEAR(b.y, 200, 1e-3f);
}

TEST(CameraWindow, PinholeMapsPointsAsTheIntrinsicsSay) {
  const float fx = 500, fy = 480, cx = 300.5f, cy = 170.25f;
  const int w = 640, h = 360;
  Camera c;
  c.near = 0.1f, c.far = 50;
  c.window = ViewWindow::pinhole(fx, fy, cx, cy, w, h);
  Mat4 p = c.projection_matrix(1);
  // u = fx * X / Z' + cx and v = cy - fy * Y / Z' with Z' = -Z the distance in front.
  for (Vec3 e : {Vec3{0, 0, -2}, Vec3{0.4f, -0.3f, -3}, Vec3{-1, 0.7f, -4.5f}}) {
    Vec3 img = to_image(p, e, w, h);
    EXPECT_NEAR(img.x, fx * e.x / -e.z + cx, 2e-3f);
    EXPECT_NEAR(img.y, cy - fy * e.y / -e.z, 2e-3f);
  }
}

TEST(CameraWindow, PinholeRendersAtThePrincipalPointWithMetricDepth) {
  // A small square on the optical axis lands on pixel (cx, cy), far from the centre.
  const int w = 96, h = 64;
  const float cx = 20, cy = 44;  // the corner between pixels 19 and 20, 43 and 44
  Camera c;
  c.position = {0, 0, 0};
  c.near = 0.5f, c.far = 20;
  c.window = ViewWindow::pinhole(80, 80, cx, cy, w, h);
  Material white;
  white.shading = Shading::Unlit;
  white.color = {1, 1, 1};
  Mesh sq = square_at({0, 0, -4}, 0.09f);  // 80 * 0.09 / 4 = 1.8 pixels from the centre each way
  Renderer r(w, h);
  r.begin_frame(c, {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &white);
  r.end_frame();
  Image img = r.color_image();
  std::vector<float> depth = r.view_depth();
  int drawn = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool lit = img.pixel(x, y)[0] == 255;
      bool inside = std::abs(x + 0.5f - cx) < 1.8f && std::abs(y + 0.5f - cy) < 1.8f;
      EXPECT_EQ(lit, inside) << x << "," << y;
      drawn += lit;
      if (lit) EXPECT_NEAR(depth[size_t(y) * w + x], 4.0f, 1e-4f);
      else EXPECT_EQ(depth[size_t(y) * w + x], 0.0f);
    }
  EXPECT_EQ(drawn, 16);  // pixels 18..21 in x and 42..45 in y: centres within 1.8
}

TEST(CameraWindow, OffCentreOrthographicDepthIsExact) {
  Camera c;
  c.position = {0, 0, 0};
  c.projection = Projection::Orthographic;
  c.near = 1, c.far = 30;
  c.window = ViewWindow{0, 4, 0, 2};  // the square at x, y in [0.5, 1.5] sits left of centre
  Material white;
  white.shading = Shading::Unlit;
  Mesh sq = square_at({1, 1, -7.25f}, 0.5f);
  Renderer r(80, 40);
  r.begin_frame(c, {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &white);
  r.end_frame();
  std::vector<float> depth = r.view_depth();
  // 20 pixels per unit: x in [10, 30), rows from the top: y in [0.5, 1.5] -> [10, 30).
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 80; ++x) {
      float d = depth[size_t(y) * 80 + x];
      if (x >= 10 && x < 30 && y >= 10 && y < 30) EXPECT_NEAR(d, 7.25f, 1e-5f) << x << "," << y;
      else EXPECT_EQ(d, 0.0f) << x << "," << y;
    }
}

TEST(CameraWindow, PinholeRejectsBadIntrinsics) {
  EXPECT_THROW(ViewWindow::pinhole(0, 1, 0, 0, 10, 10), Error);
  EXPECT_THROW(ViewWindow::pinhole(1, -1, 0, 0, 10, 10), Error);
  EXPECT_THROW(ViewWindow::pinhole(1, 1, NAN, 0, 10, 10), Error);
  EXPECT_THROW(ViewWindow::pinhole(INFINITY, 1, 0, 0, 10, 10), Error);
  EXPECT_THROW(ViewWindow::pinhole(1, 1, 0, 0, 0, 10), Error);
}
