// Texture sampling, mip-mapping, perspective-correct vs affine mapping, super-sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "core/srgb.hpp"
#include "raster/rasterize.hpp"
#include "velocity/renderer.hpp"
#include "velocity/error.hpp"
#include "velocity/texture.hpp"

using namespace velocity;
using namespace velocity::raster;

namespace {

// A w x h image whose texel (x, y) has red = r(x, y), green = g(x, y).
template <class R, class G>
Image make_image(int w, int h, R r, G g) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = img.pixel(x, y);
      p[0] = uint8_t(r(x, y)), p[1] = uint8_t(g(x, y)), p[2] = 0, p[3] = 255;
    }
  return img;
}

struct Rgba {
  float r, g, b, a;
};

// The kernels' sampler (raster/sampler-inl.h, through its test hook).
Rgba sample(const Texture& t, Filter f, bool repeat, float u, float v, float lod = 0) {
  float c[4];
  raster::sample_for_test(SamplerView(t, f, repeat ? Wrap::Repeat : Wrap::Clamp), u, v, lod, c);
  return {c[0], c[1], c[2], c[3]};
}
Rgba bilinear(const Texture& t, float u, float v, bool repeat) { return sample(t, Filter::Bilinear, repeat, u, v); }
Rgba nearest(const Texture& t, float u, float v, bool repeat) { return sample(t, Filter::Nearest, repeat, u, v); }
// Bilinear on mip level `level` alone (trilinear at an integer level of detail).
Rgba bilinear_level(const Texture& t, int level, float u, float v) {
  return sample(t, Filter::Trilinear, true, u, v, float(level));
}
Rgba unpack(uint32_t t) {
  return {float(t & 0xff) / 255, float((t >> 8) & 0xff) / 255, float((t >> 16) & 0xff) / 255, float(t >> 24) / 255};
}

}  // namespace

TEST(Texture, BilinearWeightsTheFourNearestTexels) {
  // 2x2: red 0, 100 in the top row, 200, 40 in the bottom row.
  const int red[2][2] = {{0, 100}, {200, 40}};
  Texture t(make_image(2, 2, [&](int x, int y) { return red[y][x]; }, [](int, int) { return 0; }));
  const Texture& l0 = t;
  // At a texel centre: that texel alone.
  EXPECT_NEAR(bilinear(l0, 0.25f, 0.25f, false).r * 255, 0, 1e-3);
  EXPECT_NEAR(bilinear(l0, 0.75f, 0.75f, false).r * 255, 40, 1e-3);
  // Midway between all four: the mean.
  EXPECT_NEAR(bilinear(l0, 0.5f, 0.5f, false).r * 255, (0 + 100 + 200 + 40) / 4.0, 1e-3);
  // A quarter of the way from the top-left centre to the top-right one: 3/4 and 1/4.
  EXPECT_NEAR(bilinear(l0, 0.375f, 0.25f, false).r * 255, 0.75 * 0 + 0.25 * 100, 1e-3);
  // And down: (1 - b) top + b bottom, b = 0.5.
  EXPECT_NEAR(bilinear(l0, 0.25f, 0.5f, false).r * 255, 0.5 * 0 + 0.5 * 200, 1e-3);
}

TEST(Texture, RepeatWrapsAndClampHoldsTheEdge) {
  Texture t(make_image(4, 1, [](int x, int) { return x * 60; }, [](int, int) { return 0; }));
  const Texture& l0 = t;
  EXPECT_FLOAT_EQ(nearest(l0, 1.125f, 0.5f, true).r, nearest(l0, 0.125f, 0.5f, true).r);
  EXPECT_FLOAT_EQ(nearest(l0, -0.875f, 0.5f, true).r, nearest(l0, 0.125f, 0.5f, true).r);
  EXPECT_NEAR(nearest(l0, 1.6f, 0.5f, false).r * 255, 180, 1e-3);  // clamped to the last texel
  EXPECT_NEAR(nearest(l0, -3.0f, 0.5f, false).r * 255, 0, 1e-3);
  // Bilinear across the seam: repeat mixes the last and first texels, clamp does not.
  EXPECT_NEAR(bilinear(l0, 0.0f, 0.5f, true).r * 255, (180 + 0) / 2.0, 1e-3);
  EXPECT_NEAR(bilinear(l0, 0.0f, 0.5f, false).r * 255, 0, 1e-3);
  // Huge coordinates neither overflow nor leave the texture.
  EXPECT_GE(bilinear(l0, 1e30f, -1e30f, true).r, 0.0f);
  EXPECT_GE(bilinear(l0, 1e30f, -1e30f, false).r, 0.0f);
}

