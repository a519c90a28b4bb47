#include "triangle/stage.hpp"

#include <algorithm>
#include <string>

#include "velocity/log.hpp"

namespace velocity::triangle {

void TriangleStage::start(raster::Bins& bins, int workers, bool painter) {
  bins.clear(painter);
  worker_stats_.assign(size_t(workers), FrameStats{});
  survivors_.resize(size_t(workers));
  for (auto& s : survivors_) s.resize(3 * kTrianglesPerJob);
  marks_.resize(size_t(workers));
}

void TriangleStage::run_job(raster::Bins& bins, const Job& job, const geometry::BatchDrawPlan* batch,
                            const geometry::ClearPlan* clear, uint32_t number, int worker, int width, int height) {
  StageContext cx{bins.worker(worker), worker_stats_[size_t(worker)]};
  cx.job = number;
  cx.direct = survivors_[size_t(worker)].data();
  cx.info = cx.direct + kTrianglesPerJob, cx.clipped = cx.info + kTrianglesPerJob;
  if (job.kind == Job::Kind::Batch) run_batch_job(*batch, job.begin, job.end, cx);
  else if (job.kind == Job::Kind::Clear) run_clear_job(*clear, width, height, cx);
}

void TriangleStage::run(ThreadPool& pool, raster::Bins& bins, const geometry::DrawList& plan, std::vector<Job>& jobs,
                        uint32_t first_number, int width, int height) {
  // Points mark the vertices they drew: room for the largest such mesh on every worker,
  // whichever worker its jobs fall on.
  size_t most = 0;
  for (const auto& d : plan.meshes)
    if (!d.fill_only) most = std::max(most, d.mesh->positions.size());
  for (auto& m : marks_)
    if (m.size() < most) m.resize(most);
  pool.run(int(jobs.size()), [&](int i, int worker) {
    Job& job = jobs[size_t(i)];
    StageContext cx{bins.worker(worker), worker_stats_[size_t(worker)]};
    cx.job = first_number + uint32_t(i);
    cx.direct = survivors_[size_t(worker)].data();
    cx.info = cx.direct + kTrianglesPerJob, cx.clipped = cx.info + kTrianglesPerJob;
    cx.marks = &marks_[size_t(worker)];
    switch (job.kind) {
      case Job::Kind::Mesh: run_mesh_job(plan, plan.meshes[job.draw], job.begin, job.end, cx); break;
      case Job::Kind::Batch: run_batch_job(plan.batches[job.draw], job.begin, job.end, cx); break;
      case Job::Kind::Clear: run_clear_job(plan.clears[job.draw], width, height, cx); break;
    }
    job.nonfinite = cx.nonfinite;
  });
}

void TriangleStage::add_stats(FrameStats& s) const {
  for (const FrameStats& w : worker_stats_) {
    s.objects_culled += w.objects_culled, s.triangles += w.triangles, s.triangles_rejected += w.triangles_rejected;
    s.triangles_nonfinite += w.triangles_nonfinite, s.triangles_clipped += w.triangles_clipped;
    s.triangles_culled += w.triangles_culled, s.triangles_rasterized += w.triangles_rasterized;
    s.lines += w.lines, s.points += w.points;
  }
}

void TriangleStage::warn_nonfinite(const geometry::DrawList& plan, const std::vector<Job>& jobs) {
  std::vector<size_t>& bad = nonfinite_;
  bad.assign(plan.meshes.size(), 0);
  for (const Job& j : jobs)
    if (j.kind == Job::Kind::Mesh) bad[j.draw] += j.nonfinite;
  for (size_t i = 0; i < bad.size(); ++i) {
    if (!bad[i]) continue;
    const Mesh* mesh = plan.meshes[i].mesh;
    if (warned_meshes_.size() >= 4096) warned_meshes_.clear();
    if (warned_meshes_.insert(mesh).second)
      warn("mesh '" + mesh->name + "': " + std::to_string(bad[i]) + " triangles with NaN or infinite coordinates were dropped");
  }
}

}  // namespace velocity::triangle
