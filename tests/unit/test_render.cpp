// End-to-end behaviour of the renderer on small scenes whose right answer is known.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/resolve.hpp"
#include "image_test_util.hpp"
#include "velocity/demo.hpp"
#include "velocity/error.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;
using test::at;
using test::count_not;

namespace {

constexpr uint32_t kClear = 0xff000000u;  // pack of (0, 0, 0)

Vec3 rgb(const Image& img, int x, int y) {
  const uint8_t* p = img.pixel(x, y);
  return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
}

// A square in the plane z = depth (world), facing +Z, side 2*half.
Mesh square(float half, float z) {
  Mesh m;
  m.positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  return m;
}

Material unlit(Vec3 c) {
  Material m;
  m.color = c;
  m.shading = Shading::Unlit;  // no vertex colours: the material colour, unlit
  return m;
}

Camera camera_at_origin() {
  Camera c;
  c.position = {0, 0, 0};
  c.near = 0.5f, c.far = 50.0f;
  return c;
}


}  // namespace

TEST(Render, NearerSurfaceWinsWhateverTheOrder) {
  Mesh near_sq = square(1, -3), far_sq = square(2, -6);
  Material red = unlit({1, 0, 0}), blue = unlit({0, 0, 1});
  for (int order = 0; order < 2; ++order) {
    Renderer r(64, 64);
    r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
    if (order == 0) r.draw(near_sq, Mat4::identity(), &red), r.draw(far_sq, Mat4::identity(), &blue);
    else r.draw(far_sq, Mat4::identity(), &blue), r.draw(near_sq, Mat4::identity(), &red);
    r.end_frame();
    Image img = r.color_image();
    EXPECT_EQ(rgb(img, 32, 32).x, 1.0f) << "order " << order;   // centre: the near red square
    EXPECT_EQ(rgb(img, 32, 32).z, 0.0f) << "order " << order;
  }
}

TEST(Render, DepthBufferHoldsWindowDepth) {
  Renderer r(32, 32);
  Material white = unlit({1, 1, 1});
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  Mesh sq = square(10, -5);
  r.draw(sq, Mat4::identity(), &white);
  r.end_frame();
  Image depth = r.depth_image();
  // A flat square facing the camera: all one depth, drawn white (the nearest drawn).
  EXPECT_EQ(depth.pixel(16, 16)[0], 255);
  EXPECT_EQ(depth.pixel(0, 0)[0], 255);
}

// Painter's mode sorts by depth, so the near square wins even when drawn first, without
// a depth buffer (it stays clear).
TEST(Render, PainterDrawsFarToNear) {
  Mesh near_sq = square(1, -3), far_sq = square(3, -6);  // the far one fills the view
  Material red = unlit({1, 0, 0}), blue = unlit({0, 0, 1});
  Renderer r(64, 64);
  r.options.depth_mode = DepthMode::Painter;
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(near_sq, Mat4::identity(), &red);
  r.draw(far_sq, Mat4::identity(), &blue);
  r.end_frame();
  Image img = r.color_image();
  EXPECT_EQ(rgb(img, 32, 32).x, 1.0f);
  EXPECT_EQ(rgb(img, 2, 32).z, 1.0f);  // the far square shows around the near one
  Image depth = r.depth_image();
  EXPECT_EQ(depth.pixel(32, 32)[0], 0);  // no depth written
  // Without the sort (z-buffer off would draw in order), the far square would cover it:
  // check the opposite submission order gives the same picture.
  Renderer r2(64, 64);
  r2.options.depth_mode = DepthMode::Painter;
  r2.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r2.draw(far_sq, Mat4::identity(), &blue);
  r2.draw(near_sq, Mat4::identity(), &red);
  r2.end_frame();
  EXPECT_EQ(r2.color_image().pixels, img.pixels);
}

TEST(Render, BackFacesAreCulledUnlessTwoSided) {
  Mesh sq = square(1, -3);
  std::swap(sq.triangles[0].v[1], sq.triangles[0].v[2]);
  std::swap(sq.triangles[1].v[1], sq.triangles[1].v[2]);  // now facing away
  Material m = unlit({1, 1, 1});
  Renderer r(32, 32);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &m);
  EXPECT_EQ(r.end_frame().triangles_culled, 2u);
  EXPECT_EQ(count_not(r.color_image(), kClear), 0u);
  m.two_sided = true;
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &m);
  r.end_frame();
  EXPECT_GT(count_not(r.color_image(), kClear), 0u);
}

