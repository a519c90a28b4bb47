// Tiles on several threads draw exactly what one thread draws; the pool that runs them.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/thread_pool.hpp"
#include "velocity/demo.hpp"
#include "velocity/primitives.hpp"
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

// Waits up to `seconds` for `child`; kills it if it is still running (a hang).
int wait_child(pid_t child, int seconds) {
  for (int i = 0; i < seconds * 100; ++i) {
    int status = 0;
    if (waitpid(child, &status, WNOHANG) == child) return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  return -1;  // hung
}

TEST(Threads, PoolAndRendererWorkInAForkedChild) {
#if defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "TSan does not support starting threads after a multi-threaded fork()";
#endif
  std::optional<ThreadPool> pool(4);
  pool->run(8, [](int) {});  // the workers exist and have run
  Scene scene = make_demo_scene(1.5f);
  Renderer renderer(96, 64);
  renderer.options.threads = 3;
  auto draw = [&] {
    renderer.render(scene);
    return renderer.color_image().pixels;
  };
  const std::vector<uint8_t> before = draw();
  // Past their spinning: every worker asleep on the pools' condition variables.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The child: the workers of both pools are gone. Every item still runs once, and
    // the renderer draws the same image (with a new pool of its own).
    if (!pool->orphaned()) _exit(2);
    std::vector<std::atomic<int>> hits(50);
    pool->run(50, [&](int i) { hits[size_t(i)]++; });
    for (auto& h : hits)
      if (h.load() != 1) _exit(3);
    pool.reset();  // destroying an orphaned pool does not wait for its workers either
    _exit(draw() == before ? 0 : 4);
  }
  EXPECT_FALSE(pool->orphaned());
  EXPECT_EQ(wait_child(child, 60), 0) << "-1: the child hung";
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

// A stream (ThreadPool::open_stream): every item handed over runs once, on a worker
// until close_stream, never before it is handed over, each worker's items in increasing
// order (the triangle stage's bins rely on it); the first exception comes back from
// close_stream, and the pool runs as before afterwards.
TEST(Threads, PoolStreamRunsEachItemOnceInOrderAfterItIsHandedOver) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    for (int round = 0; round < 10; ++round) {
      constexpr int kItems = 200;
      std::vector<std::atomic<int>> hits(kItems);
      std::vector<int> who(kItems, -1);
      std::atomic<int> handed{0}, early{0}, on_caller_before_close{0};
      std::atomic<bool> closing{false};
      std::vector<int> last(size_t(threads), -1);
      std::atomic<int> out_of_order{0};
      const std::function<void(int, int)> job = [&](int i, int worker) {
        if (i >= handed.load()) early++;
        if (worker == 0 && !closing.load()) on_caller_before_close++;
        if (i <= last[size_t(worker)]) out_of_order++;
        last[size_t(worker)] = i;
        who[size_t(i)] = worker;
        hits[size_t(i)]++;
        if (i == 150 && round % 2) throw std::runtime_error("item 150");
      };
      pool.open_stream(job);
      EXPECT_TRUE(pool.streaming());
      // run() during a stream: on the calling thread.
      std::atomic<int> serial{0};
      pool.run(5, [&](int, int worker) { serial += worker == 0; });
      EXPECT_EQ(serial.load(), 5);
      for (int n = 1; n <= kItems; n += 7) {
        handed = std::min(n, kItems);
        pool.stream_to(handed.load());
        if (n % 3 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
      handed = kItems;
      pool.stream_to(kItems);
      closing = true;
      if (round % 2) {
        EXPECT_THROW(pool.close_stream(), std::runtime_error);
      } else {
        EXPECT_NO_THROW(pool.close_stream());
      }
      EXPECT_FALSE(pool.streaming());
      for (int i = 0; i < kItems; ++i) ASSERT_EQ(hits[size_t(i)].load(), 1) << threads << " threads, item " << i;
      EXPECT_EQ(early.load(), 0);
      EXPECT_EQ(on_caller_before_close.load(), 0);
      EXPECT_EQ(out_of_order.load(), 0);
      if (threads == 1) {
        EXPECT_EQ(*std::max_element(who.begin(), who.end()), 0);
      }
      std::vector<std::atomic<int>> after(31);
      pool.run(31, [&](int i) { after[size_t(i)]++; });
      for (auto& h : after) ASSERT_EQ(h.load(), 1);
    }
  }
}

namespace {

// Batches of small overlapping triangles without a depth test, so that the image
// depends on their order: `count` of them from `seed`, in clip space.
struct Batches {
  std::vector<std::vector<Vec4>> positions, colors;
  Batches(int count, uint32_t seed) {
    uint32_t s = seed;
    auto next = [&] { return (s = s * 1664525u + 1013904223u) >> 8 & 0xffff; };
    for (int b = 0; b < count; ++b) {
      // Mostly pGL's piece size; one batch larger than a streamed draw may be.
      const uint32_t triangles = b == count / 2 ? 20000 : 500 + next() % 4096;
      std::vector<Vec4>& p = positions.emplace_back();
      std::vector<Vec4>& c = colors.emplace_back();
      for (uint32_t t = 0; t < triangles; ++t) {
        const float x = float(next()) / 32768.0f - 1.0f, y = float(next()) / 32768.0f - 1.0f;
        const Vec4 color{float(next() % 256) / 255.0f, float(next() % 256) / 255.0f, float(b % 7) / 6.0f, 1};
        for (int k = 0; k < 3; ++k) {
          const float dx = float(next() % 64) / 256.0f, dy = float(next() % 64) / 256.0f;
          p.push_back({x + dx, y + dy * (k == 1 ? -1.0f : 1.0f), 0.5f, 1.0f});
          c.push_back(color);
        }
      }
    }
  }
};

// Draws the batches with a clear in the first half, as one frame.
std::vector<uint8_t> draw_batches(Renderer& r, const Batches& batches, FrameStats* stats = nullptr) {
  FrameStart start;
  start.color = {0, 0, 0, 1};
  r.begin_frame(Camera{}, {}, start);
  PixelState state;
  state.depth_test = false;
  for (size_t i = 0; i < batches.positions.size(); ++i) {
    if (i == 3) {
      ClearRequest c;
      c.color_value = {0.2f, 0.4f, 0.6f, 1};
      c.scissor = true, c.x0 = 20, c.y0 = 10, c.x1 = 150, c.y1 = 90;
      r.clear(c);
    }
    PrimitiveBatch b;
    b.position = batches.positions[i].data();
    b.color = batches.colors[i].data();
    b.vertex_count = uint32_t(batches.positions[i].size());
    r.draw(b, state);
  }
  std::vector<uint8_t> rgba(size_t(r.width()) * size_t(r.height()) * 4);
  const FrameStats& s = r.end_frame_into(rgba.data(), size_t(r.width()) * 4, 4);
  if (stats) *stats = s;
  return rgba;
}

}  // namespace

// Batches drawn before end_frame start on the workers (src/frame.cpp, "Streaming"); the
// image and counts are one thread's, which never streams, also when a frame is begun
// again before it ended and when a renderer goes away in the middle of one.
TEST(Threads, StreamedBatchesDrawWhatOneThreadDraws) {
  const Batches batches(12, 7);
  Renderer one(333, 201);
  one.options.threads = 1;
  FrameStats reference_stats;
  const std::vector<uint8_t> reference = draw_batches(one, batches, &reference_stats);
  ASSERT_GT(reference_stats.triangles_rasterized, 40000u);
  for (int threads : {2, 3, 5}) {
    Renderer r(333, 201);
    r.options.threads = threads;
    for (int frame = 0; frame < 3; ++frame) {
      FrameStats stats;
      EXPECT_EQ(draw_batches(r, batches, &stats), reference) << threads << " threads, frame " << frame;
      EXPECT_EQ(stats.triangles, reference_stats.triangles);
      EXPECT_EQ(stats.triangles_rasterized, reference_stats.triangles_rasterized);
    }
    // A frame abandoned with its stream running, then a whole one.
    r.begin_frame(Camera{}, {}, FrameStart{});
    PrimitiveBatch b;
    b.position = batches.positions[0].data(), b.color = batches.colors[0].data();
    b.vertex_count = uint32_t(batches.positions[0].size());
    r.draw(b, PixelState{});
    EXPECT_EQ(draw_batches(r, batches), reference) << threads << " threads, after an abandoned frame";
    Renderer gone(333, 201);
    gone.options.threads = threads;
    gone.begin_frame(Camera{}, {}, FrameStart{});
    gone.draw(b, PixelState{});  // destroyed with its stream open
  }
}
