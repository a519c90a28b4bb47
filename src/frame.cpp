// The frame, top to bottom. Renderer::draw only records and plans a draw; end_frame
// runs the pipeline on every core:
//
//   vertex stage    chunks of vertices: transform, project, snap, light   (all cores)
//   triangle stage  chunks of triangles: reject, cull, clip, set up, bin  (all cores,
//                   each worker into its own arena and tile lists)
//   (painter's mode: sort every record far to near, then bin)
//   tiles           clear, then each record in submission order: coverage, shading
//                   kernel, depth, colour                                  (all cores)
//
// Jobs are numbered in submission order and tiles merge the workers' lists by job, so
// the image is the same for any number of threads.
#include <algorithm>
#include <chrono>
#include <deque>
#include <new>
#include <unordered_set>

#include "core/thread_pool.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/resolve.hpp"
#include "geometry/vertex_stage.hpp"
#include "raster/bins.hpp"
#include "raster/rasterize.hpp"
#include "shading/lighting.hpp"
#include "triangle/stage.hpp"
#include "velocity/error.hpp"
#include "velocity/log.hpp"
#include "velocity/renderer.hpp"

namespace velocity {

namespace {

// Work sizes: big enough that a job's overhead is nothing, small enough that every core
// gets a share of one large mesh. Fixed, so that the jobs (and hence the image) do not
// depend on the thread count.
constexpr uint32_t kVerticesPerJob = 8192;
using triangle::kTrianglesPerJob;
// Meshes up to this many vertices are tested against the view volume by their bounding
// sphere first; larger ones go straight to the vertex stage, whose region codes reject
// their triangles (a bounding sphere costs a pass over every vertex each frame).
constexpr size_t kSphereTestMaxVertices = 16384;

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

template <class T>
void grow(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace

struct Renderer::Impl {
  int width = 0, height = 0;  // the output size
  int ssaa = 1;               // samples per output pixel, per side
  Framebuffer framebuffer;    // the samples: width * ssaa x height * ssaa
  raster::Bins bins;
  std::unique_ptr<ThreadPool> pool;

  // The frame being recorded.
  triangle::DrawList plan;
  std::vector<raster::DrawState> draw_states;
  std::vector<triangle::Job> jobs;
  std::deque<std::vector<Vec3>> averaged_normals;  // for meshes that bring none, reused (stable addresses)
  size_t averaged_used = 0;
  Material default_material;
  Mat4 view, projection, view_projection;
  FrameStart start;
  FrameStats stats;
  bool in_frame = false;

  // Per worker, reused across frames.
  std::vector<FrameStats> worker_stats;
  std::vector<std::vector<uint32_t>> survivors;  // per worker: the triangle stage's scratch
  std::vector<std::vector<uint8_t>> marks;       // per worker: vertices drawn as points
  std::unordered_set<const Mesh*> warned_meshes;  // meshes already warned about

  ThreadPool& pool_for(int threads) {
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, 256);
    if (!pool || pool->size() != threads) pool = std::make_unique<ThreadPool>(threads);
    if (bins.workers() != threads || bins.tiles_x() != framebuffer.tiles_x || bins.tiles_y() != framebuffer.tiles_y)
      bins.resize(framebuffer.width, framebuffer.height, threads);
    return *pool;
  }

  // Sizes the sample buffers for an output size and super-sampling factor. Throws
  // velocity::Error (and changes nothing) when either is out of range.
  void resize(int w, int h, int k) {
    if (k < 1 || k > 4) throw Error("super-sampling factor " + std::to_string(k) + " is out of range (1..4)");
    if (w < 1 || h < 1 || w > kMaxFramebufferSide || h > kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                  std::to_string(kMaxFramebufferSide) + " a side)");
    if (int64_t(w) * k > kMaxFramebufferSide || int64_t(h) * k > kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(k) + "x" +
                  std::to_string(k) + " super-sampling needs a sample buffer over " +
                  std::to_string(kMaxFramebufferSide) + " a side");
    if (w == width && h == height && k == ssaa && framebuffer.width == w * k) return;
    // Bins first, then the framebuffer, which reuses its buffers when they are large
    // enough (a program switching sizes or super-sampling factors allocates nothing)
    // and otherwise allocates new ones before it lets go of the old: when memory runs
    // out (velocity::Error) the renderer keeps its old size and buffers. Bins sized for
    // another framebuffer are sized again by pool_for before they are used.
    try {
      bins.resize(w * k, h * k, std::max(bins.workers(), 1));
    } catch (const std::bad_alloc&) {
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + ": out of memory for the tile bins");
    }
    framebuffer.resize(w * k, h * k);
    width = w, height = h, ssaa = k;
  }

