// The lighting model's two forms (src/shading/): the SIMD one the kernels run must
// compute what the scalar one does, for every light kind and with and without a
// highlight.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "shading/lighting.hpp"

using namespace velocity;
using namespace velocity::shading;

TEST(Lighting, SimdFormIsTheScalarForm) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.1f, 1.0f);
  auto dir = [&] {
    Vec3 v;
    do v = {u(rng), u(rng), u(rng)};
    while (length(v) < 0.1f);
    return normalize(v);
  };
  EyeLights lights;
  lights.ambient = {0.1f, 0.2f, 0.15f};
  for (int i = 0; i < 2; ++i) lights.directional.push_back({dir(), {pos(rng), pos(rng), pos(rng)}});
  EyeLights::Point point;
  point.position = {u(rng), u(rng), u(rng) - 2}, point.color = {pos(rng), pos(rng), pos(rng)};
  point.linear = 0.2f, point.quadratic = 0.05f;
  lights.point.push_back(point);
  // A spot light with the physical falloff and a range, and one with OpenGL's falloff.
  EyeLights::Point spot;
  spot.position = {0.3f, 0.5f, -1.0f}, spot.color = {2.0f, 1.5f, 1.0f};
  spot.inverse_square = true, spot.inv_range4 = 1.0f / 81.0f;  // range 3
  spot.spot = true, spot.spot_axis = normalize(Vec3{-0.1f, -0.2f, -1.0f});
  detail::spot_cone(0.3f, 0.7f, spot.spot_scale, spot.spot_offset);
  lights.point.push_back(spot);
  spot.inverse_square = false, spot.inv_range4 = 0, spot.linear = 0.3f;
  spot.position = {-0.5f, 0.0f, -0.5f};
  lights.point.push_back(spot);
  const int n = 1000;
  std::vector<Vec3> normals(n), points(n);
  for (int i = 0; i < n; ++i) normals[size_t(i)] = dir(), points[size_t(i)] = {u(rng), u(rng), u(rng) - 3};
  points[7] = lights.point[0].position;  // a light at the surface point: along the normal
  for (const Specular& s : {Specular(), Specular(0.5f, 8), Specular(1.0f, 64)}) {
    std::vector<LightTerms> simd(n);
    light_for_test(lights, normals.data(), points.data(), size_t(n), s, simd.data());
    for (int i = 0; i < n; ++i) {
      const LightTerms want = light(lights, normals[size_t(i)], points[size_t(i)], s);
      const LightTerms& got = simd[size_t(i)];
      // The SIMD form's reciprocal square roots and powers are approximations (about
      // 23 bits); a highlight at its cutoff (2^-12 of Ks) may fall either side.
      const float tol = 1e-3f;
      EXPECT_NEAR(got.diffuse.x, want.diffuse.x, tol) << i;
      EXPECT_NEAR(got.diffuse.y, want.diffuse.y, tol) << i;
      EXPECT_NEAR(got.diffuse.z, want.diffuse.z, tol) << i;
      EXPECT_NEAR(got.specular.x, want.specular.x, tol) << i << " ks " << s.ks;
      EXPECT_NEAR(got.specular.y, want.specular.y, tol) << i << " ks " << s.ks;
      EXPECT_NEAR(got.specular.z, want.specular.z, tol) << i << " ks " << s.ks;
    }
  }
}

// KHR_lights_punctual's spot cone and range window, from the extension's formulas
// written out here: full intensity inside the inner cone, none outside the outer one,
// saturate(cos * scale + offset)^2 between; 1 / d^2 windowed by (1 - (d/range)^4)^2.
TEST(Lighting, SpotConeAndRangeFollowKhrLightsPunctual) {
  const float inner = 0.2f, outer = 0.6f;
  Camera cam;
  cam.position = {0, 0, 0};
  EyeLights lights;
  Light spot = Light::spot({0, 0, 0}, {0, 0, 1}, {1, 1, 1}, inner, outer);  // points down -z
  spot.falloff = Falloff::InverseSquare;
  spot.range = 10;
  eye_lights(cam.view(), {spot}, lights);
  ASSERT_EQ(lights.point.size(), 1u);
  const EyeLights::Point& l = lights.point[0];
  const Vec3 n{0, 0, 1};
  auto att_at_angle = [&](float angle, float d) {
    Vec3 to_light;
    const Vec3 p{d * std::sin(angle), 0, -d * std::cos(angle)};
    return detail::punctual(l, p, n, to_light);
  };
  const float d = 4;
  const float window = (1 - std::pow(d / 10, 4.0f)) * (1 - std::pow(d / 10, 4.0f));
  EXPECT_NEAR(att_at_angle(0, d), window / (d * d), 1e-6f);
  EXPECT_NEAR(att_at_angle(inner * 0.9f, d), window / (d * d), 1e-6f);
  EXPECT_EQ(att_at_angle(outer * 1.01f, d), 0.0f);
  const float mid = std::acos(0.5f * (std::cos(inner) + std::cos(outer)));  // halfway in cosine
  EXPECT_NEAR(att_at_angle(mid, d), 0.25f * window / (d * d), 1e-5f);
  EXPECT_EQ(att_at_angle(0, 10.5f), 0.0f);  // past the range
  // Without a range: the plain inverse square.
  lights.point[0].inv_range4 = 0;
  EXPECT_NEAR(att_at_angle(0, 7), 1.0f / 49.0f, 1e-7f);
}
