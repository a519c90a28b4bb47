// Renderer: the public promises (renderer.hpp), checked here once for every backend and
// forwarded to the one that draws (velocity/backend.hpp).
#include <memory>
#include <string>

#include "geometry/normals.hpp"
#include "velocity/backend.hpp"
#include "velocity/error.hpp"
#include "velocity/renderer.hpp"

namespace velocity {

// The normals output: the frame's mesh draws, recorded, and drawn again by end_frame with
// their normals as colours, by a backend of their own (the frame's buffers stay as
// they are).
struct Renderer::NormalsPass {
  bool active = false;  // the frame (being) drawn keeps normals
  Camera camera;
  std::vector<Light> lights;
  RenderOptions options;
  struct Draw {
    const Mesh* mesh;
    Mat4 world;
  };
  std::vector<Draw> draws;
  std::vector<Mesh> meshes;  // the draws' meshes with normals as colours
  std::unique_ptr<Backend> backend;

  // `choice`: the frame's own backend's kind (Cpu or Gpu), so that the normals cover
  // the same pixels as its depth.
  void run(int width, int height, BackendChoice choice) {
    if (!backend) {
      BackendChoice drawn_by;
      std::string reason;
      backend = make_backend(choice, width, height, drawn_by, reason);
    }
    backend->resize(width, height);
    RenderOptions o = options;
    o.object_ids = false;
    o.shading = Shading::Unlit;
    FrameStart start;
    start.color = {0.5f, 0.5f, 0.5f, 1.0f};  // the colour of a zero normal
    backend->begin_frame(camera, lights, start, o);
    meshes.resize(draws.size());
    const Mat4 view = camera.view();
    for (size_t i = 0; i < draws.size(); ++i) {
      geometry::normals_as_colors(*draws[i].mesh, view * draws[i].world, options.shading == Shading::Flat, meshes[i]);
      backend->draw(meshes[i], draws[i].world, nullptr, 0);
    }
    backend->end_frame();
  }
};

Renderer::Renderer(int width, int height, BackendChoice backend) : reason_(std::make_unique<std::string>()) {
  backend_ = make_backend(backend, width, height, drawn_by_, *reason_);
  stats_.backend = to_string(drawn_by_), stats_.backend_reason = reason_->c_str();
}
Renderer::Renderer(int width, int height, GlContextProvider& window, bool hardware_only)
    : reason_(std::make_unique<std::string>()) {
  backend_ = make_backend_on(window, width, height, hardware_only, *reason_);
  drawn_by_ = BackendChoice::Gpu;
  stats_.backend = to_string(drawn_by_), stats_.backend_reason = reason_->c_str();
}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::resize(int width, int height) { backend_->resize(width, height); }
int Renderer::width() const { return backend_->width(); }
int Renderer::height() const { return backend_->height(); }
const FrameStats& Renderer::stats() const { return stats_; }

void Renderer::begin_frame(const Camera& camera, const std::vector<Light>& lights, Vec3 clear_color) {
  FrameStart start;
  start.color = {clear_color.x, clear_color.y, clear_color.z, 1.0f};
  begin_frame(camera, lights, start);
}

void Renderer::begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start) {
  backend_->begin_frame(camera, lights, start, options);
  in_frame_ = true;
  if (options.normals) {
    if (!normals_) normals_ = std::make_unique<NormalsPass>();
    normals_->camera = camera, normals_->lights = lights, normals_->options = options;
    normals_->draws.clear();
  }
  if (normals_) normals_->active = options.normals;
}

void Renderer::draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) {
  if (!in_frame_) throw Error("Renderer::draw called outside begin_frame/end_frame");
  backend_->draw(mesh, world, material, object_id);
  if (normals_ && normals_->active) normals_->draws.push_back({&mesh, world});
}

void Renderer::draw(const PrimitiveBatch& batch, const PixelState& state) {
  if (!in_frame_) throw Error("Renderer::draw called outside begin_frame/end_frame");
  const uint32_t k = batch.kind == PrimitiveKind::Triangles ? 3 : batch.kind == PrimitiveKind::Lines ? 2 : 1;
  if (batch.vertex_count && !batch.position) throw Error("Renderer::draw: a primitive batch needs positions");
  if (batch.clip_planes > kMaxUserClipPlanes || (batch.clip_planes && batch.vertex_count && !batch.clip_distance))
    throw Error("Renderer::draw: " + std::to_string(batch.clip_planes) + " user clip planes (at most " +
                std::to_string(kMaxUserClipPlanes) + ", each with a distance per vertex)");
  if (batch.indices && batch.index_count % k)
    throw Error("Renderer::draw: " + std::to_string(batch.index_count) + " indices do not make whole primitives of " +
                std::to_string(k) + " vertices");
  backend_->draw(batch, state, batch.indices ? batch.index_count / k : batch.vertex_count / k);
}

