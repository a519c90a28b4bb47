// Appearance on scenes whose right answer is written out here from the specifications:
// spot and point lights (KHR_lights_punctual), the linear pipeline's sRGB encoding, and
// glTF 2.0's metallic-roughness BRDF at known pixels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "image_test_util.hpp"
#include "shading/ggx_albedo.hpp"
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

namespace {

// sRGB's encoding (IEC 61966-2-1), written out for the tests.
float encode(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1 / 2.4f) - 0.055f;
}

Material pbr(Vec3 base, float metallic, float roughness) {
  Material m;
  m.shading = Shading::Pbr;
  m.color = base;
  m.color_space = ColorSpace::Linear;
  m.pbr.metallic = metallic, m.pbr.roughness = roughness;
  return m;
}

Image draw_one(int w, int h, const Camera& cam, const std::vector<Light>& lights, const Mesh& mesh, const Material& m,
               RenderOptions o = {}) {
  Renderer r(w, h);
  r.options = o;
  r.begin_frame(cam, lights, {0, 0, 0});
  r.draw(mesh, Mat4::identity(), &m);
  r.end_frame();
  return r.color_image();
}

}  // namespace

// glTF's colour factors are linear: an unlit material with baseColorFactor 0.5 shows
// sRGB 188, in the Linear pipeline (Auto picks it for a Pbr frame) and in Display.
TEST(Appearance, UnlitGltfBaseColorHalfShows188) {
  Material m = pbr({0.5f, 0.5f, 0.5f}, 0, 1);
  m.pbr.unlit = true;
  for (ColorPipeline c : {ColorPipeline::Auto, ColorPipeline::Linear, ColorPipeline::Display}) {
    RenderOptions o;
    o.color = c;
    const Image img = draw_one(32, 32, ortho(10), {}, grid(10, -5, 1), m, o);
    EXPECT_EQ(channel(img, 16, 16), 188) << int(c);
  }
}

// The linear pipeline: a 50% grey (linear) lit head-on at full intensity comes out
// 188 in Phong; an sRGB colour keeps its value through decode, light and encode; the
// Display pipeline lights the 8-bit value as it is.
TEST(Appearance, LinearPipelineLightsInLinearLight) {
  const Light sun = Light::directional({0, 0, 1}, {1, 1, 1});
  Material m;
  m.shading = Shading::Phong;
  m.color = {0.5f, 0.5f, 0.5f};
  RenderOptions linear;
  linear.color = ColorPipeline::Linear;
  m.color_space = ColorSpace::Linear;
  EXPECT_EQ(channel(draw_one(32, 32, ortho(10), {sun}, grid(10, -5, 1), m, linear), 16, 16), 188);
  m.color_space = ColorSpace::Srgb;  // 127.5 through the tables: either side
  EXPECT_NEAR(channel(draw_one(32, 32, ortho(10), {sun}, grid(10, -5, 1), m, linear), 16, 16), 128, 1);
  // Half the light: linear 0.5 * 0.214 = 0.107 -> sRGB 92, where Display gives 64.
  const Light half = Light::directional({0, 0, 1}, {0.5f, 0.5f, 0.5f});
  EXPECT_NEAR(channel(draw_one(32, 32, ortho(10), {half}, grid(10, -5, 1), m, linear), 16, 16),
              255 * encode(0.5f * 0.21404114f), 1);
  EXPECT_EQ(channel(draw_one(32, 32, ortho(10), {half}, grid(10, -5, 1), m), 16, 16), 64);  // Auto: Display
}

// A point light 2 units in front of a 10x10 quad, lit per pixel (the example,
// where Gouraud on two triangles gave 2/255 at the centre): a PBR grey of 0.5 under
// radiance 1 is 0.5 / pi, sRGB 112, at the centre.
TEST(Appearance, PointLightInFrontOfAQuadPerPixel) {
  Material m = pbr({0.5f, 0.5f, 0.5f}, 0, 1);
  Light point = Light::point({0, 0, -3}, {1, 1, 1});
  const Image img = draw_one(64, 64, ortho(10), {point}, grid(10, -5, 1), m);
  EXPECT_NEAR(channel(img, 32, 32), 255 * encode(0.5f / float(M_PI)), 3);
  EXPECT_LT(channel(img, 0, 0), channel(img, 32, 32) - 40);
}

