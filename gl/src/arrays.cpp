// Vertex arrays: fetching an element's attributes, and glArrayElement, glDrawArrays and
// glDrawElements, which feed the vertex stage as glBegin/glEnd would.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "context.hpp"

namespace velocity::gl {

namespace {
size_t type_size(GLenum t) {
  switch (t) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_DOUBLE: return 8;
    default: return 4;
  }
}
}  // namespace

const unsigned char* ClientArray::element(GLint index, size_t bytes) const {
  const size_t at = size_t(index) * (stride ? size_t(stride) : bytes);
  if (!buffer) return static_cast<const unsigned char*>(pointer) + at;
  // In a buffer object: the offset and the element inside its data (a buffer holds
  // at most kMaxBufferBytes, so none of these sums overflows).
  const size_t offset = reinterpret_cast<uintptr_t>(pointer), n = buffer->size;
  if (offset > n || at > n - offset || bytes > n - offset - at) return nullptr;
  return buffer->data.data() + offset + at;
}

bool ArrayState::edge(GLint i) const {
  if (edge_buffer) {
    const size_t at = reinterpret_cast<uintptr_t>(edge_pointer) + size_t(i) * size_t(edge_stride ? edge_stride : 1);
    return at < edge_buffer->size ? edge_buffer->data[at] != 0 : true;
  }
  return edge_pointer[size_t(i) * size_t(edge_stride ? edge_stride : 1)] != 0;
}

Vec4 ClientArray::fetch(GLint index, Vec4 v) const {
  const unsigned char* p = element(index, size_t(size) * type_size(type));
  if (!p) return v;  // outside its buffer object: the current defaults
  float* out[4] = {&v.x, &v.y, &v.z, &v.w};
  for (int k = 0; k < size && k < 4; ++k) {
    float f;
    switch (type) {
      case GL_FLOAT: { float x; std::memcpy(&x, p + 4 * k, 4); f = x; break; }
      case GL_DOUBLE: { double x; std::memcpy(&x, p + 8 * k, 8); f = float(x); break; }
      case GL_INT: { int32_t x; std::memcpy(&x, p + 4 * k, 4); f = float(x); break; }
      case GL_UNSIGNED_INT: { uint32_t x; std::memcpy(&x, p + 4 * k, 4); f = float(x); break; }
      case GL_SHORT: { int16_t x; std::memcpy(&x, p + 2 * k, 2); f = float(x); break; }
      case GL_UNSIGNED_SHORT: { uint16_t x; std::memcpy(&x, p + 2 * k, 2); f = float(x); break; }
      case GL_BYTE: f = float(int8_t(p[k])); break;
      default: f = float(p[k]); break;
    }
    *out[k] = f;
  }
  return v;
}

Vec4 ClientArray::fetch_normalized(GLint index, Vec4 defaults, int components) const {
  float scale;
  switch (type) {
    case GL_BYTE: scale = 1.0f / 127; break;
    case GL_UNSIGNED_BYTE: scale = 1.0f / 255; break;
    case GL_SHORT: scale = 1.0f / 32767; break;
    case GL_UNSIGNED_SHORT: scale = 1.0f / 65535; break;
    case GL_INT: scale = 1.0f / 2147483647.0f; break;
    case GL_UNSIGNED_INT: scale = 1.0f / 4294967295.0f; break;
    default: return fetch(index, defaults);
  }
  Vec4 v = fetch(index, defaults);
  float* c[4] = {&v.x, &v.y, &v.z, &v.w};
  for (int k = 0; k < components && k < 4; ++k) *c[k] *= scale;
  return v;
}

void Context::client_state(GLenum cap, bool on) {
  switch (cap) {
    case GL_VERTEX_ARRAY: arrays.vertex.enabled = on; break;
    case GL_NORMAL_ARRAY: arrays.normal.enabled = on; break;
    case GL_COLOR_ARRAY: arrays.color.enabled = on; break;
    case GL_TEXTURE_COORD_ARRAY: arrays.texcoord.enabled = on; break;
    case GL_EDGE_FLAG_ARRAY: arrays.edge_enabled = on; break;
    default:
      if (color_sum_client_state(cap, on)) break;  // (color_sum.cpp)
      error(GL_INVALID_ENUM);
  }
}

void Context::array_element(GLint i) {
  if (i < 0) return error(GL_INVALID_VALUE);
  note_array_extras();
  element(i);
}

// Are the arrays GL 1.3 and 1.4 add (the texture unit glClientActiveTexture does not
// name, the secondary colour, the fog coordinate) on? Once per draw, not per element.
void Context::note_array_extras() {
  array_extras_ = parked_texcoord_.enabled || arrays.secondary_color.enabled || arrays.fog_coord.enabled;
}

