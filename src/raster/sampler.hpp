// Texture sampling: nearest, bilinear and trilinear, with repeat or clamp addressing.
//
// Addressing follows OpenGL: texel i covers [i, i+1) / size in u, so the sample point
// u * size - 0.5 sits between the four nearest texel centres (bilinear); nearest takes
// floor(u * size). Levels of detail: lambda = log2(rho), rho the larger screen-space
// footprint of a pixel in texels, max(|d(uv)/dx|, |d(uv)/dy|) in texel units;
// lambda <= 0 magnifies (bilinear on level 0), otherwise the two levels around lambda
// are blended (trilinear).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "velocity/math.hpp"
#include "velocity/texture.hpp"

namespace velocity::raster {

struct Rgba {
  float r, g, b, a;  // 0..1
};

inline Rgba unpack(uint32_t t) {
  constexpr float k = 1.0f / 255.0f;
  return {float(t & 0xff) * k, float((t >> 8) & 0xff) * k, float((t >> 16) & 0xff) * k, float(t >> 24) * k};
}

// Texel index along one axis, wrapped or clamped.
inline int address(int i, int size, bool repeat) {
  if (repeat) {
    i %= size;
    return i < 0 ? i + size : i;
  }
  return std::clamp(i, 0, size - 1);
}

inline Rgba texel(const Texture::Level& l, int x, int y, bool repeat) {
  return unpack(l.texels[size_t(address(y, l.height, repeat)) * l.width + address(x, l.width, repeat)]);
}

// Keeps a coordinate in [-1, 2] before it becomes a texel index; NaN (from an infinite
// uv, say) becomes -1, where std::clamp would pass it on to an undefined conversion.
inline float clamp_uv(float u) { return u > -1.0f ? (u < 2.0f ? u : 2.0f) : -1.0f; }

inline Rgba nearest(const Texture::Level& l, float u, float v, bool repeat) {
  // Wrap in float first, so huge uvs cannot overflow the integer conversion.
  if (repeat) u -= std::floor(u), v -= std::floor(v);
  u = clamp_uv(u), v = clamp_uv(v);
  return texel(l, int(std::floor(u * float(l.width))), int(std::floor(v * float(l.height))), repeat);
}

// The four nearest texels weighted by the sample point's position between their centres.
inline Rgba bilinear(const Texture::Level& l, float u, float v, bool repeat) {
  if (repeat) u -= std::floor(u), v -= std::floor(v);
  u = clamp_uv(u), v = clamp_uv(v);
  float x = u * float(l.width) - 0.5f, y = v * float(l.height) - 0.5f;
  float fx = std::floor(x), fy = std::floor(y);
  float a = x - fx, b = y - fy;
  int x0 = int(fx), y0 = int(fy);
  Rgba t00 = texel(l, x0, y0, repeat), t10 = texel(l, x0 + 1, y0, repeat);
  Rgba t01 = texel(l, x0, y0 + 1, repeat), t11 = texel(l, x0 + 1, y0 + 1, repeat);
  auto mix = [&](float c00, float c10, float c01, float c11) {
    return (c00 * (1 - a) + c10 * a) * (1 - b) + (c01 * (1 - a) + c11 * a) * b;
  };
  return {mix(t00.r, t10.r, t01.r, t11.r), mix(t00.g, t10.g, t01.g, t11.g), mix(t00.b, t10.b, t01.b, t11.b),
          mix(t00.a, t10.a, t01.a, t11.a)};
}

// Level of detail from the screen-space derivatives of (u, v).
inline float level_of_detail(const Texture& t, float dudx, float dvdx, float dudy, float dvdy) {
  float w = float(t.width()), h = float(t.height());
  float rx = (dudx * w) * (dudx * w) + (dvdx * h) * (dvdx * h);
  float ry = (dudy * w) * (dudy * w) + (dvdy * h) * (dvdy * h);
  float rho2 = std::max(rx, ry);
  return rho2 > 0 ? 0.5f * std::log2(rho2) : -100.0f;  // log2(sqrt(rho2))
}

template <Filter F>
inline Rgba sample(const Texture& t, float u, float v, float lod, bool repeat) {
  const auto& levels = t.levels();
  if constexpr (F == Filter::Nearest) {
    return nearest(levels[0], u, v, repeat);
  } else if constexpr (F == Filter::Bilinear) {
    return bilinear(levels[0], u, v, repeat);
  } else {
    if (!(lod > 0)) return bilinear(levels[0], u, v, repeat);
    float top = float(levels.size() - 1);
    if (lod >= top) return bilinear(levels.back(), u, v, repeat);
    int l0 = int(lod);
    float f = lod - float(l0);
    Rgba a = bilinear(levels[size_t(l0)], u, v, repeat), b = bilinear(levels[size_t(l0) + 1], u, v, repeat);
    return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, a.a + (b.a - a.a) * f};
  }
}

}  // namespace velocity::raster