// A floor from under the camera to far away: it crosses the near plane and has vertices
// behind the eye. What shows is exactly the part in front, and nothing crashes.
TEST(Render, GeometryThroughTheNearPlaneAndBehindTheEye) {
  Mesh floor;
  floor.positions = {{-50, -1, 20}, {50, -1, 20}, {50, -1, -40}, {-50, -1, -40}};
  floor.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
  Material m = unlit({0, 1, 0});
  Renderer r(80, 60);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(floor, Mat4::identity(), &m);
  const FrameStats& s = r.end_frame();
  EXPECT_EQ(s.triangles_clipped, 2u);
  Image img = r.color_image();
  // Below the horizon (lower half) is floor, above it is empty.
  for (int x = 0; x < 80; ++x) {
    EXPECT_EQ(at(img, x, 59), 0xff00ff00u) << x;
    EXPECT_EQ(at(img, x, 0), kClear) << x;
  }
}

// A triangle reaching far beyond the guard band still fills exactly the screen.
TEST(Render, HugeTriangleFillsTheScreen) {
  Mesh big;
  big.positions = {{-1e6f, -1e6f, -5}, {1e6f, -1e6f, -5}, {0, 1e6f, -5}};
  big.triangles = {{{0, 1, 2}}};
  Material m = unlit({1, 1, 1});
  Renderer r(97, 55);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(big, Mat4::identity(), &m);
  r.end_frame();
  EXPECT_EQ(count_not(r.color_image(), 0xffffffffu), 0u);
}

TEST(Render, NonFiniteVerticesAreDropped) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Mesh m;
  m.positions = {{0, 0, -3}, {1, 0, -3}, {nan, 1, -3}, {0, inf, -3}, {1e30f, 1e30f, -3}};
  m.triangles = {{{0, 1, 2}}, {{0, 1, 3}}, {{0, 1, 4}}};
  Material mat = unlit({1, 1, 1});
  Renderer r(32, 32);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(m, Mat4::identity(), &mat);
  const FrameStats& s = r.end_frame();
  EXPECT_EQ(s.triangles_nonfinite, 2u);
  EXPECT_EQ(s.triangles, 3u);
}

TEST(Render, ObjectOutsideTheViewIsRejectedWhole) {
  Mesh sq = square(1, -3);
  Material m = unlit({1, 1, 1});
  Renderer r(32, 32);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(sq, translate({100, 0, 0}), &m);
  r.draw(sq, translate({0, 0, 10}), &m);  // behind the camera
  const FrameStats& s = r.end_frame();
  EXPECT_EQ(s.objects_culled, 2u);
  EXPECT_EQ(s.triangles, 0u);
}

TEST(Render, WireframeAndPointsDrawWithDepth) {
  Mesh sq = square(1, -3);
  Material wire = unlit({1, 1, 1});
  wire.shading = Shading::Wireframe;
  Renderer r(64, 64);
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &wire);
  const FrameStats& s = r.end_frame();
  EXPECT_EQ(s.lines, 6u);
  Image img = r.color_image();
  EXPECT_EQ(at(img, 32, 32 - 1), 0xffffffffu);  // the diagonal passes the centre
  EXPECT_EQ(at(img, 40, 28), kClear);           // inside a face: empty

  Material pts = wire;
  pts.shading = Shading::Points;
  r.begin_frame(camera_at_origin(), {}, {0, 0, 0});
  r.draw(sq, Mat4::identity(), &pts);
  EXPECT_EQ(r.end_frame().points, 4u);  // each shared vertex once
  EXPECT_EQ(count_not(r.color_image(), kClear), 4u);
}

TEST(Render, GouraudInterpolatesThreeColours) {
  Mesh tri;
  tri.positions = {{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}};
  tri.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tri.triangles = {{{0, 1, 2}}};
  Material m;
  m.shading = Shading::Unlit;
  Scene scene;
  ObjectId id = scene.add_object("tri", std::make_shared<Mesh>(tri));
  scene.object(id).material = m;
  scene.camera = camera_at_origin();
  scene.background = {0, 0, 0};
  Renderer r(101, 101);
  r.render(scene);
  Image img = r.color_image();
  Vec3 centre = rgb(img, 50, 60);  // somewhere inside: a mix of all three
  EXPECT_GT(centre.x, 0.1f);
  EXPECT_GT(centre.y, 0.1f);
  EXPECT_GT(centre.z, 0.1f);
  EXPECT_NEAR(centre.x + centre.y + centre.z, 1.0f, 0.02f);  // barycentric weights sum to 1
}

TEST(Render, RejectsBadSizes) {
  EXPECT_THROW(Renderer(0, 10), std::exception);
  EXPECT_THROW(Renderer(10, -1), std::exception);
  EXPECT_THROW(Renderer(16385, 1), std::exception);
  EXPECT_NO_THROW(Renderer(1, 1));
}

