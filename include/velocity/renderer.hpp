// The renderer: draws a Scene, or meshes one by one, into its framebuffer.
//
//   velocity::Renderer r(1280, 720);
//   r.render(scene);                     // clear, draw every visible object, resolve
//   velocity::write_png("out.png", r.color_image());
//
// A frame goes load -> scene -> transform (vertex lighting) -> cull and clip -> set-up
// -> bin to 64x64 tiles -> rasterize and shade each tile -> framebuffer. See
// docs/pipeline.md. What draws is a backend (velocity/backend.hpp): the CPU pipeline,
// or, when asked for, OpenGL 3.3 on a GPU (docs/gpu.md):
//
//   velocity::Renderer r(1280, 720, velocity::BackendChoice::Auto);  // a hardware GPU, else the CPU
//   std::printf("%s: %s\n", r.stats().backend, r.stats().backend_reason);
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "velocity/image.hpp"
#include "velocity/material.hpp"
#include "velocity/math.hpp"
#include "velocity/mesh.hpp"
#include "velocity/primitives.hpp"
#include "velocity/scene.hpp"

namespace velocity {

class Backend;
class GlContextProvider;

// What draws a Renderer's frames (docs/gpu.md).
enum class BackendChoice {
  Cpu,   // Velocity's own pipeline (src/frame.cpp)
  Gpu,   // OpenGL 3.3 core through EGL, in libvelocity-gpu (loaded when asked for);
         // velocity::Error when no such context can be made, naming what was missing
  Auto,  // a hardware GPU when EGL reports one, never a software GL (Mesa's llvmpipe is
         // slower than the CPU pipeline); else Cpu. stats() says which ran and why.
};
// "cpu", "gpu", "auto".
const char* to_string(BackendChoice choice);
std::optional<BackendChoice> parse_backend(std::string_view name);

enum class DepthMode {
  ZBuffer,  // per-pixel depth test (LESS) and write
  Painter,  // no depth buffer: primitives sorted by mean depth, drawn far to near (seeds 001, 004)
};

// How colours become light and light becomes pixels (docs/appearance.md).
enum class ColorPipeline {
  Auto,     // Linear for a frame with a Pbr material, else Display
  Linear,   // sRGB inputs decoded, lighting in linear light, the output encoded to sRGB
  Display,  // the 8-bit values lit as they are and written as they are (the seed's look, OpenGL 1.x's)
};

// Tone mapping of linear light before the output encoding (Linear only).
enum class ToneMap { None, Aces, KhronosNeutral };

struct RenderOptions {
  DepthMode depth_mode = DepthMode::ZBuffer;
  bool cull_back_faces = true;       // two-sided materials are never culled
  std::optional<Shading> shading;    // when set, overrides every material's shading
  // When set, replace every material's base texture / environment map / filter.
  std::shared_ptr<const Texture> texture;
  std::shared_ptr<const Texture> env_map;
  std::optional<Filter> filter;
  // Interpolate linearly in screen space instead of perspective-correct (the seed's
  // affine texture mapping, to see the difference; depth stays correct).
  bool affine = false;
  // Super-sampling: render at ssaa x ssaa times the output size (colour and depth at
  // every sample), then average each ssaa x ssaa block (box filter). 1..4; 3 is seed
  // 000's high-resolution mode (800x600 out, 2400x1800 inside).
  int ssaa = 1;
  // Threads that rasterize tiles: 0 uses every core (std::thread::hardware_concurrency).
  // The image is the same for any count: each tile is drawn by one thread, in order.
  int threads = 0;
  // Keep an object-id buffer: every sample remembers the id of the draw that last
  // wrote its colour (0 where nothing was drawn). Read it with object_ids().
  bool object_ids = false;
  // Also keep the eye-space normals of the frame's mesh draws: end_frame draws them a
  // second time, unlit, with their normals as colours (8 bits a component), into buffers
  // of their own. Read them with read_normals().
  bool normals = false;
  ColorPipeline color = ColorPipeline::Auto;
  ToneMap tone_map = ToneMap::None;  // off by default, as pyrender's
  float exposure = 1.0f;             // linear light is multiplied by this before tone mapping
  // Shadow maps for the lights that cast shadows (directional, spot, point), filtered
  // (PCF), shadow_map_size texels a side.
  bool shadows = false;
  int shadow_map_size = 2048;
  // The side of a point (Shading::Points, point clouds) in pixels of the output image,
  // 1..64 (scaled by ssaa inside).
  float point_size = 1.0f;
};

// How begin_frame starts the frame: cleared (the default), or from what the previous
// frame left (an OpenGL context keeps its framebuffer between flushes).
struct FrameStart {
  FrameStart() {}  // not an aggregate: begin_frame(camera, lights, {r, g, b}) stays the Vec3 one
  bool clear_color_buffer = true;  // false: the colour buffer starts as the last frame left it
  Vec4 color{0.1f, 0.1f, 0.15f, 1.0f};
  bool clear_depth_buffer = true;  // the same for the depth buffer
  float depth = 1.0f;
  bool clear_stencil_buffer = true;  // and the 8-bit stencil buffer (PixelState's stencil test)
  uint8_t stencil = 0;
};

// What the last frame did, for --verbose output and tests.
struct FrameStats {
  size_t objects = 0;                 // objects submitted
  size_t objects_culled = 0;          // rejected whole by their bounding sphere
  size_t triangles = 0;               // triangles submitted
  size_t triangles_rejected = 0;      // trivially outside one view plane (region codes)
  size_t triangles_nonfinite = 0;     // dropped for a NaN or infinite coordinate
  size_t triangles_clipped = 0;       // cut by the near, far or guard-band planes
  size_t triangles_culled = 0;        // back faces, and triangles covering no pixel centre
  size_t triangles_rasterized = 0;    // set up and binned (after clipping)
  size_t lines = 0, points = 0;       // set up and binned
  // Wall-clock time of end_frame's stages, in milliseconds (for benchmarks).
  double vertex_ms = 0;    // transform, project, light: every vertex
  double triangle_ms = 0;  // reject, cull, clip, set up, bin: every triangle (and the painter's sort)
  double tile_ms = 0;      // clear, rasterize and shade: every tile (GPU: draw and read back)
  double shadow_ms = 0;    // the shadow maps' depth passes (RenderOptions::shadows), before the rest
  // The GPU backend's own stages (0 on the CPU). Within tile_ms: finding changed meshes
  // and textures (fingerprints) and uploading them; issuing the frame's GL calls; waiting
  // for the GPU to finish the frame. Then reading pixels back, which the GPU backend does
  // when the caller first reads each plane (color_image, read_color, the depths,
  // object_ids), after end_frame: readback_ms is the PREVIOUS frame's reads.
  double upload_ms = 0, submit_ms = 0, gpu_wait_ms = 0, readback_ms = 0;
  // The GPU's own time per pass (GL_TIME_ELAPSED queries): the shadow maps; the opaque
  // draws, batches and clears; the blended (and painter's) draws; the read-back copies
  // and resolve, the PREVIOUS frame's as readback_ms.
  double gpu_shadow_ms = 0, gpu_opaque_ms = 0, gpu_blend_ms = 0, gpu_read_ms = 0;
  // GPU: meshes whose bytes were hashed this frame (unmarked, Mesh::revision 0).
  size_t meshes_hashed = 0;
  // The backend that drew ("cpu" or "gpu") and why it was chosen, e.g. "asked for" or
  // "auto: only a software OpenGL driver (llvmpipe), the CPU pipeline is faster". Set
  // from construction on, before any frame; valid while the Renderer lives.
  const char* backend = "cpu";
  const char* backend_reason = "asked for";
};

// The instruction set the pixel and vertex kernels run with on this processor, as
// Highway names it ("AVX3" for AVX-512, "AVX2", "SSE4", "EMU128" or "SCALAR" for the
// plain C++ build): the best the processor has, chosen at run time.
const char* simd_target();

class Renderer {
 public:
  // Throws velocity::Error unless 1 <= width, height <= 16384, or when `backend` is Gpu
  // and no OpenGL 3.3 context can be made (the message names what was missing).
  Renderer(int width, int height, BackendChoice backend = BackendChoice::Cpu);
  // The GPU backend drawing with a window's OpenGL 3.3 core context (velocity/backend.hpp's
  // GlContextProvider, e.g. the real-time presenter's SDL one) instead of an EGL context
  // of its own; present_window() shows its frames there. `hardware_only` refuses a
  // software driver (as Auto does). Throws velocity::Error naming what was missing.
  Renderer(int width, int height, GlContextProvider& window, bool hardware_only = false);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  // Changes the output size (same limits as the constructor; with super-sampling the
  // sample buffer, size x ssaa, must also fit 16384 a side).
  void resize(int width, int height);
  int width() const;
  int height() const;

