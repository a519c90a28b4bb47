#include "raster/rasterize.hpp"

#include <cmath>

#include "framebuffer/framebuffer.hpp"
#include "geometry/lighting.hpp"
#include "raster/coverage.hpp"

namespace velocity::raster {

namespace {

struct TileTarget {
  uint32_t* color;
  float* depth;
  int stride;
  PixelRect rect;
};

// --- shaders: what a kernel computes per pixel, given the interpolated values.

struct FlatShader {
  uint32_t color;
  FlatShader(const TriangleSetup& t, const DrawState&, const FramePrimitives&) : color(t.flat_color) {}
  void begin(float, float) {}
  uint32_t shade() const { return color; }
  void step() {}
};

// Perspective-correct interpolation of N varyings: each plane holds varying / w, and
// 1 / w is interpolated alongside, so varying = plane(x, y) / inv_w(x, y).
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
};

struct SmoothShader {
  Varyings<3> in;
  SmoothShader(const TriangleSetup& t, const DrawState&, const FramePrimitives&) : in(t) {}
  void begin(float fx, float fy) { in.begin(fx, fy); }
  uint32_t shade() const {
    float w = in.w();
    return pack_rgba(in.v[0] * w, in.v[1] * w, in.v[2] * w);
  }
  void step() { in.step(); }
};

struct PhongShader {
  Varyings<kPhongVaryings> in;
  const DrawState& draw;
  const geometry::EyeLights& lights;
  PhongShader(const TriangleSetup& t, const DrawState& d, const FramePrimitives& f)
      : in(t), draw(d), lights(*f.lights) {}
  void begin(float fx, float fy) { in.begin(fx, fy); }
  uint32_t shade() const {
    float w = in.w();
    Vec3 base{in.v[0] * w, in.v[1] * w, in.v[2] * w};
    Vec3 n = normalize(Vec3{in.v[3], in.v[4], in.v[5]});  // w cancels in the normalisation
    Vec3 p{in.v[6] * w, in.v[7] * w, in.v[8] * w};
    Vec3 c = geometry::apply(geometry::light(lights, n, p, draw.specular, draw.shininess), base);
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
        color[x] = shader.shade();
      }
      z += t.depth.dx;
      shader.step();
    }
  });
}

using TriangleFn = void (*)(const TriangleSetup&, const FramePrimitives&, const TileTarget&);

template <bool kDepthTest>
constexpr TriangleFn kTriangleKernels[] = {
    &draw_triangle<kDepthTest, FlatShader>,
    &draw_triangle<kDepthTest, SmoothShader>,
    &draw_triangle<kDepthTest, PhongShader>,
};

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