  // The vertex stage's outputs for every draw, in one set of arrays.
  void allocate_vertices() {
    triangle::DrawList& p = plan;
    size_t total = 0;
    bool light = false, specular = false, normal = false, eye = false;
    for (auto& d : p.meshes) {
      d.vertex_base = total, total += d.mesh->positions.size();
      light |= d.light, specular |= d.vertex_specular_terms, normal |= d.normal, eye |= d.eye;
    }
    for (auto& b : p.batches) b.vertex_base = total, total += b.batch.vertex_count;
    triangle::VertexArrays& v = p.vertices;
    try {
      grow(v.projected, total), grow(v.codes, total);
      if (light) grow(v.diffuse, total);
      if (specular) grow(v.specular, total);
      if (normal) grow(v.normal, total);
      if (eye) grow(v.eye, total);
    } catch (const std::bad_alloc&) {
      throw Error("frame: out of memory for " + std::to_string(total) + " vertices");
    }
  }

  // The vertex stage, on every core.
  struct VertexJob {
    bool batch;
    uint32_t draw;
    size_t begin, end;
  };
  std::vector<VertexJob> vertex_jobs;  // reused across frames
  std::vector<size_t> nonfinite;       // per mesh draw, reused
  std::vector<Mat4> world;             // render(scene)'s matrices, reused

  void vertex_stage(ThreadPool& pool) {
    std::vector<VertexJob>& work = vertex_jobs;
    work.clear();
    for (uint32_t i = 0; i < plan.meshes.size(); ++i)
      for (size_t b = 0, n = plan.meshes[i].mesh->positions.size(); b < n; b += kVerticesPerJob)
        work.push_back({false, i, b, std::min<size_t>(b + kVerticesPerJob, n)});
    for (uint32_t i = 0; i < plan.batches.size(); ++i)
      for (size_t b = 0, n = plan.batches[i].batch.vertex_count; b < n; b += kVerticesPerJob)
        work.push_back({true, i, b, std::min<size_t>(b + kVerticesPerJob, n)});
    triangle::VertexArrays& va = plan.vertices;
    pool.run(int(work.size()), [&](int i) {
      const VertexJob& w = work[size_t(i)];
      if (w.batch) {
        const triangle::BatchDrawPlan& b = plan.batches[w.draw];
        geometry::ClipVertexJob job;
        job.positions = b.batch.position, job.begin = w.begin, job.end = w.end, job.viewport = b.viewport;
        job.out.projected = va.projected.data() + b.vertex_base, job.out.codes = va.codes.data() + b.vertex_base;
        geometry::project_clip_vertices(job);
        return;
      }
      const triangle::MeshDrawPlan& d = plan.meshes[w.draw];
      geometry::MeshVertexJob job;
      job.positions = d.mesh->positions.data(), job.normals = d.normals->data();
      job.begin = w.begin, job.end = w.end;
      job.mvp = d.mvp, job.model_view = d.model_view, job.normal_matrix = d.normal_matrix;
      job.viewport = plan.viewport;
      const size_t base = d.vertex_base;
      job.out.projected = va.projected.data() + base, job.out.codes = va.codes.data() + base;
      if (d.light) {
        job.lights = &plan.lights, job.specular = d.vertex_specular;
        job.out.diffuse = va.diffuse.data() + base;
        if (d.vertex_color) job.base_color = &d.uniform_color;
        if (d.vertex_specular_terms) job.out.specular = va.specular.data() + base;
      }
      if (d.normal) job.out.normal = va.normal.data() + base;
      if (d.eye) job.out.eye = va.eye.data() + base;
      geometry::transform_mesh_vertices(job);
    });
  }

