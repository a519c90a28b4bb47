// Shadow maps (RenderOptions::shadows) on scenes whose shadows are known exactly: a box
// standing on a plane, seen from straight above, lit by a directional, a spot and a point
// light. Each pixel of the plane is classed by casting a ray from the point it shows
// towards the light against the box (here, not by the renderer); the pixels whose
// neighbourhood (2 pixels, or a few texels of a coarse map) is all of one class must be exactly what the renderer draws without
// shadows (lit: no acne) or without that light (shadowed: the shadow is there, up to the
// box's contact edge: no peter-panning).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "image_test_util.hpp"
#include "velocity/error.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;

namespace {

constexpr int kSize = 160;        // the image, square
constexpr float kView = 12.0f;    // world units across it
const Vec3 kBoxMin{-1, 0, -1}, kBoxMax{1, 2, 1};

// Where a ray o + t d first enters the box kBoxMin..kBoxMax for t in (t0, t1); false: it
// misses.
bool hits_box(Vec3 o, Vec3 d, float t0, float t1) {
  const float oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
  const float lo[3] = {kBoxMin.x, kBoxMin.y, kBoxMin.z}, hi[3] = {kBoxMax.x, kBoxMax.y, kBoxMax.z};
  for (int a = 0; a < 3; ++a) {
    if (dd[a] == 0) {
      if (oo[a] < lo[a] || oo[a] > hi[a]) return false;
      continue;
    }
    float ta = (lo[a] - oo[a]) / dd[a], tb = (hi[a] - oo[a]) / dd[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// An orthographic camera straight above the origin.
Camera above() {
  Camera c;
  c.position = {0, 20, 0};
  c.projection = Projection::Orthographic;
  c.ortho_height = kView;
  c.near = 1, c.far = 40;
  c.look_at({0, 0, 0});
  return c;
}

// The world point of the plane y = 0 under pixel (i, j) of above(): the pixel centre
// taken back through the camera's matrices.
Vec3 plane_point(int i, int j) {
  static const Mat4 inverse = [] {
    Mat4 m;
    const Camera c = above();
    invert(c.projection_matrix(1.0f) * c.view(), m);
    return m;
  }();
  const float x = (float(i) + 0.5f) / kSize * 2 - 1, y = 1 - (float(j) + 0.5f) / kSize * 2;
  const Vec4 a = inverse * Vec4{x, y, -1, 1}, b = inverse * Vec4{x, y, 1, 1};
  const Vec3 p = a.xyz() * (1 / a.w), q = b.xyz() * (1 / b.w);
  return p + (q - p) * (p.y / (p.y - q.y));
}

enum class Class { Box, Lit, Shadow };

struct Frames {
  Image on, off, unlit;  // shadows on; off; without the light (ambient only)
};

Frames render_box_scene(const Light& light, Shading shading, int map_size, int threads = 0) {
  const Mesh plane = make_plane_grid(kView, 1);
  const Mesh box = make_cube(2.0f);
  Material m;
  m.color = {0.8f, 0.8f, 0.8f};
  m.shading = shading;
  if (shading == Shading::Pbr) m.pbr.metallic = 0, m.pbr.roughness = 0.6f;
  const Light ambient = Light::ambient({0.15f, 0.15f, 0.15f});
  auto draw = [&](const std::vector<Light>& lights, bool shadows) {
    Renderer r(kSize, kSize);
    r.options.color = ColorPipeline::Display;
    r.options.shadows = shadows;
    r.options.shadow_map_size = map_size;
    r.options.threads = threads;
    r.begin_frame(above(), lights, {0, 0, 0});
    r.draw(plane, Mat4::identity(), &m);
    r.draw(box, translate({0, 1, 0}), &m);
    r.end_frame();
    return r.color_image();
  };
  return Frames{draw({ambient, light}, true), draw({ambient, light}, false), draw({ambient}, false)};
}

struct Tally {
  int lit = 0, shadow = 0, box = 0;
  int acne = 0, missing = 0, box_acne = 0;  // lit pixels darkened; shadow pixels lit; the box's top darkened
  int contact = 0, contact_gap = 0;         // shadow pixels touching the box, and those of them not dark
};

// Classes every pixel (`to_light(p)`: the direction and reach, 1 or infinite, of the ray
// from a plane point to the light) and checks the sure ones.
// A lit point of the plane closer to the box's walls than the bias moves a lookup (a
// few texels: `margin`, world units) may read the wall's depth; those are left out.
// Pixels are checked where the class is the same `margin` (at least 2 pixels) around.
template <class ToLight>
Tally check(const Frames& f, float margin, ToLight to_light) {
  Class cls[kSize][kSize];
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      const Vec3 p = plane_point(i, j);
      if (p.x > kBoxMin.x && p.x < kBoxMax.x && p.z > kBoxMin.z && p.z < kBoxMax.z) {
        cls[j][i] = Class::Box;
        continue;
      }
      float reach;
      const Vec3 d = to_light(p, reach);
      cls[j][i] = hits_box(p, d, 1e-4f, reach) ? Class::Shadow : Class::Lit;
    }
  auto diff = [](const Image& a, const Image& b, int i, int j) {
    int m = 0;
    for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(int(a.pixel(i, j)[c]) - int(b.pixel(i, j)[c])));
    return m;
  };
  // Sure: every pixel within `r` is of the same class, r = 2 pixels or, for a coarse map,
  // the margin (the shadow's edge is drawn within a few texels of where it belongs).
  const int r = std::max(2, int(std::ceil(margin / (kView / kSize))));
  Tally t;
  for (int j = r; j < kSize - r; ++j)
    for (int i = r; i < kSize - r; ++i) {
      const Class c = cls[j][i];
      bool sure = true, touches_box = false;
      for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
          const Class n = cls[j + y][i + x];
          if (n == Class::Box) touches_box = touches_box || (std::abs(x) <= 1 && std::abs(y) <= 1);
          else if (c != Class::Box && n != c) sure = false;
          else if (c == Class::Box) sure = sure && n == Class::Box;
        }
      if (!sure) continue;
      if (c == Class::Lit) {
        const Vec3 p = plane_point(i, j);
        const float dx = std::max({kBoxMin.x - p.x, p.x - kBoxMax.x, 0.0f}), dz = std::max({kBoxMin.z - p.z, p.z - kBoxMax.z, 0.0f});
        if (std::sqrt(dx * dx + dz * dz) < margin) continue;
      }
      if (c == Class::Box) {
        t.box++;
        t.box_acne += diff(f.on, f.off, i, j) > 0;
      } else if (c == Class::Lit) {
        t.lit++;
        t.acne += diff(f.on, f.off, i, j) > 0;
      } else {
        t.shadow++;
        const bool dark = diff(f.on, f.unlit, i, j) <= 1;
        t.missing += !dark;
        if (touches_box) t.contact++, t.contact_gap += !dark;
      }
    }
  return t;
}

// Three and a half texels of a map `size` texels a side over the scene (about 18 units
// across: the plane's diagonal).
float margin(int size) { return 3.5f * 18.0f / float(size); }

void expect_clean(const Tally& t, std::string_view what) {
  SCOPED_TRACE(std::string(what));
  EXPECT_GT(t.lit, 2000);
  EXPECT_GT(t.shadow, 400);
  EXPECT_GT(t.box, 200);
  EXPECT_EQ(t.acne, 0) << "lit plane pixels darker than without shadows";
  EXPECT_EQ(t.box_acne, 0) << "pixels of the box's top darker than without shadows";
  EXPECT_EQ(t.missing, 0) << "shadowed pixels with light on them";
  EXPECT_GT(t.contact, 20);
  EXPECT_EQ(t.contact_gap, 0) << "pixels between the box and its shadow";
}

}  // namespace

