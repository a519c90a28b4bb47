// Tiles on several threads draw exactly what one thread draws.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <thread>

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
