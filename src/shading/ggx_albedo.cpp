#include "shading/ggx_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace velocity::shading {

namespace {

constexpr int kN = kGgxAlbedoSize;

// E(roughness, mu) by importance sampling the GGX distribution on a stratified 32 x 32
// grid: with h drawn with pdf D (N.H) and l the mirror of v about h, each sample
// weighs f N.L / pdf(l) = 4 Vis N.L V.H / N.H.
float integrate(float roughness, float mu) {
  const double a = double(roughness) * roughness, a2 = a * a;
  const double nv = std::max(double(mu), 1e-4), vx = std::sqrt(1 - nv * nv);
  constexpr int kSteps = 32;
  static const std::array<double, kSteps> cos_phi = [] {
    std::array<double, kSteps> c{};
    for (int j = 0; j < kSteps; ++j) c[size_t(j)] = std::cos(2 * M_PI * (j + 0.5) / kSteps);
    return c;
  }();
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double x1 = (i + 0.5) / kSteps;
    const double ch = std::sqrt((1 - x1) / (1 + (a2 - 1) * x1)), sh = std::sqrt(std::max(0.0, 1 - ch * ch));
    for (int j = 0; j < kSteps; ++j) {
      const double vh = vx * sh * cos_phi[size_t(j)] + nv * ch;
      const double nl = 2 * vh * ch - nv;
      if (nl <= 0 || vh <= 0) continue;
      const double vis = 0.5 / (nl * std::sqrt(a2 + (1 - a2) * nv * nv) + nv * std::sqrt(a2 + (1 - a2) * nl * nl));
      sum += 4 * vis * nl * vh / ch;
    }
  }
  return float(sum / (kSteps * kSteps));
}

}  // namespace

const float* ggx_albedo_table() {
  static const std::array<float, kN * kN> table = [] {
    std::array<float, kN * kN> t{};
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) t[size_t(j * kN + i)] = integrate((float(i) + 0.5f) / kN, (float(j) + 0.5f) / kN);
    return t;
  }();
  return table.data();
}

float ggx_albedo(float roughness, float n_dot_v) {
  const float* t = ggx_albedo_table();
  auto axis = [](float v, int& i0, float& f) {
    const float x = std::clamp(std::isnan(v) ? 0.0f : v * kN - 0.5f, 0.0f, float(kN - 1));
    i0 = std::min(int(x), kN - 2);
    f = x - float(i0);
  };
  int i, j;
  float fx, fy;
  axis(roughness, i, fx);
  axis(n_dot_v, j, fy);
  const float* r0 = t + j * kN + i;
  const float* r1 = r0 + kN;
  const float top = r0[0] + (r0[1] - r0[0]) * fx, bottom = r1[0] + (r1[1] - r1[0]) * fx;
  return top + (bottom - top) * fy;
}

}  // namespace velocity::shading
