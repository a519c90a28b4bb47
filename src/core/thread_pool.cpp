#include "core/thread_pool.hpp"

#include <pthread.h>

#include <chrono>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace velocity {

namespace {

// Polls `ready` for up to about 100 microseconds (long enough to span the gap between
// two stages of a frame, short enough that an idle pool soon stops using the CPU);
// true if it became true. After the first 10 microseconds it yields the core between
// polls: on a machine busy with other programs a spinning worker must not take the
// time slice of the thread it waits for.
// A stream's worker waits for the next item with a shorter `limit`: items come a few
// hundred microseconds apart while the caller records, and the worker's spinning would
// be CPU time taken from the rest of the machine.
template <class Ready>
bool spin_until(Ready ready, std::chrono::microseconds limit = std::chrono::microseconds(100)) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  bool yielding = false;
  for (int i = 0;; ++i) {
    if (ready()) return true;
    if ((i & 63) == 63) {
      const auto spent = Clock::now() - start;
      if (spent > limit) return false;
      yielding = spent > std::chrono::microseconds(10);
    }
    if (yielding) {
      std::this_thread::yield();
    } else {
#if defined(__x86_64__) || defined(__i386__)
      _mm_pause();
#else
      std::this_thread::yield();
#endif
    }
  }
}

std::atomic<unsigned> g_forks{0};

void count_fork() { g_forks.fetch_add(1, std::memory_order_relaxed); }

// Counts forks from the moment the library is loaded, before any pool exists.
const int g_fork_handler = pthread_atfork(nullptr, nullptr, count_fork);

}  // namespace

unsigned ThreadPool::fork_count() { return g_forks.load(std::memory_order_relaxed); }

ThreadPool::ThreadPool(int threads) {
  (void)g_fork_handler;
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { work(i); });
}

ThreadPool::~ThreadPool() {
  if (streaming_ && !orphaned()) {
    try {
      close_stream();  // the workers may be inside its items
    } catch (...) {
    }
  }
  if (orphaned()) {
    // The workers' std::thread handles name threads of the parent: joining one would
    // wait forever, and so would destroying the condition variables they slept on.
    // Keep both, never destroyed (destroying a joinable thread calls std::terminate),
    // from a static, so that leak checkers still reach them.
    struct Orphans {
      std::vector<std::thread> threads;
      std::vector<std::unique_ptr<Sync>> syncs;
    };
    static auto* orphans = new Orphans;
    for (auto& t : workers_) orphans->threads.push_back(std::move(t));
    orphans->syncs.push_back(std::move(sync_));
    return;
  }
  {
    std::lock_guard lock(mutex_);
    stop_.store(true, std::memory_order_release);
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadPool::drain(int worker) {
  for (int i = next_.fetch_add(1, std::memory_order_relaxed); i < count_; i = next_.fetch_add(1, std::memory_order_relaxed)) {
    try {
      job_(i, worker);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void ThreadPool::work(int worker) {
  unsigned seen = 0;
  auto woken = [&] {
    return stop_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen;
  };
  for (;;) {
    if (!spin_until(woken)) {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, woken);
    }
    if (stop_.load(std::memory_order_acquire)) return;
    seen = generation_.load(std::memory_order_acquire);
    if (stream_run_.load(std::memory_order_relaxed)) drain_stream(worker);
    else drain(worker);
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      // The caller may be asleep: take the lock so that the wake-up cannot fall between
      // its test of busy_ and its wait.
      std::lock_guard lock(mutex_);
      done_.notify_one();
    }
  }
}

void ThreadPool::start_generation() {
  next_.store(0, std::memory_order_relaxed);
  busy_.store(int(workers_.size()), std::memory_order_relaxed);
  {
    // Under the lock, so that a worker going to sleep sees either the old generation
    // and then the notification, or the new generation.
    std::lock_guard lock(mutex_);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
}

void ThreadPool::wait_workers() {
  auto finished = [&] { return busy_.load(std::memory_order_acquire) == 0; };
  if (!spin_until(finished)) {
    std::unique_lock lock(mutex_);
    done_.wait(lock, finished);
  }
}

void ThreadPool::run_items(int count, Job job) {
  if (workers_.empty() || count <= 1 || orphaned() || streaming_) {
    for (int i = 0; i < count; ++i) job(i, 0);  // exceptions propagate as they are
    return;
  }
  job_ = job;
  count_ = count;
  start_generation();
  drain(0);
  wait_workers();
  job_ = {nullptr, nullptr};
  std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

// Takes the stream's items in order; waits for each until it is handed over, or the
// stream is closed without it.
void ThreadPool::drain_stream(int worker) {
  for (;;) {
    const int i = next_.fetch_add(1, std::memory_order_relaxed);
    auto ready = [&] {
      return i < stream_count_.load(std::memory_order_acquire) || stream_closed_.load(std::memory_order_acquire);
    };
    if (!spin_until(ready, std::chrono::microseconds(20))) {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, ready);
    }
    // (closed: the count is final, stored before stream_closed_)
    if (i >= stream_count_.load(std::memory_order_acquire)) return;
    try {
      (*stream_job_)(i, worker);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }
}

void ThreadPool::open_stream(const std::function<void(int, int)>& job) {
  streaming_ = true;
  stream_job_ = &job;
  stream_count_.store(0, std::memory_order_relaxed);
  stream_closed_.store(false, std::memory_order_relaxed);
  if (workers_.empty() || orphaned()) return;  // close_stream runs every item
  stream_run_.store(true, std::memory_order_relaxed);
  start_generation();
}

void ThreadPool::stream_to(int count) {
  {
    // Under the lock, as a new generation: a worker about to sleep sees the new count
    // or gets the notification.
    std::lock_guard lock(mutex_);
    stream_count_.store(count, std::memory_order_release);
  }
  wake_.notify_all();
}

void ThreadPool::close_stream() {
  {
    std::lock_guard lock(mutex_);
    stream_closed_.store(true, std::memory_order_release);
  }
  wake_.notify_all();
  if (!stream_run_.load(std::memory_order_relaxed)) {
    // No workers: every item here, the first exception rethrown once all have run, as
    // with workers.
    const std::function<void(int, int)>& job = *std::exchange(stream_job_, nullptr);
    streaming_ = false;
    const int count = stream_count_.load(std::memory_order_relaxed);
    std::exception_ptr error;
    for (int i = 0; i < count; ++i) {
      try {
        job(i, 0);
      } catch (...) {
        if (!error) error = std::current_exception();
      }
    }
    if (error) std::rethrow_exception(error);
    return;
  }
  drain_stream(0);
  // In a child forked while the stream was open there are no workers to wait for.
  if (!orphaned()) wait_workers();
  stream_run_.store(false, std::memory_order_relaxed);
  streaming_ = false;
  stream_job_ = nullptr;
  std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace velocity