TEST(Render, DrawOutsideAFrameIsAnError) {
  Renderer r(8, 8);
  Mesh sq = square(1, -3);
  EXPECT_THROW(r.draw(sq, Mat4::identity()), std::exception);
  EXPECT_THROW(r.end_frame(), std::exception);
}

// A mesh built without normals is lit with normals averaged over the faces sharing each
// vertex: Gouraud shading of a hand-made sphere is smooth, not faceted.
TEST(Render, MeshWithoutNormalsGetsAveragedNormals) {
  Mesh with = make_sphere(24);
  Mesh without = with;
  without.normals.clear();
  Material m;
  m.shading = Shading::Gouraud;
  auto draw = [&](const Mesh& mesh) {
    Renderer r(96, 96);
    Camera cam;
    r.begin_frame(cam, {}, {0, 0, 0});
    r.draw(mesh, Mat4::identity(), &m);
    r.end_frame();
    return r.color_image();
  };
  Image a = draw(with), b = draw(without);
  int worst = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  EXPECT_LE(worst, 6);  // averaged face normals differ from the analytic ones only slightly
}

// read_color gives the image color_image gives, as RGBA or RGB rows of any pitch, with
// and without super-sampling; other channel counts are an error.
TEST(Render, ReadColorMatchesTheImage) {
  Scene scene = make_demo_scene(1.5f);
  for (int ssaa : {1, 2}) {
    Renderer r(101, 67);  // partial blocks and tiles
    r.options.ssaa = ssaa;
    r.render(scene);
    const Image img = r.color_image();
    for (int channels : {4, 3}) {
      const size_t pitch = size_t(101) * channels + 5;
      std::vector<uint8_t> out(pitch * 67, 0xab);
      r.read_color(out.data(), pitch, channels);
      for (int y = 0; y < 67; ++y)
        for (int x = 0; x < 101; ++x)
          for (int c = 0; c < channels; ++c)
            ASSERT_EQ(out[size_t(y) * pitch + size_t(x) * channels + c], img.pixel(x, y)[c])
                << x << "," << y << " channel " << c << " of " << channels << ", ssaa " << ssaa;
      for (int y = 0; y < 67; ++y) EXPECT_EQ(out[size_t(y) * pitch + pitch - 1], 0xab);  // the pitch's padding
    }
    std::vector<uint8_t> any(101 * 67 * 4);
    EXPECT_THROW(r.read_color(any.data(), 101 * 2, 2), Error);
  }
}

// end_frame_into (each tile copied out as it is drawn) writes the bytes end_frame and
// read_color write, for RGBA and RGB rows with a padded pitch, sizes with partial tiles
// and blocks, with and without super-sampling, on one thread and two; the pitch's
// padding is left alone; other channel counts and a call outside a frame are errors.
TEST(Render, EndFrameIntoMatchesEndFrameThenReadColor) {
  Scene scene = make_demo_scene(1.5f);
  for (auto [w, h] : {std::pair{101, 67}, std::pair{203, 130}})
    for (int ssaa : {1, 2})
      for (int threads : {1, 2})
        for (int channels : {4, 3}) {
          // RGBA rows 16-byte aligned (whole tile rows go by non-temporal stores), RGB
          // rows at an odd pitch.
          const size_t pitch = channels == 4 ? (size_t(w) * 4 + 31) & ~size_t(15) : size_t(w) * 3 + 5;
          std::vector<uint8_t> want(pitch * h, 0xab), got(pitch * h, 0xab);
          Renderer a(w, h), b(w, h);
          for (Renderer* r : {&a, &b}) r->options.ssaa = ssaa, r->options.threads = threads;
          a.render(scene);
          a.read_color(want.data(), pitch, channels);
          b.begin_frame(scene.camera, scene.lights, scene.background);
          std::vector<Mat4> world;
          scene.world_matrices(world);
          for (size_t i = 0; i < scene.objects().size(); ++i) {
            const Object& o = scene.objects()[i];
            if (o.visible && o.mesh) b.draw(*o.mesh, world[i], o.material ? &*o.material : nullptr, uint32_t(i + 1));
          }
          b.end_frame_into(got.data(), pitch, channels);
          ASSERT_EQ(got, want) << w << "x" << h << ", ssaa " << ssaa << ", " << threads << " threads, " << channels
                               << " channels";
          for (int y = 0; y < h; ++y) EXPECT_EQ(got[size_t(y) * pitch + pitch - 1], 0xab);
        }
  Renderer r(64, 64);
  std::vector<uint8_t> any(64 * 64 * 4);
  EXPECT_THROW(r.end_frame_into(any.data(), 64 * 4, 4), Error);  // no frame begun
  r.begin_frame(Camera{}, {}, {0, 0, 0});
  EXPECT_THROW(r.end_frame_into(any.data(), 64 * 2, 2), Error);
}