  RenderOptions options;

  // Draws the scene: begin_frame with its camera, lights and background, every visible
  // object with its world matrix, end_frame.
  const FrameStats& render(const Scene& scene);

  // The same, one mesh at a time (for an immediate-mode front end or a game loop).
  // With no lights, kDefaultLight (scene.hpp) is used, in eye space.
  void begin_frame(const Camera& camera, const std::vector<Light>& lights, Vec3 clear_color);
  void begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start);
  // `material`, when given, replaces the mesh's own materials and face colours.
  // `object_id` is what the object-id buffer records for its pixels (render() uses the
  // object's index + 1). The mesh and material must stay alive and unchanged until
  // end_frame() returns.
  void draw(const Mesh& mesh, const Mat4& world, const Material* material = nullptr, uint32_t object_id = 0);
  // Pre-transformed points, lines or triangles with fixed-function pixel state (see
  // primitives.hpp; the OpenGL front end's path). Throws velocity::Error for a batch
  // without positions or with an index count that does not fit its kind.
  void draw(const PrimitiveBatch& batch, const PixelState& state);
  // Clears the framebuffer, or the request's rectangle of it, in draw order.
  void clear(const ClearRequest& request);
  const FrameStats& end_frame();
  // end_frame, then read_color(rgba, row_bytes, channels) of the frame, in one pass on
  // the CPU: each tile is copied out as soon as it is drawn, while it is in the core's
  // cache, rather than read again afterwards (pGL's glFinish into the OSMesa buffer).
  // The same bytes as end_frame followed by read_color.
  const FrameStats& end_frame_into(uint8_t* rgba, size_t row_bytes, int channels = 4);

