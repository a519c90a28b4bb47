// The C entry points of GL 1.5's buffer objects (buffer_objects.cpp) and occlusion
// queries (occlusion.cpp), under their core names and ARB_vertex_buffer_object's and
// ARB_occlusion_query's (the same functions); glGetPointerv.
// The buffer and query calls are never compiled into a display list (GL 1.5, 5.4).
#include <GL/gl.h>

#include <algorithm>
#include <cstdint>

#include "api_entry.hpp"
#include "context.hpp"

extern "C" {

void glGenBuffers(GLsizei n, GLuint* buffers) { NOW(c.gen_buffers(n, buffers)); }
void glDeleteBuffers(GLsizei n, const GLuint* buffers) { NOW(c.delete_buffers(n, buffers)); }
void glBindBuffer(GLenum target, GLuint buffer) { NOW(c.bind_buffer(target, buffer)); }
GLboolean glIsBuffer(GLuint buffer) {
  GLboolean r = GL_FALSE;
  NOW(if (!c.in_begin_error()) r = c.is_buffer(buffer) ? GL_TRUE : GL_FALSE);
  return r;
}
void glBufferData(GLenum target, GLsizeiptr size, const GLvoid* data, GLenum usage) {
  NOW(c.buffer_data(target, size, data, usage));
}
void glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const GLvoid* data) {
  NOW(c.buffer_sub_data(target, offset, size, data));
}
void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, GLvoid* data) {
  NOW(c.get_buffer_sub_data(target, offset, size, data));
}
GLvoid* glMapBuffer(GLenum target, GLenum access) {
  GLvoid* r = nullptr;
  NOW(r = c.map_buffer(target, access));
  return r;
}
GLboolean glUnmapBuffer(GLenum target) {
  GLboolean r = GL_FALSE;
  NOW(r = c.unmap_buffer(target));
  return r;
}
void glGetBufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  NOW(c.get_buffer_parameter(target, pname, params));
}
void glGetBufferPointerv(GLenum target, GLenum pname, GLvoid** params) {
  NOW(c.get_buffer_pointer(target, pname, params));
}

void glGenBuffersARB(GLsizei n, GLuint* buffers) { glGenBuffers(n, buffers); }
void glDeleteBuffersARB(GLsizei n, const GLuint* buffers) { glDeleteBuffers(n, buffers); }
void glBindBufferARB(GLenum target, GLuint buffer) { glBindBuffer(target, buffer); }
GLboolean glIsBufferARB(GLuint buffer) { return glIsBuffer(buffer); }
void glBufferDataARB(GLenum target, GLsizeiptrARB size, const GLvoid* data, GLenum usage) {
  glBufferData(target, size, data, usage);
}
void glBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size, const GLvoid* data) {
  glBufferSubData(target, offset, size, data);
}
void glGetBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size, GLvoid* data) {
  glGetBufferSubData(target, offset, size, data);
}
GLvoid* glMapBufferARB(GLenum target, GLenum access) { return glMapBuffer(target, access); }
GLboolean glUnmapBufferARB(GLenum target) { return glUnmapBuffer(target); }
void glGetBufferParameterivARB(GLenum target, GLenum pname, GLint* params) {
  glGetBufferParameteriv(target, pname, params);
}
void glGetBufferPointervARB(GLenum target, GLenum pname, GLvoid** params) { glGetBufferPointerv(target, pname, params); }

void glGenQueries(GLsizei n, GLuint* ids) { NOW(c.gen_queries(n, ids)); }
void glDeleteQueries(GLsizei n, const GLuint* ids) { NOW(c.delete_queries(n, ids)); }
GLboolean glIsQuery(GLuint id) {
  GLboolean r = GL_FALSE;
  NOW(if (!c.in_begin_error()) r = c.is_query(id) ? GL_TRUE : GL_FALSE);
  return r;
}
void glBeginQuery(GLenum target, GLuint id) { NOW(c.begin_query(target, id)); }
void glEndQuery(GLenum target) { NOW(c.end_query(target)); }
void glGetQueryiv(GLenum target, GLenum pname, GLint* params) { NOW(c.get_query(target, pname, params)); }
// The count as GL's integer types hold it: clamped to their largest value.
void glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params) {
  NOW(uint64_t v; if (c.get_query_object(id, pname, &v) && params) *params = GLint(std::min<uint64_t>(v, 0x7fffffff)));
}
void glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint* params) {
  NOW(uint64_t v; if (c.get_query_object(id, pname, &v) && params) *params = GLuint(std::min<uint64_t>(v, 0xffffffffu)));
}

void glGenQueriesARB(GLsizei n, GLuint* ids) { glGenQueries(n, ids); }
void glDeleteQueriesARB(GLsizei n, const GLuint* ids) { glDeleteQueries(n, ids); }
GLboolean glIsQueryARB(GLuint id) { return glIsQuery(id); }
void glBeginQueryARB(GLenum target, GLuint id) { glBeginQuery(target, id); }
void glEndQueryARB(GLenum target) { glEndQuery(target); }
void glGetQueryivARB(GLenum target, GLenum pname, GLint* params) { glGetQueryiv(target, pname, params); }
void glGetQueryObjectivARB(GLuint id, GLenum pname, GLint* params) { glGetQueryObjectiv(id, pname, params); }
void glGetQueryObjectuivARB(GLuint id, GLenum pname, GLuint* params) { glGetQueryObjectuiv(id, pname, params); }

// The pointers the gl*Pointer calls and the selection and feedback buffers were given
// (an offset, for an array in a buffer object).
void glGetPointerv(GLenum pname, GLvoid** params) {
  NOW(if (c.in_begin_error()) return; const void* p = nullptr; switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: p = c.arrays.vertex.pointer; break;
    case GL_NORMAL_ARRAY_POINTER: p = c.arrays.normal.pointer; break;
    case GL_COLOR_ARRAY_POINTER: p = c.arrays.color.pointer; break;
    case GL_TEXTURE_COORD_ARRAY_POINTER: p = c.arrays.texcoord.pointer; break;
    case GL_EDGE_FLAG_ARRAY_POINTER: p = c.arrays.edge_pointer; break;
    case GL_SELECTION_BUFFER_POINTER: p = c.selection().buffer; break;
    case GL_FEEDBACK_BUFFER_POINTER: p = c.feedback().buffer; break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: p = c.arrays.secondary_color.pointer; break;
    case GL_FOG_COORD_ARRAY_POINTER: p = c.arrays.fog_coord.pointer; break;
    case GL_INDEX_ARRAY_POINTER: p = c.arrays.index.pointer; break;
    default: return c.error(GL_INVALID_ENUM);
  } if (params) *params = const_cast<void*>(p));
}

}  // extern "C"