TEST(Texture, MipChainIsBoxFilteredDownToOneTexel) {
  Texture t(make_image(4, 4, [](int x, int) { return x < 2 ? 0 : 200; }, [](int, int y) { return y * 80; }));
  ASSERT_EQ(t.levels().size(), 3u);  // 4x4, 2x2, 1x1
  Rgba l1 = unpack(t.levels()[1].texels[0]);
  EXPECT_NEAR(l1.r * 255, 0, 0.5);
  EXPECT_NEAR(l1.g * 255, (0 + 80) / 2.0, 0.5);
  Rgba l2 = unpack(t.levels()[2].texels[0]);
  EXPECT_NEAR(l2.r * 255, 100, 0.5);
  EXPECT_NEAR(l2.g * 255, 120, 0.5);
  Texture odd(make_image(5, 3, [](int, int) { return 10; }, [](int, int) { return 20; }));
  EXPECT_EQ(odd.levels()[1].width, 2);
  EXPECT_EQ(odd.levels()[1].height, 1);
  EXPECT_EQ(odd.levels().back().width, 1);
}

TEST(Texture, LevelOfDetailFollowsTheFootprint) {
  Texture t(make_checkerboard(256, 32));
  const float texel = 1.0f / 256;
  const SamplerView view(t, Filter::Trilinear, Wrap::Repeat);
  auto level_of_detail = [&](float a, float b, float c, float d) { return raster::level_of_detail_for_test(view, a, b, c, d); };
  EXPECT_NEAR(level_of_detail(texel, 0, 0, texel), 0.0f, 1e-4);        // one texel per pixel
  EXPECT_NEAR(level_of_detail(2 * texel, 0, 0, 2 * texel), 1.0f, 1e-4);
  EXPECT_NEAR(level_of_detail(0, 0, 0, 8 * texel), 3.0f, 1e-4);        // the larger axis wins
  EXPECT_LT(level_of_detail(texel / 4, 0, 0, texel / 4), 0.0f);        // magnified
  // Trilinear at lod 1.5 is the even blend of bilinear at levels 1 and 2.
  Rgba a = bilinear_level(t, 1, 0.3f, 0.6f), b = bilinear_level(t, 2, 0.3f, 0.6f);
  Rgba c = sample(t, Filter::Trilinear, true, 0.3f, 0.6f, 1.5f);
  EXPECT_NEAR(c.r, (a.r + b.r) / 2, 1e-5);
  EXPECT_NEAR(c.b, (a.b + b.b) / 2, 1e-5);
}

namespace {

// A floor plane y = -1 from z = -1 to z = -101, 4 units wide, seen from the origin at a
// grazing angle, textured with u = red (0..255 across, nearest). Returns the texel column
// (red value) drawn at pixel (x, y).
Image render_floor(bool affine) {
  Mesh floor;
  floor.positions = {{-2, -1, -1}, {2, -1, -1}, {2, -1, -101}, {-2, -1, -101}};
  // u runs along the depth: 0 at the near edge, 1 at the far edge.
  floor.uvs = {{0, 0.5f}, {0, 0.5f}, {1, 0.5f}, {1, 0.5f}};
  floor.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  Material m;
  m.shading = Shading::Flat;
  m.texture = std::make_shared<const Texture>(make_image(256, 1, [](int x, int) { return x; }, [](int, int) { return 0; }));
  m.texture_mode = TextureMode::Replace;
  m.filter = Filter::Nearest;
  Renderer r(200, 200);
  r.options.affine = affine;
  Camera cam;
  cam.position = {0, 0, 0};
  cam.fov_y = radians(90);
  cam.near = 0.5f, cam.far = 200;
  r.begin_frame(cam, {}, {0, 0, 0});
  r.draw(floor, Mat4::identity(), &m);
  r.end_frame();
  return r.color_image();
}

}  // namespace

