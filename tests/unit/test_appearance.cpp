// Appearance on scenes whose right answer is written out here from the specifications:
// spot and point lights (KHR_lights_punctual), the linear pipeline's sRGB encoding, and
// glTF 2.0's metallic-roughness BRDF at known pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "image_test_util.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;

namespace {

// A square of side `side` in the plane z = `z`, facing +Z, cut into cells x cells quads.
Mesh grid(float side, float z, int cells) {
  Mesh m;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i)
      m.positions.push_back({side * (float(i) / float(cells) - 0.5f), side * (float(j) / float(cells) - 0.5f), z});
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const uint32_t a = uint32_t(j * (cells + 1) + i), b = a + 1, c = a + uint32_t(cells) + 2, e = a + uint32_t(cells) + 1;
      m.triangles.push_back({{a, b, c}});
      m.triangles.push_back({{a, c, e}});
    }
  m.normals.assign(m.positions.size(), {0, 0, 1});
  return m;
}

// An orthographic camera at the origin looking down -z, `height` world units high.
Camera ortho(float height) {
  Camera c;
  c.position = {0, 0, 0};
  c.projection = Projection::Orthographic;
  c.ortho_height = height;
  c.near = 0.5f, c.far = 50.0f;
  return c;
}

// The world x (and y) of pixel column i's centre (row j's) for ortho(height) on a
// size x size image.
float world_of(int i, int size, float height) { return (float(i) + 0.5f - 0.5f * float(size)) * height / float(size); }

int channel(const Image& img, int x, int y, int c = 0) { return img.pixel(x, y)[c]; }

}  // namespace

// A spot light over a plane, in Phong (per pixel) and Gouraud (per vertex, on a grid as
// fine as the pixels): every pixel of a row is what KHR_lights_punctual's cone gives,
// computed here from the extension's formula.
TEST(Appearance, SpotLightConeInPhongAndGouraud) {
  const int size = 100;
  const float height = 10, z = -5;
  const Vec3 light_at{0.5f, 0, -1};
  const float inner = 0.15f, outer = 0.35f;
  Light spot = Light::spot(light_at, {0, 0, 1}, {1, 1, 1}, inner, outer);  // pointing down -z
  for (Shading mode : {Shading::Phong, Shading::Gouraud}) {
    Renderer r(size, size);
    r.options.color = ColorPipeline::Display;
    Material m;
    m.color = {0.5f, 0.5f, 0.5f};
    m.shading = mode;
    const Mesh plane = grid(height, z, mode == Shading::Gouraud ? size : 1);
    r.begin_frame(ortho(height), {spot}, {0, 0, 0});
    r.draw(plane, Mat4::identity(), &m);
    r.end_frame();
    const Image img = r.color_image();
    const float scale = 1.0f / (std::cos(inner) - std::cos(outer)), offset = -std::cos(outer) * scale;
    int lit = 0;
    for (int i = 0; i < size; ++i) {
      const Vec3 p{world_of(i, size, height), world_of(size / 2, size, height) * -1, z};
      const Vec3 to_light = normalize(light_at - p);
      const float cd = to_light.z;  // the axis is -z; the direction from the light is -to_light
      const float a = std::clamp(cd * scale + offset, 0.0f, 1.0f);
      const float want = 0.5f * a * a * to_light.z * 255.0f;  // N.L = to_light.z
      EXPECT_NEAR(channel(img, i, size / 2), want, mode == Shading::Phong ? 1.0f : 2.0f) << to_string(mode) << " x " << i;
      lit += want > 1;
    }
    EXPECT_GT(lit, 10);
    EXPECT_LT(lit, 40);  // the cone, not the whole row
  }
}

// A point light 2 units in front of a 10x10 quad with the physical falloff and a range:
// per pixel, 1/d^2 windowed, as KHR_lights_punctual writes it.
TEST(Appearance, PointLightInverseSquareWithRange) {
  const int size = 64;
  const float height = 10, z = -5;
  Light point = Light::point({0, 0, z + 2}, {4, 4, 4});
  point.falloff = Falloff::InverseSquare;
  point.range = 5;
  Renderer r(size, size);
  r.options.color = ColorPipeline::Display;
  Material m;
  m.color = {0.5f, 0.5f, 0.5f};
  m.shading = Shading::Phong;
  const Mesh plane = grid(height, z, 1);
  r.begin_frame(ortho(height), {point}, {0, 0, 0});
  r.draw(plane, Mat4::identity(), &m);
  r.end_frame();
  const Image img = r.color_image();
  for (int i = 0; i < size; ++i) {
    const Vec3 p{world_of(i, size, height), -world_of(size / 2, size, height), z};
    const Vec3 v = point.position - p;
    const float d = length(v);
    const float w = std::clamp(1 - std::pow(d / 5, 4.0f), 0.0f, 1.0f);
    const float want = std::min(1.0f, 0.5f * 4 * w * w / (d * d) * (v.z / d)) * 255.0f;
    EXPECT_NEAR(channel(img, i, size / 2), want, 1.0f) << "x " << i;
  }
}
