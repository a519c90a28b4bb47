// Hostile geometry and sizes: NaN/Inf vertices (dropped, with one warning per mesh), the
// camera inside an object, exactly on a vertex, looking straight up and straight down,
// framebuffers from 1x1 to 16384x16384, and sizes that must be refused. Several cases
// render on 4 threads as well, so the TSan stage (scripts/sanitize.sh tsan) sees the
// tile pool work on them.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "image_test_util.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"

namespace velocity {
namespace {

using test::at;
using test::count_not;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Collects warnings for the lifetime of the object, then puts the old handler back.
class WarningCapture {
 public:
  WarningCapture() : old_(set_warning_handler([this](std::string_view m) { messages.emplace_back(m); })) {}
  ~WarningCapture() { set_warning_handler(std::move(old_)); }
  std::vector<std::string> messages;

 private:
  WarningHandler old_;
};

constexpr uint32_t kBlack = 0xff000000u;  // the background below: (0, 0, 0)

Scene one_object(std::shared_ptr<const Mesh> mesh, Shading shading = Shading::Gouraud) {
  Scene s;
  s.background = {0, 0, 0};
  ObjectId id = s.add_object("m", std::move(mesh));
  Material m;
  m.color = {0.9f, 0.6f, 0.3f};
  m.shading = shading;
  s.object(id).material = m;
  s.camera.position = {0, 0, 4};
  return s;
}

// Sanitizer and valgrind runs have their own limits on how much memory a test may touch.
bool big_allocations_are_slow() {
#if defined(__SANITIZE_THREAD__)
  return true;
#else
  const char* preload = std::getenv("LD_PRELOAD");
  return preload && std::strstr(preload, "vgpreload");  // valgrind
#endif
}

// --- NaN and infinite vertices ------------------------------------------------------------

TEST(Hostile, NanAndInfVerticesAreDroppedWithOneWarningPerMesh) {
  WarningCapture warnings;
  auto nan_mesh = std::make_shared<Mesh>(make_sphere(16));
  nan_mesh->name = "has_nan";
  nan_mesh->positions[20].x = kNaN;
  nan_mesh->positions[40].z = kInf;
  nan_mesh->positions[41].y = -kInf;
  compute_normals(*nan_mesh);  // NaN normals too, around the bad vertices
  auto clean = std::make_shared<Mesh>(make_cube(0.5f));
  clean->name = "clean";

  Scene scene = one_object(nan_mesh);
  ObjectId c = scene.add_object("clean", clean);
  scene.object(c).transform.translation = {1.2f, 0, 0};
  for (int threads : {1, 4}) {
    Renderer r(96, 64);
    r.options.threads = threads;
    for (Shading s : {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Wireframe, Shading::Points}) {
      r.options.shading = s;
      const FrameStats& st = r.render(scene);
      if (s != Shading::Wireframe && s != Shading::Points) {
        EXPECT_GT(st.triangles_nonfinite, 0u);
        EXPECT_GT(st.triangles_rasterized, 0u);  // the rest of the sphere, and the cube
      }
      Image img = r.color_image();
      const bool filled = s != Shading::Wireframe && s != Shading::Points;
      EXPECT_GT(count_not(img, kBlack), filled ? 400u : 20u) << to_string(s);
    }
  }
  // One warning per mesh with bad vertices, per renderer: not one per frame, per
  // shading mode or per triangle; the clean mesh never warns.
  ASSERT_EQ(warnings.messages.size(), 2u);
  for (const std::string& m : warnings.messages) {
    EXPECT_NE(m.find("mesh 'has_nan'"), std::string::npos) << m;
    EXPECT_NE(m.find("NaN or infinite"), std::string::npos) << m;
  }
}

TEST(Hostile, AllVerticesNanDrawsNothingAndWarnsOnce) {
  WarningCapture warnings;
  auto m = std::make_shared<Mesh>(make_cube());
  m->name = "all_nan";
  for (Vec3& p : m->positions) p = {kNaN, kNaN, kNaN};
  Renderer r(32, 32);
  for (int i = 0; i < 3; ++i) {
    const FrameStats& st = r.render(one_object(m));
    EXPECT_EQ(st.triangles_rasterized, 0u);
  }
  EXPECT_EQ(count_not(r.color_image(), kBlack), 0u);
  EXPECT_EQ(warnings.messages.size(), 1u);
}

TEST(Hostile, HugeButFiniteCoordinatesAndTransforms) {
  // 1e30 vertices, and transforms that overflow to infinity: dropped or clipped, never
  // a crash; a sane object beside them still draws.
  auto huge = std::make_shared<Mesh>();
  huge->name = "huge";
  huge->positions = {{-1e30f, -1e30f, 0}, {1e30f, -1e30f, 0}, {0, 1e30f, 0}, {1e30f, 1e30f, -1e30f}};
  huge->triangles = {{{0, 1, 2}}, {{1, 3, 2}}};
  WarningCapture warnings;
  Scene scene = one_object(huge);
  ObjectId big = scene.add_object("scaled", std::make_shared<Mesh>(make_cube()));
  scene.object(big).transform.scale = {1e30f, 1e30f, 1e30f};
  ObjectId inf = scene.add_object("inf", std::make_shared<Mesh>(make_cube()));
  scene.object(inf).transform.translation = {kInf, 0, 0};
  scene.add_object("sane", std::make_shared<Mesh>(make_cube(0.5f)));
  Renderer r(64, 64);
  r.options.threads = 4;
  r.options.cull_back_faces = false;
  r.render(scene);
  EXPECT_EQ(r.color_image().width, 64);
}

// --- the camera in awkward places ------------------------------------------------------------

TEST(Hostile, CameraInsideAClosedObject) {
  // From inside a cube, every face is a back face: culled, nothing drawn. Two-sided, the
  // walls fill the whole view (clipped by the near plane where they pass the eye).
  auto cube = std::make_shared<Mesh>(make_cube(2.0f));
  for (bool two_sided : {false, true}) {
    Scene scene = one_object(cube);
    scene.object(0).material->two_sided = two_sided;
    scene.camera.position = {0.3f, -0.2f, 0.1f};
    scene.camera.yaw = 0.7f, scene.camera.pitch = 0.3f;
    for (int threads : {1, 4}) {
      Renderer r(80, 60);
      r.options.threads = threads;
      r.render(scene);
      size_t n = count_not(r.color_image(), kBlack);
      if (two_sided)
        EXPECT_EQ(n, 80u * 60u) << "threads " << threads;
      else
        EXPECT_EQ(n, 0u) << "threads " << threads;
    }
  }
}

TEST(Hostile, CameraExactlyOnAVertex) {
  // The eye on a vertex: that vertex has w = 0 in clip space, so every triangle using it
  // is cut by the near plane; the rest of the mesh draws as usual.
  auto sphere = std::make_shared<Mesh>(make_sphere(24));
  for (size_t v : {size_t(0), size_t(37), sphere->positions.size() - 1}) {
    Scene scene = one_object(sphere);
    scene.object(0).material->two_sided = true;
    scene.camera.position = sphere->positions[v];
    scene.camera.near = 0.01f;
    for (Shading s : {Shading::Flat, Shading::Phong, Shading::Wireframe, Shading::Points}) {
      Renderer r(64, 48);
      r.options.threads = 4;
      r.options.shading = s;
      const FrameStats& st = r.render(scene);
      EXPECT_EQ(st.triangles_nonfinite, 0u) << "vertex " << v;
      EXPECT_EQ(r.color_image().width, 64);
    }
    // Looking at the centre from there, the inside of the sphere fills the view.
    scene.camera.look_at({0, 0, 0});
    Renderer r(64, 48);
    const FrameStats& st = r.render(scene);
    EXPECT_GT(st.triangles_clipped, 0u) << "vertex " << v;
    EXPECT_GT(count_not(r.color_image(), kBlack), 64u * 48u / 2) << "vertex " << v;
  }
}

// A floor (facing up) 2 below the eye and a ceiling (facing down) 2 above it.
Scene floor_and_ceiling() {
  Scene s;
  s.background = {0, 0, 0};
  auto floor = std::make_shared<Mesh>(make_plane_grid(40, 4));
  ObjectId f = s.add_object("floor", floor);
  s.object(f).transform.translation = {0, -2, 0};
  Material red;
  red.color = {1, 0, 0};
  red.shading = Shading::Unlit;  // unlit: the material colour as it is
  s.object(f).material = red;
  ObjectId c = s.add_object("ceiling", floor);
  s.object(c).transform.translation = {0, 2, 0};
  s.object(c).transform.rotation = {radians(180), 0, 0};  // faces down
  Material blue = red;
  blue.color = {0, 0, 1};
  s.object(c).material = blue;
  s.camera.position = {0, 0, 0};
  s.camera.far = 1000;
  return s;
}

TEST(Hostile, LookingStraightUpAndStraightDown) {
  const uint32_t kRed = 0xff0000ffu, kBlue = 0xffff0000u;
  for (bool use_look_at : {false, true}) {
    for (float yaw : {0.0f, 1.3f, -2.9f}) {
      Scene scene = floor_and_ceiling();
      scene.camera.yaw = yaw;
      // Straight down: pitch -90 degrees, the whole view is floor.
      if (use_look_at)
        scene.camera.look_at({0, -5, 0});
      else
        scene.camera.pitch = radians(-90);
      Renderer r(64, 48);
      r.options.threads = 4;
      r.render(scene);
      Image down = r.color_image();
      EXPECT_EQ(at(down, 32, 24), kRed) << "look_at " << use_look_at << " yaw " << yaw;
      EXPECT_EQ(count_not(down, kBlack), 64u * 48u);
      // Straight up: pitch +90 degrees, the whole view is ceiling.
      scene.camera.yaw = yaw, scene.camera.pitch = 0;
      if (use_look_at)
        scene.camera.look_at({0, 5, 0});
      else
        scene.camera.pitch = radians(90);
      r.render(scene);
      Image up = r.color_image();
      EXPECT_EQ(at(up, 32, 24), kBlue) << "look_at " << use_look_at << " yaw " << yaw;
      EXPECT_EQ(count_not(up, kBlack), 64u * 48u);
    }
  }
}

TEST(Hostile, LookAtItselfKeepsTheOrientation) {
  Camera c;
  c.position = {1, 2, 3};
  c.yaw = 0.5f, c.pitch = -0.25f;
  c.look_at({1, 2, 3});
  EXPECT_EQ(c.yaw, 0.5f);
  EXPECT_EQ(c.pitch, -0.25f);
  Mat4 v = c.view();
  for (auto& row : v.m)
    for (float x : row) EXPECT_TRUE(std::isfinite(x));
}

// --- sizes --------------------------------------------------------------------------------------

// A small scene (a cube in the middle), at any size.
void render_small_scene(Renderer& r, Shading shading = Shading::Phong) {
  Scene scene = one_object(std::make_shared<Mesh>(make_cube(1.5f)), shading);
  scene.object(0).transform.rotation = {0.4f, 0.6f, 0};
  r.render(scene);
}

TEST(Hostile, OneByOnePixel) {
  for (int ssaa : {1, 2, 4}) {
    Renderer r(1, 1);
    r.options.ssaa = ssaa;
    render_small_scene(r);
    Image img = r.color_image();
    ASSERT_EQ(img.width, 1);
    ASSERT_EQ(img.height, 1);
    EXPECT_NE(at(img, 0, 0), kBlack);  // the cube covers the one pixel centre
    EXPECT_EQ(r.depth_image().width, 1);
  }
}

// Colour, depth and stencil bytes of a w x h sample buffer: stored in whole 64x64 tiles
// (framebuffer.hpp), so a 1-pixel-high image holds 64 rows.
size_t framebuffer_bytes(int w, int h) { return size_t((w + 63) / 64 * 64) * size_t((h + 63) / 64 * 64) * 9; }

TEST(Hostile, ThinAndLargeFramebuffers) {
  // Odd sizes, so that the middle of the view is a pixel centre: the cube is under a
  // pixel tall when the frame is 1 pixel high.
  for (auto [w, h] : {std::pair{1, 4095}, std::pair{4095, 1}, std::pair{2048, 2048}, std::pair{16383, 3}}) {
    Renderer r(w, h);
    r.options.threads = 4;
    render_small_scene(r);
    Image img = r.color_image();
    EXPECT_EQ(img.width, w);
    EXPECT_EQ(img.height, h);
    EXPECT_GT(count_not(img, kBlack), 0u) << w << "x" << h;
    EXPECT_EQ(r.framebuffer_bytes(), framebuffer_bytes(w, h));
  }
}

TEST(Hostile, LargestFramebuffer16384Squared) {
  // 16384x16384: 1 GiB of colour, 1 GiB of depth, 256 MiB of stencil, plus a 1 GiB image out.
  if (big_allocations_are_slow())
    GTEST_SKIP() << "skipped under ThreadSanitizer and valgrind (a 2 GiB framebuffer is too much for their "
                    "shadow memory); the normal and ASan runs cover it";
  Renderer r(16384, 16384);
  EXPECT_EQ(r.framebuffer_bytes(), size_t(16384) * 16384 * 9);
  r.options.threads = 0;  // every core
  render_small_scene(r, Shading::Flat);
  Image img = r.color_image();
  ASSERT_EQ(img.width, 16384);
  ASSERT_EQ(img.height, 16384);
  EXPECT_NE(at(img, 8192, 8192), kBlack);  // the cube, in the middle
  EXPECT_EQ(at(img, 0, 0), kBlack);
  EXPECT_EQ(at(img, 16383, 16383), kBlack);
}

TEST(Hostile, ZeroNegativeAndOversizedSizesAreErrors) {
  for (auto [w, h] : {std::pair{0, 10}, std::pair{10, 0}, std::pair{-1, 10}, std::pair{10, -5}, std::pair{0, 0},
                      std::pair{16385, 1}, std::pair{1, 16385}, std::pair{INT32_MIN, INT32_MIN},
                      std::pair{INT32_MAX, INT32_MAX}})
    EXPECT_THROW(Renderer(w, h), Error) << w << "x" << h;

  Renderer r(32, 24);
  for (auto [w, h] : {std::pair{0, 10}, std::pair{-3, 10}, std::pair{20000, 10}}) {
    EXPECT_THROW(r.resize(w, h), Error);
    EXPECT_EQ(r.width(), 32);  // unchanged
    EXPECT_EQ(r.height(), 24);
  }
  // Super-sampling out of range, or making the sample buffer too large, is refused at
  // the frame and changes nothing.
  for (int ssaa : {0, -1, 5}) {
    r.options.ssaa = ssaa;
    EXPECT_THROW(render_small_scene(r), Error) << "ssaa " << ssaa;
  }
  Renderer wide(8192, 16);
  wide.options.ssaa = 3;  // 24576 samples wide
  EXPECT_THROW(render_small_scene(wide), Error);
  EXPECT_EQ(wide.framebuffer_bytes(), framebuffer_bytes(8192, 16));
  wide.options.ssaa = 2;  // 16384: fine
  render_small_scene(wide);
  EXPECT_EQ(wide.color_image().width, 8192);

  for (auto [w, h] : {std::pair{0, 1}, std::pair{1, -1}, std::pair{65537, 1}}) EXPECT_THROW(Image(w, h), Error);
}

// Runs `body` in a child process whose address space is limited to `limit` bytes, so
// that large allocations fail there (and only there). Returns the child's exit code.
[[maybe_unused]] int run_with_address_space_limit(size_t limit, const std::function<int()>& body) {
  pid_t pid = fork();
  if (pid == 0) {
    rlimit r{limit, limit};
    setrlimit(RLIMIT_AS, &r);
    int rc = 99;
    try {
      rc = body();
    } catch (...) {
      rc = 98;  // anything but velocity::Error escaped
    }
    std::_Exit(rc);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Hostile, OutOfMemoryIsAVelocityErrorAndChangesNothing) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "skipped under the sanitizers: they reserve terabytes of address space, so an address-space "
                  "limit cannot make one allocation fail (the normal build and valgrind run it)";
#else
  if (big_allocations_are_slow()) GTEST_SKIP() << "skipped under valgrind, which manages the address space itself";
  // 768 MiB of address space: a 16384x16384 framebuffer (2 GiB) cannot be allocated.
  int rc = run_with_address_space_limit(size_t(768) << 20, [] {
    try {
      Renderer r(16384, 16384);
      return 1;  // allocated?
    } catch (const Error& e) {
      if (!std::strstr(e.what(), "cannot allocate")) return 2;
    }
    Renderer r(64, 48);
    try {
      r.resize(16384, 16384);
      return 3;
    } catch (const Error&) {
    }
    if (r.width() != 64 || r.height() != 48 || r.framebuffer_bytes() != framebuffer_bytes(64, 48)) return 4;
    render_small_scene(r);  // still works
    if (r.color_image().width != 64) return 5;
    try {
      Image big(65536, 65536);  // 16 GiB
      return 6;
    } catch (const Error& e) {
      if (!std::strstr(e.what(), "cannot allocate")) return 7;
    }
    return 0;
  });
  EXPECT_EQ(rc, 0) << "1: allocated, 2: wrong message, 3: resize allocated, 4: size changed, 5: broken after, "
                      "6: image allocated, 7: wrong image message, 98: another exception, >128: a signal";
#endif
}

TEST(Hostile, ARendererStillWorksAfterErrors) {
  Renderer r(40, 30);
  EXPECT_THROW(r.resize(0, 0), Error);
  r.options.ssaa = 7;
  EXPECT_THROW(render_small_scene(r), Error);
  r.options.ssaa = 2;
  render_small_scene(r);
  EXPECT_GT(count_not(r.color_image(), kBlack), 100u);
}

}  // namespace
}  // namespace velocity