// A directional light low over the plane (the box's shadow reaches 4 units): its
// orthographic map, in Phong (per pixel) and PBR.
TEST(Shadows, DirectionalBoxOnPlane) {
  const Vec3 towards = normalize({1.0f, 0.9f, 0.45f});
  const Light sun = Light::directional(towards, {0.8f, 0.8f, 0.8f});
  for (Shading s : {Shading::Phong, Shading::Pbr}) {
    const Frames f = render_box_scene(sun, s, 1024);
    const Tally t = check(f, margin(1024), [&](Vec3, float& reach) {
      reach = 1e9f;
      return towards;
    });
    expect_clean(t, to_string(s));
  }
}

// The default map size (2048) and a small one (256) are as clean: the bias scales with
// the texel.
TEST(Shadows, BiasHoldsAtEveryMapSize) {
  const Vec3 towards = normalize({-0.6f, 1.0f, 0.8f});
  const Light sun = Light::directional(towards, {0.8f, 0.8f, 0.8f});
  for (int size : {256, 2048}) {
    const Tally t = check(render_box_scene(sun, Shading::Phong, size), margin(size), [&](Vec3, float& reach) {
      reach = 1e9f;
      return towards;
    });
    expect_clean(t, size == 256 ? "256" : "2048");
  }
}

