// The Python module's scene: pyrender's model of nodes (a mesh, a camera or a light, a
// pose, a parent), cameras and lights as pyrender defines them, and the frame built
// from it for the core Renderer. No Python here: module.cpp binds these types and
// builds a SceneCopy while holding the GIL, then renders it without.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "velocity/renderer.hpp"

namespace velocity::python {

// A pyrender Mesh: one or more parts (a loaded file's nodes), each with its pose in the
// mesh's frame. Immutable once made, so frames and threads share it freely.
struct MeshData {
  std::string name;
  std::vector<std::shared_ptr<const Mesh>> parts;
  std::vector<Mat4> poses;  // part -> mesh
  Sphere bounds;            // bounding sphere in the mesh's frame
};
std::shared_ptr<const MeshData> make_mesh_data(std::string name, std::vector<std::shared_ptr<const Mesh>> parts,
                                               std::vector<Mat4> poses);

// Cameras, as pyrender's: znear / zfar along the view axis; a missing zfar (perspective
// only) is fitted to the scene when a frame is built.
struct CameraBase {
  virtual ~CameraBase() = default;
  std::string name;
  double znear = 0.05;
  std::optional<double> zfar;
  // Sets the projection part of `camera` for a width x height image.
  virtual void apply(Camera& camera, int width, int height) const = 0;
  // Checks the parameters; throws velocity::Error with what is wrong (a perspective
  // camera's znear too small for the depth buffer at zfar included).
  virtual void validate() const;
  virtual bool perspective() const { return true; }
};
struct PerspectiveCamera : CameraBase {
  double yfov = 1.0;                   // radians
  std::optional<double> aspect_ratio;  // width / height; none: the image's
  void apply(Camera& camera, int width, int height) const override;
  void validate() const override;
};
struct OrthographicCamera : CameraBase {
  double xmag = 1.0, ymag = 1.0;  // half the view volume's width and height
  bool perspective() const override { return false; }
  void apply(Camera& camera, int width, int height) const override;
  void validate() const override;
};
struct IntrinsicsCamera : CameraBase {
  double fx = 1, fy = 1, cx = 0, cy = 0;  // pixels; see ViewWindow::pinhole
  void apply(Camera& camera, int width, int height) const override;
  void validate() const override;
};

// Lights, as pyrender's: colour times intensity. Velocity's lighting is Lambertian
// (colour = albedo * sum of lights * N.L); the intensity is divided by pi, the factor
// between a physically based diffuse BRDF (albedo / pi, as pyrender's shader) and that.
struct LightBase {
  virtual ~LightBase() = default;
  std::string name;
  Vec3 color{1, 1, 1};
  double intensity = 1.0;
  // Casts a shadow when the frame has shadows (RenderOptions::shadows, or a SHADOWS_*
  // render flag naming its type).
  bool cast_shadows = true;
  // The core light for a light at `world` (row-major 4x4).
  virtual Light make(const double world[16]) const = 0;
};
struct DirectionalLight : LightBase {  // shines along its pose's -Z
  Light make(const double world[16]) const override;
};
struct PointLight : LightBase {  // at its pose's origin, falling off as 1 / d^2
  std::optional<double> range;  // KHR_lights_punctual's cut-off distance; none: infinite
  Light make(const double world[16]) const override;
};
struct SpotLight : PointLight {  // a point light shining along its pose's -Z in a cone
  double inner_cone = 0, outer_cone = 0.7853981633974483;  // half-angles, radians
  Light make(const double world[16]) const override;
  // Throws velocity::Error unless 0 <= inner < outer <= pi/2.
  void validate() const;
};

struct NodeData {
  std::string name;
  std::shared_ptr<const MeshData> mesh;
  std::shared_ptr<CameraBase> camera;
  std::shared_ptr<LightBase> light;
  double pose[16];  // relative to the parent, row-major
  int64_t parent = -1;
  bool removed = false;
};

struct SceneData {
  std::vector<NodeData> nodes;  // node id = index + 1; parents come first
  double bg_color[4] = {1, 1, 1, 1};
  Vec3 ambient{0, 0, 0};
  int64_t main_camera = -1;  // index, or -1
  // Every node's world pose (row-major), parents applied.
  std::vector<std::array<double, 16>> world_poses() const;
};

// What one render needs, copied out of a scene (meshes shared, not copied), so that the
// render runs without the GIL while Python goes on, even changing the scene.
struct SceneCopy {
  Camera camera;
  std::vector<Light> lights;
  FrameStart start;
  struct Item {
    std::shared_ptr<const Mesh> mesh;
    Mat4 world;
    uint32_t id;  // the node's id, for the mask
  };
  std::vector<Item> items;
};

// Copies what a width x height image of the scene needs, seen from its main camera.
// Throws velocity::Error when there is no camera or a pose is not usable.
SceneCopy copy_scene(const SceneData& scene, int width, int height);

// Outputs of one render, top row first.
struct RenderOutput {
  // The colour went into RenderRequest::color_buffer (width * height * 4 bytes): RGBA,
  // or packed RGB in its first 3/4 when !alpha.
  // View-axis distance, 0 = nothing: into RenderRequest::depth_buffer when given, else here.
  std::vector<float> depth;
  std::vector<uint32_t> mask;   // node ids, 0 = nothing; empty if not asked
  std::vector<float> normals;   // width * height * 3, camera space; empty if not asked
  // What the engine was given: the frame's options and, per light of the frame (in the
  // scene's order, the ambient term last), whether it cast a shadow.
  RenderOptions options;
  std::vector<bool> cast_shadows;
};
struct RenderRequest {
  bool color = true, alpha = false, mask = false, normals = false;
  uint8_t* color_buffer = nullptr;  // width * height * 4 bytes, when color
  float* depth_buffer = nullptr;    // width * height floats, or null: RenderOutput::depth
  std::optional<Shading> shading;
  bool cull_back_faces = true;
  // Shadow maps for the lights of these types (pyrender's SHADOWS_* flags), besides those
  // of every light when the renderer's options.shadows is on.
  bool shadows_directional = false, shadows_point = false, shadows_spot = false;
  std::optional<ColorPipeline> color_pipeline;  // none: the renderer's options.color
};
RenderOutput render_frame(Renderer& renderer, const SceneCopy& frame, const RenderRequest& request);

// Colour buffers for a renderer's frames, handed back when numpy frees the array, so
// that a steady stream of frames allocates (and page-faults) nothing new. Thread-safe.
class BufferPool {
 public:
  std::unique_ptr<uint8_t[]> take(size_t bytes);
  void give(std::unique_ptr<uint8_t[]> buffer, size_t bytes);

 private:
  std::mutex mutex_;
  size_t bytes_ = 0;
  std::vector<std::unique_ptr<uint8_t[]>> free_;  // each bytes_ long; at most 4 kept
};

}  // namespace velocity::python
