// What draws for a Renderer: every promise renderer.hpp makes, as one interface that an
// implementation fills in. The CPU pipeline (src/frame.cpp) is one; the GPU backend
// (gpu/, OpenGL 3.3 through EGL, in its own shared library libvelocity-gpu, loaded by
// make_backend only when asked for) is the other. Calls are per frame or per draw,
// never per pixel, so the virtual calls cost nothing measurable.
//
// The Renderer checks its callers (a draw outside a frame, a batch whose indices do not
// make whole primitives, a bad channel count) before it calls a backend: a backend may
// assume calls in order (begin_frame, draws and clears, end_frame) with valid arguments.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "velocity/image.hpp"
#include "velocity/material.hpp"
#include "velocity/math.hpp"
#include "velocity/mesh.hpp"
#include "velocity/primitives.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"

namespace velocity {

// An OpenGL context that someone else made and owns: a window's (the real-time
// presenter's SDL GL context, present/sdl/presenter.cpp). A GPU backend made on one
// (make_backend_on) draws with it instead of an EGL context of its own, and shows its
// frames in the context's default framebuffer (Backend::present_window). GL entry
// points still come from libepoxy, which resolves them through whichever context is
// current (GLX or EGL): the provider only binds the context. It is used from the
// thread that made it, and outlives the backend.
class GlContextProvider {
 public:
  virtual ~GlContextProvider() = default;
  // Binds the context to the calling thread; false with why in `error` when it cannot.
  virtual bool make_current(std::string& error) = 0;
  virtual bool is_current() const = 0;
  // What it is, for FrameStats::backend_reason, e.g. "SDL GL context (x11)".
  virtual std::string name() const = 0;
};

class Backend {
 public:
  virtual ~Backend() = default;

  // The output size (Renderer's limits; velocity::Error and no change outside them).
  // Super-sampling follows RenderOptions::ssaa at begin_frame.
  virtual void resize(int width, int height) = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;

  // A frame: draws and clears are recorded in order and run by end_frame. The frame
  // uses `options` as they are at begin_frame.
  virtual void begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start,
                           const RenderOptions& options) = 0;
  // The mesh and material stay alive and unchanged until end_frame returns.
  virtual void draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) = 0;
  // `primitives`: the batch's whole primitives (at least one).
  virtual void draw(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) = 0;
  virtual void clear(const ClearRequest& request) = 0;
  virtual const FrameStats& end_frame() = 0;
  // end_frame and read_color in one (Renderer::end_frame_into); this default does one
  // after the other.
  virtual const FrameStats& end_frame_into(uint8_t* rgba, size_t row_bytes, int channels) {
    const FrameStats& s = end_frame();
    read_color(rgba, row_bytes, channels);
    return s;
  }
  virtual const FrameStats& stats() const = 0;

  // The last frame, read back as Renderer's functions of the same names describe.
  virtual Image color_image() const = 0;
  virtual Image depth_image() const = 0;
  virtual void read_color(uint8_t* rgba, size_t row_bytes, int channels) const = 0;
  virtual void read_view_depth(float* out) const = 0;
  virtual void read_window_depth(float* out) const = 0;
  virtual void read_stencil(uint8_t* out) const = 0;
  virtual std::vector<uint32_t> object_ids() const = 0;
  virtual size_t framebuffer_bytes() const = 0;

  // A backend made on a window's GL context (make_backend_on): draws the last frame
  // into the context's default framebuffer (window_width x window_height pixels), scaled
  // to fit with its aspect ratio kept (nearest pixels, black bars), and over it
  // `overlay` when not null: premultiplied RGBA8 at the frame's size, top row first
  // (the 2D layer). The caller swaps buffers. Others throw velocity::Error.
  virtual void present_window(int window_width, int window_height, const uint8_t* overlay);
};

// The CPU pipeline (src/frame.cpp) at width x height; throws as Renderer's constructor.
std::unique_ptr<Backend> make_cpu_backend(int width, int height);

// The backend for a choice (renderer.hpp's BackendChoice): Cpu, or the GPU backend from
// libvelocity-gpu (src/backend_choice.cpp finds and loads it: VELOCITY_GPU_LIBRARY, else
// the dynamic linker's path, the build tree and the install's library folder). `drawn_by`
// becomes Cpu or Gpu and `reason` says why. Throws velocity::Error for Gpu when the
// library or an OpenGL 3.3 context is missing; Auto then falls back to Cpu instead.
std::unique_ptr<Backend> make_backend(BackendChoice choice, int width, int height, BackendChoice& drawn_by,
                                      std::string& reason);

// The GPU backend on a window's OpenGL 3.3 core context (`window`; see GlContextProvider),
// for Renderer's windowed constructor. `reason` says what drew. Throws velocity::Error
// naming what was missing (the library, OpenGL 3.3 core in that context), or, with
// `hardware_only`, when the context is a software driver's.
std::unique_ptr<Backend> make_backend_on(GlContextProvider& window, int width, int height, bool hardware_only,
                                         std::string& reason);

// The entry point libvelocity-gpu exports (extern "C", looked up by name): a new GPU
// backend, or null with a one-line reason in `message`. `hardware_only` (Auto) refuses a
// software driver. `window`, when not null, is the context to draw with instead of an EGL
// one of its own (make_backend_on). `abi` must be kGpuBackendAbi: the library and the core library it is
// loaded into were built from the same headers.
inline constexpr unsigned long kGpuBackendAbi =
    20261127ul * 7 + sizeof(RenderOptions) * 131 + sizeof(PixelState) * 17 + sizeof(FrameStats) + sizeof(Material) * 3;
using GpuBackendEntry = Backend* (*)(unsigned long abi, int width, int height, int hardware_only, char* message,
                                     size_t message_size, GlContextProvider* window);
inline constexpr const char* kGpuBackendEntry = "velocity_gpu_make_backend";

}  // namespace velocity
