// The vertex stage for a frame: the vertex arrays sized for every draw, and the draws
// cut into chunks of vertices that run on every core (vertex_stage.hpp's kernels).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/thread_pool.hpp"
#include "geometry/draw_plan.hpp"

namespace velocity::geometry {

class VertexStage {
 public:
  // Fills plan.vertices (each draw's at its vertex_base, set here). Throws
  // velocity::Error when the arrays do not fit in memory.
  void run(ThreadPool& pool, DrawList& plan);

 private:
  void allocate(DrawList& plan);

  struct Chunk {
    bool batch;
    uint32_t draw;
    size_t begin, end;
  };
  std::vector<Chunk> chunks_;  // reused across frames
};

}  // namespace velocity::geometry