// Tiles left clean (the clear colour alone, nothing drawn) are written out from the
// clear colour without reading them: the bytes are still the framebuffer's, frame after
// frame (clean from the last frame, cleaned in this one, a new clear colour that makes
// every tile dirty again), with an asymmetric colour so a swapped channel shows; for an
// image written with ordinary stores and one past 16 MiB, streamed.
TEST(Render, EndFrameIntoWritesCleanTilesAsTheFramebufferHoldsThem) {
  for (auto [w, h] : {std::pair{320, 200}, std::pair{2112, 2048}}) {
    Scene scene = make_demo_scene(float(w) / float(h));
    scene.camera.position = scene.camera.position * 4.0f;  // the scene small in the middle: most tiles empty
    const size_t pitch = size_t(w) * 4;
    Renderer r(w, h);
    r.options.threads = 2;
    std::vector<Mat4> world;
    scene.world_matrices(world);
    for (Vec4 clear : {Vec4{0.2f, 0.4f, 0.6f, 0.8f}, Vec4{0.2f, 0.4f, 0.6f, 0.8f}, Vec4{0.9f, 0.1f, 0.3f, 1.0f}}) {
      FrameStart start;
      start.color = clear;
      r.begin_frame(scene.camera, scene.lights, start);
      for (size_t i = 0; i < scene.objects().size(); ++i) {
        const Object& o = scene.objects()[i];
        if (o.visible && o.mesh) r.draw(*o.mesh, world[i], o.material ? &*o.material : nullptr, uint32_t(i + 1));
      }
      std::vector<uint8_t> got(pitch * h, 0xab), want(pitch * h, 0xcd);
      r.end_frame_into(got.data(), pitch, 4);
      r.read_color(want.data(), pitch, 4);
      ASSERT_EQ(got, want) << w << "x" << h << ", clear " << clear.x << "," << clear.y << "," << clear.z;
      EXPECT_EQ(got[0], uint8_t(std::lround(clear.x * 255)));  // a corner: the background
      EXPECT_EQ(got[3], uint8_t(std::lround(clear.w * 255)));
    }
  }
}

// With super-sampling the tile workers resolve each tile as they finish it, and the
// pixels that straddle two tiles after (k = 3: 64 samples are not a whole number of
// pixels): the image is the box filter, by hand, of the same scene drawn without
// super-sampling at k times the size, frame after frame (tiles left clean by the last
// frame keep their pixels; a change of factor or size resolves every tile again).
TEST(Ssaa, TileResolveIsTheBoxFilterOfTheSamples) {
  auto box = [](const Image& big, int k) {
    Image out(big.width / k, big.height / k);
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x)
        for (int c = 0; c < 4; ++c) {
          int sum = 0;
          for (int sy = 0; sy < k; ++sy)
            for (int sx = 0; sx < k; ++sx) sum += big.pixel(x * k + sx, y * k + sy)[c];
          out.pixel(x, y)[c] = uint8_t((sum + k * k / 2) / (k * k));
        }
    return out;
  };
  Renderer r(101, 67);  // 303 x 201 samples at k = 3: seams in both directions
  r.options.threads = 3;
  int frame = 0;
  for (auto [k, w, h, t] : {std::tuple{3, 101, 67, 1.5f}, std::tuple{3, 101, 67, 2.5f}, std::tuple{3, 101, 67, 2.5f},
                            std::tuple{2, 101, 67, 2.5f}, std::tuple{3, 101, 67, 2.5f}, std::tuple{3, 150, 90, 4.0f},
                            std::tuple{4, 40, 31, 4.0f}}) {
    const Scene scene = make_demo_scene(t);
    r.resize(w, h);
    r.options.ssaa = k;
    r.render(scene);
    Renderer big(w * k, h * k);
    big.render(scene);
    const Image want = box(big.color_image(), k), got = r.color_image();
    ASSERT_EQ(got.width, w);
    ASSERT_GT(count_not(want, at(want, 0, 0)), size_t(w * h / 10)) << "frame " << frame;  // the scene is in view
    std::vector<uint8_t> rgb(size_t(w) * h * 3);
    r.read_color(rgb.data(), size_t(w) * 3, 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        ASSERT_EQ(at(got, x, y), at(want, x, y)) << "frame " << frame << " k=" << k << " at " << x << "," << y;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(rgb[(size_t(y) * w + x) * 3 + c], want.pixel(x, y)[c]);
      }
    ++frame;
  }
}