TEST(Texture, PerspectiveCorrectAtGrazingAngleAffineIsNot) {
  Image correct = render_floor(false), affine = render_floor(true);
  // Pixel row y: the ray through its centre meets the floor y = -1 at depth d, where
  // ndc_y = -(1 - (y + 0.5) / 100) and d = 1 / -ndc_y (90 degree field of view).
  int worst_correct = 0, worst_affine = 0;
  for (int y = 120; y < 199; y += 6) {
    double ndc_y = -(((y + 0.5) / 100.0) - 1.0);
    double depth = 1.0 / -ndc_y;
    if (depth < 1 || depth > 101) continue;
    int expected = int(std::floor((depth - 1) / 100.0 * 256));
    int got = correct.pixel(100, y)[0], got_affine = affine.pixel(100, y)[0];
    worst_correct = std::max(worst_correct, std::abs(got - expected));
    worst_affine = std::max(worst_affine, std::abs(got_affine - expected));
  }
  EXPECT_LE(worst_correct, 1) << "perspective-correct mapping is off by more than a texel";
  EXPECT_GT(worst_affine, 40) << "affine mapping should visibly swim at a grazing angle";
}

TEST(Texture, SuperSamplingGivesCoverageLevels) {
  // An orthographic view 30 units wide on 30 pixels (10 at 3x3 samples per pixel): a
  // white square whose left edge sits a third of the way into pixel 10 and whose top
  // edge two thirds of the way into pixel 5. Sample centres are at 1/6, 1/2, 5/6.
  Mesh sq;
  const float l = 10 + 1.0f / 3, r = 20, t = 5 + 2.0f / 3, b = 25;
  // Pixel (px, py) covers x in [px, px + 1]; world x = px - 15, world y = 15 - py.
  sq.positions = {{l - 15, 15 - b, -1}, {r - 15, 15 - b, -1}, {r - 15, 15 - t, -1}, {l - 15, 15 - t, -1}};
  sq.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  Material white;
  white.color = {1, 1, 1};
  white.shading = Shading::Unlit;
  Camera cam;
  cam.position = {0, 0, 0};
  cam.projection = Projection::Orthographic;
  cam.ortho_height = 30;
  cam.near = 0.5f, cam.far = 2;
  Renderer renderer(30, 30);
  renderer.options.ssaa = 3;
  renderer.begin_frame(cam, {}, {0, 0, 0});
  renderer.draw(sq, Mat4::identity(), &white);
  renderer.end_frame();
  Image img = renderer.color_image();
  ASSERT_EQ(img.width, 30);
  EXPECT_EQ(img.pixel(9, 15)[0], 0);            // left of the edge
  EXPECT_EQ(img.pixel(10, 15)[0], 170);         // 2 of 3 sample columns: 6/9
  EXPECT_EQ(img.pixel(11, 15)[0], 255);
  EXPECT_EQ(img.pixel(15, 5)[0], 85);           // 1 of 3 sample rows: 3/9
  EXPECT_EQ(img.pixel(10, 5)[0], 57);           // the corner: 2 x 1 of 9 samples, 2/9 of 255
  EXPECT_EQ(img.pixel(15, 15)[0], 255);
}

TEST(Texture, SeedHighResolutionModeIs2400x1800Inside) {
  Renderer r(800, 600);
  r.options.ssaa = 3;
  Scene empty;
  r.render(empty);
  // 2400x1800 samples of colour and depth, stored in whole 64x64 tiles (2432x1856).
  EXPECT_EQ(r.framebuffer_bytes(), size_t(38 * 64) * (29 * 64) * (4 + 4 + 1));
  EXPECT_EQ(r.color_image().width, 800);
  EXPECT_EQ(r.color_image().height, 600);
  r.options.ssaa = 5;
  EXPECT_THROW(r.render(empty), std::exception);
  Renderer big(8192, 8);
  big.options.ssaa = 3;  // 24576 samples wide: too large
  EXPECT_THROW(big.render(empty), std::exception);
}

