// No heap allocation per frame in steady state: once a renderer has drawn a scene, the
// same frames again allocate nothing (its buffers, pools and scratch are reused). This
// binary replaces the global operator new to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "velocity/demo.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace velocity;

namespace {

// Allocations made by `frames` more frames of `scene`, after warm-up frames.
long allocations_per_frames(Renderer& r, const Scene& scene, int frames) {
  for (int i = 0; i < 3; ++i) r.render(scene);  // warm-up: buffers and pools grow here
  const long before = g_allocations.load();
  for (int i = 0; i < frames; ++i) r.render(scene);
  return g_allocations.load() - before;
}

}  // namespace

TEST(SteadyState, FramesAllocateNothing) {
  Scene scene = make_demo_scene(1.5f);  // meshes, hierarchy, textures, environment map
  for (int threads : {1, 2, 4}) {
    for (int ssaa : {1, 3}) {
      Renderer r(320, 200);
      r.options.threads = threads;
      r.options.ssaa = ssaa;
      EXPECT_EQ(allocations_per_frames(r, scene, 10), 0) << threads << " threads, ssaa " << ssaa;
    }
  }
}

TEST(SteadyState, EveryShadingModeAndPainterAllocateNothing) {
  Scene scene = make_demo_scene(1.5f);
  auto tex = std::make_shared<const Texture>(make_checkerboard());
  for (Shading s : {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Unlit, Shading::Wireframe, Shading::Points}) {
    for (bool painter : {false, true}) {
      Renderer r(200, 150);
      r.options.threads = 2;
      r.options.shading = s;
      r.options.texture = s == Shading::Phong ? tex : nullptr;
      r.options.depth_mode = painter ? DepthMode::Painter : DepthMode::ZBuffer;
      r.options.object_ids = true;
      EXPECT_EQ(allocations_per_frames(r, scene, 5), 0) << to_string(s) << (painter ? ", painter" : "");
    }
  }
}
