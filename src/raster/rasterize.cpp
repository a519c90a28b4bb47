#include "raster/rasterize.hpp"

#include <cmath>
#include <iterator>

#include "framebuffer/framebuffer.hpp"
#include "geometry/lighting.hpp"
#include "raster/coverage.hpp"
#include "raster/sampler.hpp"

namespace velocity::raster {

namespace {

struct TileTarget {
  uint32_t* color;
  float* depth;
  int stride;
  PixelRect rect;
};

// --- shaders: what a kernel computes per pixel, given the interpolated values.
// Each has begin(fx, fy) at a span's first pixel (offsets from the set-up's anchor),
// shade(x) per pixel and step() to the next pixel on the right.

// Perspective-correct interpolation of N varyings: each plane holds varying / w, and
// 1 / w is interpolated alongside, so varying = plane(x, y) / inv_w(x, y). In affine
// mode the set-up made 1 / w constant, so the same code interpolates linearly.
template <int N>
struct Varyings {
  const TriangleSetup& t;
  float inv_w, dinv_w;
  float v[N], dv[N];
  explicit Varyings(const TriangleSetup& s) : t(s) {}
  void begin(float fx, float fy) {
    inv_w = t.inv_w.c + t.inv_w.dx * fx + t.inv_w.dy * fy;
    dinv_w = t.inv_w.dx;
    for (int i = 0; i < N; ++i) v[i] = t.var[i].c + t.var[i].dx * fx + t.var[i].dy * fy, dv[i] = t.var[i].dx;
  }
  void step() {
    inv_w += dinv_w;
    for (int i = 0; i < N; ++i) v[i] += dv[i];
  }
  float w() const { return 1.0f / inv_w; }
  // Varying i at this pixel, and its screen-space derivatives: d(V/Q) = (dV - (V/Q) dQ) / Q.
  float value(int i, float w_) const { return v[i] * w_; }
  float ddx(int i, float value_, float w_) const { return (dv[i] - value_ * dinv_w) * w_; }
  float ddy(int i, float value_, float w_) const { return (t.var[i].dy - value_ * t.inv_w.dy) * w_; }
};

// The level of detail of a texture addressed by varyings iu, iv: computed once per 2x2
// pixel quad (at the quad's first pixel in the span), from the analytic screen-space
// derivatives of the perspective-correct uv.
template <Filter F, int N>
struct UvLookup {
  const Texture& tex;
  bool repeat;
  float lod = 0;
  template <class In>
  Rgba operator()(const In& in, int iu, int iv, int x, bool first, float w) {
    float u = in.value(iu, w), v = in.value(iv, w);
    if constexpr (F == Filter::Trilinear) {
      if (first || !(x & 1))
        lod = level_of_detail(tex, in.ddx(iu, u, w), in.ddx(iv, v, w), in.ddy(iu, u, w), in.ddy(iv, v, w));
    }
    return sample<F>(tex, u, v, lod, repeat);
  }
};

// Flat and Gouraud kernels sample one texture at per-vertex uvs: the base texture, or
// else the environment map (uvs from the per-vertex normal; clamped, never wrapped).
inline const Texture& per_vertex_texture(const DrawState& d) { return d.texture ? *d.texture : *d.env_map; }

struct FlatShader {
  uint32_t color;
  FlatShader(const TriangleSetup& t, const DrawState&, const FramePrimitives&) : color(t.flat_color) {}
  void begin(float, float) {}
  uint32_t shade(int) { return color; }
  void step() {}
};

struct SmoothShader {
  Varyings<3> in;
  SmoothShader(const TriangleSetup& t, const DrawState&, const FramePrimitives&) : in(t) {}
  void begin(float fx, float fy) { in.begin(fx, fy); }
  uint32_t shade(int) {
    float w = in.w();
    return pack_rgba(in.v[0] * w, in.v[1] * w, in.v[2] * w);
  }
  void step() { in.step(); }
};

// The constant colour (lit per face, or white for "replace") times the texture.
template <Filter F>
struct FlatTexShader {
  Varyings<2> in;
  Rgba color;
  UvLookup<F, 2> lookup;
  bool first = true;
  FlatTexShader(const TriangleSetup& t, const DrawState& d, const FramePrimitives&)
      : in(t), color(unpack(t.flat_color)), lookup{per_vertex_texture(d), d.texture && d.repeat} {}
  void begin(float fx, float fy) { in.begin(fx, fy), first = true; }
  uint32_t shade(int x) {
    Rgba c = lookup(in, 0, 1, x, first, in.w());
    first = false;
    return pack_rgba(color.r * c.r, color.g * c.g, color.b * c.b);
  }
  void step() { in.step(); }
};

// Gouraud's lit colour times the texture (OpenGL's GL_MODULATE).
template <Filter F>
struct SmoothTexShader {
  Varyings<5> in;
  UvLookup<F, 5> lookup;
  bool first = true;
  SmoothTexShader(const TriangleSetup& t, const DrawState& d, const FramePrimitives&)
      : in(t), lookup{per_vertex_texture(d), d.texture && d.repeat} {}
  void begin(float fx, float fy) { in.begin(fx, fy), first = true; }
  uint32_t shade(int x) {
    float w = in.w();
    Rgba c = lookup(in, 3, 4, x, first, w);
    first = false;
    return pack_rgba(in.v[0] * w * c.r, in.v[1] * w * c.g, in.v[2] * w * c.b);
  }
  void step() { in.step(); }
};

// Per-pixel lighting; optionally a base texture (uv) and a sphere environment map
// (addressed by the normal: u = 0.5 + 0.5 Nx, v = 0.5 + 0.5 Ny).
template <Filter F, bool kTex, bool kEnv>
struct PhongShader {
  static constexpr int N = (kTex || kEnv) ? kPhongTexVaryings : kPhongVaryings;
  Varyings<N> in;
  const DrawState& draw;
  const geometry::EyeLights& lights;
  float tex_lod = 0, env_lod = 0;
  bool first = true;
  PhongShader(const TriangleSetup& t, const DrawState& d, const FramePrimitives& f)
      : in(t), draw(d), lights(*f.lights) {}
  void begin(float fx, float fy) { in.begin(fx, fy), first = true; }