// Materials are per face: one mesh, two materials, one textured.
TEST(Texture, PerFaceMaterialsCarryTheirOwnTexture) {
  Mesh m;
  m.positions = {{-2, -1, -3}, {0, -1, -3}, {0, 1, -3}, {-2, 1, -3}, {2, -1, -3}, {2, 1, -3}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {0, 1}};
  m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{1, 4, 5}}, {{1, 5, 2}}};
  Material plain;
  plain.shading = Shading::Unlit;
  plain.color = {0, 1, 0};
  Material textured = plain;
  textured.color = {1, 1, 1};
  textured.texture = std::make_shared<const Texture>(make_image(1, 1, [](int, int) { return 255; }, [](int, int) { return 0; }));
  textured.texture_mode = TextureMode::Replace;
  m.materials = {textured, plain};
  m.face_materials = {0, 0, 1, 1};  // left half textured (red), right half plain (green)
  Scene scene;
  scene.add_object("two materials", std::make_shared<Mesh>(m));
  scene.camera.position = {0, 0, 0};
  scene.background = {0, 0, 0};
  Renderer r(64, 32);
  r.render(scene);
  Image img = r.color_image();
  EXPECT_EQ(img.pixel(20, 16)[0], 255);
  EXPECT_EQ(img.pixel(20, 16)[1], 0);
  EXPECT_EQ(img.pixel(44, 16)[0], 0);
  EXPECT_EQ(img.pixel(44, 16)[1], 255);
}

// A linear frame's colour textures: every level decoded from sRGB once, to RGBA16, and
// sampled from there (the sampler decodes nothing per texel).
TEST(Texture, LinearLevelsDecodeEverySrgbValueOnce) {
  Image img(256, 2);  // asymmetric: red rises, green falls, alpha rises in steps of 3
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 256; ++x) {
      uint8_t* p = img.pixel(x, y);
      p[0] = uint8_t(x), p[1] = uint8_t(255 - x), p[2] = uint8_t(y * 200), p[3] = uint8_t((x * 3) & 0xff);
    }
  const Texture t(img);
  const auto& linear = t.linear_levels();
  ASSERT_EQ(linear.size(), t.levels().size());
  for (size_t l = 0; l < linear.size(); ++l) ASSERT_EQ(linear[l].size(), t.levels()[l].texels.size()) << "level " << l;
  auto unorm16 = [](int v) { return uint64_t(std::lround(65535.0 * color::srgb_to_linear(float(v) / 255.0f))); };
  for (size_t l = 0; l < linear.size(); ++l)
    for (size_t i = 0; i < linear[l].size(); ++i) {
      const uint32_t s = t.levels()[l].texels[i];
      const uint64_t q = linear[l][i];
      ASSERT_EQ(q & 0xffff, unorm16(int(s & 0xff))) << "level " << l << " texel " << i;
      ASSERT_EQ((q >> 16) & 0xffff, unorm16(int((s >> 8) & 0xff)));
      ASSERT_EQ((q >> 32) & 0xffff, unorm16(int((s >> 16) & 0xff)));
      ASSERT_EQ(q >> 48, uint64_t(s >> 24) * 257);  // alpha is linear
    }
  EXPECT_EQ(t.linear_levels()[0].data(), linear[0].data());  // made once
  const Texture copy = t;
  EXPECT_EQ(copy.linear_levels()[0].data(), linear[0].data());  // and shared by copies

  // Sampled through an sRGB view: texel centres give the decoded values, bilinear
  // halfway between sRGB 0 and 255 gives linear 0.5 (not the decode of 128), and the
  // border colour keeps its [0, 1] value.
  SamplerState st;
  st.mag = st.min = SamplerState::Texel::Linear, st.mip = SamplerState::Mip::None;
  st.wrap_s = st.wrap_t = Wrap::ClampToBorder, st.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
  SamplerView v(t, st);
  v.read_as_srgb(true);
  ASSERT_TRUE(v.srgb);
  float c[4];
  for (int x : {0, 1, 10, 11, 128, 200, 255}) {
    raster::sample_for_test(v, (float(x) + 0.5f) / 256, 0.25f, 0, c);
    EXPECT_NEAR(c[0], color::srgb_to_linear(float(x) / 255), 1e-4f) << "x " << x;
    EXPECT_NEAR(c[1], color::srgb_to_linear(float(255 - x) / 255), 1e-4f) << "x " << x;
    EXPECT_NEAR(c[2], 0.0f, 1e-6f);
    EXPECT_NEAR(c[3], float((x * 3) & 0xff) / 255, 1e-4f) << "x " << x;
  }
  raster::sample_for_test(v, 0.5f / 256, 0.5f, 0, c);  // halfway between rows 0 (blue 0) and 1 (blue 200)
  EXPECT_NEAR(c[2], 0.5f * color::srgb_to_linear(200.0f / 255), 1e-4f);
  raster::sample_for_test(v, -0.5f, 0.25f, 0, c);
  EXPECT_NEAR(c[0], 0.25f, 1e-6f);
  EXPECT_NEAR(c[1], 0.5f, 1e-6f);
  EXPECT_NEAR(c[2], 0.75f, 1e-6f);
  EXPECT_NEAR(c[3], 1.0f, 1e-6f);
}

