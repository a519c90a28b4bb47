// A small fixed pool of worker threads for data-parallel loops (tiles).
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace velocity {

class ThreadPool {
 public:
  // `threads` >= 1 in all, the calling thread included (so threads - 1 workers).
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return int(workers_.size()) + 1; }

  // Calls job(i) for every i in [0, count), spread over the pool and the calling
  // thread, and returns when all are done. Items are taken one at a time from a shared
  // counter, so uneven items (busy and empty tiles) balance themselves. `job` must not
  // throw.
  void run(int count, const std::function<void(int)>& job);

 private:
  void work();
  void drain();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int count_ = 0;
  std::atomic<int> next_{0};
  int busy_ = 0;               // workers still inside the current generation
  unsigned generation_ = 0;    // bumped for each run()
  bool stop_ = false;
};

}  // namespace velocity
