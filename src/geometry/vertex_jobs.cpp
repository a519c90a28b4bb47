#include "geometry/vertex_jobs.hpp"

#include <algorithm>
#include <new>
#include <string>

#include "geometry/vertex_stage.hpp"
#include "velocity/error.hpp"

namespace velocity::geometry {

namespace {

// Big enough that a chunk's overhead is nothing, small enough that every core gets a
// share of one large mesh.
constexpr size_t kVerticesPerJob = 8192;

template <class T>
void grow(std::vector<T>& v, size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace

// The vertex stage's outputs for every draw, in one set of arrays.
void VertexStage::allocate(DrawList& p) {
  size_t total = 0;
  bool light = false, specular = false, normal = false, eye = false;
  for (auto& d : p.meshes) {
    d.vertex_base = total, total += d.mesh->positions.size();
    light |= d.light, specular |= d.vertex_specular_terms, normal |= d.normal, eye |= d.eye;
  }
  for (auto& b : p.batches) b.vertex_base = total, total += b.batch.vertex_count;
  VertexArrays& v = p.vertices;
  try {
    grow(v.projected, total), grow(v.codes, total);
    if (light) grow(v.diffuse, total);
    if (specular) grow(v.specular, total);
    if (normal) grow(v.normal, total);
    if (eye) grow(v.eye, total);
  } catch (const std::bad_alloc&) {
    throw Error("frame: out of memory for " + std::to_string(total) + " vertices");
  }
}

void VertexStage::run(ThreadPool& pool, DrawList& plan) {
  allocate(plan);
  std::vector<Chunk>& work = chunks_;
  work.clear();
  for (uint32_t i = 0; i < plan.meshes.size(); ++i)
    for (size_t b = 0, n = plan.meshes[i].mesh->positions.size(); b < n; b += kVerticesPerJob)
      work.push_back({false, i, b, std::min<size_t>(b + kVerticesPerJob, n)});
  for (uint32_t i = 0; i < plan.batches.size(); ++i)
    for (size_t b = 0, n = plan.batches[i].batch.vertex_count; b < n; b += kVerticesPerJob)
      work.push_back({true, i, b, std::min<size_t>(b + kVerticesPerJob, n)});
  VertexArrays& va = plan.vertices;
  for (BatchDrawPlan& b : plan.batches)
    b.projected = va.projected.data() + b.vertex_base, b.codes = va.codes.data() + b.vertex_base;
  pool.run(int(work.size()), [&](int i) {
    const Chunk& w = work[size_t(i)];
    if (w.batch) {
      const BatchDrawPlan& b = plan.batches[w.draw];
      ClipVertexJob job;
      job.positions = b.batch.position, job.begin = w.begin, job.end = w.end, job.viewport = b.viewport;
      job.out.projected = va.projected.data() + b.vertex_base, job.out.codes = va.codes.data() + b.vertex_base;
      project_clip_vertices(job);
      return;
    }
    const MeshDrawPlan& d = plan.meshes[w.draw];
    MeshVertexJob job;
    job.positions = d.mesh->positions.data(), job.normals = d.normals->data();
    job.begin = w.begin, job.end = w.end;
    job.mvp = d.mvp, job.model_view = d.model_view, job.normal_matrix = d.normal_matrix;
    job.viewport = plan.viewport;
    const size_t base = d.vertex_base;
    job.out.projected = va.projected.data() + base, job.out.codes = va.codes.data() + base;
    if (d.light) {
      job.lights = &plan.lights, job.specular = d.vertex_specular;
      job.out.diffuse = va.diffuse.data() + base;
      if (d.vertex_color) job.base_color = &d.uniform_color;
      if (d.vertex_specular_terms) job.out.specular = va.specular.data() + base;
    }
    if (d.normal) job.out.normal = va.normal.data() + base;
    if (d.eye) job.out.eye = va.eye.data() + base;
    transform_mesh_vertices(job);
  });
}

}  // namespace velocity::geometry