namespace velocity {
// The super-sampling resolve adds two channels at a time (16-bit lanes): every pixel is
// still the rounded mean of its k x k samples, channel by channel, for samples of every
// value (all 255 included, the lanes' largest sum), at k = 2, 3, 4 and 16.
TEST(Resolve, BoxFilterIsTheRoundedMeanOfEachChannel) {
  for (int k : {2, 3, 4, 16}) {
    Framebuffer fb;
    const int w = 5, h = 3;
    fb.resize(w * k, h * k);
    uint32_t state = 12345u + uint32_t(k);
    for (int y = 0; y < h * k; ++y)
      for (int x = 0; x < w * k; ++x) {
        state = state * 1664525u + 1013904223u;
        fb.color[fb.index(x, y)] = x < k ? 0xffffffffu : state;  // the first pixel column all 255
      }
    const Image out = resolve_color(fb, k);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c) {
          uint32_t sum = 0;
          for (int sy = 0; sy < k; ++sy)
            for (int sx = 0; sx < k; ++sx) sum += (fb.color[fb.index(x * k + sx, y * k + sy)] >> (8 * c)) & 0xff;
          const uint32_t want = (sum + uint32_t(k * k / 2)) / uint32_t(k * k);
          ASSERT_EQ(out.pixels[(size_t(y) * w + x) * 4 + size_t(c)], want) << "k=" << k << " x=" << x << " c=" << c;
        }
  }
}

// The frame's resolve, a tile at a time and then the seams, writes every output pixel
// once, each the rounded mean of its samples per channel (k = 3 leaves pixels astride
// tile edges: 64 is not a multiple of 3; 2 and 4 leave none).
TEST(Resolve, TilesThenSeamsCoverEveryPixelOnce) {
  for (auto [k, w, h] : {std::tuple{3, 101, 67}, std::tuple{3, 250, 150}, std::tuple{2, 77, 40}, std::tuple{4, 33, 17},
                         std::tuple{3, 1, 1}}) {
    Framebuffer fb;
    fb.resize(w * k, h * k);
    uint32_t state = 777u + uint32_t(k * w);
    for (int y = 0; y < h * k; ++y)
      for (int x = 0; x < w * k; ++x) {
        state = state * 1664525u + 1013904223u;
        fb.color[fb.index(x, y)] = state;
      }
    std::vector<uint32_t> out(size_t(w) * h, 0), writes(size_t(w) * h, 0);
    // Pixels written twice would show up as changed sentinels: each pass writes into a
    // fresh buffer and the counts add up.
    auto pass = [&](auto&& resolve) {
      std::vector<uint32_t> once(size_t(w) * h, 0x5a5a5a5au);
      resolve(once.data());
      std::vector<uint32_t> probe(size_t(w) * h, 0xa5a5a5a5u);
      resolve(probe.data());
      for (size_t i = 0; i < once.size(); ++i)
        if (once[i] != 0x5a5a5a5au || probe[i] != 0xa5a5a5a5u) ++writes[i], out[i] = once[i];
    };
    for (int tile = 0; tile < fb.tiles_x * fb.tiles_y; ++tile)
      pass([&](uint32_t* o) { resolve_tile_color(fb, k, tile, o, size_t(w)); });
    const int seams = resolve_seam_count(fb, k);
    if (k != 3) {
      EXPECT_EQ(seams, 0);
    } else if (w == 250) {
      EXPECT_EQ(seams, 5 + 8);  // edges at 64 m, m not a multiple of 3
    }
    for (int line = 0; line < seams; ++line) pass([&](uint32_t* o) { resolve_seam(fb, k, line, o, size_t(w)); });
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        ASSERT_EQ(writes[size_t(y) * w + x], 1u) << "k=" << k << " " << w << "x" << h << " at " << x << "," << y;
        for (int c = 0; c < 4; ++c) {
          uint32_t sum = 0;
          for (int sy = 0; sy < k; ++sy)
            for (int sx = 0; sx < k; ++sx) sum += (fb.color[fb.index(x * k + sx, y * k + sy)] >> (8 * c)) & 0xff;
          ASSERT_EQ((out[size_t(y) * w + x] >> (8 * c)) & 0xff, (sum + uint32_t(k * k / 2)) / uint32_t(k * k))
              << "k=" << k << " at " << x << "," << y << " channel " << c;
        }
      }
  }
}
}  // namespace velocity