// Colour textures are decoded from sRGB before they are filtered: halfway between a
// black and a white texel is linear 0.5, sRGB 188 (filtering the 8-bit values would
// give 128).
TEST(Appearance, SrgbTexturesDecodeBeforeFiltering) {
  Image tex(2, 1);
  const uint8_t px[8] = {0, 0, 0, 255, 255, 255, 255, 255};
  std::copy(px, px + 8, tex.pixels.begin());
  Material m = pbr({1, 1, 1}, 0, 1);
  m.pbr.unlit = true;
  m.texture = std::make_shared<Texture>(tex);
  m.filter = Filter::Bilinear;
  m.wrap = Wrap::Clamp;
  Mesh quad = grid(10, -5, 1);
  for (size_t i = 0; i < quad.positions.size(); ++i)
    quad.uvs.push_back({quad.positions[i].x / 10 + 0.5f, 0.5f - quad.positions[i].y / 10});
  const int size = 64;
  const Image img = draw_one(size, size, ortho(10), {}, quad, m);
  for (int i = 0; i < size; ++i) {
    const float u = (float(i) + 0.5f) / float(size);
    const float lin = std::clamp(u * 2 - 0.5f, 0.0f, 1.0f);
    EXPECT_NEAR(channel(img, i, size / 2), 255 * encode(lin), 1.0f) << "x " << i;
  }
}

// The directional albedo of the GGX lobe with Fresnel 1, E(roughness, N.V) = the
// integral of D Vis N.L over the hemisphere of light directions, by the midpoint rule in
// (theta, phi): a different method from the library's (importance sampling), and a fine
// one (the lobe of roughness 0.3 spans about 20 steps).
namespace {
float specular_albedo(float roughness, float nv) {
  const double a = double(roughness) * roughness, a2 = a * a;
  const double vx = std::sqrt(1 - double(nv) * nv);
  constexpr int kTheta = 400, kPhi = 200;
  double sum = 0;
  for (int i = 0; i < kTheta; ++i) {
    const double th = (i + 0.5) / kTheta * M_PI / 2, nl = std::cos(th), st = std::sin(th);
    for (int j = 0; j < kPhi; ++j) {
      const double ph = (j + 0.5) / kPhi * M_PI;  // symmetric about the plane of v: twice the half
      const double lx = st * std::cos(ph), ly = st * std::sin(ph);
      const double hx = lx + vx, hy = ly, hz = nl + nv, hl = std::sqrt(hx * hx + hy * hy + hz * hz);
      const double nh = hz / hl;
      const double dd = nh * nh * (a2 - 1) + 1, D = a2 / (M_PI * dd * dd);
      const double vis = 0.5 / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
      sum += D * vis * nl * st;
    }
  }
  return float(2 * sum * (M_PI / 2 / kTheta) * (M_PI / kPhi));
}
}  // namespace

// The library's table of E (read as the kernels read it) against the integral above,
// within what reading a 16 x 16 table bilinearly loses (0.0126 at roughness 0.72, N.V 0.2):
// near 1 for a smooth lobe seen head-on, losing energy as roughness grows.
TEST(Appearance, GgxAlbedoTableIsTheIntegral) {
  for (float r : {0.3f, 0.5f, 0.72f, 0.9f})
    for (float nv : {0.2f, 0.53f, 0.81f, 0.97f})
      EXPECT_NEAR(shading::ggx_albedo(r, nv), specular_albedo(r, nv), 0.015f) << "roughness " << r << " N.V " << nv;
  EXPECT_GT(shading::ggx_albedo(0.1f, 0.95f), 0.98f);
  EXPECT_LT(shading::ggx_albedo(0.95f, 0.95f), 0.5f);
}