  // The triangle stage, on every core: each worker sets up and bins into its own bins.
  void triangle_stage(ThreadPool& pool, bool painter_mode) {
    bins.clear(painter_mode);
    const int workers = pool.size();
    worker_stats.assign(size_t(workers), FrameStats{});
    survivors.resize(size_t(workers));
    for (auto& s : survivors) s.resize(3 * kTrianglesPerJob);
    marks.resize(size_t(workers));
    // Points mark the vertices they drew: room for the largest such mesh on every worker,
    // whichever worker its jobs fall on.
    size_t most = 0;
    for (const auto& d : plan.meshes)
      if (!d.fill_only) most = std::max(most, d.mesh->positions.size());
    for (auto& m : marks)
      if (m.size() < most) m.resize(most);
    const int width = framebuffer.width, height = framebuffer.height;
    pool.run(int(jobs.size()), [&](int i, int worker) {
      triangle::Job& job = jobs[size_t(i)];
      triangle::StageContext cx{bins.worker(worker), worker_stats[size_t(worker)]};
      cx.job = uint32_t(i);
      cx.direct = survivors[size_t(worker)].data();
      cx.info = cx.direct + kTrianglesPerJob, cx.clipped = cx.info + kTrianglesPerJob;
      cx.marks = &marks[size_t(worker)];
      switch (job.kind) {
        case triangle::Job::Kind::Mesh: run_mesh_job(plan, plan.meshes[job.draw], job.begin, job.end, cx); break;
        case triangle::Job::Kind::Batch: run_batch_job(plan, plan.batches[job.draw], job.begin, job.end, cx); break;
        case triangle::Job::Kind::Clear: run_clear_job(plan.clears[job.draw], width, height, cx); break;
      }
      job.nonfinite = cx.nonfinite;
    });
  }

  const FrameStats& run_frame(bool painter);
};

const char* simd_target() { return raster::simd_target(); }

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
  const Framebuffer& fb = impl_->framebuffer;
  return fb.color.size() * sizeof(uint32_t) + fb.depth.size() * sizeof(float) + fb.ids.size() * sizeof(uint32_t);
}
namespace {

// Calls rows(y0, y1) for bands of an image's `height` rows, on `pool` when there is one
// (the read-back is memory-bound: both cores' bandwidth). Bands of 64 rows, a tile row
// of samples without super-sampling.
template <class Rows>
void for_row_bands(ThreadPool* pool, int height, Rows&& rows) {
  constexpr int kBand = 64;
  const int bands = (height + kBand - 1) / kBand;
  auto band = [&](int b) { rows(b * kBand, std::min(height, (b + 1) * kBand)); };
  if (pool) {
    pool->run(bands, band);
  } else {
    for (int b = 0; b < bands; ++b) band(b);
  }
}

}  // namespace

void Renderer::read_color(uint8_t* rgba, size_t row_bytes, int channels) const {
  if (channels != 3 && channels != 4) throw Error("Renderer::read_color: channels must be 3 or 4, not " + std::to_string(channels));
  const Impl& r = *impl_;
  for_row_bands(r.pool.get(), r.height, [&](int y0, int y1) {
    resolve_color_rows(r.framebuffer, r.ssaa, rgba, row_bytes, channels, y0, y1);
  });
}

std::vector<float> Renderer::window_depth() const {
  std::vector<float> d(size_t(impl_->width) * size_t(impl_->height));
  read_window_depth(d.data());
  return d;
}

void Renderer::read_window_depth(float* out) const {
  const Impl& r = *impl_;
  for_row_bands(r.pool.get(), r.height, [&](int y0, int y1) { resolve_window_depth_rows(r.framebuffer, r.ssaa, out, y0, y1); });
}

std::vector<uint32_t> Renderer::object_ids() const { return resolve_object_ids(impl_->framebuffer, impl_->ssaa); }

std::vector<float> Renderer::view_depth() const {
  std::vector<float> d(size_t(impl_->width) * size_t(impl_->height));
  read_view_depth(d.data());
  return d;
}

