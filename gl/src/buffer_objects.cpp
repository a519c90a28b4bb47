// GL 1.5's buffer objects (ARB_vertex_buffer_object): vertex and index data kept by the
// library in its own memory. glGenBuffers reserves names; the object is made when a
// name is first bound. With a buffer bound to GL_ARRAY_BUFFER, the gl*Pointer calls
// take an offset into it (each array keeps the buffer it was given: ClientArray::buffer);
// with one bound to GL_ELEMENT_ARRAY_BUFFER, glDrawElements' indices are an offset
// into that. The arrays are read when the draw is made (the vertex stage runs then),
// so a buffer changed after a draw changes nothing drawn. A draw from a mapped buffer
// reads what it holds (no error: Mesa gives none; GL 1.5 leaves it undefined).
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
bool valid_usage(GLenum u) {
  switch (u) {
    case GL_STREAM_DRAW: case GL_STREAM_READ: case GL_STREAM_COPY:
    case GL_STATIC_DRAW: case GL_STATIC_READ: case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW: case GL_DYNAMIC_READ: case GL_DYNAMIC_COPY:
      return true;
    default: return false;
  }
}
}  // namespace

std::shared_ptr<BufferObject>* Context::buffer_binding(GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER: return &arrays.array_buffer;
    case GL_ELEMENT_ARRAY_BUFFER: return &arrays.element_buffer;
    default: error(GL_INVALID_ENUM); return nullptr;
  }
}

// The buffer bound to `target`, or null with GL's error (a bad target, or none bound).
BufferObject* Context::bound_buffer(GLenum target) {
  std::shared_ptr<BufferObject>* b = buffer_binding(target);
  if (!b) return nullptr;
  if (!*b) error(GL_INVALID_OPERATION);
  return b->get();
}

void Context::gen_buffers(GLsizei n, GLuint* out) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!out) return;
  for (GLsizei i = 0; i < n; ++i) {
    while (buffers_.next_name == 0 || buffers_.objects.count(buffers_.next_name)) ++buffers_.next_name;
    out[i] = buffers_.next_name++;
  }
}

void Context::delete_buffers(GLsizei n, const GLuint* ids) {
  if (in_begin_error()) return;
  if (n < 0) return error(GL_INVALID_VALUE);
  if (!ids) return;
  for (GLsizei i = 0; i < n; ++i) {
    auto it = buffers_.objects.find(ids[i]);
    if (ids[i] == 0 || it == buffers_.objects.end()) continue;  // unused names are ignored
    const BufferObject* gone = it->second.get();
    // Every binding to it in this context goes back to 0 (GL 1.5, 2.9). An array that
    // read from it is left with no data (rather than its offset taken as an address).
    for (ClientArray* a : {&arrays.vertex, &arrays.normal, &arrays.color, &arrays.texcoord})
      if (a->buffer.get() == gone) a->buffer.reset(), a->pointer = nullptr;
    if (arrays.edge_buffer.get() == gone) arrays.edge_buffer.reset(), arrays.edge_pointer = nullptr;
    if (arrays.array_buffer.get() == gone) arrays.array_buffer.reset();
    if (arrays.element_buffer.get() == gone) arrays.element_buffer.reset();
    it->second->mapped = false;  // deleting a mapped buffer unmaps it
    buffers_.total_bytes -= it->second->size;
    buffers_.objects.erase(it);
  }
}

void Context::bind_buffer(GLenum target, GLuint id) {
  if (in_begin_error()) return;
  std::shared_ptr<BufferObject>* b = buffer_binding(target);
  if (!b) return;
  if (id == 0) return b->reset();
  if (!buffers_.objects.count(id) && buffers_.objects.size() >= kMaxBufferObjects) return error(GL_OUT_OF_MEMORY);
  std::shared_ptr<BufferObject>& object = buffers_.objects[id];  // a name is made a buffer on first bind
  if (!object) {
    object = std::make_shared<BufferObject>();
    object->name = id;
    object->data.resize(1);
  }
  *b = object;
}

void Context::buffer_data(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  if (in_begin_error()) return;
  if (!buffer_binding(target)) return;
  if (size < 0) return error(GL_INVALID_VALUE);
  if (!valid_usage(usage)) return error(GL_INVALID_ENUM);
  BufferObject* b = bound_buffer(target);
  if (!b) return;
  const size_t bytes = size_t(size);
  const size_t others = buffers_.total_bytes - b->size;
  if (bytes > kMaxBufferBytes || bytes > kMaxBufferTotalBytes - others) return error(GL_OUT_OF_MEMORY);
  // New storage (a buffer mapped is unmapped, as Mesa does); the old contents go.
  std::vector<uint8_t> storage(bytes ? bytes : 1);
  if (data && bytes) std::memcpy(storage.data(), data, bytes);
  b->data.swap(storage);
  b->size = bytes;
  b->usage = usage;
  b->mapped = false;
  b->access = GL_READ_WRITE;
  buffers_.total_bytes = others + bytes;
}

