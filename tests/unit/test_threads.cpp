// Tiles on several threads draw exactly what one thread draws.
#include <gtest/gtest.h>

#include "core/thread_pool.hpp"
#include "velocity/demo.hpp"
#include "velocity/renderer.hpp"

using namespace velocity;

TEST(Threads, PoolRunsEveryItemOnce) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    for (int round = 0; round < 20; ++round) {
      std::vector<std::atomic<int>> hits(97);
      pool.run(97, [&](int i) { hits[size_t(i)]++; });
      for (auto& h : hits) ASSERT_EQ(h.load(), 1) << threads << " threads";
    }
  }
}

TEST(Threads, ImageIndependentOfThreadCount) {
  Scene scene = make_demo_scene(1.5f);
  Image reference;
  for (int threads : {1, 2, 4, 7}) {
    Renderer r(333, 201);  // partial tiles on the right and bottom
    r.options.threads = threads;
    r.options.ssaa = 2;
    r.render(scene);
    Image img = r.color_image();
    if (threads == 1) reference = img;
    else EXPECT_EQ(img.pixels, reference.pixels) << threads << " threads";
  }
}