// The bilinear filter at 16 points at once (a 4x4 block's pixels, as the kernels
// sample), against the filter written out point by point from the texels: magnified
// blocks, whose lanes the sampler serves from a window of texels loaded once, and
// minified ones, which it gathers; near and across the edges in every wrap mode, for
// RGBA8 and sRGB (RGBA16 linear) texels. An asymmetric 13x9 image, no texel like another.
TEST(Texture, BilinearAtABlocksPointsMatchesTheFilterPointByPoint) {
  const int w = 13, h = 9;
  const Texture t(make_image(w, h, [](int x, int y) { return (x * 37 + y * 101) % 251; },
                             [](int x, int y) { return (x * x * 7 + y * 59 + 13) % 253; }));
  const auto& linear = t.linear_levels()[0];
  const std::vector<uint32_t>& texels = t.levels()[0].texels;
  const float border[4] = {0.2f, 0.4f, 0.6f, 0.8f};
  std::uint32_t seed = 12345;
  auto random = [&](float lo, float hi) {
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * float(seed >> 8) / float(1 << 24);
  };
  for (bool srgb : {false, true})
    for (Wrap wrap : {Wrap::Repeat, Wrap::MirroredRepeat, Wrap::Clamp, Wrap::ClampToBorder}) {
      SamplerState st;
      st.mag = st.min = SamplerState::Texel::Linear, st.mip = SamplerState::Mip::None;
      st.wrap_s = st.wrap_t = wrap, st.border_color = {border[0], border[1], border[2], border[3]};
      SamplerView view(t, st);
      view.read_as_srgb(srgb);
      // Texel i of an axis n long in this wrap mode; -1: the border.
      auto wrapped = [&](int i, int n) {
        switch (wrap) {
          case Wrap::Repeat: return ((i % n) + n) % n;
          case Wrap::MirroredRepeat: {
            const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
          }
          case Wrap::Clamp: return std::clamp(i, 0, n - 1);
          default: return i >= 0 && i < n ? i : -1;
        }
      };
      auto channel = [&](int x, int y, int k) {
        if (x < 0 || y < 0) return double(border[k]);
        const size_t at = size_t(y) * size_t(w) + size_t(x);
        if (srgb) return double((linear[at] >> (16 * k)) & 0xffff) / 65535.0;
        return double((texels[at] >> (8 * k)) & 0xff) / 255.0;
      };
      auto expected = [&](float u, float v, int k) {
        // GL's repeat and mirrored repeat wrap the coordinate first (as the sampler does).
        double s = u, r = v;
        if (wrap == Wrap::Repeat) s -= std::floor(s), r -= std::floor(r);
        if (wrap == Wrap::MirroredRepeat) s -= 2 * std::floor(s / 2), r -= 2 * std::floor(r / 2);
        const double x = s * w - 0.5, y = r * h - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double a = x - x0, b = y - y0;
        const int xa = wrapped(x0, w), xb = wrapped(x0 + 1, w), ya = wrapped(y0, h), yb = wrapped(y0 + 1, h);
        const double top = channel(xa, ya, k) * (1 - a) + channel(xb, ya, k) * a;
        const double bottom = channel(xa, yb, k) * (1 - a) + channel(xb, yb, k) * a;
        return top * (1 - b) + bottom * b;
      };
      for (int block = 0; block < 600; ++block) {
        // A block's uv: a point anywhere from past one edge to past the other, and steps
        // per pixel of up to 0.45 texels (magnified) or, for one block in four, 2.
        const float reach = block % 4 == 3 ? 2.0f : 0.45f;
        const float u0 = random(-0.4f, 1.4f), v0 = random(-0.4f, 1.4f);
        const float ux = random(-reach, reach) / w, uy = random(-reach, reach) / w;
        const float vx = random(-reach, reach) / h, vy = random(-reach, reach) / h;
        float u[16], v[16], got[64];
        for (int i = 0; i < 16; ++i) u[i] = u0 + ux * float(i & 3) + uy * float(i >> 2), v[i] = v0 + vx * float(i & 3) + vy * float(i >> 2);
        raster::sample_points_for_test(view, u, v, 16, 0, got);
        for (int i = 0; i < 16; ++i)
          for (int k = 0; k < 4; ++k)
            ASSERT_NEAR(got[4 * i + k], expected(u[i], v[i], k), 2e-5)
                << (srgb ? "sRGB" : "RGBA8") << " wrap " << int(wrap) << " block " << block << " point " << i << " ("
                << u[i] << ", " << v[i] << ") channel " << k;
      }
    }
}