void Renderer::read_view_depth(float* out) const {
  // Window depth d = 0.5 z_ndc + 0.5 with z_ndc = (P22 z + P23) / (P32 z + P33) for the
  // eye-space z: solved for z, in double (the projection's own inverse, so it is exact
  // for perspective and orthographic cameras alike up to float depth).
  const Impl& r = *impl_;
  const Mat4& p = r.projection;
  const double p22 = p.m[2][2], p23 = p.m[2][3], p32 = p.m[3][2], p33 = p.m[3][3];
  const size_t w = size_t(r.width);
  for_row_bands(r.pool.get(), r.height, [&](int y0, int y1) {
    resolve_window_depth_rows(r.framebuffer, r.ssaa, out, y0, y1);
    float* d = out + size_t(y0) * w;
    const size_t n = size_t(y1 - y0) * w;
    for (size_t i = 0; i < n; ++i) {  // no branch: the compiler vectorises it
      const double ndc = 2.0 * double(d[i]) - 1.0;
      const float z = float((ndc * p33 - p23) / (ndc * p32 - p22));
      d[i] = d[i] < 1.0f ? z : 0.0f;
    }
  });
}

void Renderer::begin_frame(const Camera& camera, const std::vector<Light>& lights, Vec3 clear_color) {
  FrameStart start;
  start.color = {clear_color.x, clear_color.y, clear_color.z, 1.0f};
  begin_frame(camera, lights, start);
}

void Renderer::begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start) {
  Impl& r = *impl_;
  r.resize(r.width, r.height, options.ssaa);  // follows a change of options.ssaa
  r.framebuffer.keep_ids(options.object_ids);
  const int w = r.framebuffer.width, h = r.framebuffer.height;
  triangle::DrawList& p = r.plan;
  p.width = w, p.height = h;
  const Mat4 view = camera.view();
  r.view = view;
  r.projection = camera.projection_matrix(float(w) / float(h));
  r.view_projection = r.projection * view;
  p.viewport = geometry::viewport_map(0, 0, w, h, 0.0f, 1.0f);
  p.guard = p.viewport.guard;
  shading::eye_lights(view, lights, p.lights);
  p.options = options;
  p.mesh_setup = {};
  p.mesh_setup.x1 = p.mesh_setup.px1 = w - 1;
  p.mesh_setup.y1 = p.mesh_setup.py1 = h - 1;
  p.mesh_setup.affine = options.affine;
  p.meshes.clear(), p.batches.clear(), p.clears.clear(), p.slots.clear();
  r.draw_states.clear();
  r.jobs.clear();
  r.averaged_used = 0;
  r.start = start;
  r.stats = {};
  r.in_frame = true;
}

void Renderer::draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) try {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::draw called outside begin_frame/end_frame");
  r.stats.objects++;
  if (mesh.triangles.empty()) return;
  // Whole-object rejection: a bounding sphere entirely outside one plane of the view
  // volume costs one test instead of a pass over every vertex.
  if (mesh.positions.size() <= kSphereTestMaxVertices && Frustum(r.view_projection).outside(world_sphere(mesh, world)))
    return void(r.stats.objects_culled++);
  triangle::DrawList& p = r.plan;
  triangle::MeshDrawPlan d;
  d.mesh = &mesh;
  d.override_material = material;
  d.object_id = object_id;
  d.model_view = r.view * world;
  d.mvp = r.projection * d.model_view;
  d.normal_matrix = normal_matrix(d.model_view);
  if (!mesh.normals.empty()) {
    d.normals = &mesh.normals;
  } else {
    // Normals averaged over the faces sharing each vertex (area-weighted), for meshes
    // built by hand; loaders compute normals once (compute_normals, smoothing groups).
    if (r.averaged_used == r.averaged_normals.size()) r.averaged_normals.emplace_back();
    std::vector<Vec3>& n = r.averaged_normals[r.averaged_used++];
    n.assign(mesh.positions.size(), Vec3{});
    for (const Triangle& t : mesh.triangles) {
      Vec3 a = mesh.positions[t.v[0]], b = mesh.positions[t.v[1]], c = mesh.positions[t.v[2]];
      Vec3 fn = cross(b - a, c - a);
      for (uint32_t v : t.v) n[v] += fn;
    }
    d.normals = &n;  // normalised when transformed to eye space
  }
  triangle::plan_mesh_draw(p, r.draw_states, d, material, r.default_material);
  const uint32_t index = uint32_t(p.meshes.size());
  p.meshes.push_back(d);
  const size_t nt = mesh.triangles.size();
  for (size_t b = 0; b < nt; b += kTrianglesPerJob)
    r.jobs.push_back({triangle::Job::Kind::Mesh, index, uint32_t(b), uint32_t(std::min(b + kTrianglesPerJob, nt))});
} catch (const std::bad_alloc&) {
  throw Error("Renderer::draw: out of memory recording mesh '" + mesh.name + "'");
}