// A spot light's perspective map: the shadow fans out from the light.
TEST(Shadows, SpotBoxOnPlane) {
  const Vec3 at{3.5f, 4.5f, 1.5f};
  Light spot = Light::spot(at, at, {30, 30, 30}, 0.6f, 0.9f);  // pointing at the origin
  spot.falloff = Falloff::InverseSquare;
  for (Shading s : {Shading::Phong, Shading::Pbr}) {
    const Tally t = check(render_box_scene(spot, s, 1024), margin(1024), [&](Vec3 p, float& reach) {
      reach = 1;
      return at - p;
    });
    expect_clean(t, to_string(s));
  }
}

// A point light's cube map: the plane around it falls into five of its six faces.
TEST(Shadows, PointBoxOnPlane) {
  const Vec3 at{2.5f, 3.5f, -2.0f};
  Light point = Light::point(at, {30, 30, 30});
  point.falloff = Falloff::InverseSquare;
  for (Shading s : {Shading::Phong, Shading::Pbr}) {
    const Tally t = check(render_box_scene(point, s, 1024), margin(1024), [&](Vec3 p, float& reach) {
      reach = 1;
      return at - p;
    });
    expect_clean(t, to_string(s));
  }
}

// The maps are drawn by the frame's pipeline on its threads: the image is the same for
// any number of them.
TEST(Shadows, ShadowsAreTheSameForAnyThreadCount) {
  const Light sun = Light::directional(normalize({1.0f, 0.9f, 0.45f}), {0.8f, 0.8f, 0.8f});
  const Frames one = render_box_scene(sun, Shading::Phong, 512, 1);
  const Frames four = render_box_scene(sun, Shading::Phong, 512, 4);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) ASSERT_EQ(test::at(one.on, i, j), test::at(four.on, i, j)) << i << ", " << j;
}

// One renderer's maps are kept between frames while casters, lights and camera stay
// (CpuBackend::ShadowKey); each kind of change below draws them again: every frame must
// be what a new renderer draws of the same scene, and the changes must show.
TEST(Shadows, KeptMapsFollowEveryChange) {
  const Mesh plane = make_plane_grid(kView, 1);
  Mesh box = make_cube(2.0f);
  Material m;
  m.color = {0.8f, 0.8f, 0.8f};
  m.shading = Shading::Phong;
  const Light ambient = Light::ambient({0.15f, 0.15f, 0.15f});
  Light sun = Light::directional(normalize({1.0f, 0.9f, 0.45f}), {0.8f, 0.8f, 0.8f});
  Mat4 box_at = translate({0, 1, 0});
  auto frame = [&](Renderer& r) {
    r.options.color = ColorPipeline::Display;
    r.options.shadows = true;
    r.options.shadow_map_size = 512;
    r.begin_frame(above(), {ambient, sun}, {0, 0, 0});
    r.draw(plane, Mat4::identity(), &m);
    r.draw(box, box_at, &m);
    r.end_frame();
    return r.color_image();
  };
  auto fresh = [&] {
    Renderer r(kSize, kSize);
    return frame(r);
  };
  auto differing = [](const Image& a, const Image& b) {
    int n = 0;
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) n += test::at(a, i, j) != test::at(b, i, j);
    return n;
  };
  Renderer kept(kSize, kSize);
  const Image first = frame(kept);
  EXPECT_EQ(differing(frame(kept), first), 0) << "the same scene again";
  sun = Light::directional(normalize({-1.0f, 0.8f, 0.3f}), {0.8f, 0.8f, 0.8f});
  Image now = frame(kept);
  EXPECT_GT(differing(now, first), 500) << "the light moved";
  EXPECT_EQ(differing(now, fresh()), 0) << "the light moved";
  box_at = translate({2, 1, 1});
  Image before = now;
  now = frame(kept);
  EXPECT_GT(differing(now, before), 500) << "the box moved";
  EXPECT_EQ(differing(now, fresh()), 0) << "the box moved";
  // The same mesh, its vertices moved in place (as an animation does) within the same
  // bounds, so that the maps' views stay: its top narrowed to a third.
  for (Vec3& p : box.positions)
    if (p.y > 0) p.x *= 0.3f, p.z *= 0.3f;
  before = now;
  now = frame(kept);
  EXPECT_GT(differing(now, before), 100) << "the box's vertices moved";
  EXPECT_EQ(differing(now, fresh()), 0) << "the box's vertices moved";
}

