// The frame, top to bottom: scene -> per-object culling -> geometry stage (transform,
// light, clip, set up) -> bin -> rasterize tiles -> framebuffer.
#include <algorithm>
#include <new>
#include <unordered_set>

#include "core/thread_pool.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/resolve.hpp"
#include "geometry/draw_mesh.hpp"
#include "raster/bins.hpp"
#include "raster/rasterize.hpp"
#include "velocity/error.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"

namespace velocity {

namespace {

// The convention's light when a scene brings none: white, from (0.3, 0.5, 1) in eye
// space, ambient 0.2, diffuse 0.8.
geometry::EyeLights default_lights() {
  geometry::EyeLights l;
  l.ambient = {0.2f, 0.2f, 0.2f};
  l.directional.push_back({normalize({0.3f, 0.5f, 1.0f}), {0.8f, 0.8f, 0.8f}});
  return l;
}

geometry::EyeLights eye_lights(const Mat4& view, const std::vector<Light>& lights) {
  if (lights.empty()) return default_lights();
  geometry::EyeLights l;
  for (const Light& light : lights) {
    switch (light.type) {
      case LightType::Ambient: l.ambient += light.color; break;
      case LightType::Directional:
        l.directional.push_back({normalize(view.transform_vector(light.direction)), light.color});
        break;
      case LightType::Point:
        l.point.push_back({view.transform_point(light.position), light.color, light.constant, light.linear,
                           light.quadratic});
        break;
    }
  }
  return l;
}

// The six planes of the view volume in world space (Gribb and Hartmann: rows of the
// view-projection matrix), normalised so that a sphere tests with one dot product.
struct Frustum {
  Vec4 planes[6];
  explicit Frustum(const Mat4& vp) {
    auto row = [&](int r) { return Vec4{vp.m[r][0], vp.m[r][1], vp.m[r][2], vp.m[r][3]}; };
    Vec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    Vec4 p[6] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
    for (int i = 0; i < 6; ++i) {
      float len = length(p[i].xyz());
      planes[i] = len > 0 ? p[i] * (1.0f / len) : p[i];
    }
  }
  bool outside(const Sphere& s) const {
    for (const Vec4& p : planes)
      if (dot(p.xyz(), s.center) + p.w < -s.radius) return true;
    return false;
  }
};

Sphere world_sphere(const Mesh& mesh, const Mat4& world) {
  Sphere s = mesh.bounding_sphere();
  float stretch = 0;
  for (int c = 0; c < 3; ++c) stretch = std::max(stretch, length({world.m[0][c], world.m[1][c], world.m[2][c]}));
  return {world.transform_point(s.center), s.radius * stretch};
}

}  // namespace

struct Renderer::Impl {
  int width = 0, height = 0;  // the output size
  int ssaa = 1;               // samples per output pixel, per side
  Framebuffer framebuffer;    // the samples: width * ssaa x height * ssaa
  raster::Bins bins;
  raster::FramePrimitives primitives;
  geometry::VertexScratch scratch;
  geometry::FrameParams params;
  Mat4 view_projection;
  uint32_t clear_color = 0;
  FrameStats stats;
  bool in_frame = false;
  std::unordered_set<const Mesh*> warned_meshes;  // meshes already warned about
  std::unique_ptr<ThreadPool> pool;

  ThreadPool& pool_for(int threads) {
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, 256);
    if (!pool || pool->size() != threads) pool = std::make_unique<ThreadPool>(threads);
    return *pool;
  }

  // Sizes the sample buffers for an output size and super-sampling factor. Throws
  // velocity::Error (and changes nothing) when either is out of range.
  void resize(int w, int h, int k) {
    if (k < 1 || k > 4) throw Error("super-sampling factor " + std::to_string(k) + " is out of range (1..4)");
    if (w < 1 || h < 1 || w > raster::kMaxFramebufferSide || h > raster::kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                  std::to_string(raster::kMaxFramebufferSide) + " a side)");
    if (int64_t(w) * k > raster::kMaxFramebufferSide || int64_t(h) * k > raster::kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(k) + "x" +
                  std::to_string(k) + " super-sampling needs a sample buffer over " +
                  std::to_string(raster::kMaxFramebufferSide) + " a side");
    if (w == width && h == height && k == ssaa && framebuffer.width == w * k) return;
    // Allocate first, then swap in: when memory runs out (Framebuffer::resize throws
    // velocity::Error; Bins::resize changes nothing if it throws) the renderer keeps its
    // old buffers and size, consistent with each other.
    Framebuffer next;
    next.resize(w * k, h * k);
    try {
      bins.resize(w * k, h * k);
    } catch (const std::bad_alloc&) {
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + ": out of memory for the tile bins");
    }
    framebuffer = std::move(next);
    width = w, height = h, ssaa = k;
  }
};