// glTF 2.0's BRDF (Appendix B) at known pixels of a sphere under one directional light,
// computed here from the specification's formulas (metal and dielectric BRDFs mixed by
// metallic; 0.4 is where the pre-2024 pseudocode's (1 - F) diffuse differs), with the
// specular lobe's multiple-scattering compensation M (shade_pbr-inl.h): the ray through each pixel's centre
// meets the unit sphere, whose normal there the mesh interpolates.
TEST(Appearance, PbrSphereMatchesTheClosedFormBrdf) {
  const int w = 96, h = 96;
  Camera cam;
  cam.position = {0, 0, 0};
  cam.near = 0.5f, cam.far = 20;
  const Vec3 centre{0, 0, -4};
  const Vec3 to_light = normalize(Vec3{0.4f, 0.6f, 1.0f});
  const Vec3 radiance{3.0f, 2.5f, 2.0f};
  Mesh sphere = make_sphere(192);
  for (Vec3& p : sphere.positions) p = p + centre;
  const Vec3 base{0.8f, 0.4f, 0.2f};
  struct Case {
    float metallic, roughness;
  };
  for (Case c : {Case{0, 0.5f}, Case{1, 0.3f}, Case{0.4f, 0.8f}}) {
    const Image img = draw_one(w, h, cam, {Light::directional(to_light, radiance)}, sphere, pbr(base, c.metallic, c.roughness));
    const float t = std::tan(cam.fov_y / 2);
    int checked = 0;
    for (int j = 20; j < 80; j += 7)
      for (int i = 20; i < 80; i += 9) {
        const Vec3 dir = normalize(Vec3{((float(i) + 0.5f) / float(w) * 2 - 1) * t, (1 - (float(j) + 0.5f) / float(h) * 2) * t, -1});
        const float b = dot(dir, centre), disc = b * b - (dot(centre, centre) - 1);
        if (disc < 0.05f) continue;  // off the sphere, or at its rim (tessellation)
        const Vec3 p = dir * (b - std::sqrt(disc));
        const Vec3 n = normalize(p - centre), v = normalize(-p), l = to_light;
        const Vec3 hv = normalize(l + v);
        const float nl = std::max(dot(n, l), 0.0f), nv = std::max(dot(n, v), 1e-4f);
        const float nh = std::max(dot(n, hv), 0.0f), vh = std::max(dot(v, hv), 0.0f);
        const float a = c.roughness * c.roughness, a2 = a * a;
        const float dd = nh * nh * (a2 - 1) + 1;
        const float D = a2 / (float(M_PI) * dd * dd);
        const float Vis = 0.5f / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
        const float bc[3] = {base.x, base.y, base.z}, rad[3] = {radiance.x, radiance.y, radiance.z};
        const float e = specular_albedo(c.roughness, nv);
        for (int k = 0; k < 3; ++k) {
          const float cdiff = bc[k] * (1 - c.metallic), f0 = 0.04f * (1 - c.metallic) + bc[k] * c.metallic;
          const float M = 1 + f0 * (1 / e - 1);  // multiple scattering (Turquin)
          // mix(dielectric, metal, metallic): the dielectric's diffuse under its own
          // Fresnel (f0 0.04), the specular under the blended f0's.
          const float F = f0 + (1 - f0) * std::pow(1 - vh, 5.0f);
          const float Fd = 0.04f + 0.96f * std::pow(1 - vh, 5.0f);
          const float f = (1 - Fd) * cdiff / float(M_PI) + F * D * Vis * M;
          const float want = 255 * encode(f * rad[k] * nl);
          EXPECT_NEAR(channel(img, i, j, k), want, 2.0f) << "m " << c.metallic << " r " << c.roughness << " at " << i << ","
                                                        << j << " channel " << k;
        }
        ++checked;
      }
    EXPECT_GT(checked, 30);
  }
}

