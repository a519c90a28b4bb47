// The triangle stage: the frame's draws cut into jobs (a range of one draw's
// primitives, or a clear), run on every core. Per primitive: assemble, reject, cull
// (cull.hpp's first pass, N triangles at a time), clip (clip.hpp), set up (setup.hpp)
// and emit the record to the worker's bins.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "core/thread_pool.hpp"
#include "geometry/draw_plan.hpp"
#include "raster/bins.hpp"
#include "velocity/renderer.hpp"

namespace velocity::triangle {

// The most triangles (or primitives) one job of the triangle stage holds.
inline constexpr uint32_t kTrianglesPerJob = 4096;

// One piece of the triangle stage: a range of one draw's primitives, or a clear.
struct Job {
  enum class Kind : uint8_t { Mesh, Batch, Clear } kind;
  uint32_t draw;         // index into meshes, batches or clears
  uint32_t begin, end;   // primitives
  size_t nonfinite = 0;  // filled in by the worker that ran it
};

// What one worker needs while it runs jobs of the triangle stage.
struct StageContext {
  raster::WorkerBins& bins;
  FrameStats& stats;
  uint32_t job = 0;
  size_t nonfinite = 0;  // triangles of this job dropped for NaN/Inf
  // The worker's scratch for the first pass's survivors (kTrianglesPerJob each).
  uint32_t* direct = nullptr;
  uint32_t* info = nullptr;
  uint32_t* clipped = nullptr;
  std::vector<uint8_t>* marks = nullptr;  // points: which vertices this job drew

  // The record goes to the tiles (raster/bins.hpp decides when).
  void emit(raster::RecordHeader& r, uint32_t ref, float sort_key) { bins.emit(job, r, ref, sort_key); }
};

// The triangle stage for one job: assemble, reject, cull, clip, set up and bin.
void run_mesh_job(const geometry::DrawList& plan, const geometry::MeshDrawPlan& draw, uint32_t begin, uint32_t end,
                  StageContext& cx);
// (A batch's vertices are read from draw.projected and draw.codes.)
void run_batch_job(const geometry::BatchDrawPlan& draw, uint32_t begin, uint32_t end, StageContext& cx);
void run_clear_job(const geometry::ClearPlan& clear, int width, int height, StageContext& cx);

// The whole stage for a frame, on every core: each worker runs jobs in increasing order
// and sets up and bins into its own bins. Holds the workers' scratch across frames.
class TriangleStage {
 public:
  // A frame's stage: start() clears `bins` (`painter`: the records are deferred for
  // Bins::bin_deferred) and the workers' counts for `workers` threads; then run_job
  // runs single jobs as their draws come (CpuBackend's stream), and run() the rest.
  void start(raster::Bins& bins, int workers, bool painter);
  // Job `job`, numbered `number` in the frame, on worker `worker` (a batch's or a
  // clear's, whose plans live outside the DrawList until the frame ends).
  void run_job(raster::Bins& bins, const Job& job, const geometry::BatchDrawPlan* batch,
               const geometry::ClearPlan* clear, uint32_t number, int worker, int width, int height);
  // Runs `jobs` (their nonfinite counts filled in), numbered from `first_number` on, into
  // `bins`, for a width x height framebuffer, on every core. After start().
  void run(ThreadPool& pool, raster::Bins& bins, const geometry::DrawList& plan, std::vector<Job>& jobs,
           uint32_t first_number, int width, int height);
  // Adds the workers' counts of the last run to `stats`.
  void add_stats(FrameStats& stats) const;
  // One warning per mesh with non-finite vertices (not one per frame, nor per
  // triangle). The set only grows with distinct bad meshes; a long-running program that
  // makes new ones forever forgets them now and then (and may warn again) rather than
  // grow.
  void warn_nonfinite(const geometry::DrawList& plan, const std::vector<Job>& jobs);

 private:
  std::vector<FrameStats> worker_stats_;
  std::vector<std::vector<uint32_t>> survivors_;  // per worker: the first pass's survivors
  std::vector<std::vector<uint8_t>> marks_;       // per worker: vertices drawn as points
  std::vector<size_t> nonfinite_;                 // per mesh draw
  std::unordered_set<const Mesh*> warned_meshes_;
};

}  // namespace velocity::triangle