Renderer::Renderer(int width, int height) : impl_(std::make_unique<Impl>()) { impl_->resize(width, height, 1); }
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::resize(int width, int height) { impl_->resize(width, height, impl_->ssaa); }
int Renderer::width() const { return impl_->width; }
int Renderer::height() const { return impl_->height; }
const FrameStats& Renderer::stats() const { return impl_->stats; }
Image Renderer::color_image() const { return resolve_color(impl_->framebuffer, impl_->ssaa); }
Image Renderer::depth_image() const { return resolve_depth(impl_->framebuffer, impl_->ssaa); }
size_t Renderer::framebuffer_bytes() const {
  return impl_->framebuffer.color.size() * sizeof(uint32_t) + impl_->framebuffer.depth.size() * sizeof(float);
}

void Renderer::begin_frame(const Camera& camera, const std::vector<Light>& lights, Vec3 clear_color) {
  Impl& r = *impl_;
  r.resize(r.width, r.height, options.ssaa);  // follows a change of options.ssaa
  int w = r.framebuffer.width, h = r.framebuffer.height;
  r.params.view = camera.view();
  r.params.projection = camera.projection_matrix(float(w) / float(h));
  r.params.width = w, r.params.height = h;
  r.params.guard = geometry::GuardBand::for_viewport(w, h);
  r.params.lights = eye_lights(r.params.view, lights);
  r.params.options = options;
  r.view_projection = r.params.projection * r.params.view;
  r.clear_color = raster::pack_rgba(clear_color.x, clear_color.y, clear_color.z);
  r.primitives.clear();
  r.primitives.lights = &r.params.lights;
  r.stats = {};
  r.in_frame = true;
}

void Renderer::draw(const Mesh& mesh, const Mat4& world, const Material* material) {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::draw called outside begin_frame/end_frame");
  r.stats.objects++;
  if (mesh.triangles.empty()) return;
  // Whole-object rejection: a bounding sphere entirely outside one plane of the view
  // volume costs one test instead of a pass over every vertex.
  if (Frustum(r.view_projection).outside(world_sphere(mesh, world))) return void(r.stats.objects_culled++);
  size_t nonfinite_before = r.stats.triangles_nonfinite;
  geometry::draw_mesh(r.params, mesh, world, material, r.scratch, r.primitives, r.stats);
  // One warning per mesh with non-finite vertices (not one per frame, nor per triangle).
  // The set only grows with distinct bad meshes; a long-running program that makes new
  // ones forever forgets them now and then (and may warn again) rather than grow.
  if (r.stats.triangles_nonfinite > nonfinite_before) {
    if (r.warned_meshes.size() >= 4096) r.warned_meshes.clear();
    if (r.warned_meshes.insert(&mesh).second)
      warn("mesh '" + mesh.name + "': " + std::to_string(r.stats.triangles_nonfinite - nonfinite_before) +
           " triangles with NaN or infinite coordinates were dropped");
  }
}

const FrameStats& Renderer::end_frame() {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::end_frame called without begin_frame");
  r.in_frame = false;
  raster::FramePrimitives& prims = r.primitives;
  const bool painter = r.params.options.depth_mode == DepthMode::Painter;

  // Painter's mode: draw far to near by mean depth (seed 004's sort), stable so that
  // equal depths keep their submission order.
  if (painter) {
    auto key = [&](uint32_t c) {
      uint32_t i = raster::command_index(c);
      switch (raster::command_kind(c)) {
        case raster::CommandKind::Triangle: return prims.triangles[i].sort_key;
        case raster::CommandKind::Line: return prims.lines[i].sort_key;
        default: return prims.points[i].sort_key;
      }
    };
    std::stable_sort(prims.order.begin(), prims.order.end(), [&](uint32_t a, uint32_t b) { return key(a) > key(b); });
  }

  // Bin, in draw order, so that every tile list keeps that order.
  r.bins.clear();
  for (uint32_t c : prims.order) {
    uint32_t i = raster::command_index(c);
    switch (raster::command_kind(c)) {
      case raster::CommandKind::Triangle: {
        const auto& t = prims.triangles[i];
        r.bins.add(c, t.min_x, t.min_y, t.max_x, t.max_y);
        break;
      }
      case raster::CommandKind::Line: {
        const auto& l = prims.lines[i];
        r.bins.add(c, l.min_x, l.min_y, l.max_x, l.max_y);
        break;
      }
      case raster::CommandKind::Point: {
        const auto& p = prims.points[i];
        r.bins.add(c, p.x, p.y, p.x, p.y);
        break;
      }
    }
  }

  // Rasterize: tiles are independent (each reads the shared, now immutable, frame data
  // and writes only its own pixels), so they go to the thread pool as they come.
  raster::TileSettings settings{!painter, r.clear_color};
  ThreadPool& pool = r.pool_for(r.params.options.threads);
  pool.run(r.bins.tile_count(), [&](int tile) { raster::rasterize_tile(prims, r.bins, tile, settings, r.framebuffer); });
  return r.stats;
}

const FrameStats& Renderer::render(const Scene& scene) {
  begin_frame(scene.camera, scene.lights, scene.background);
  std::vector<Mat4> world = scene.world_matrices();
  const auto& objects = scene.objects();
  for (size_t i = 0; i < objects.size(); ++i) {
    const Object& o = objects[i];
    if (!o.visible || !o.mesh) continue;
    draw(*o.mesh, world[i], o.material ? &*o.material : nullptr);
  }
  return end_frame();
}

}  // namespace velocity