  const FrameStats& stats() const;
  // The output image: with super-sampling, each pixel is the mean of its samples.
  Image color_image() const;
  // See Framebuffer::depth_image: nearest white, farthest drawn dark grey, empty black.
  // With super-sampling, each pixel shows its nearest sample.
  Image depth_image() const;
  // The output image into `rgba` (width * height * 4 bytes, `row_bytes` apart, top row
  // first), without an intermediate Image. With channels = 3, RGB without alpha
  // (width * 3 bytes a row); channels must be 3 or 4.
  // The read-back functions run on the renderer's threads (bands of rows); like
  // render(), call them from one thread at a time.
  void read_color(uint8_t* rgba, size_t row_bytes, int channels = 4) const;
  // Per output pixel (top row first), the distance from the camera plane along the
  // view axis (-z in eye space; exact for orthographic cameras as well), 0 where
  // nothing was drawn. With super-sampling, the nearest of the pixel's samples.
  // Only for frames begun with a Camera (mesh draws).
  std::vector<float> view_depth() const;
  // view_depth into caller memory: width * height floats, top row first.
  void read_view_depth(float* out) const;
  // Per output pixel, window depth in [0, 1] (1 where nothing was drawn): what
  // glReadPixels(GL_DEPTH_COMPONENT) returns. With super-sampling, the nearest sample.
  std::vector<float> window_depth() const;
  // window_depth into caller memory: width * height floats, top row first.
  void read_window_depth(float* out) const;
  // Per output pixel (top row first), the 8-bit stencil value: what
  // glReadPixels(GL_STENCIL_INDEX) returns. With super-sampling, the first sample.
  // Throws velocity::Error on a backend that keeps no stencil buffer (the GPU's).
  void read_stencil(uint8_t* out) const;
  // Per output pixel, the object id of what was drawn there (0 for nothing), when
  // options.object_ids was set for the frame; otherwise empty. With super-sampling,
  // the id of the nearest sample, never a mix.
  std::vector<uint32_t> object_ids() const;
  // Per output pixel (top row first), x, y, z of the unit eye-space normal of the mesh
  // drawn there (0, 0, 0 where nothing was drawn; 8 bits a component), into `out`
  // (width * height * 3 floats). Throws velocity::Error unless options.normals was set
  // for the frame.
  void read_normals(float* out) const;
  // Bytes held by the sample buffers (colour and depth) at the current size and ssaa.
  size_t framebuffer_bytes() const;
  // A renderer made on a window's context: draws the last frame into the window's
  // default framebuffer (window_width x window_height), scaled to fit keeping its aspect
  // ratio, with `overlay` (premultiplied RGBA8 at the frame's size, top row first; may
  // be null) blended over it; nothing is read back. The caller swaps buffers. Throws
  // velocity::Error on any other renderer.
  void present_window(int window_width, int window_height, const uint8_t* overlay = nullptr);

 private:
  // What draws (velocity/backend.hpp): the CPU pipeline or the GPU's.
  std::unique_ptr<Backend> backend_;
  BackendChoice drawn_by_ = BackendChoice::Cpu;  // Cpu or Gpu, after Auto's choice
  std::unique_ptr<std::string> reason_;          // stats_.backend_reason points into it (stable across moves)
  FrameStats stats_;                             // the backend's, with which backend it was
  bool in_frame_ = false;
  std::vector<Mat4> world_;  // render()'s matrices, reused
  struct NormalsPass;        // options.normals: the second pass and its buffers
  std::unique_ptr<NormalsPass> normals_;
};

}  // namespace velocity