// The first use decodes once however many threads ask at the same time (a frame's
// draws are planned on one thread, but two renderers may share a texture).
TEST(Texture, LinearLevelsAreMadeOnceAcrossThreads) {
  const Texture t(make_image(64, 32, [](int x, int) { return x * 4; }, [](int, int y) { return y * 8; }));
  const uint64_t* seen[4] = {};
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) threads.emplace_back([&t, &seen, i] { seen[i] = t.linear_levels()[0].data(); });
  for (auto& th : threads) th.join();
  for (const uint64_t* p : seen) EXPECT_EQ(p, seen[0]);
  EXPECT_EQ(t.linear_levels().size(), t.levels().size());
}

// --- 3-D textures (Texture::volume; pGL's GL_TEXTURE_3D)

namespace {
// A w x h x d volume whose texel (x, y, z) has red = 10 x + 1, green = 20 y, blue = 30 z.
Texture::Level volume_level(int w, int h, int d) {
  Texture::Level l{w, h, std::vector<uint32_t>(size_t(w) * h * d), d};
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        l.texels[(size_t(z) * h + y) * w + x] = uint32_t(10 * x + 1) | uint32_t(20 * y) << 8 | uint32_t(30 * z) << 16 | 0xffu << 24;
  return l;
}
Rgba sample3(const Texture& t, SamplerState s, float u, float v, float w, float lod = 0) {
  float c[4];
  raster::sample3_for_test(SamplerView(t, s), u, v, w, lod, c);
  return {c[0] * 255, c[1] * 255, c[2] * 255, c[3] * 255};
}
}  // namespace

TEST(Texture3D, NearestReadsTheTexelUnderTheSamplePoint) {
  const Texture t({volume_level(4, 3, 5)}, true);
  ASSERT_TRUE(t.volume());
  SamplerState s;
  s.mag = s.min = SamplerState::Texel::Nearest, s.mip = SamplerState::Mip::None;
  // Texel (2, 1, 3) covers [2, 3)/4 x [1, 2)/3 x [3, 4)/5.
  const Rgba c = sample3(t, s, 2.5f / 4, 1.5f / 3, 3.2f / 5);
  EXPECT_NEAR(c.r, 21, 1e-3);
  EXPECT_NEAR(c.g, 20, 1e-3);
  EXPECT_NEAR(c.b, 90, 1e-3);
  // r wraps with wrap_r alone: repeat reads slice 0 past the end, clamp the last slice.
  EXPECT_NEAR(sample3(t, s, 0.1f, 0.1f, 1.05f).b, 0, 1e-3);
  s.wrap_r = Wrap::Clamp;
  EXPECT_NEAR(sample3(t, s, 0.1f, 0.1f, 1.05f).b, 120, 1e-3);
  EXPECT_NEAR(sample3(t, s, 0.1f, 0.1f, -7.0f).b, 0, 1e-3);
  // Outside with clamp-to-border on r: the border colour.
  s.wrap_r = Wrap::ClampToBorder, s.border_color = {0, 1, 0, 1};
  EXPECT_NEAR(sample3(t, s, 0.1f, 0.1f, -0.5f).g, 255, 1e-3);
  // NaN and huge coordinates stay inside the texture.
  s.wrap_r = Wrap::Repeat;
  EXPECT_GE(sample3(t, s, NAN, 1e30f, -1e30f).a, 0.0f);
}