// glBufferSubData's and glGetBufferSubData's checks: the range inside the buffer, which
// is not mapped.
BufferObject* Context::buffer_range(GLenum target, GLintptr offset, GLsizeiptr size) {
  if (in_begin_error()) return nullptr;
  if (!buffer_binding(target)) return nullptr;
  BufferObject* b = bound_buffer(target);
  if (!b) return nullptr;
  if (offset < 0 || size < 0 || size_t(offset) > b->size || size_t(size) > b->size - size_t(offset)) {
    error(GL_INVALID_VALUE);
    return nullptr;
  }
  if (b->mapped) {
    error(GL_INVALID_OPERATION);
    return nullptr;
  }
  return b;
}

void Context::buffer_sub_data(GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  BufferObject* b = buffer_range(target, offset, size);
  if (b && data && size) std::memcpy(b->data.data() + offset, data, size_t(size));
}

void Context::get_buffer_sub_data(GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  const BufferObject* b = buffer_range(target, offset, size);
  if (b && data && size) std::memcpy(data, b->data.data() + offset, size_t(size));
}

void* Context::map_buffer(GLenum target, GLenum access) {
  if (in_begin_error()) return nullptr;
  if (!buffer_binding(target)) return nullptr;
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    error(GL_INVALID_ENUM);
    return nullptr;
  }
  BufferObject* b = bound_buffer(target);
  if (!b) return nullptr;
  if (b->mapped) {
    error(GL_INVALID_OPERATION);
    return nullptr;
  }
  b->mapped = true;
  b->access = access;
  return b->data.data();
}

GLboolean Context::unmap_buffer(GLenum target) {
  if (in_begin_error()) return GL_FALSE;
  if (!buffer_binding(target)) return GL_FALSE;
  BufferObject* b = bound_buffer(target);
  if (!b) return GL_FALSE;
  if (!b->mapped) {
    error(GL_INVALID_OPERATION);
    return GL_FALSE;
  }
  b->mapped = false;
  b->access = GL_READ_WRITE;
  return GL_TRUE;  // the library's memory is never lost
}

void Context::get_buffer_parameter(GLenum target, GLenum pname, GLint* out) {
  if (in_begin_error()) return;
  if (!buffer_binding(target)) return;
  if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS && pname != GL_BUFFER_MAPPED)
    return error(GL_INVALID_ENUM);
  const BufferObject* b = bound_buffer(target);
  if (!b || !out) return;
  switch (pname) {
    case GL_BUFFER_SIZE: *out = GLint(std::min<size_t>(b->size, 0x7fffffff)); break;
    case GL_BUFFER_USAGE: *out = GLint(b->usage); break;
    case GL_BUFFER_ACCESS: *out = GLint(b->access); break;
    default: *out = b->mapped ? GL_TRUE : GL_FALSE; break;
  }
}

void Context::get_buffer_pointer(GLenum target, GLenum pname, void** out) {
  if (in_begin_error()) return;
  if (!buffer_binding(target)) return;
  if (pname != GL_BUFFER_MAP_POINTER) return error(GL_INVALID_ENUM);
  const BufferObject* b = bound_buffer(target);
  if (!b || !out) return;
  *out = b->mapped ? const_cast<uint8_t*>(b->data.data()) : nullptr;
}

bool Context::get_buffer_binding(GLenum pname, std::vector<double>& out) const {
  auto name = [](const std::shared_ptr<BufferObject>& b) { return b ? double(b->name) : 0.0; };
  switch (pname) {
    case GL_ARRAY_BUFFER_BINDING: out = {name(arrays.array_buffer)}; return true;
    case GL_ELEMENT_ARRAY_BUFFER_BINDING: out = {name(arrays.element_buffer)}; return true;
    case GL_VERTEX_ARRAY_BUFFER_BINDING: out = {name(arrays.vertex.buffer)}; return true;
    case GL_NORMAL_ARRAY_BUFFER_BINDING: out = {name(arrays.normal.buffer)}; return true;
    case GL_COLOR_ARRAY_BUFFER_BINDING: out = {name(arrays.color.buffer)}; return true;
    case GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING: out = {name(arrays.texcoord.buffer)}; return true;
    case GL_EDGE_FLAG_ARRAY_BUFFER_BINDING: out = {name(arrays.edge_buffer)}; return true;
    // (color_sum.cpp's arrays)
    case GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING: out = {name(arrays.secondary_color.buffer)}; return true;
    case GL_FOG_COORD_ARRAY_BUFFER_BINDING: out = {name(arrays.fog_coord.buffer)}; return true;
    case GL_INDEX_ARRAY_BUFFER_BINDING: out = {name(arrays.index.buffer)}; return true;
    default: return false;
  }
}

const uint8_t* Context::element_indices(GLsizei count, GLenum type, const void* indices) const {
  const BufferObject* b = arrays.element_buffer.get();
  if (!b) return static_cast<const uint8_t*>(indices);
  const size_t offset = reinterpret_cast<uintptr_t>(indices);
  const size_t bytes = size_t(count) * (type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4);
  if (offset > b->size || bytes > b->size - offset) return nullptr;  // past the buffer's end: nothing is drawn
  return b->data.data() + offset;
}

}  // namespace velocity::gl
