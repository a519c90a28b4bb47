#include "raster/bins.hpp"

#include <algorithm>
#include <cstdlib>
#include <new>

namespace velocity::raster {

namespace {
// A tile list's first chunk is small (most tiles of a sparse frame hold a few records;
// 65536 tiles of a 16384x16384 frame times the workers must stay cheap), later ones
// larger.
constexpr uint32_t kFirstChunkEntries = 6;
constexpr uint32_t kChunkEntries = 126;
}  // namespace

BlockPool::~BlockPool() {
  for (uint32_t i = 0; i < count_; ++i) std::free(blocks_[i]);
}

uint32_t BlockPool::take() {
  std::lock_guard lock(mutex_);
  if (!free_.empty()) {
    uint32_t b = free_.back();
    free_.pop_back();
    return b;
  }
  if (count_ >= kMaxBlocks) return UINT32_MAX;
  auto* p = static_cast<std::byte*>(std::aligned_alloc(64, kBlockBytes));
  if (!p) return UINT32_MAX;
  blocks_[count_] = p;
  return count_++;
}

uint32_t BlockPool::reset(uint32_t want) {
  const uint32_t taken = count_ - uint32_t(free_.size());
  // Blocks for the next frame, made now rather than during it (a failure here is no
  // error: take() tries again when it runs out).
  want = std::min(want, kMaxBlocks);
  while (count_ < want) {
    auto* p = static_cast<std::byte*>(std::aligned_alloc(64, kBlockBytes));
    if (!p) break;
    blocks_[count_++] = p;
  }
  free_.clear();
  // Handed out lowest first, so that a frame fills the same blocks as the last one.
  for (uint32_t i = count_; i-- > 0;) free_.push_back(i);
  return taken;
}

void WorkerBins::resize(int tiles_x, int tiles_y) {
  const int tile_count = tiles_x * tiles_y;
  // Never shrunk: switching sizes allocates nothing. If this throws, nothing changed.
  if (heads_.size() < size_t(tile_count)) {
    std::vector<uint32_t> h(static_cast<size_t>(tile_count)), t(static_cast<size_t>(tile_count));
    heads_.swap(h), tails_.swap(t);
  }
  tiles_x_ = tiles_x;
  clear();
}

void WorkerBins::clear(bool painter) {
  painter_ = painter;
  std::fill(heads_.begin(), heads_.end(), ListChunk::kNone);
  std::fill(tails_.begin(), tails_.end(), ListChunk::kNone);
  painter_head_ = painter_tail_ = ListChunk::kNone;
  block_ = UINT32_MAX;
  used_ = BlockPool::kBlockBytes;
}

RecordHeader* WorkerBins::allocate(size_t bytes, uint32_t& ref) {
  if (used_ + bytes > BlockPool::kBlockBytes) {
    const uint32_t b = pool_->take();
    if (b == UINT32_MAX) return nullptr;
    block_ = b, used_ = 0;
  }
  ref = (block_ << 16) | uint32_t(used_);
  RecordHeader* r = reinterpret_cast<RecordHeader*>(pool_->block(block_) + used_);
  used_ += bytes;
  return r;
}

void WorkerBins::append(uint32_t& head, uint32_t& tail_ref, BinEntry e) {
  const uint32_t tail = tail_ref;
  ListChunk* c = tail == ListChunk::kNone ? nullptr : reinterpret_cast<ListChunk*>(pool_->at(tail));
  if (!c || c->count == c->capacity) {
    const uint32_t cap = c ? kChunkEntries : kFirstChunkEntries;
    uint32_t ref;
    auto* fresh = reinterpret_cast<ListChunk*>(allocate(sizeof(ListChunk) + cap * sizeof(BinEntry), ref));
    if (!fresh) return;  // the pool is exhausted: the record is dropped from this tile
    *fresh = {ListChunk::kNone, 0, cap, 0};
    if (c) c->next = ref;
    else head = ref;
    tail_ref = ref;
    c = fresh;
  }
  c->entries()[c->count++] = e;
}

void Bins::resize(int width, int height, int workers) {
  const int tiles_x = (width + kTileSize - 1) / kTileSize, tiles_y = (height + kTileSize - 1) / kTileSize;
  // Workers are kept: a resize must not turn into fresh allocations of everything.
  while (workers_.size() < size_t(std::max(workers, 1))) {
    workers_.push_back(std::make_unique<WorkerBins>());
    workers_.back()->attach(&pool_);
  }
  workers_.resize(size_t(std::max(workers, 1)));
  for (auto& w : workers_) w->resize(tiles_x, tiles_y);
  width_ = width, height_ = height;
  tiles_x_ = tiles_x, tiles_y_ = tiles_y;
}

void Bins::clear(bool painter) {
  // As many blocks as the largest frame took, and room for what the schedule can add
  // to that (which jobs fall on which worker changes the part-filled blocks and list
  // chunks each leaves): one block per worker and a quarter more. So frames like the
  // ones before allocate nothing, however their jobs fall on the workers.
  const uint32_t nw = uint32_t(workers_.size());
  most_taken_ = std::max(most_taken_, pool_.reset(most_taken_ + most_taken_ / 4 + nw + 1));
  for (auto& w : workers_) w->clear(painter);
}

void Bins::bin_deferred() {
  painter_.clear();
  merge([&](int w) { return workers_[size_t(w)]->deferred(); },
        [&](const RecordHeader& r, uint32_t ref) { painter_.push_back({r.sort_key, uint32_t(painter_.size()), ref, &r}); });
  // Stable by the order as a second key (std::stable_sort would allocate every frame).
  std::sort(painter_.begin(), painter_.end(),
            [](const Sorted& a, const Sorted& b) { return a.key != b.key ? a.key > b.key : a.order < b.order; });
  WorkerBins& into = *workers_[0];  // one worker's lists hold them all
  for (size_t rank = 0; rank < painter_.size(); ++rank) into.bin(uint32_t(rank), painter_[rank].ref, *painter_[rank].record);
}

}  // namespace velocity::raster