// Alpha as glTF says: MASK keeps the pixels at or over the cut-off (and only they write
// depth); BLEND mixes over what is there, farthest draw first whatever the order of the
// calls, without writing depth.
TEST(Appearance, AlphaMaskAndBlend) {
  Material m = pbr({1, 1, 1}, 0, 1);
  m.pbr.unlit = true;
  m.alpha_mode = AlphaMode::Mask;
  m.alpha_cutoff = 0.5f;
  m.alpha = 0.4f;
  EXPECT_EQ(channel(draw_one(16, 16, ortho(10), {}, grid(10, -5, 1), m), 8, 8), 0);
  m.alpha = 0.6f;
  EXPECT_EQ(channel(draw_one(16, 16, ortho(10), {}, grid(10, -5, 1), m), 8, 8), 255);
  // Blending: red at 50% over blue at 50% over black, drawn near first.
  Material red = pbr({1, 0, 0}, 0, 1), blue = pbr({0, 0, 1}, 0, 1);
  for (Material* x : {&red, &blue}) x->pbr.unlit = true, x->alpha_mode = AlphaMode::Blend, x->alpha = 0.5f;
  const Mesh near_quad = grid(10, -3, 1), far_quad = grid(10, -6, 1);
  Renderer r(16, 16);
  r.begin_frame(ortho(10), {}, {0, 0, 0});
  r.draw(near_quad, Mat4::identity(), &red);
  r.draw(far_quad, Mat4::identity(), &blue);
  r.end_frame();
  const Image img = r.color_image();
  // Blue over black: 255 * 0.5 = 127.5; then red over it: r = 127.5, b = 63.75.
  EXPECT_NEAR(channel(img, 8, 8, 0), 128, 1);
  EXPECT_NEAR(channel(img, 8, 8, 2), 64, 1);
  // No depth written by either: the depth image stays clear.
  EXPECT_EQ(r.depth_image().pixel(8, 8)[0], 0);
}

// A normal map tilts the normal in the tangent frame glTF defines: +x along u, +y up
// the image (v decreasing), with tangents generated for a mesh that has none. A map
// leaning right (+x) is brighter under a light from the right; one leaning up (+y)
// under a light from above; the flat map is lit the same from either side.
TEST(Appearance, NormalMapFollowsTheTangentFrame) {
  Mesh quad = grid(10, -5, 1);
  for (const Vec3& p : quad.positions) quad.uvs.push_back({p.x / 10 + 0.5f, 0.5f - p.y / 10});  // upright
  auto lit = [&](Vec3 map_normal, Vec3 light_dir) {
    Image tex(1, 1);
    tex.pixels = {uint8_t(std::lround(127.5f * (map_normal.x + 1))), uint8_t(std::lround(127.5f * (map_normal.y + 1))),
                  uint8_t(std::lround(127.5f * (map_normal.z + 1))), 255};
    Material m = pbr({0.5f, 0.5f, 0.5f}, 0, 1);
    m.pbr.normal.texture = std::make_shared<Texture>(tex);
    return channel(draw_one(16, 16, ortho(10), {Light::directional(light_dir, {3, 3, 3})}, quad, m), 8, 8);
  };
  const Vec3 right{0.6f, 0, 0.8f}, up{0, 0.6f, 0.8f}, flat{0, 0, 1};
  EXPECT_GT(lit(right, {1, 0, 1}), lit(right, {-1, 0, 1}) + 30);
  EXPECT_GT(lit(up, {0, 1, 1}), lit(up, {0, -1, 1}) + 30);
  EXPECT_NEAR(lit(flat, {0, 1, 1}), lit(flat, {0, -1, 1}), 1);
  // Given tangents win over generated ones: a tangent along -x mirrors the map.
  quad.tangents.assign(quad.positions.size(), {-1, 0, 0, 1});
  EXPECT_LT(lit(right, {1, 0, 1}), lit(right, {-1, 0, 1}) - 30);
}