void Context::element(GLint i) {
  if (arrays.color.enabled && arrays.color.usable())
    set_color(arrays.color.fetch_normalized(i, {0, 0, 0, 1}, arrays.color.size));
  if (arrays.normal.enabled && arrays.normal.usable()) normal_ = arrays.normal.fetch_normalized(i, {}, 3).xyz();
  // The coordinates of the unit glClientActiveTexture names (multitexture.cpp).
  if (arrays.texcoord.enabled && arrays.texcoord.usable())
    (live_client_unit_ == 0 ? texcoord_ : texcoord1_) = arrays.texcoord.fetch(i, {0, 0, 0, 1});
  if (arrays.edge_enabled && arrays.edge_usable()) edge_flag_ = arrays.edge(i);
  if (array_extras_) {
    if (const ClientArray& t = parked_texcoord_; t.enabled && t.usable())
      (live_client_unit_ == 0 ? texcoord1_ : texcoord_) = t.fetch(i, {0, 0, 0, 1});
    if (arrays.secondary_color.enabled && arrays.secondary_color.usable())
      secondary_ = arrays.secondary_color.fetch_normalized(i, {0, 0, 0, 1}, 3);
    if (arrays.fog_coord.enabled && arrays.fog_coord.usable()) fog_coord_ = arrays.fog_coord.fetch(i, {}).x;
  }
  if (arrays.vertex.enabled && arrays.vertex.usable()) vertex(arrays.vertex.fetch(i, {0, 0, 0, 1}));
}

// GL leaves the current colour, normal, texture coordinates and edge flag undefined
// after glDrawArrays or glDrawElements with their arrays enabled; Mesa leaves them (and
// the material GL_COLOR_MATERIAL makes follow the colour) as they were before the draw,
// and programs count on it (piglit's draw-vertices draws white after coloured arrays).
// glArrayElement does set them, as the immediate-mode calls it stands for.
struct Context::KeptCurrent {
  Vec4 color, texcoord;
  Vec3 normal;
  bool edge;
  Material materials[2];
  Vec4 secondary;
  float fog_coord;
  Vec4 texcoord1;
};

Context::KeptCurrent Context::keep_current() const {
  return {color_, texcoord_, normal_, edge_flag_, {lighting_.materials[0], lighting_.materials[1]}, secondary_, fog_coord_, texcoord1_};
}

void Context::restore_current(const KeptCurrent& k) {
  color_ = k.color, texcoord_ = k.texcoord, normal_ = k.normal, edge_flag_ = k.edge;
  lighting_.materials[0] = k.materials[0], lighting_.materials[1] = k.materials[1];
  secondary_ = k.secondary, fog_coord_ = k.fog_coord, texcoord1_ = k.texcoord1;
}

void Context::draw_arrays(GLenum mode, GLint first, GLsizei count) {
  if (mode > GL_POLYGON) return error(GL_INVALID_ENUM);
  if (count < 0 || first < 0) return error(GL_INVALID_VALUE);
  if (in_begin_error()) return;
  if (!arrays.vertex.enabled || !arrays.vertex.usable()) return;
  const KeptCurrent kept = keep_current();
  begin(mode);
  note_array_extras();
  for (int64_t i = first; i < int64_t(first) + count && i <= INT32_MAX; ++i) element(GLint(i));
  end();
  restore_current(kept);
}

