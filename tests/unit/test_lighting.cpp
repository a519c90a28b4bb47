// The lighting model's two forms (src/shading/): the SIMD one the kernels run must
// compute what the scalar one does, for every light kind and with and without a
// highlight.
#include <gtest/gtest.h>

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
  lights.point.push_back({{u(rng), u(rng), u(rng) - 2}, {pos(rng), pos(rng), pos(rng)}, 1.0f, 0.2f, 0.05f});
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