// A light that does not cast, or a frame without shadows: the image is the one without.
TEST(Shadows, OffOrNotCastingIsTheUnshadowedImage) {
  Light sun = Light::directional(normalize({1.0f, 0.9f, 0.45f}), {0.8f, 0.8f, 0.8f});
  sun.cast_shadows = false;
  const Frames f = render_box_scene(sun, Shading::Phong, 512);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) ASSERT_EQ(test::at(f.on, i, j), test::at(f.off, i, j)) << i << ", " << j;
}

// A sphere under a directional light shadows only itself, beyond its terminator: every
// pixel it lights at N.L above 0.1 (as the render without shadows shows) is untouched.
TEST(Shadows, SphereHasNoAcneOnItsLitSide) {
  const Mesh sphere = make_sphere(64);
  const Vec3 towards = normalize({0.7f, 0.5f, 0.5f});
  for (Shading s : {Shading::Phong, Shading::Pbr}) {
    Material m;
    m.color = {0.9f, 0.9f, 0.9f};
    m.shading = s;
    m.pbr.metallic = 0, m.pbr.roughness = 0.5f;
    auto draw = [&](bool shadows, Vec3 light) {
      Renderer r(200, 200);
      r.options.color = ColorPipeline::Display;
      r.options.shadows = shadows;
      Camera c;
      c.position = {0, 0, 3.2f};
      r.begin_frame(c, {Light::directional(towards, light)}, {0, 0, 0});
      r.draw(sphere, Mat4::identity(), &m);
      r.end_frame();
      return r.color_image();
    };
    const Image on = draw(true, {1, 1, 1}), off = draw(false, {1, 1, 1});
    int lit = 0, acne = 0, dark_side = 0;
    for (int j = 0; j < 200; ++j)
      for (int i = 0; i < 200; ++i) {
        const int g = off.pixel(i, j)[1];
        if (g > 0.1f * 0.9f * 255 + 2) {
          lit++;
          acne += test::at(on, i, j) != test::at(off, i, j);
        } else if (g > 0) {
          dark_side += on.pixel(i, j)[1] > g;  // a shadow never adds light
        }
      }
    EXPECT_GT(lit, 5000) << to_string(s);
    EXPECT_EQ(acne, 0) << to_string(s);
    EXPECT_EQ(dark_side, 0) << to_string(s);
  }
}

