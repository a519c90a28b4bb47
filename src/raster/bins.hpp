// Binning: each primitive's record goes to the list of every 64x64 tile its bounding box
// touches. The policy is here and only here: a record is emitted once (WorkerBins::emit)
// and binned at once, or in painter's mode deferred, sorted far to near with the whole
// frame's records and binned in that order (Bins::bin_deferred). Tiles are then
// rasterised independently, each reading only its own lists, which is what lets them
// run on separate cores.
//
// The front end runs on every core too: the frame's work is cut into jobs (a range of
// one draw's triangles, a clear, ...) numbered in submission order, and each worker
// thread writes the records of the jobs it takes, and its tile lists, into memory of its
// own. A worker takes jobs in increasing order, so each of its lists is sorted by job; a
// tile merges the workers' lists by job number and so sees every primitive in submission
// order, whatever the number of threads.
//
// Memory: records and list chunks are carved out of 64 KiB blocks that the workers take
// from one pool shared by the frame and give back at the next frame. So the memory a
// renderer holds is what its largest frame needed, not that times the number of
// workers (which frame's work lands on which worker is up to the scheduler), and there
// is no allocation per frame in steady state.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "raster/contract.hpp"

namespace velocity::raster {

// The frame's blocks. A reference (uint32) is block index << 16 | byte offset.
class BlockPool {
 public:
  static constexpr size_t kBlockBytes = size_t(1) << 16;
  static constexpr uint32_t kMaxBlocks = 1u << 16;  // 4 GiB

  // The table of blocks and the free list are allocated whole (768 KiB of address space,
  // touched as they fill): they never move or grow, and a worker reads only the entries of blocks it was handed
  // (under the mutex), so workers read it while another one takes a new block.
  BlockPool() : blocks_(new std::byte*[kMaxBlocks]) { free_.reserve(kMaxBlocks); }
  ~BlockPool();
  BlockPool(const BlockPool&) = delete;
  BlockPool& operator=(const BlockPool&) = delete;

  // Hands out a free block (allocating one when none is free); UINT32_MAX when the pool
  // is at its limit or memory runs out. Thread-safe.
  uint32_t take();
  // Every block is free again, and at least `want` blocks exist (between frames; not
  // thread-safe). Returns how many blocks the last frame took.
  uint32_t reset(uint32_t want);
  std::byte* block(uint32_t index) const { return blocks_[index]; }
  std::byte* at(uint32_t ref) const { return blocks_[ref >> 16] + (ref & 0xffff); }
  size_t bytes() const { return size_t(count_) * kBlockBytes; }  // between frames

 private:
  std::unique_ptr<std::byte*[]> blocks_;  // [0, count_) allocated
  uint32_t count_ = 0;
  std::vector<uint32_t> free_;
  std::mutex mutex_;
};

// One entry of a tile list: which job wrote the record, and where it is.
struct BinEntry {
  uint32_t job;
  uint32_t record;  // BlockPool reference
};

// A chunk of a tile list, in the pool: `count` entries follow, then the next chunk.
struct ListChunk {
  uint32_t next;   // reference of the next chunk, or kNone
  uint32_t count;
  uint32_t capacity;
  uint32_t pad;
  static constexpr uint32_t kNone = UINT32_MAX;
  BinEntry* entries() { return reinterpret_cast<BinEntry*>(this + 1); }
  const BinEntry* entries() const { return reinterpret_cast<const BinEntry*>(this + 1); }
};

// A worker's records and tile lists.
class WorkerBins {
 public:
  void attach(BlockPool* pool) { pool_ = pool; }
  // Sizes the tile grid (keeps the storage of a larger one).
  void resize(int tiles_x, int tiles_y);
  // Forgets the frame's records and lists (the pool is reset by the owner). `painter`:
  // the frame's records are deferred, not binned, when emitted.
  void clear(bool painter = false);

  // Space for a record of `bytes` (a multiple of 8, at most a few hundred). Returns
  // nullptr when the pool is exhausted (the primitive is then dropped).
  RecordHeader* allocate(size_t bytes, uint32_t& ref);
  // Hands a finished record (at `ref`) of job `job` to the tiles: binned now, or in
  // painter's mode kept with its sort key (mean window depth) until the frame's records
  // are sorted.
  void emit(uint32_t job, RecordHeader& r, uint32_t ref, float sort_key) {
    if (painter_) {
      r.sort_key = sort_key;
      append(painter_head_, painter_tail_, {job, ref});
      return;
    }
    bin(job, ref, r);
  }
  // Adds the record to every tile its inclusive pixel box touches.
  void bin(uint32_t job, uint32_t ref, const RecordHeader& r) {
    const int tx0 = r.min_x >> kTileSizeLog2, tx1 = r.max_x >> kTileSizeLog2;
    const int ty0 = r.min_y >> kTileSizeLog2, ty1 = r.max_y >> kTileSizeLog2;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) append(ty * tiles_x_ + tx, {job, ref});
  }