TEST(Texture3D, LinearWeightsTheEightNearestTexels) {
  const Texture t({volume_level(2, 2, 2)}, true);
  SamplerState s;
  s.mag = s.min = SamplerState::Texel::Linear, s.mip = SamplerState::Mip::None;
  s.wrap_s = s.wrap_t = s.wrap_r = Wrap::Clamp;
  // Midway between all eight centres: the mean on each axis.
  Rgba c = sample3(t, s, 0.5f, 0.5f, 0.5f);
  EXPECT_NEAR(c.r, 6, 1e-3);
  EXPECT_NEAR(c.g, 10, 1e-3);
  EXPECT_NEAR(c.b, 15, 1e-3);
  // A quarter of the way from slice 0's centre to slice 1's: 3/4 and 1/4 in blue only.
  c = sample3(t, s, 0.25f, 0.25f, 0.375f);
  EXPECT_NEAR(c.r, 1, 1e-3);
  EXPECT_NEAR(c.b, 7.5, 1e-3);
}

TEST(Texture3D, MipChainHalvesDepthAndBlendsLevels) {
  // 4x2x8 -> 2x1x4 -> 1x1x2 -> 1x1x1, each texel the 2x2x2 box average.
  std::vector<Texture::Level> chain{volume_level(4, 2, 8)};
  while (chain.back().width > 1 || chain.back().height > 1 || chain.back().depth > 1)
    chain.push_back(next_mip_level(chain.back()));
  ASSERT_EQ(chain.size(), 4u);
  EXPECT_EQ(chain[1].depth, 4);
  EXPECT_EQ(chain[2].width, 1);
  EXPECT_EQ(chain[2].depth, 2);
  // Level 1's texel (1, 0, 2): red (21 + 31) / 2, green 10, blue (120 + 150) / 2.
  const Rgba l1 = unpack(chain[1].texels[(2 * 1 + 0) * 2 + 1]);
  EXPECT_NEAR(l1.r * 255, 26, 0.5);
  EXPECT_NEAR(l1.g * 255, 10, 0.5);
  EXPECT_NEAR(l1.b * 255, 135, 0.5);
  const Texture t(chain, true);
  SamplerState s;
  s.mag = s.min = SamplerState::Texel::Nearest, s.mip = SamplerState::Mip::Linear;
  // Level of detail 1.5: levels 1 and 2 blended half and half.
  const Rgba a = sample3(t, s, 0.1f, 0.1f, 0.1f, 1.0f), b = sample3(t, s, 0.1f, 0.1f, 0.1f, 2.0f);
  const Rgba m = sample3(t, s, 0.1f, 0.1f, 0.1f, 1.5f);
  EXPECT_NEAR(m.b, (a.b + b.b) / 2, 0.5);
  EXPECT_NE(a.b, b.b);
}

TEST(Texture3D, SlicesMustMatchTheSizeAndHalve) {
  EXPECT_THROW(Texture({volume_level(2, 2, 3)}, false), Error);  // a 2-D texture has one slice
  Texture::Level bad = volume_level(2, 2, 3);
  bad.texels.pop_back();
  EXPECT_THROW(Texture({bad}, true), Error);
  EXPECT_THROW(Texture({volume_level(4, 4, 4), volume_level(2, 2, 4)}, true), Error);
  EXPECT_NO_THROW(Texture({volume_level(4, 4, 1), volume_level(2, 2, 1)}, true));
}

// --- texture borders (Texture::Level::border; OpenGL's border = 1)