void Renderer::draw(const PrimitiveBatch& batch, const PixelState& state) try {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::draw called outside begin_frame/end_frame");
  const uint32_t k = batch.kind == PrimitiveKind::Triangles ? 3 : batch.kind == PrimitiveKind::Lines ? 2 : 1;
  if (batch.vertex_count && !batch.position) throw Error("Renderer::draw: a primitive batch needs positions");
  if (batch.indices && batch.index_count % k)
    throw Error("Renderer::draw: " + std::to_string(batch.index_count) + " indices do not make whole primitives of " +
                std::to_string(k) + " vertices");
  const uint32_t primitives = batch.indices ? batch.index_count / k : batch.vertex_count / k;
  r.stats.objects++;
  if (primitives == 0) return;
  triangle::DrawList& p = r.plan;
  triangle::BatchDrawPlan d;
  d.batch = batch;
  d.primitive_count = primitives;
  d.textured = state.texture.texture != nullptr;
  d.fog = state.fog;
  d.kernel = raster::fixed_kernel(d.textured, d.fog);
  d.num_varyings = raster::fixed_varyings(d.textured, d.fog);

  // The viewport, within the guard band's reach of the framebuffer (as OpenGL's
  // GL_MAX_VIEWPORT_DIMS bounds it).
  const int fw = p.width, fh = p.height;
  const Viewport& v = batch.viewport;
  const int vw = v.width > 0 ? std::min(v.width, kMaxFramebufferSide) : fw;
  const int vh = v.height > 0 ? std::min(v.height, kMaxFramebufferSide) : fh;
  const int vx = v.width > 0 ? std::clamp(v.x, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  const int vy = v.height > 0 ? std::clamp(v.y, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  d.viewport = geometry::viewport_map(vx, vy, vw, vh, std::clamp(v.depth_near, 0.0f, 1.0f), std::clamp(v.depth_far, 0.0f, 1.0f));
  // Triangles stay inside the viewport (the view volume's sides are not clipped, they
  // are this box); points and wide lines may reach past it by half their size.
  triangle::SetupParams& s = d.setup;
  int sx0 = 0, sy0 = 0, sx1 = fw - 1, sy1 = fh - 1;
  if (state.scissor) {
    sx0 = std::max(sx0, state.scissor_x0), sy0 = std::max(sy0, state.scissor_y0);
    sx1 = std::min(sx1, state.scissor_x1 - 1), sy1 = std::min(sy1, state.scissor_y1 - 1);
  }
  s.x0 = std::max(sx0, vx), s.y0 = std::max(sy0, vy), s.x1 = std::min(sx1, vx + vw - 1), s.y1 = std::min(sy1, vy + vh - 1);
  const int reach = int(std::max(batch.point_size, batch.line_width) * 0.5f) + 1;
  s.px0 = std::max(sx0, vx - reach), s.py0 = std::max(sy0, vy - reach);
  s.px1 = std::min(sx1, vx + vw - 1 + reach), s.py1 = std::min(sy1, vy + vh - 1 + reach);
  s.offset = state.polygon_offset;
  s.offset_factor = state.offset_factor, s.offset_units = state.offset_units;

  raster::DrawState st;
  st.pixel = state;
  if (d.textured) st.texture = raster::SamplerView(*state.texture.texture, state.texture.sampler);
  d.draw_state = uint32_t(r.draw_states.size());
  r.draw_states.push_back(st);
  const uint32_t index = uint32_t(p.batches.size());
  p.batches.push_back(d);
  for (uint32_t b = 0; b < primitives; b += kTrianglesPerJob)
    r.jobs.push_back({triangle::Job::Kind::Batch, index, b, std::min(b + kTrianglesPerJob, primitives)});
} catch (const std::bad_alloc&) {
  throw Error("Renderer::draw: out of memory recording a primitive batch");
}

void Renderer::clear(const ClearRequest& request) {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::clear called outside begin_frame/end_frame");
  triangle::ClearPlan c{request, 0, 0, r.plan.width - 1, r.plan.height - 1};
  if (request.scissor) {
    c.x0 = std::max(c.x0, request.x0), c.y0 = std::max(c.y0, request.y0);
    c.x1 = std::min(c.x1, request.x1 - 1), c.y1 = std::min(c.y1, request.y1 - 1);
  }
  const uint32_t index = uint32_t(r.plan.clears.size());
  r.plan.clears.push_back(c);
  r.jobs.push_back({triangle::Job::Kind::Clear, index, 0, 1});
}

const FrameStats& Renderer::end_frame() {
  Impl& r = *impl_;
  if (!r.in_frame) throw Error("Renderer::end_frame called without begin_frame");
  r.in_frame = false;
  try {
    return r.run_frame(options.depth_mode == DepthMode::Painter);
  } catch (const std::bad_alloc&) {
    throw Error("Renderer::end_frame: out of memory");
  }
}

const FrameStats& Renderer::Impl::run_frame(bool painter) {
  Impl& r = *this;
  ThreadPool& pool = r.pool_for(r.plan.options.threads);

  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const Clock::time_point t0 = Clock::now();
  r.allocate_vertices();
  r.vertex_stage(pool);
  const Clock::time_point t1 = Clock::now();
  r.triangle_stage(pool, painter);
  if (painter) r.bins.bin_deferred();
  const Clock::time_point t2 = Clock::now();

  raster::TileInputs frame;
  frame.bins = &r.bins;
  frame.draws = &r.draw_states;
  frame.lights = &r.plan.lights;
  frame.depth_test = !painter;
  frame.clear_color = r.start.clear_color, frame.clear_depth = r.start.clear_depth;
  frame.color = raster::pack_rgba(r.start.color.x, r.start.color.y, r.start.color.z, r.start.color.w);
  frame.depth = std::clamp(r.start.depth, 0.0f, 1.0f);
  r.framebuffer.expect_clear(frame.color, frame.depth);
  pool.run(r.bins.tile_count(), [&](int tile) { raster::rasterize_tile(frame, tile, r.framebuffer); });
  const Clock::time_point t3 = Clock::now();
  r.stats.vertex_ms = ms(t0, t1), r.stats.triangle_ms = ms(t1, t2), r.stats.tile_ms = ms(t2, t3);

  // The frame's statistics, and one warning per mesh with non-finite vertices (not one
  // per frame, nor per triangle). The set only grows with distinct bad meshes; a
  // long-running program that makes new ones forever forgets them now and then (and
  // may warn again) rather than grow.
  for (const FrameStats& w : r.worker_stats) {
    FrameStats& s = r.stats;
    s.objects_culled += w.objects_culled, s.triangles += w.triangles, s.triangles_rejected += w.triangles_rejected;
    s.triangles_nonfinite += w.triangles_nonfinite, s.triangles_clipped += w.triangles_clipped;
    s.triangles_culled += w.triangles_culled, s.triangles_rasterized += w.triangles_rasterized;
    s.lines += w.lines, s.points += w.points;
  }
  std::vector<size_t>& bad = r.nonfinite;
  bad.assign(r.plan.meshes.size(), 0);
  for (const triangle::Job& j : r.jobs)
    if (j.kind == triangle::Job::Kind::Mesh) bad[j.draw] += j.nonfinite;
  for (size_t i = 0; i < bad.size(); ++i) {
    if (!bad[i]) continue;
    const Mesh* mesh = r.plan.meshes[i].mesh;
    if (r.warned_meshes.size() >= 4096) r.warned_meshes.clear();
    if (r.warned_meshes.insert(mesh).second)
      warn("mesh '" + mesh->name + "': " + std::to_string(bad[i]) + " triangles with NaN or infinite coordinates were dropped");
  }
  return r.stats;
}

const FrameStats& Renderer::render(const Scene& scene) {
  begin_frame(scene.camera, scene.lights, scene.background);
  std::vector<Mat4>& world = impl_->world;
  scene.world_matrices(world);
  const auto& objects = scene.objects();
  for (size_t i = 0; i < objects.size(); ++i) {
    const Object& o = objects[i];
    if (!o.visible || !o.mesh) continue;
    draw(*o.mesh, world[i], o.material ? &*o.material : nullptr, uint32_t(i + 1));
  }
  return end_frame();
}

}  // namespace velocity