  // The first chunk of a tile's list (ListChunk::kNone when empty).
  uint32_t list(int tile) const { return heads_[size_t(tile)]; }
  uint32_t deferred() const { return painter_head_; }

 private:
  void append(int tile, BinEntry e) { append(heads_[size_t(tile)], tails_[size_t(tile)], e); }
  void append(uint32_t& head, uint32_t& tail, BinEntry e);

  BlockPool* pool_ = nullptr;
  uint32_t block_ = UINT32_MAX;  // the block being filled
  size_t used_ = BlockPool::kBlockBytes;
  std::vector<uint32_t> heads_, tails_;  // per tile: first and last chunk, or kNone
  int tiles_x_ = 0;
  bool painter_ = false;
  // Painter's mode: the records of this worker in the order it made them.
  uint32_t painter_head_ = ListChunk::kNone, painter_tail_ = ListChunk::kNone;
};

// Every worker's bins for a frame, and the pool they share.
class Bins {
 public:
  // Sizes for a width x height framebuffer and `workers` threads. If it throws
  // (std::bad_alloc) the bins are left unusable until a resize succeeds.
  void resize(int width, int height, int workers);
  // A new frame: every list empty, every block free. `painter`: records are deferred
  // when emitted, and binned by bin_deferred once every one is made.
  void clear(bool painter = false);
  // Painter's mode: every deferred record far to near by its sort key (seed 004's sort),
  // stable so that equal keys keep their submission order; binned in that order, each
  // record its own job (serial: between the triangle stage and the tiles).
  void bin_deferred();

  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  int tile_count() const { return tiles_x_ * tiles_y_; }
  int workers() const { return int(workers_.size()); }
  WorkerBins& worker(int w) { return *workers_[size_t(w)]; }
  const BlockPool& pool() const { return pool_; }
  size_t pool_bytes() const { return pool_.bytes(); }

  // Whether no record was binned to `tile`.
  bool empty(int tile) const {
    for (const auto& w : workers_)
      if (w->list(tile) != ListChunk::kNone) return false;
    return true;
  }

  // Calls f(record) for every record binned to `tile`, in job order.
  template <class F>
  void for_each_in_order(int tile, F&& f) const { merge([&](int w) { return workers_[size_t(w)]->list(tile); }, f); }

 private:
  // Calls f(record, reference) for the entries of the lists head(w) of every worker w,
  // merged by job number.
  template <class Head, class F>
  void merge(Head&& head, F&& f) const;

  int width_ = 0, height_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  uint32_t most_taken_ = 0;  // the most blocks a frame took
  BlockPool pool_;
  struct Sorted {
    float key;
    uint32_t order;  // submission order, for ties
    uint32_t ref;
    const RecordHeader* record;
  };
  std::vector<Sorted> painter_;  // painter's mode: every record of the frame, reused
  std::vector<std::unique_ptr<WorkerBins>> workers_;
};

template <class Head, class F>
void Bins::merge(Head&& list_head, F&& f) const {
  const size_t nw = workers_.size();
  // A cursor per worker: its current chunk and position. Each job's entries come from
  // one worker, contiguous; a k-way merge by job number restores submission order.
  constexpr size_t kMaxWorkers = 256;
  const ListChunk* chunk[kMaxWorkers];
  uint32_t pos[kMaxWorkers];
  size_t live = 0;
  for (size_t w = 0; w < nw; ++w) {
    const uint32_t head = list_head(int(w));
    chunk[w] = head == ListChunk::kNone ? nullptr : reinterpret_cast<const ListChunk*>(pool_.at(head));
    pos[w] = 0;
    live += chunk[w] != nullptr;
  }
  auto advance = [&](size_t w) {
    if (++pos[w] == chunk[w]->count) {
      chunk[w] = chunk[w]->next == ListChunk::kNone ? nullptr : reinterpret_cast<const ListChunk*>(pool_.at(chunk[w]->next));
      pos[w] = 0;
    }
  };
  if (live == 1 || nw == 1) {
    for (size_t w = 0; w < nw; ++w)
      while (chunk[w]) {
        const uint32_t ref = chunk[w]->entries()[pos[w]].record;
        f(*reinterpret_cast<const RecordHeader*>(pool_.at(ref)), ref);
        advance(w);
      }
    return;
  }
  for (;;) {
    size_t best = nw;
    uint32_t best_job = UINT32_MAX;
    for (size_t w = 0; w < nw; ++w)
      if (chunk[w] && chunk[w]->entries()[pos[w]].job < best_job) best = w, best_job = chunk[w]->entries()[pos[w]].job;
    if (best == nw) return;
    do {
      const uint32_t ref = chunk[best]->entries()[pos[best]].record;
      f(*reinterpret_cast<const RecordHeader*>(pool_.at(ref)), ref);
      advance(best);
    } while (chunk[best] && chunk[best]->entries()[pos[best]].job == best_job);
  }
}

}  // namespace velocity::raster