TEST(TextureBorder, ClampToBorderReadsTheRingTheOtherModesDoNot) {
  // A 2x2 image (red 10, 20 / 30, 40) inside a ring of red 200 (left, right columns)
  // and 100 (top, bottom rows): 4x4 texels.
  Texture::Level l{2, 2, std::vector<uint32_t>(16), 1, 1};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const bool inside = x > 0 && x < 3 && y > 0 && y < 3;
      const uint32_t red = inside ? uint32_t(10 * ((y - 1) * 2 + (x - 1) + 1)) : (x == 0 || x == 3) ? 200u : 100u;
      l.texels[size_t(y) * 4 + x] = red | 0xff000000u;
    }
  const Texture t({l});
  SamplerState s;
  s.mag = s.min = SamplerState::Texel::Nearest, s.mip = SamplerState::Mip::None;
  s.border_color = {0, 1, 0, 1};
  auto red = [&](float u, float v) {
    float c[4];
    raster::sample_for_test(SamplerView(t, s), u, v, 0, c);
    return c[0] * 255;
  };
  EXPECT_FALSE(SamplerView(t, s).volume);
  // Inside: the image, not the ring.
  EXPECT_NEAR(red(0.25f, 0.25f), 10, 1e-3);
  EXPECT_NEAR(red(0.75f, 0.75f), 40, 1e-3);
  // Repeat and clamp-to-edge never read the ring.
  EXPECT_NEAR(red(1.25f, 0.25f), 10, 1e-3);
  s.wrap_s = s.wrap_t = Wrap::Clamp;
  EXPECT_NEAR(red(-0.5f, 0.25f), 10, 1e-3);
  // Clamp-to-border reads the ring's texels, not the border colour.
  s.wrap_s = s.wrap_t = Wrap::ClampToBorder;
  EXPECT_NEAR(red(-0.25f, 0.25f), 200, 1e-3);
  EXPECT_NEAR(red(0.75f, 1.4f), 100, 1e-3);
  // Linear at the image's edge blends the last texel and the ring half and half.
  s.mag = SamplerState::Texel::Linear;
  EXPECT_NEAR(red(0.0f, 0.25f), (200 + 10) / 2.0, 1e-3);
  // A border of 2, or levels with different borders, are refused.
  Texture::Level two = l;
  two.border = 2;
  EXPECT_THROW(Texture({two}), Error);
}

// OpenGL's GL_CLAMP (Wrap::ClampHalfBorder): coordinates clamped to [0, 1]; the nearest
// texel is always an edge one, the bilinear filter blends half the border colour in at
// the edge and never more; GL_CLAMP_TO_BORDER reads the whole border past it.
TEST(Texture, GlClampHalfBorder) {
  const Texture t(make_image(4, 2, [](int x, int) { return 40 + 60 * x; }, [](int, int y) { return 100 * y; }));
  SamplerState st;
  st.mip = SamplerState::Mip::None;
  st.border_color = {1.0f, 0.5f, 0.25f, 0.0f};
  auto at = [&](SamplerState::Texel f, Wrap w, float u, float v) {
    st.mag = st.min = f, st.wrap_s = st.wrap_t = w;
    float c[4];
    raster::sample_for_test(SamplerView(t, st), u, v, 0, c);
    return Rgba{c[0], c[1], c[2], c[3]};
  };
  using T = SamplerState::Texel;
  for (float u : {1.0f, 1.4f, 7.0f}) {  // nearest: the last texel, never the border
    const Rgba c = at(T::Nearest, Wrap::ClampHalfBorder, u, 0.25f);
    EXPECT_NEAR(c.r, 220 / 255.0f, 1e-5f) << "u " << u;
    EXPECT_NEAR(c.a, 1.0f, 1e-5f) << "u " << u;
  }
  EXPECT_NEAR(at(T::Nearest, Wrap::ClampHalfBorder, -3.0f, 0.25f).r, 40 / 255.0f, 1e-5f);
  // Bilinear at and past the right edge (row 0's centre in v): half texel 3, half border.
  for (float u : {1.0f, 1.3f}) {
    const Rgba c = at(T::Linear, Wrap::ClampHalfBorder, u, 0.25f);
    EXPECT_NEAR(c.r, 0.5f * (220 / 255.0f) + 0.5f * 1.0f, 1e-4f) << "u " << u;
    EXPECT_NEAR(c.a, 0.5f, 1e-4f) << "u " << u;
  }
  // A texel centre inside reads the texel alone; GL_CLAMP_TO_BORDER past the edge reads the border.
  EXPECT_NEAR(at(T::Linear, Wrap::ClampHalfBorder, 0.375f, 0.25f).r, 100 / 255.0f, 1e-4f);
  const Rgba b = at(T::Linear, Wrap::ClampToBorder, 1.3f, 0.25f);
  EXPECT_NEAR(b.r, 1.0f, 1e-5f);
  EXPECT_NEAR(b.g, 0.5f, 1e-5f);
  EXPECT_NEAR(b.a, 0.0f, 1e-5f);
  // NaN clamps to 0: the first column's half border, not a read outside the image.
  const Rgba n = at(T::Linear, Wrap::ClampHalfBorder, std::nanf(""), 0.25f);
  EXPECT_NEAR(n.r, 0.5f * (40 / 255.0f) + 0.5f, 1e-4f);
}