// A torus on its side, lit from along its axis's side: its far inner ring lies in the
// shadow of its near one, while the outside of the ring facing the light is clean.
TEST(Shadows, TorusShadowsItsOwnInnerRing) {
  const Mesh torus = make_torus(0.7f, 0.3f, 96, 48);
  Material m;
  m.color = {0.9f, 0.9f, 0.9f};
  m.shading = Shading::Phong;
  const Vec3 towards = normalize({1.0f, 0.25f, 0.3f});
  auto draw = [&](bool shadows) {
    Renderer r(240, 240);
    r.options.color = ColorPipeline::Display;
    r.options.shadows = shadows;
    Camera c;
    c.position = {0, 2.6f, 0.01f};
    c.look_at({0, 0, 0});
    r.begin_frame(c, {Light::ambient({0.1f, 0.1f, 0.1f}), Light::directional(towards, {0.9f, 0.9f, 0.9f})}, {0, 0, 0});
    r.draw(torus, Mat4::identity(), &m);
    r.end_frame();
    return r.color_image();
  };
  const Image on = draw(true), off = draw(false);
  int darker = 0, brighter = 0;
  for (int j = 0; j < 240; ++j)
    for (int i = 0; i < 240; ++i) {
      darker += on.pixel(i, j)[1] + 2 < off.pixel(i, j)[1];
      brighter += on.pixel(i, j)[1] > off.pixel(i, j)[1];
    }
  EXPECT_GT(darker, 300);  // the inner ring's far side
  EXPECT_EQ(brighter, 0);
}

// A MASK quad casts its cut-out, not its square: a 4x4 texture whose alpha spells an
// asymmetric pattern (no mirror or turn of it is the same) over a plane, the sun 27
// degrees above the plane so that the shadow falls beside the quad. Each plane pixel is
// classed by a ray to the sun through the quad's texel. The same with the alpha in the
// vertices (a ramp across x: the right half passes), and a BLEND quad, which casts as
// MASK at 0.5.
namespace {

// The quad: y = 2 over x, z in [-1.6, 1.6]; uv (0, 0) at (-1.6, -1.6) (u along x, v
// along z).
constexpr float kQuadY = 2.0f, kQuadHalf = 1.6f;
constexpr bool kCut[4][4] = {{1, 1, 1, 0}, {1, 0, 0, 0}, {1, 1, 0, 1}, {1, 0, 0, 1}};  // [v][u]: opaque

Mesh cut_out_quad(bool vertex_alpha) {
  Mesh q;
  const int n = vertex_alpha ? 8 : 1;  // a grid, so that the vertex alpha ramps across it
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = float(i) / n, v = float(j) / n;
      q.positions.push_back({kQuadHalf * (2 * u - 1), kQuadY, kQuadHalf * (2 * v - 1)});
      q.normals.push_back({0, 1, 0});
      q.uvs.push_back({u, v});
      if (vertex_alpha) q.alphas.push_back(u);  // alone, without Mesh::colors
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + uint32_t(n + 1);
      q.triangles.push_back({a, b, b + 1});  // counter-clockwise seen from above (+y)
      q.triangles.push_back({a, b + 1, a + 1});
    }
  return q;
}

// Whether the ray from plane point p to the sun passes through an opaque part of the
// quad, and whether it passes near an edge of one (within `near` world units).
bool quad_blocks(Vec3 p, Vec3 to_sun, bool vertex_alpha, float near, bool& unsure) {
  const Vec3 c = p + to_sun * ((kQuadY - p.y) / to_sun.y);
  const float u = (c.x + kQuadHalf) / (2 * kQuadHalf), v = (c.z + kQuadHalf) / (2 * kQuadHalf);
  auto opaque = [&](float uu, float vv) {
    if (uu < 0 || uu >= 1 || vv < 0 || vv >= 1) return false;
    return vertex_alpha ? uu >= 0.5f : kCut[int(vv * 4)][int(uu * 4)];
  };
  const bool o = opaque(u, v);
  const float e = near / (2 * kQuadHalf);  // world units to uv
  unsure = false;
  for (float du : {-e, 0.0f, e})
    for (float dv : {-e, 0.0f, e}) unsure = unsure || opaque(u + du, v + dv) != o;
  return o;
}

}  // namespace

