// A small fixed pool of worker threads for data-parallel loops (the frame's stages).
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <type_traits>
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

  // True in a child process forked after the pool was made: fork() copies only the
  // thread that called it, so the workers are gone. run() then does every item on the
  // calling thread (never waiting for workers that do not exist), and the destructor
  // lets go of the workers without joining them; make a new pool to have threads again.
  bool orphaned() const { return forks_ != fork_count(); }
  // How many fork()s this process descends through since the library was loaded
  // (pthread_atfork's child handler counts them).
  static unsigned fork_count();

  // Calls job(i, worker) for every i in [0, count), spread over the pool and the
  // calling thread, and returns when all are done. `worker` (0 .. size() - 1) is the
  // thread's own index, the calling thread being 0: per-worker buffers need no locks.
  // Items are taken one at a time from a shared counter, in increasing order, so a
  // worker's items are increasing too and uneven items (busy and empty tiles) balance
  // themselves. If items throw, the rest still run and the first exception is
  // rethrown here once all are done. `job` is called through a reference to it (no
  // copy, no allocation per run): job(i, worker) or job(i).
  // While a stream (below) is open, run() does every item on the calling thread.
  template <class F>
  void run(int count, F&& job) {
    if constexpr (std::is_invocable_v<F&, int, int>) {
      run_items(count, Job{&job, [](void* f, int i, int w) { (*static_cast<std::remove_reference_t<F>*>(f))(i, w); }});
    } else {
      run_items(count, Job{&job, [](void* f, int i, int) { (*static_cast<std::remove_reference_t<F>*>(f))(i); }});
    }
  }

  // A run whose items are handed over while it runs, so that the workers start on them
  // while the calling thread is still busy making the next ones (the renderer's triangle
  // stage while pGL records the rest of a frame). open_stream(job) starts it with no
  // items; stream_to(count) lets items [0, count) run (count only grows); close_stream()
  // runs what is left on the calling thread too, returns once every item handed over is
  // done, and rethrows the first exception an item threw. The workers take items one at
  // a time in increasing order, as run() does, and call job(i, worker) with worker >= 1;
  // until close_stream the calling thread runs none. `job` is called through a
  // reference: it must live until close_stream returns (a pool destroyed with its
  // stream open closes it first). One stream at a time; with no workers (size() == 1,
  // or orphaned) close_stream runs every item.
  void open_stream(const std::function<void(int, int)>& job);
  void stream_to(int count);
  void close_stream();
  bool streaming() const { return streaming_; }

 private:
  // A callable by reference: what run() hands the workers.
  struct Job {
    void* callable;
    void (*call)(void*, int, int);
    void operator()(int i, int worker) const { call(callable, i, worker); }
  };
  void run_items(int count, Job job);
  void work(int worker);
  void drain(int worker);
  void drain_stream(int worker);
  void start_generation();
  void wait_workers();

  std::vector<std::thread> workers_;
  // Workers and the caller wait by spinning a little (a frame runs its stages back to
  // back, and waking a sleeping thread costs tens of microseconds, more in a virtual
  // machine), then by sleeping on these. On the heap: in a forked child they may hold
  // waiters that no longer exist, and destroying such a condition variable waits for
  // them forever, so an orphaned pool never destroys them.
  struct Sync {
    std::mutex mutex;
    std::condition_variable wake, done;
  };
  std::unique_ptr<Sync> sync_ = std::make_unique<Sync>();
  std::mutex& mutex_ = sync_->mutex;
  std::condition_variable &wake_ = sync_->wake, &done_ = sync_->done;
  // The run in progress: written by run_items before it publishes a new generation,
  // read by the workers after they see it.
  Job job_{nullptr, nullptr};
  int count_ = 0;
  std::exception_ptr error_;   // the first exception an item threw in this run (under mutex_)
  std::atomic<int> next_{0};   // the next item to take
  std::atomic<int> busy_{0};   // workers still inside the current generation
  std::atomic<unsigned> generation_{0};  // bumped for each run()
  std::atomic<bool> stop_{false};
  // The stream (open_stream): items [0, stream_count_) may run; once stream_closed_,
  // none will be added. Both written under mutex_ (the workers sleep on wake_ for them).
  bool streaming_ = false;  // the calling thread's view: a stream is open
  std::atomic<bool> stream_run_{false};  // the generation the workers see is a stream
  const std::function<void(int, int)>* stream_job_ = nullptr;
  std::atomic<int> stream_count_{0};
  std::atomic<bool> stream_closed_{false};
  unsigned forks_ = fork_count();  // fork_count() when the workers were started
};

}  // namespace velocity
