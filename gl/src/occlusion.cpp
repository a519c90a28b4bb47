// GL 1.5's occlusion queries (ARB_occlusion_query): glBeginQuery(GL_SAMPLES_PASSED)
// makes the draws that follow count the fragments that pass the stencil and depth
// tests (PixelState::samples_passed: the renderer's fixed-function kernel counts them
// as the frame's tiles finish) until glEndQuery. The count is known once the frame
// holding those draws has run, so asking for the result (or whether it is available)
// runs it if it has not run: the answer is always available, and exact.
#include <algorithm>

#include "context.hpp"

namespace velocity::gl {

void Context::settle_query(QueryObject& q) {
  if (q.pending && (in_frame_ || have_pending_)) run_frame();
  q.pending = false;
}

void Context::gen_queries(GLsizei n, GLuint* out) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!out) return;
  for (GLsizei i = 0; i < n; ++i) {
    while (queries_.next_name == 0 || queries_.objects.count(queries_.next_name)) ++queries_.next_name;
    out[i] = queries_.next_name++;
  }
}

void Context::delete_queries(GLsizei n, const GLuint* ids) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = queries_.objects.find(ids[i]);
    if (it == queries_.objects.end()) continue;
    if (ids[i] == queries_.active) {  // deleting the active query ends it (as Mesa)
      queries_.active = 0, queries_.active_object = nullptr;
      changed();
      it->second->pending = true;
    }
    settle_query(*it->second);  // no pending draw may count into it once it is gone
    queries_.objects.erase(it);
  }
}

void Context::begin_query(GLenum target, GLuint id) {
  if (in_begin_error()) return;
  if (target != GL_SAMPLES_PASSED) return error(GL_INVALID_ENUM);
  if (id == 0 || queries_.active != 0) return error(GL_INVALID_OPERATION);
  if (!queries_.objects.count(id) && queries_.objects.size() >= kMaxQueryObjects) return error(GL_OUT_OF_MEMORY);
  std::unique_ptr<QueryObject>& q = queries_.objects[id];  // a name is made a query when first begun
  if (!q) q = std::make_unique<QueryObject>();
  settle_query(*q);  // draws of its last use still pending count into it: run them first
  q->samples.store(0, std::memory_order_relaxed);
  queries_.active = id, queries_.active_object = q.get();
  changed();  // the draws from here on count (a new batch)
}

void Context::end_query(GLenum target) {
  if (in_begin_error()) return;
  if (target != GL_SAMPLES_PASSED) return error(GL_INVALID_ENUM);
  if (queries_.active == 0) return error(GL_INVALID_OPERATION);
  queries_.active_object->pending = true;
  queries_.active = 0, queries_.active_object = nullptr;
  changed();
}

void Context::get_query(GLenum target, GLenum pname, GLint* out) {
  if (in_begin_error()) return;
  if (target != GL_SAMPLES_PASSED) return error(GL_INVALID_ENUM);
  GLint v;
  switch (pname) {
    case GL_QUERY_COUNTER_BITS: v = 64; break;  // the renderer counts in 64 bits
    case GL_CURRENT_QUERY: v = GLint(queries_.active); break;
    default: return error(GL_INVALID_ENUM);
  }
  if (out) *out = v;
}

bool Context::get_query_object(GLuint id, GLenum pname, uint64_t* out) {
  if (in_begin_error()) return false;
  auto it = queries_.objects.find(id);
  if (it == queries_.objects.end() || id == queries_.active) return error(GL_INVALID_OPERATION), false;
  if (pname != GL_QUERY_RESULT && pname != GL_QUERY_RESULT_AVAILABLE) return error(GL_INVALID_ENUM), false;
  settle_query(*it->second);
  *out = pname == GL_QUERY_RESULT ? it->second->samples.load(std::memory_order_relaxed) : 1;
  return true;
}

}  // namespace velocity::gl