// Tone mapping and exposure (Linear only), against the curves written out here:
// three.js's ACESFilmicToneMapping and Khronos PBR Neutral, of an unlit colour.
TEST(Appearance, ToneMappingAcesAndNeutral) {
  const float in[3] = {2.0f, 0.6f, 0.1f};
  Material m = pbr({in[0], in[1], in[2]}, 0, 1);
  m.pbr.unlit = true;
  auto aces = [](const float c[3], float exposure) {
    float v[3];
    for (int k = 0; k < 3; ++k) v[k] = c[k] * exposure / 0.6f;
    const float i[3] = {0.59719f * v[0] + 0.35458f * v[1] + 0.04823f * v[2], 0.07600f * v[0] + 0.90834f * v[1] + 0.01566f * v[2],
                        0.02840f * v[0] + 0.13383f * v[1] + 0.83777f * v[2]};
    float f[3];
    for (int k = 0; k < 3; ++k)
      f[k] = (i[k] * (i[k] + 0.0245786f) - 0.000090537f) / (i[k] * (0.983729f * i[k] + 0.4329510f) + 0.238081f);
    return std::array<float, 3>{1.60475f * f[0] - 0.53108f * f[1] - 0.07367f * f[2],
                                -0.10208f * f[0] + 1.10813f * f[1] - 0.00605f * f[2],
                                -0.00327f * f[0] - 0.07276f * f[1] + 1.07602f * f[2]};
  };
  auto neutral = [](const float c[3], float exposure) {
    std::array<float, 3> v{c[0] * exposure, c[1] * exposure, c[2] * exposure};
    const float x = std::min({v[0], v[1], v[2]});
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    for (float& e : v) e -= offset;
    const float peak = std::max({v[0], v[1], v[2]});
    if (peak < 0.76f) return v;
    const float d = 0.24f, new_peak = 1 - d * d / (peak + d - 0.76f);
    const float g = 1 - 1 / (0.15f * (peak - new_peak) + 1);
    for (float& e : v) e = e * new_peak / peak * (1 - g) + new_peak * g;
    return v;
  };
  for (float exposure : {1.0f, 0.7f}) {
    for (ToneMap tm : {ToneMap::Aces, ToneMap::KhronosNeutral}) {
      RenderOptions o;
      o.tone_map = tm, o.exposure = exposure;
      const Image img = draw_one(8, 8, ortho(10), {}, grid(10, -5, 1), m, o);
      const std::array<float, 3> want = tm == ToneMap::Aces ? aces(in, exposure) : neutral(in, exposure);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(channel(img, 4, 4, k), 255 * encode(want[k]), 1) << int(tm) << " " << k;
    }
  }
  // Off by default: the colour clipped.
  EXPECT_EQ(channel(draw_one(8, 8, ortho(10), {}, grid(10, -5, 1), m), 4, 4, 0), 255);
}

// Emission adds to the light; occlusion darkens the ambient light only.
TEST(Appearance, EmissiveAndOcclusion) {
  Material m = pbr({0.5f, 0.5f, 0.5f}, 0, 1);
  m.pbr.emissive = {0.2f, 0, 0};
  Image grey(1, 1);
  grey.pixels = {64, 64, 64, 255};
  m.pbr.occlusion.texture = std::make_shared<Texture>(grey);
  m.pbr.occlusion_strength = 1;
  const Light ambient = Light::ambient({0.4f, 0.4f, 0.4f});
  const Image img = draw_one(8, 8, ortho(10), {ambient}, grid(10, -5, 1), m);
  const float ao = 64.0f / 255.0f;  // occlusion reads the texture's linear R
  EXPECT_NEAR(channel(img, 4, 4, 0), 255 * encode(0.5f * 0.4f * ao + 0.2f), 1);
  EXPECT_NEAR(channel(img, 4, 4, 1), 255 * encode(0.5f * 0.4f * ao), 1);
}