void Renderer::clear(const ClearRequest& request) {
  if (!in_frame_) throw Error("Renderer::clear called outside begin_frame/end_frame");
  backend_->clear(request);
}

const FrameStats& Renderer::end_frame() {
  if (!in_frame_) throw Error("Renderer::end_frame called without begin_frame");
  in_frame_ = false;
  stats_ = backend_->end_frame();
  stats_.backend = to_string(drawn_by_), stats_.backend_reason = reason_->c_str();
  if (normals_ && normals_->active) normals_->run(width(), height(), drawn_by_);
  return stats_;
}

const FrameStats& Renderer::end_frame_into(uint8_t* rgba, size_t row_bytes, int channels) {
  if (!in_frame_) throw Error("Renderer::end_frame_into called without begin_frame");
  if (channels != 3 && channels != 4)
    throw Error("Renderer::end_frame_into: channels must be 3 or 4, not " + std::to_string(channels));
  // The normals overlay draws after the frame: read back after it.
  if (options.normals) {
    end_frame();
    read_color(rgba, row_bytes, channels);
    return stats_;
  }
  in_frame_ = false;
  stats_ = backend_->end_frame_into(rgba, row_bytes, channels);
  stats_.backend = to_string(drawn_by_), stats_.backend_reason = reason_->c_str();
  return stats_;
}

const FrameStats& Renderer::render(const Scene& scene) {
  begin_frame(scene.camera, scene.lights, scene.background);
  scene.world_matrices(world_);
  const auto& objects = scene.objects();
  for (size_t i = 0; i < objects.size(); ++i) {
    const Object& o = objects[i];
    if (!o.visible || !o.mesh) continue;
    draw(*o.mesh, world_[i], o.material ? &*o.material : nullptr, uint32_t(i + 1));
  }
  return end_frame();
}

void Renderer::present_window(int window_width, int window_height, const uint8_t* overlay) {
  if (in_frame_) throw Error("Renderer::present_window called inside a frame");
  if (window_width < 1 || window_height < 1) return;  // a minimised window: nothing to show
  backend_->present_window(window_width, window_height, overlay);
}

Image Renderer::color_image() const { return backend_->color_image(); }
Image Renderer::depth_image() const { return backend_->depth_image(); }
size_t Renderer::framebuffer_bytes() const { return backend_->framebuffer_bytes(); }

void Renderer::read_color(uint8_t* rgba, size_t row_bytes, int channels) const {
  if (channels != 3 && channels != 4) throw Error("Renderer::read_color: channels must be 3 or 4, not " + std::to_string(channels));
  backend_->read_color(rgba, row_bytes, channels);
}

std::vector<float> Renderer::view_depth() const {
  std::vector<float> d(size_t(width()) * size_t(height()));
  read_view_depth(d.data());
  return d;
}
void Renderer::read_view_depth(float* out) const { backend_->read_view_depth(out); }

std::vector<float> Renderer::window_depth() const {
  std::vector<float> d(size_t(width()) * size_t(height()));
  read_window_depth(d.data());
  return d;
}
void Renderer::read_window_depth(float* out) const { backend_->read_window_depth(out); }
void Renderer::read_stencil(uint8_t* out) const { backend_->read_stencil(out); }

std::vector<uint32_t> Renderer::object_ids() const { return backend_->object_ids(); }

void Renderer::read_normals(float* out) const {
  if (!normals_ || !normals_->active) throw Error("Renderer::read_normals: the frame was not drawn with options.normals");
  const size_t pixels = size_t(width()) * size_t(height());
  std::vector<uint8_t> rgba(pixels * 4);
  normals_->backend->read_color(rgba.data(), size_t(width()) * 4, 4);
  std::vector<float> depth(pixels);
  backend_->read_view_depth(depth.data());
  for (size_t i = 0; i < pixels; ++i) {
    const Vec3 n = depth[i] == 0 ? Vec3{} : geometry::normal_from_color(&rgba[i * 4]);
    out[i * 3] = n.x, out[i * 3 + 1] = n.y, out[i * 3 + 2] = n.z;
  }
}

}  // namespace velocity