// glDrawElements(GL_TRIANGLES) on the quick path (context.hpp): the vertices the
// general path would make, in the same order (each element's first reference), with
// the same triangles, but read from the arrays and lit in runs, and no Vertex records.
// Only the positions and normals matter under the quick path's lighting: colours,
// texture coordinates, edge flags and the GL 1.3/1.4 extras are not read (the general
// path's current values would be put back after the draw). The triangles go to the
// batch every kQuickRun references, so that the renderer's workers set up the first
// batches while the rest are fetched.
template <class IndexAt>
void Context::quick_elements(GLsizei count, const IndexAt& index_at, size_t cache_size) {
  const ClientArray& va = arrays.vertex;
  const ClientArray& na = arrays.normal;
  const bool normals = na.enabled && na.usable();
  // Plain float arrays in the caller's memory are read directly; others through fetch.
  const bool plain_v = !va.buffer && va.type == GL_FLOAT && (va.size == 3 || va.size == 4);
  const bool plain_n = normals && !na.buffer && na.type == GL_FLOAT && na.size == 3;
  const auto* vbase = static_cast<const unsigned char*>(va.pointer);
  const auto* nbase = static_cast<const unsigned char*>(na.pointer);
  const size_t vstride = va.stride ? size_t(va.stride) : size_t(va.size) * 4, nstride = na.stride ? size_t(na.stride) : 12;
  grow_quick_arrays(size_t(count));
  quick_order_.clear();
  uint32_t fetched = 0, lit = 0;  // vertices made, and lit
  auto assemble_run = [&] {
    light_vertices(quick_position_.data() + lit, quick_normal_.data() + lit, fetched - lit, quick_clip_.data() + lit,
                   quick_color_.data() + lit);
    lit = fetched;
    emitted_.resize(fetched);  // (new vertices are in no batch)
    const size_t whole = quick_order_.size() / 3;
    quick_triangles<true>(quick_clip_.data(), quick_color_.data(), quick_order_.data(), whole);
    quick_order_.erase(quick_order_.begin(), quick_order_.begin() + ptrdiff_t(3 * whole));
  };
  for (GLsizei k = 0; k < count; ++k) {
    const uint32_t i = index_at(k);
    if (i > 0x7fffffffu) continue;
    if (i < cache_size && element_cache_[i]) {
      quick_order_.push_back(element_cache_[i] - 1);
    } else {
      Vec4& p = quick_position_[fetched];
      if (plain_v) {
        // (A copy of a size known here: one of a size known at run time is a call.)
        float f[4] = {0, 0, 0, 1};
        const unsigned char* from = vbase + size_t(i) * vstride;
        if (va.size == 3) std::memcpy(f, from, 12);
        else std::memcpy(f, from, 16);
        p.x = f[0], p.y = f[1], p.z = f[2], p.w = f[3];
      } else {
        p = va.fetch(GLint(i), {0, 0, 0, 1});
      }
      Vec3& n = quick_normal_[fetched];
      if (plain_n) {
        std::memcpy(&n, nbase + size_t(i) * nstride, sizeof(Vec3));
      } else {
        n = normals ? na.fetch_normalized(GLint(i), {}, 3).xyz() : normal_;
      }
      if (i < cache_size) element_cache_[i] = fetched + 1;
      quick_order_.push_back(fetched++);
    }
    if (quick_order_.size() >= kQuickRun) assemble_run();
  }
  assemble_run();  // (one or two references left over are dropped)
}

void Context::draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (mode > GL_POLYGON) return error(GL_INVALID_ENUM);
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) return error(GL_INVALID_ENUM);
  if (count < 0) return error(GL_INVALID_VALUE);
  if (in_begin_error()) return;
  const uint8_t* bytes = element_indices(count, type, indices);  // (buffer_objects.cpp)
  if (!arrays.vertex.enabled || !arrays.vertex.usable() || !bytes) return;
  auto index_at = [&](GLsizei k) -> uint32_t {
    if (type == GL_UNSIGNED_BYTE) return bytes[k];
    if (type == GL_UNSIGNED_SHORT) {
      uint16_t s;
      std::memcpy(&s, bytes + 2 * size_t(k), 2);
      return s;
    }
    uint32_t i;
    std::memcpy(&i, bytes + 4 * size_t(k), 4);
    return i;
  };
  // Each element is processed once however often it is referenced (the vertex stage is
  // a function of the element: the arrays cannot change during the call). The cache
  // covers the indices up to the largest one, bounded by a multiple of the count.
  uint32_t largest = 0;
  for (GLsizei k = 0; k < count; ++k) largest = std::max(largest, index_at(k));
  const size_t cache_size = std::min(size_t(largest) + 1, size_t(count) * 4 + 1024);
  element_cache_.assign(cache_size, 0);
  const KeptCurrent kept = keep_current();
  begin(mode);
  if (quick_ && size_t(count) <= kMaxPrimitiveVertices) {
    quick_elements(count, index_at, cache_size);
    end();
    return restore_current(kept);
  }
  quick_ = false;  // (prim_ and the element cache below, vertex by vertex)
  note_array_extras();
  caching_ = true;
  for (GLsizei k = 0; k < count; ++k) {
    const uint32_t i = index_at(k);
    if (i > 0x7fffffffu) continue;
    if (i < cache_size && element_cache_[i]) {
      if (order_.size() < kMaxPrimitiveVertices) order_.push_back(element_cache_[i] - 1);
      continue;
    }
    const size_t before = prim_.size();
    element(GLint(i));
    if (i < cache_size && prim_.size() > before) element_cache_[i] = uint32_t(prim_.size());
  }
  caching_ = false;
  end();
  restore_current(kept);
}

}  // namespace velocity::gl
