// The lighting model's two forms (src/shading/): the SIMD one the kernels run must
// compute what the scalar one does, for every light kind and with and without a
// highlight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "shading/gl_vertices.hpp"
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

// pGL's vertex runs (gl_vertices): bit for bit the scalar path's clip position (Mat4 *
// Vec4) and clamped colour (light_gl of the transformed, optionally renormalised normal),
// for every run length up to a few vectors (the partial last vector), three coloured
// directional lights, an emissive material with and without a highlight, colours past
// 1 and below 0 (clamped), zero and NaN normals.
TEST(Lighting, GlVertexRunIsTheScalarVertexPath) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.1f, 1.0f);
  GlLight lights[3];
  for (GlLight& l : lights) {
    l.colors = {{pos(rng) * 0.2f, 0, pos(rng) * 0.1f}, {pos(rng), pos(rng) * 1.5f, pos(rng)}, {pos(rng), pos(rng), -0.2f}};
    l.direction = normalize(Vec3{u(rng), u(rng), 1.0f});
    l.half = normalize(l.direction + Vec3{0, 0, 1});
  }
  Mat4 mvp, normal_matrix;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) mvp.m[r][c] = u(rng) * 2, normal_matrix.m[r][c] = u(rng);
  const size_t most = 53;
  std::vector<Vec4> position(most);
  std::vector<Vec3> normal(most);
  for (size_t i = 0; i < most; ++i) position[i] = {u(rng) * 3, u(rng) * 3, u(rng) * 3, 1 + u(rng) * 0.5f};
  for (size_t i = 0; i < most; ++i) normal[i] = {u(rng) * 2, u(rng) * 2, u(rng) * 2};
  normal[5] = {0, 0, 0};
  normal[11] = {std::numeric_limits<float>::quiet_NaN(), 0, 1};
  for (float shininess : {0.0f, 23.5f})
    for (bool renormalize : {false, true}) {
      GlMaterial m;
      m.ambient = {0.3f, 0.1f, 0.2f, 1}, m.diffuse = {0.9f, 0.6f, 0.3f, 0.7f}, m.specular = {0.8f, 0.8f, 1.2f, 1};
      m.emission = {0.05f, 0.3f, 0, 1}, m.shininess = shininess;
      const Vec3 model_ambient{0.2f, 0.25f, 0.1f};
      for (size_t count = 1; count <= most; ++count) {
        std::vector<Vec4> clip(count), color(count);
        GlVertexRun run;
        run.position = position.data(), run.normal = normal.data(), run.count = count;
        run.mvp = mvp, run.normal_matrix = normal_matrix, run.normalize = renormalize;
        run.lights = lights, run.light_count = 3, run.model_ambient = model_ambient, run.material = m;
        run.clip = clip.data(), run.color = color.data();
        gl_vertices(run);
        for (size_t i = 0; i < count; ++i) {
          const Vec4 want_clip = mvp * position[i];
          Vec3 n = normal_matrix.transform_vector(normal[i]);
          if (renormalize) n = normalize(n);
          const Vec4 c = light_gl(lights, 3, model_ambient, false, m, n, {});
          auto unit = [](float v) { return v > 0 ? (v < 1 ? v : 1.0f) : 0.0f; };
          const Vec4 want_color{unit(c.x), unit(c.y), unit(c.z), unit(c.w)};
          EXPECT_EQ(std::memcmp(&clip[i], &want_clip, sizeof(Vec4)), 0) << i << " of " << count;
          EXPECT_EQ(std::memcmp(&color[i], &want_color, sizeof(Vec4)), 0)
              << i << " of " << count << ", shininess " << shininess << ", normalize " << renormalize << ": "
              << color[i].x << " " << color[i].y << " " << color[i].z << " " << color[i].w << " want " << want_color.x
              << " " << want_color.y << " " << want_color.z << " " << want_color.w;
        }
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