  static Vec2 env_uv(Vec3 n_plane) {
    Vec3 n = normalize(n_plane);
    return {0.5f + 0.5f * n.x, 0.5f + 0.5f * n.y};
  }

  uint32_t shade(int x) {
    float w = in.w();
    Vec3 base{in.v[0] * w, in.v[1] * w, in.v[2] * w};
    Vec3 n_plane{in.v[3], in.v[4], in.v[5]};  // the normal / w: w cancels in normalising
    Vec3 n = normalize(n_plane);
    Vec3 p{in.v[6] * w, in.v[7] * w, in.v[8] * w};
    const bool new_quad = first || !(x & 1);
    if constexpr (kTex) {
      float u = in.value(9, w), v = in.value(10, w);
      if (F == Filter::Trilinear && new_quad)
        tex_lod = level_of_detail(*draw.texture, in.ddx(9, u, w), in.ddx(10, v, w), in.ddy(9, u, w), in.ddy(10, v, w));
      Rgba c = sample<F>(*draw.texture, u, v, tex_lod, draw.repeat);
      base = base * Vec3{c.r, c.g, c.b};
    }
    if constexpr (kEnv) {
      Vec2 e = env_uv(n_plane);
      if (F == Filter::Trilinear && new_quad) {
        // Finite differences to the right and below, as a GPU's pixel quad would.
        const auto& t = in.t;
        Vec2 ex = env_uv({in.v[3] + in.dv[3], in.v[4] + in.dv[4], in.v[5] + in.dv[5]});
        Vec2 ey = env_uv({in.v[3] + t.var[3].dy, in.v[4] + t.var[4].dy, in.v[5] + t.var[5].dy});
        env_lod = level_of_detail(*draw.env_map, ex.x - e.x, ex.y - e.y, ey.x - e.x, ey.y - e.y);
      }
      Rgba c = sample<F>(*draw.env_map, e.x, e.y, env_lod, false);
      base = base + (Vec3{c.r, c.g, c.b} - base) * draw.env_mix;
    }
    first = false;
    Vec3 c = geometry::apply(geometry::light(lights, n, p, draw.specular), base);
    return pack_rgba(c.x, c.y, c.z);
  }
  void step() { in.step(); }
};

// --- the triangle kernel: spans from the coverage walk, depth test, shade.

template <bool kDepthTest, class Shader>
void draw_triangle(const TriangleSetup& t, const FramePrimitives& f, const TileTarget& target) {
  Shader shader(t, f.draws[t.draw], f);
  for_each_span(t, target.rect, [&](int y, int x_first, int x_last) {
    uint32_t* color = target.color + size_t(y) * target.stride;
    float* depth = target.depth + size_t(y) * target.stride;
    const float fx = float(x_first - t.min_x), fy = float(y - t.min_y);
    float z = t.depth.c + t.depth.dx * fx + t.depth.dy * fy;
    shader.begin(fx, fy);
    for (int x = x_first; x <= x_last; ++x) {
      if (!kDepthTest || z < depth[x]) {
        if constexpr (kDepthTest) depth[x] = z;
        color[x] = shader.shade(x);
      }
      z += t.depth.dx;
      shader.step();
    }
  });
}

using TriangleFn = void (*)(const TriangleSetup&, const FramePrimitives&, const TileTarget&);

// One entry per (kernel, filter), indexed by kernel_id().
template <bool D, class S>
constexpr TriangleFn fn = &draw_triangle<D, S>;
template <bool D, template <Filter> class S>
constexpr TriangleFn kFiltered[3] = {fn<D, S<Filter::Nearest>>, fn<D, S<Filter::Bilinear>>, fn<D, S<Filter::Trilinear>>};
template <Filter F>
using PhongPlain = PhongShader<F, false, false>;
template <Filter F>
using PhongTex = PhongShader<F, true, false>;
template <Filter F>
using PhongEnv = PhongShader<F, false, true>;
template <Filter F>
using PhongTexEnv = PhongShader<F, true, true>;

template <bool D>
constexpr TriangleFn kTriangleKernels[] = {
    fn<D, FlatShader>,       fn<D, FlatShader>,       fn<D, FlatShader>,        // Flat
    fn<D, SmoothShader>,     fn<D, SmoothShader>,     fn<D, SmoothShader>,      // Smooth
    kFiltered<D, PhongPlain>[0],  kFiltered<D, PhongPlain>[1],  kFiltered<D, PhongPlain>[2],
    kFiltered<D, FlatTexShader>[0], kFiltered<D, FlatTexShader>[1], kFiltered<D, FlatTexShader>[2],
    kFiltered<D, SmoothTexShader>[0], kFiltered<D, SmoothTexShader>[1], kFiltered<D, SmoothTexShader>[2],
    kFiltered<D, PhongTex>[0],    kFiltered<D, PhongTex>[1],    kFiltered<D, PhongTex>[2],
    kFiltered<D, PhongEnv>[0],    kFiltered<D, PhongEnv>[1],    kFiltered<D, PhongEnv>[2],
    kFiltered<D, PhongTexEnv>[0], kFiltered<D, PhongTexEnv>[1], kFiltered<D, PhongTexEnv>[2],
};
static_assert(std::size(kTriangleKernels<true>) == size_t(Kernel::Count) * 3);

template <bool kDepthTest>
inline void plot(const TileTarget& target, int x, int y, float z, uint32_t color) {
  size_t i = size_t(y) * target.stride + x;
  if (kDepthTest) {
    if (!(z < target.depth[i])) return;
    target.depth[i] = z;
  }
  target.color[i] = color;
}

// Lines are sampled once per column (x-major) or row (y-major) at pixel centres along
// the major axis, over the half-open range [start, end): OpenGL's diamond-exit rule in
// effect, so two lines meeting at a vertex do not both draw it.
template <bool kDepthTest>
void draw_line(const LineSetup& l, const TileTarget& target) {
  const PixelRect& r = target.rect;
  float dx = l.x1 - l.x0, dy = l.y1 - l.y0;
  bool x_major = std::fabs(dx) >= std::fabs(dy);
  float a0 = x_major ? l.x0 : l.y0, a1 = x_major ? l.x1 : l.y1;  // major axis
  float b0 = x_major ? l.y0 : l.x0, b1 = x_major ? l.y1 : l.x1;  // minor axis
  float z0 = l.z0, z1 = l.z1;
  if (a1 < a0) std::swap(a0, a1), std::swap(b0, b1), std::swap(z0, z1);
  float len = a1 - a0;
  if (!(len > 0)) return;
  int lo = int(std::ceil(a0 - 0.5f)), hi = int(std::ceil(a1 - 0.5f)) - 1;
  lo = std::max(lo, x_major ? r.x0 : r.y0);
  hi = std::min(hi, (x_major ? r.x1 : r.y1) - 1);
  for (int a = lo; a <= hi; ++a) {
    float s = (float(a) + 0.5f - a0) / len;
    int b = int(std::floor(b0 + s * (b1 - b0)));
    int x = x_major ? a : b, y = x_major ? b : a;
    if (x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1) continue;
    plot<kDepthTest>(target, x, y, z0 + s * (z1 - z0), l.color);
  }
}

template <bool kDepthTest>
void run_commands(const FramePrimitives& f, const std::vector<uint32_t>& commands, const TileTarget& target) {
  for (uint32_t c : commands) {
    uint32_t i = command_index(c);
    switch (command_kind(c)) {
      case CommandKind::Triangle: {
        const TriangleSetup& t = f.triangles[i];
        kTriangleKernels<kDepthTest>[t.kernel](t, f, target);
        break;
      }
      case CommandKind::Line: draw_line<kDepthTest>(f.lines[i], target); break;
      case CommandKind::Point: {
        const PointSetup& p = f.points[i];
        if (p.x >= target.rect.x0 && p.x < target.rect.x1 && p.y >= target.rect.y0 && p.y < target.rect.y1)
          plot<kDepthTest>(target, p.x, p.y, p.z, p.color);
        break;
      }
    }
  }
}

}  // namespace

void rasterize_tile(const FramePrimitives& frame, const Bins& bins, int tile, const TileSettings& settings,
                    Framebuffer& fb) {
  TileTarget target{fb.color.data(), fb.depth.data(), fb.width, bins.rect(tile)};
  const PixelRect& r = target.rect;
  for (int y = r.y0; y < r.y1; ++y) {
    size_t row = size_t(y) * fb.width;
    std::fill(&fb.color[row + r.x0], &fb.color[row + r.x1], settings.clear_color);
    std::fill(&fb.depth[row + r.x0], &fb.depth[row + r.x1], 1.0f);
  }
  if (settings.depth_test)
    run_commands<true>(frame, bins.commands(tile), target);
  else
    run_commands<false>(frame, bins.commands(tile), target);
}

}  // namespace velocity::raster