TEST(Shadows, MaskMaterialsCastTheirCutOut) {
  Image alpha(4, 4);
  for (int v = 0; v < 4; ++v)
    for (int u = 0; u < 4; ++u) {
      // Opaque texels 200 or 255 alpha, cut ones 40 or 100: all on their side of 0.5.
      const uint8_t a = kCut[v][u] ? uint8_t(200 + 55 * ((u + v) & 1)) : uint8_t(40 + 60 * ((u + v) & 1));
      uint8_t* px = &alpha.pixels[size_t(v * 4 + u) * 4];
      px[0] = 200, px[1] = 180, px[2] = 160, px[3] = a;
    }
  const auto texture = std::make_shared<Texture>(alpha);
  const Vec3 to_sun = normalize({2.0f, 1.0f, 0.3f});
  const Light sun = Light::directional(to_sun, {0.8f, 0.8f, 0.8f});
  const Light ambient = Light::ambient({0.15f, 0.15f, 0.15f});
  const Mesh plane = make_plane_grid(kView, 1);
  Material floor;
  floor.shading = Shading::Pbr, floor.color = {0.8f, 0.8f, 0.8f}, floor.pbr.metallic = 0, floor.pbr.roughness = 0.6f;
  struct Case {
    const char* what;
    bool vertex_alpha;
    AlphaMode mode;
  };
  for (const Case& k : {Case{"texture alpha, MASK", false, AlphaMode::Mask}, Case{"vertex alpha, MASK", true, AlphaMode::Mask},
                        Case{"texture alpha, BLEND", false, AlphaMode::Blend}}) {
    SCOPED_TRACE(k.what);
    const Mesh quad = cut_out_quad(k.vertex_alpha);
    Material m = floor;
    m.alpha_mode = k.mode, m.alpha_cutoff = 0.5f, m.two_sided = true;
    m.filter = Filter::Nearest;
    if (!k.vertex_alpha) m.texture = texture;
    auto draw = [&](const std::vector<Light>& lights, bool shadows) {
      Renderer r(kSize, kSize);
      r.options.color = ColorPipeline::Display;
      r.options.shadows = shadows;
      r.options.shadow_map_size = 1024;
      r.begin_frame(above(), lights, {0, 0, 0});
      r.draw(plane, Mat4::identity(), &floor);
      r.draw(quad, Mat4::identity(), &m);
      r.end_frame();
      return r.color_image();
    };
    const Image on = draw({ambient, sun}, true), off = draw({ambient, sun}, false), unlit = draw({ambient}, false);
    auto diff = [](const Image& a, const Image& b, int i, int j) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixel(i, j)[c]) - int(b.pixel(i, j)[c])));
      return d;
    };
    int lit = 0, shadow = 0, acne = 0, missing = 0;
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) {
        const Vec3 p = plane_point(i, j);
        const float h = kQuadHalf + 0.2f;
        if (p.x > -h && p.x < h && p.z > -h && p.z < h) continue;  // under the quad in view
        bool unsure = false;
        // Two pixels, or 3.5 texels of the map, from an edge of the cut-out is unsure.
        const bool blocked = quad_blocks(p, to_sun, k.vertex_alpha, std::max(2 * kView / kSize, margin(1024)), unsure);
        if (unsure) continue;
        if (blocked) shadow++, missing += diff(on, unlit, i, j) > 1;
        else lit++, acne += diff(on, off, i, j) > 0;
      }
    EXPECT_GT(lit, 10000);
    EXPECT_GT(shadow, k.vertex_alpha ? 400 : 250);
    EXPECT_EQ(acne, 0) << "plane pixels darkened where the cut-out lets the light through";
    EXPECT_EQ(missing, 0) << "plane pixels lit where the cut-out's opaque part is in the way";
  }
}

TEST(Shadows, MapSizeOutOfRangeIsAnError) {
  Renderer r(16, 16);
  r.options.shadows = true;
  r.options.shadow_map_size = 8;
  try {
    r.begin_frame(Camera{}, {}, {0, 0, 0});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "shadow map size 8 is out of range (16..8192)");
  }
  r.options.shadow_map_size = 1 << 20;
  EXPECT_THROW(r.begin_frame(Camera{}, {}, {0, 0, 0}), Error);
  r.options.shadows = false;  // not read without shadows
  EXPECT_NO_THROW(r.begin_frame(Camera{}, {}, {0, 0, 0}));
}
