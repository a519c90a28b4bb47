// OpenGL's C entry points: each one converts its arguments, then either runs on the
// current context or, while a display list is being compiled, is recorded into it
// (and run too with GL_COMPILE_AND_EXECUTE). Commands GL never compiles (glGen*,
// glGet*, glReadPixels, client state, glFinish...) always run at once. No C++
// exception leaves an entry point: out of memory is GL_OUT_OF_MEMORY.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>

#include "api_entry.hpp"
#include "context.hpp"
#include "pixels.hpp"

using velocity::Vec3;
using velocity::Vec4;
using velocity::gl::Context;
using velocity::gl::current;
using velocity::gl::ListCommand;
using velocity::Mat4;
using velocity::gl::load_column_major;

namespace {

using velocity::gl::entry::compiled;
using velocity::gl::entry::now;

// GL's integer-to-float conversions for colours and normals.
float b2f(GLbyte v) { return (2.0f * v + 1.0f) / 255.0f; }
float s2f(GLshort v) { return (2.0f * v + 1.0f) / 65535.0f; }
float i2f(GLint v) { return float((2.0 * v + 1.0) / 4294967295.0); }
float ub2f(GLubyte v) { return v / 255.0f; }
float us2f(GLushort v) { return v / 65535.0f; }
float ui2f(GLuint v) { return float(v / 4294967295.0); }

// How many values a glLight / glMaterial / glFog / glLightModel / glTex* parameter has.
int param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_POSITION:
    case GL_AMBIENT_AND_DIFFUSE: case GL_FOG_COLOR: case GL_LIGHT_MODEL_AMBIENT: case GL_TEXTURE_ENV_COLOR:
    case GL_TEXTURE_BORDER_COLOR:
      return 4;
    case GL_SPOT_DIRECTION: return 3;
    default: return 1;
  }
}
// Integer forms of colour parameters map to [-1, 1]; others are taken as they are.
bool is_color_param(GLenum pname) { return param_count(pname) == 4 && pname != GL_POSITION; }

std::array<float, 4> params_f(GLenum pname, const GLfloat* v) {
  std::array<float, 4> p{0, 0, 0, 0};
  if (v)
    for (int i = 0; i < param_count(pname); ++i) p[size_t(i)] = v[i];
  return p;
}
std::array<float, 4> params_i(GLenum pname, const GLint* v) {
  std::array<float, 4> p{0, 0, 0, 0};
  if (v)
    for (int i = 0; i < param_count(pname); ++i)
      p[size_t(i)] = is_color_param(pname) ? float(v[i] / 2147483647.0) : float(v[i]);
  return p;
}
std::array<float, 4> param1(GLfloat v) { return {v, 0, 0, 0}; }

// A vertex array element's values, fetched now for a display list.
void record_array_element(Context& c, GLint i) {
  if (c.arrays.color.enabled && c.arrays.color.usable()) {
    const Vec4 col = c.arrays.color.fetch_normalized(i, {0, 0, 0, 1}, c.arrays.color.size);
    compiled([=](Context& k) { k.set_color(col); });
  }
  if (c.arrays.normal.enabled && c.arrays.normal.usable()) {
    const Vec3 n = c.arrays.normal.fetch_normalized(i, {}, 3).xyz();
    compiled([=](Context& k) { k.set_normal(n); });
  }
  for (GLenum unit : {GLenum(GL_TEXTURE0), GLenum(GL_TEXTURE1)}) {  // each unit's array (multitexture.cpp)
    const velocity::gl::ClientArray& a = c.texcoord_array(int(unit - GL_TEXTURE0));
    if (!a.enabled || !a.usable()) continue;
    const Vec4 t = a.fetch(i, {0, 0, 0, 1});
    compiled([=](Context& k) { k.multi_tex_coord(unit, t); });
  }
  if (c.arrays.edge_enabled && c.arrays.edge_usable()) {
    const bool e = c.arrays.edge(i);
    compiled([=](Context& k) { k.set_edge_flag(e); });
  }
  if (c.arrays.secondary_color.enabled && c.arrays.secondary_color.usable()) {
    const Vec4 s = c.arrays.secondary_color.fetch_normalized(i, {0, 0, 0, 1}, 3);
    compiled([=](Context& k) { k.set_secondary_color(s); });
  }
  if (c.arrays.fog_coord.enabled && c.arrays.fog_coord.usable()) {
    const float f = c.arrays.fog_coord.fetch(i, {}).x;
    compiled([=](Context& k) { k.set_fog_coord(f); });
  }
  if (c.arrays.vertex.enabled && c.arrays.vertex.usable()) {
    const Vec4 v = c.arrays.vertex.fetch(i, {0, 0, 0, 1});
    compiled([=](Context& k) { k.vertex(v); });
  }
}

bool valid_array_type(GLenum t, bool bytes_ok, bool unsigned_ok) {
  switch (t) {
    case GL_SHORT: case GL_INT: case GL_FLOAT: case GL_DOUBLE: return true;
    case GL_BYTE: return bytes_ok;
    case GL_UNSIGNED_BYTE: case GL_UNSIGNED_SHORT: case GL_UNSIGNED_INT: return unsigned_ok;
    default: return false;
  }
}

// With a buffer bound to GL_ARRAY_BUFFER, `p` is an offset into it (GL 1.5).
void set_array(Context& c, velocity::gl::ClientArray& a, GLint size, GLenum type, GLsizei stride, const void* p) {
  a.size = size, a.type = type, a.stride = stride, a.pointer = p;
  a.buffer = c.arrays.array_buffer;
}

}  // namespace

namespace {
template <class T, class Convert>
void get_values(GLenum pname, T* params, Convert convert) {
  now([&](Context& c) {
    if (c.in_begin_error()) return;
    std::vector<double> v;
    int kind = 0;
    if (!c.get(pname, v, kind)) return c.error(GL_INVALID_ENUM);
    if (!params) return;
    for (size_t i = 0; i < v.size(); ++i) params[i] = convert(v[i], kind);
  });
}
}  // namespace

struct osmesa_context {
  Context gl;
  osmesa_context(GLenum format, int depth_bits, int stencil_bits, int accum_bits)
      : gl(format, depth_bits, stencil_bits, accum_bits) {}
};

namespace {
thread_local osmesa_context* g_osmesa = nullptr;

// glVertex4f and glNormal3f but for their common case, out of line: that case then
// needs no saved registers (the mesh bench makes 600,000 such calls a frame).
[[gnu::noinline, gnu::cold]] void vertex_listed(GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  LIST(c.vertex({x, y, z, w}));
}
[[gnu::noinline, gnu::cold]] void normal_listed(GLfloat x, GLfloat y, GLfloat z) { LIST(c.set_normal({x, y, z})); }
}  // namespace

extern "C" {

// --- glBegin / glEnd and vertex attributes ---------------------------------------

void glBegin(GLenum mode) { LIST(c.begin(mode)); }
void glEnd(void) { LIST(c.end()); }

void glVertex2d(GLdouble x, GLdouble y) { glVertex4f(float(x), float(y), 0, 1); }
void glVertex2f(GLfloat x, GLfloat y) { glVertex4f(x, y, 0, 1); }
void glVertex2i(GLint x, GLint y) { glVertex4f(float(x), float(y), 0, 1); }
void glVertex2s(GLshort x, GLshort y) { glVertex4f(x, y, 0, 1); }
void glVertex3d(GLdouble x, GLdouble y, GLdouble z) { glVertex4f(float(x), float(y), float(z), 1); }
void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { glVertex4f(x, y, z, 1); }
void glVertex3i(GLint x, GLint y, GLint z) { glVertex4f(float(x), float(y), float(z), 1); }
void glVertex3s(GLshort x, GLshort y, GLshort z) { glVertex4f(x, y, z, 1); }
void glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { glVertex4f(float(x), float(y), float(z), float(w)); }
void glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  // The quick path (context.hpp) first: no list is compiled there, so nothing is recorded.
  if (Context* c = current(); c && c->quick_vertex(x, y, z, w)) return;
  vertex_listed(x, y, z, w);
}
void glVertex4i(GLint x, GLint y, GLint z, GLint w) { glVertex4f(float(x), float(y), float(z), float(w)); }
void glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w) { glVertex4f(x, y, z, w); }
void glVertex2dv(const GLdouble* v) { glVertex2d(v[0], v[1]); }
void glVertex2fv(const GLfloat* v) { glVertex2f(v[0], v[1]); }
void glVertex2iv(const GLint* v) { glVertex2i(v[0], v[1]); }
void glVertex2sv(const GLshort* v) { glVertex2s(v[0], v[1]); }
void glVertex3dv(const GLdouble* v) { glVertex3d(v[0], v[1], v[2]); }
void glVertex3fv(const GLfloat* v) { glVertex3f(v[0], v[1], v[2]); }
void glVertex3iv(const GLint* v) { glVertex3i(v[0], v[1], v[2]); }
void glVertex3sv(const GLshort* v) { glVertex3s(v[0], v[1], v[2]); }
void glVertex4dv(const GLdouble* v) { glVertex4d(v[0], v[1], v[2], v[3]); }
void glVertex4fv(const GLfloat* v) { glVertex4f(v[0], v[1], v[2], v[3]); }
void glVertex4iv(const GLint* v) { glVertex4i(v[0], v[1], v[2], v[3]); }
void glVertex4sv(const GLshort* v) { glVertex4s(v[0], v[1], v[2], v[3]); }

void glNormal3f(GLfloat x, GLfloat y, GLfloat z) {
  if (Context* c = current(); c && !c->compiling()) return c->set_normal({x, y, z});
  normal_listed(x, y, z);
}
void glNormal3b(GLbyte x, GLbyte y, GLbyte z) { glNormal3f(b2f(x), b2f(y), b2f(z)); }
void glNormal3d(GLdouble x, GLdouble y, GLdouble z) { glNormal3f(float(x), float(y), float(z)); }
void glNormal3i(GLint x, GLint y, GLint z) { glNormal3f(i2f(x), i2f(y), i2f(z)); }
void glNormal3s(GLshort x, GLshort y, GLshort z) { glNormal3f(s2f(x), s2f(y), s2f(z)); }
void glNormal3bv(const GLbyte* v) { glNormal3b(v[0], v[1], v[2]); }
void glNormal3dv(const GLdouble* v) { glNormal3d(v[0], v[1], v[2]); }
void glNormal3fv(const GLfloat* v) { glNormal3f(v[0], v[1], v[2]); }
void glNormal3iv(const GLint* v) { glNormal3i(v[0], v[1], v[2]); }
void glNormal3sv(const GLshort* v) { glNormal3s(v[0], v[1], v[2]); }

void glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { LIST(c.set_color({r, g, b, a})); }
void glColor3f(GLfloat r, GLfloat g, GLfloat b) { glColor4f(r, g, b, 1); }
void glColor3b(GLbyte r, GLbyte g, GLbyte b) { glColor4f(b2f(r), b2f(g), b2f(b), 1); }
void glColor3d(GLdouble r, GLdouble g, GLdouble b) { glColor4f(float(r), float(g), float(b), 1); }
void glColor3i(GLint r, GLint g, GLint b) { glColor4f(i2f(r), i2f(g), i2f(b), 1); }
void glColor3s(GLshort r, GLshort g, GLshort b) { glColor4f(s2f(r), s2f(g), s2f(b), 1); }
void glColor3ub(GLubyte r, GLubyte g, GLubyte b) { glColor4f(ub2f(r), ub2f(g), ub2f(b), 1); }
void glColor3ui(GLuint r, GLuint g, GLuint b) { glColor4f(ui2f(r), ui2f(g), ui2f(b), 1); }
void glColor3us(GLushort r, GLushort g, GLushort b) { glColor4f(us2f(r), us2f(g), us2f(b), 1); }
void glColor4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { glColor4f(b2f(r), b2f(g), b2f(b), b2f(a)); }
void glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) { glColor4f(float(r), float(g), float(b), float(a)); }
void glColor4i(GLint r, GLint g, GLint b, GLint a) { glColor4f(i2f(r), i2f(g), i2f(b), i2f(a)); }
void glColor4s(GLshort r, GLshort g, GLshort b, GLshort a) { glColor4f(s2f(r), s2f(g), s2f(b), s2f(a)); }
void glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { glColor4f(ub2f(r), ub2f(g), ub2f(b), ub2f(a)); }
void glColor4ui(GLuint r, GLuint g, GLuint b, GLuint a) { glColor4f(ui2f(r), ui2f(g), ui2f(b), ui2f(a)); }
void glColor4us(GLushort r, GLushort g, GLushort b, GLushort a) { glColor4f(us2f(r), us2f(g), us2f(b), us2f(a)); }
void glColor3bv(const GLbyte* v) { glColor3b(v[0], v[1], v[2]); }
void glColor3dv(const GLdouble* v) { glColor3d(v[0], v[1], v[2]); }
void glColor3fv(const GLfloat* v) { glColor3f(v[0], v[1], v[2]); }
void glColor3iv(const GLint* v) { glColor3i(v[0], v[1], v[2]); }
void glColor3sv(const GLshort* v) { glColor3s(v[0], v[1], v[2]); }
void glColor3ubv(const GLubyte* v) { glColor3ub(v[0], v[1], v[2]); }
void glColor3uiv(const GLuint* v) { glColor3ui(v[0], v[1], v[2]); }
void glColor3usv(const GLushort* v) { glColor3us(v[0], v[1], v[2]); }
void glColor4bv(const GLbyte* v) { glColor4b(v[0], v[1], v[2], v[3]); }
void glColor4dv(const GLdouble* v) { glColor4d(v[0], v[1], v[2], v[3]); }
void glColor4fv(const GLfloat* v) { glColor4f(v[0], v[1], v[2], v[3]); }
void glColor4iv(const GLint* v) { glColor4i(v[0], v[1], v[2], v[3]); }
void glColor4sv(const GLshort* v) { glColor4s(v[0], v[1], v[2], v[3]); }
void glColor4ubv(const GLubyte* v) { glColor4ub(v[0], v[1], v[2], v[3]); }
void glColor4uiv(const GLuint* v) { glColor4ui(v[0], v[1], v[2], v[3]); }
void glColor4usv(const GLushort* v) { glColor4us(v[0], v[1], v[2], v[3]); }

void glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q) { LIST(c.set_texcoord({s, t, r, q})); }
void glTexCoord1d(GLdouble s) { glTexCoord4f(float(s), 0, 0, 1); }
void glTexCoord1f(GLfloat s) { glTexCoord4f(s, 0, 0, 1); }
void glTexCoord1i(GLint s) { glTexCoord4f(float(s), 0, 0, 1); }
void glTexCoord1s(GLshort s) { glTexCoord4f(s, 0, 0, 1); }
void glTexCoord2d(GLdouble s, GLdouble t) { glTexCoord4f(float(s), float(t), 0, 1); }
void glTexCoord2f(GLfloat s, GLfloat t) { glTexCoord4f(s, t, 0, 1); }
void glTexCoord2i(GLint s, GLint t) { glTexCoord4f(float(s), float(t), 0, 1); }
void glTexCoord2s(GLshort s, GLshort t) { glTexCoord4f(s, t, 0, 1); }
void glTexCoord3d(GLdouble s, GLdouble t, GLdouble r) { glTexCoord4f(float(s), float(t), float(r), 1); }
void glTexCoord3f(GLfloat s, GLfloat t, GLfloat r) { glTexCoord4f(s, t, r, 1); }
void glTexCoord3i(GLint s, GLint t, GLint r) { glTexCoord4f(float(s), float(t), float(r), 1); }
void glTexCoord3s(GLshort s, GLshort t, GLshort r) { glTexCoord4f(s, t, r, 1); }
void glTexCoord4d(GLdouble s, GLdouble t, GLdouble r, GLdouble q) { glTexCoord4f(float(s), float(t), float(r), float(q)); }
void glTexCoord4i(GLint s, GLint t, GLint r, GLint q) { glTexCoord4f(float(s), float(t), float(r), float(q)); }
void glTexCoord4s(GLshort s, GLshort t, GLshort r, GLshort q) { glTexCoord4f(s, t, r, q); }
void glTexCoord1dv(const GLdouble* v) { glTexCoord1d(v[0]); }
void glTexCoord1fv(const GLfloat* v) { glTexCoord1f(v[0]); }
void glTexCoord1iv(const GLint* v) { glTexCoord1i(v[0]); }
void glTexCoord1sv(const GLshort* v) { glTexCoord1s(v[0]); }
void glTexCoord2dv(const GLdouble* v) { glTexCoord2d(v[0], v[1]); }
void glTexCoord2fv(const GLfloat* v) { glTexCoord2f(v[0], v[1]); }
void glTexCoord2iv(const GLint* v) { glTexCoord2i(v[0], v[1]); }
void glTexCoord2sv(const GLshort* v) { glTexCoord2s(v[0], v[1]); }
void glTexCoord3dv(const GLdouble* v) { glTexCoord3d(v[0], v[1], v[2]); }
void glTexCoord3fv(const GLfloat* v) { glTexCoord3f(v[0], v[1], v[2]); }
void glTexCoord3iv(const GLint* v) { glTexCoord3i(v[0], v[1], v[2]); }
void glTexCoord3sv(const GLshort* v) { glTexCoord3s(v[0], v[1], v[2]); }
void glTexCoord4dv(const GLdouble* v) { glTexCoord4d(v[0], v[1], v[2], v[3]); }
void glTexCoord4fv(const GLfloat* v) { glTexCoord4f(v[0], v[1], v[2], v[3]); }
void glTexCoord4iv(const GLint* v) { glTexCoord4i(v[0], v[1], v[2], v[3]); }
void glTexCoord4sv(const GLshort* v) { glTexCoord4s(v[0], v[1], v[2], v[3]); }

void glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { LIST(c.rect(x1, y1, x2, y2)); }
void glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2) { glRectf(float(x1), float(y1), float(x2), float(y2)); }
void glRecti(GLint x1, GLint y1, GLint x2, GLint y2) { glRectf(float(x1), float(y1), float(x2), float(y2)); }
void glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { glRectf(x1, y1, x2, y2); }

// --- matrices -------------------------------------------------------------------

void glMatrixMode(GLenum mode) { LIST(c.matrix_mode(mode)); }
void glLoadIdentity(void) { LIST(c.load_identity()); }
void glPushMatrix(void) { LIST(c.push_matrix()); }
void glPopMatrix(void) { LIST(c.pop_matrix()); }
void glLoadMatrixf(const GLfloat* m) {
  if (!m) return;
  const Mat4 x = load_column_major(m);
  LIST(c.load(x));
}
void glLoadMatrixd(const GLdouble* m) {
  if (!m) return;
  const Mat4 x = load_column_major(m);
  LIST(c.load(x));
}
void glMultMatrixf(const GLfloat* m) {
  if (!m) return;
  const Mat4 x = load_column_major(m);
  LIST(c.multiply(x));
}
void glMultMatrixd(const GLdouble* m) {
  if (!m) return;
  const Mat4 x = load_column_major(m);
  LIST(c.multiply(x));
}
void glRotatef(GLfloat angle, GLfloat x, GLfloat y, GLfloat z) { LIST(c.rotate(angle, x, y, z)); }
void glRotated(GLdouble angle, GLdouble x, GLdouble y, GLdouble z) { glRotatef(float(angle), float(x), float(y), float(z)); }
void glScalef(GLfloat x, GLfloat y, GLfloat z) { LIST(c.scale(x, y, z)); }
void glScaled(GLdouble x, GLdouble y, GLdouble z) { glScalef(float(x), float(y), float(z)); }
void glTranslatef(GLfloat x, GLfloat y, GLfloat z) { LIST(c.translate(x, y, z)); }
void glTranslated(GLdouble x, GLdouble y, GLdouble z) { glTranslatef(float(x), float(y), float(z)); }
void glOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) { LIST(c.ortho(l, r, b, t, n, f)); }
void glFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  LIST(c.frustum(l, r, b, t, n, f));
}

// --- viewport, buffers, per-fragment state ---------------------------------------

void glViewport(GLint x, GLint y, GLsizei w, GLsizei h) { LIST(c.viewport(x, y, w, h)); }
void glDepthRange(GLclampd n, GLclampd f) { LIST(c.depth_range(n, f)); }
void glScissor(GLint x, GLint y, GLsizei w, GLsizei h) { LIST(c.scissor(x, y, w, h)); }
void glClear(GLbitfield mask) { LIST(c.clear(mask)); }
void glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  LIST(if (!c.in_begin_error()) c.clear_color({r, g, b, a}));
}
void glClearDepth(GLclampd d) { LIST(c.clear_depth(d)); }
void glClearStencil(GLint s) { LIST(c.clear_stencil(s)); }
void glClearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { LIST(c.clear_accum(r, g, b, a)); }
void glAccum(GLenum op, GLfloat value) { LIST(c.accum(op, value)); }
void glDrawBuffer(GLenum mode) { LIST(c.draw_buffer(mode)); }
void glReadBuffer(GLenum mode) { LIST(c.read_buffer(mode)); }
void glPushAttrib(GLbitfield mask) { LIST(c.push_attrib(mask)); }
void glEdgeFlag(GLboolean flag) { LIST(c.set_edge_flag(flag != 0)); }  // (allowed between glBegin and glEnd)
void glEdgeFlagv(const GLboolean* flag) {
  if (flag) glEdgeFlag(*flag);
}
void glEdgeFlagPointer(GLsizei stride, const GLvoid* pointer) {
  NOW(if (stride < 0) return c.error(GL_INVALID_VALUE);
      c.arrays.edge_stride = stride, c.arrays.edge_pointer = static_cast<const GLboolean*>(pointer);
      c.arrays.edge_buffer = c.arrays.array_buffer);
}
GLint glRenderMode(GLenum mode) {  // never compiled
  GLint r = 0;
  NOW(r = c.render_mode(mode));
  return r;
}
void glSelectBuffer(GLsizei size, GLuint* buffer) { NOW(c.select_buffer(size, buffer)); }  // never compiled
void glFeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {  // never compiled
  NOW(c.feedback_buffer(size, type, buffer));
}
void glPassThrough(GLfloat token) { LIST(c.pass_through(token)); }
void glInitNames(void) { LIST(c.init_names()); }
void glPushName(GLuint name) { LIST(c.push_name(name)); }
void glPopName(void) { LIST(c.pop_name()); }
void glLoadName(GLuint name) { LIST(c.load_name(name)); }
void glPopAttrib(void) { LIST(c.pop_attrib()); }
void glPushClientAttrib(GLbitfield mask) { NOW(c.push_client_attrib(mask)); }  // client state: never compiled
void glPopClientAttrib(void) { NOW(c.pop_client_attrib()); }
void glStencilFunc(GLenum func, GLint ref, GLuint mask) { LIST(c.stencil_func(func, ref, mask)); }
void glStencilOp(GLenum fail, GLenum zfail, GLenum zpass) { LIST(c.stencil_op(fail, zfail, zpass)); }
void glStencilMask(GLuint mask) { LIST(c.stencil_mask(mask)); }
void glDepthFunc(GLenum f) { LIST(c.depth_func(f)); }
void glDepthMask(GLboolean flag) { LIST(c.depth_mask(flag != 0)); }
void glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) { LIST(c.color_mask(r, g, b, a)); }
void glEnable(GLenum cap) { LIST(c.enable(cap, true)); }
void glDisable(GLenum cap) { LIST(c.enable(cap, false)); }
GLboolean glIsEnabled(GLenum cap) {
  GLboolean r = GL_FALSE;
  NOW(if (c.in_begin_error()) return; bool known; r = c.is_enabled(cap, &known) ? GL_TRUE : GL_FALSE;
      if (!known) c.error(GL_INVALID_ENUM));
  return r;
}
void glBlendFunc(GLenum s, GLenum d) { LIST(c.blend_func(s, d)); }
void glBlendFuncSeparate(GLenum sr, GLenum dr, GLenum sa, GLenum da) { LIST(c.blend_func_separate(sr, dr, sa, da)); }
void glBlendEquation(GLenum mode) { LIST(c.blend_equation(mode)); }
void glLogicOp(GLenum opcode) { LIST(c.logic_op(opcode)); }
void glBlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { LIST(c.blend_color({r, g, b, a})); }
void glBlendFuncSeparateEXT(GLenum sr, GLenum dr, GLenum sa, GLenum da) { glBlendFuncSeparate(sr, dr, sa, da); }
void glBlendEquationEXT(GLenum mode) { glBlendEquation(mode); }
void glBlendColorEXT(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { glBlendColor(r, g, b, a); }
void glAlphaFunc(GLenum f, GLclampf ref) { LIST(c.alpha_func(f, ref)); }
void glFogfv(GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.fog(pname, p.data()));
}
void glFogiv(GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.fog(pname, p.data()));
}
void glFogf(GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(c.fog(pname, p.data()));
}
void glFogi(GLenum pname, GLint v) {
  const auto p = param1(float(v));
  LIST(c.fog(pname, p.data()));
}
void glHint(GLenum target, GLenum mode) { LIST(c.hint(target, mode)); }

// --- lighting -------------------------------------------------------------------

void glShadeModel(GLenum mode) { LIST(c.shade_model(mode)); }
void glLightfv(GLenum light, GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.light(light, pname, p.data()));
}
void glLightiv(GLenum light, GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.light(light, pname, p.data()));
}
void glLightf(GLenum light, GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(if (param_count(pname) != 1) c.error(GL_INVALID_ENUM); else c.light(light, pname, p.data()));
}
void glLighti(GLenum light, GLenum pname, GLint v) { glLightf(light, pname, float(v)); }
void glGetLightfv(GLenum light, GLenum pname, GLfloat* v) {
  NOW(if (c.in_begin_error()) return; float tmp[4] = {0, 0, 0, 0}; if (!c.get_light(light, pname, tmp)) return c.error(GL_INVALID_ENUM);
      if (v) std::memcpy(v, tmp, sizeof(float) * size_t(param_count(pname))));
}
void glLightModelfv(GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.light_model(pname, p.data()));
}
void glLightModeliv(GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.light_model(pname, p.data()));
}
void glLightModelf(GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(if (pname == GL_LIGHT_MODEL_AMBIENT) c.error(GL_INVALID_ENUM); else c.light_model(pname, p.data()));
}
void glLightModeli(GLenum pname, GLint v) { glLightModelf(pname, float(v)); }
void glMaterialfv(GLenum face, GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.material(face, pname, p.data()));
}
void glMaterialiv(GLenum face, GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.material(face, pname, p.data()));
}
void glMaterialf(GLenum face, GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(if (pname != GL_SHININESS) c.error(GL_INVALID_ENUM); else c.material(face, pname, p.data()));
}
void glMateriali(GLenum face, GLenum pname, GLint v) { glMaterialf(face, pname, float(v)); }
void glGetMaterialfv(GLenum face, GLenum pname, GLfloat* v) {
  NOW(if (c.in_begin_error()) return; float tmp[4] = {0, 0, 0, 0};
      if (!c.get_material(face, pname, tmp)) return c.error(GL_INVALID_ENUM);
      if (v) std::memcpy(v, tmp, sizeof(float) * size_t(param_count(pname))));
}
void glColorMaterial(GLenum face, GLenum mode) { LIST(c.color_material(face, mode)); }

// --- rasterization --------------------------------------------------------------

void glCullFace(GLenum mode) { LIST(c.cull_face(mode)); }
void glFrontFace(GLenum mode) { LIST(c.front_face(mode)); }
void glPolygonMode(GLenum face, GLenum mode) { LIST(c.polygon_mode(face, mode)); }
void glPolygonOffset(GLfloat factor, GLfloat units) { LIST(c.polygon_offset(factor, units)); }
void glPointSize(GLfloat size) { LIST(c.point_size(size)); }
void glLineWidth(GLfloat width) { LIST(c.line_width(width)); }
void glLineStipple(GLint factor, GLushort pattern) { LIST(c.line_stipple(factor, pattern)); }

// --- textures -------------------------------------------------------------------

void glGenTextures(GLsizei n, GLuint* textures) { NOW(c.gen_textures(n, textures)); }
void glDeleteTextures(GLsizei n, const GLuint* textures) { NOW(c.delete_textures(n, textures)); }
void glBindTexture(GLenum target, GLuint texture) { LIST(c.bind_texture(target, texture)); }
GLboolean glIsTexture(GLuint texture) {
  GLboolean r = GL_FALSE;
  NOW(if (c.in_begin_error()) return; r = texture != 0 && c.is_texture(texture) ? GL_TRUE : GL_FALSE);
  return r;
}

void glTexImage2D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border, GLenum format,
                  GLenum type, const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      // GL_PROXY_TEXTURE_2D asks whether such an image would fit: the size is checked,
      // nothing is read or kept but the answer, and the call is never compiled.
      const bool proxy = target == GL_PROXY_TEXTURE_2D;
      if (target != GL_TEXTURE_2D && !proxy) return c.error(GL_INVALID_ENUM);
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || h < 0 || border < 0 || border > 1 ||
          !Context::base_format(internal))
          return c.error(GL_INVALID_VALUE);
      if (proxy) {
        if (c.in_begin_error()) return;
        // (A packed type of another number of components: GL_INVALID_OPERATION.)
        if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
        if (!velocity::gl::unpack_rgba(format, type, 0, 0, c.pixels.unpack, nullptr)) return c.error(GL_INVALID_ENUM);
        return c.proxy_tex_image(level, internal, w, h, border);
      }
      if (w - 2 * border > (velocity::gl::kMaxTextureSize >> level) || h - 2 * border > (velocity::gl::kMaxTextureSize >> level))
          return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      auto texels = velocity::gl::unpack_rgba(format, type, w, h, c.pixels.unpack, pixels, c.pixels.transfer);
      if (!texels) return c.error(GL_INVALID_ENUM);
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      const bool given = pixels != nullptr;
      compiled([=](Context& k) { k.tex_image(target, level, internal, w, h, border, given ? data.get() : nullptr); }));
}

void glTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type,
                     const GLvoid* pixels) {
  NOW(
      if (c.refuses_in_begin()) return;  // (before the caller's memory is read)
      if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
      if (level < 0 || level >= velocity::gl::kMaxTextureLevels || w < 0 || h < 0 ||
          w > velocity::gl::kMaxTextureSize + 2 || h > velocity::gl::kMaxTextureSize + 2)
          return c.error(GL_INVALID_VALUE);
      if (velocity::gl::check_draw_format(format, type) == GL_INVALID_OPERATION) return c.error(GL_INVALID_OPERATION);
      // Null pixels: the ranges are still checked (tex_sub_image), nothing is written.
      auto texels = velocity::gl::unpack_rgba(format, type, pixels ? w : 0, pixels ? h : 0, c.pixels.unpack, pixels,
                                              c.pixels.transfer);
      if (!texels) return c.error(GL_INVALID_ENUM);
      auto data = std::make_shared<const std::vector<uint32_t>>(std::move(*texels));
      compiled([=](Context& k) { k.tex_sub_image(target, level, x, y, w, h, *data); }));
}

void glCopyTexImage2D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w, GLsizei h, GLint border) {
  LIST(if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);  // (the 1-D and 3-D targets have their own calls)
       c.copy_tex_image(target, level, internal, x, y, w, h, border));
}
void glCopyTexSubImage2D(GLenum target, GLint level, GLint xo, GLint yo, GLint x, GLint y, GLsizei w, GLsizei h) {
  LIST(if (target != GL_TEXTURE_2D) return c.error(GL_INVALID_ENUM);
       c.copy_tex_sub_image(target, level, xo, yo, x, y, w, h));
}
void glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  NOW(c.get_tex_image(target, level, format, type, pixels));
}
void glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  NOW(GLint v = 0; if (c.tex_level_parameter(target, level, pname, &v) && params) *params = v);
}
void glGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  NOW(GLint v = 0; if (c.tex_level_parameter(target, level, pname, &v) && params) *params = GLfloat(v));
}

void glTexParameterfv(GLenum target, GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.tex_parameter(target, pname, p.data()));
}
void glTexParameteriv(GLenum target, GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.tex_parameter(target, pname, p.data()));
}
void glTexParameterf(GLenum target, GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(c.tex_parameter(target, pname, p.data()));
}
void glTexParameteri(GLenum target, GLenum pname, GLint v) { glTexParameterf(target, pname, float(v)); }
void glTexEnvfv(GLenum target, GLenum pname, const GLfloat* v) {
  const auto p = params_f(pname, v);
  LIST(c.tex_env(target, pname, p.data()));
}
void glTexEnviv(GLenum target, GLenum pname, const GLint* v) {
  const auto p = params_i(pname, v);
  LIST(c.tex_env(target, pname, p.data()));
}
void glTexEnvf(GLenum target, GLenum pname, GLfloat v) {
  const auto p = param1(v);
  LIST(c.tex_env(target, pname, p.data()));
}
void glTexEnvi(GLenum target, GLenum pname, GLint v) { glTexEnvf(target, pname, float(v)); }
void glPixelStorei(GLenum pname, GLint v) { NOW(c.pixel_store(pname, v)); }

// --- vertex arrays --------------------------------------------------------------

void glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (size < 2 || size > 4 || stride < 0) return c.error(GL_INVALID_VALUE);
      if (!valid_array_type(type, false, false)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.vertex, size, type, stride, p));
}
void glNormalPointer(GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (stride < 0) return c.error(GL_INVALID_VALUE); if (!valid_array_type(type, true, false)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.normal, 3, type, stride, p));
}
void glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (size < 3 || size > 4 || stride < 0) return c.error(GL_INVALID_VALUE);
      if (!valid_array_type(type, true, true)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.color, size, type, stride, p));
}
void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* p) {
  NOW(if (size < 1 || size > 4 || stride < 0) return c.error(GL_INVALID_VALUE);
      if (!valid_array_type(type, false, false)) return c.error(GL_INVALID_ENUM);
      set_array(c, c.arrays.texcoord, size, type, stride, p));
}
// GL 1.5 section 2.8, Table 2.5: each format's arrays, sizes and offsets in one record
// (colours as 4 unsigned bytes take one float's room).
void glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid* pointer) {  // never compiled
  struct Layout {
    GLenum format;
    GLint st, sc, sv;  // texture, colour, vertex sizes (0: no such array)
    GLenum tc;         // the colour's type
    bool normal;
    GLint pc, pn, pv, s;  // offsets and the record's size, in floats
  };
  static constexpr GLenum F = GL_FLOAT, UB = GL_UNSIGNED_BYTE;
  static constexpr Layout layouts[] = {
      {GL_V2F, 0, 0, 2, 0, false, 0, 0, 0, 2},
      {GL_V3F, 0, 0, 3, 0, false, 0, 0, 0, 3},
      {GL_C4UB_V2F, 0, 4, 2, UB, false, 0, 0, 1, 3},
      {GL_C4UB_V3F, 0, 4, 3, UB, false, 0, 0, 1, 4},
      {GL_C3F_V3F, 0, 3, 3, F, false, 0, 0, 3, 6},
      {GL_N3F_V3F, 0, 0, 3, 0, true, 0, 0, 3, 6},
      {GL_C4F_N3F_V3F, 0, 4, 3, F, true, 0, 4, 7, 10},
      {GL_T2F_V3F, 2, 0, 3, 0, false, 0, 0, 2, 5},
      {GL_T4F_V4F, 4, 0, 4, 0, false, 0, 0, 4, 8},
      {GL_T2F_C4UB_V3F, 2, 4, 3, UB, false, 2, 0, 3, 6},
      {GL_T2F_C3F_V3F, 2, 3, 3, F, false, 2, 0, 5, 8},
      {GL_T2F_N3F_V3F, 2, 0, 3, 0, true, 0, 2, 5, 8},
      {GL_T2F_C4F_N3F_V3F, 2, 4, 3, F, true, 2, 6, 9, 12},
      {GL_T4F_C4F_N3F_V4F, 4, 4, 4, F, true, 4, 8, 11, 15},
  };
  NOW(if (stride < 0) return c.error(GL_INVALID_VALUE);
      const Layout* l = nullptr;
      for (const Layout& k : layouts) if (k.format == format) l = &k;
      if (!l) return c.error(GL_INVALID_ENUM);
      const GLsizei s = stride ? stride : GLsizei(l->s * sizeof(GLfloat));
      // (An offset into the bound GL_ARRAY_BUFFER, when there is one: 0 is one too.)
      const bool offsets = c.arrays.array_buffer != nullptr;
      auto at = [&](GLint floats) -> const void* {
        if (!pointer && !offsets) return nullptr;
        return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(pointer) + size_t(floats) * sizeof(GLfloat));
      };
      c.arrays.edge_enabled = false;
      c.arrays.texcoord.enabled = l->st != 0;
      if (l->st) set_array(c, c.arrays.texcoord, l->st, F, s, at(0));
      c.arrays.color.enabled = l->sc != 0;
      if (l->sc) set_array(c, c.arrays.color, l->sc, l->tc, s, at(l->pc));
      c.arrays.normal.enabled = l->normal;
      if (l->normal) set_array(c, c.arrays.normal, 3, F, s, at(l->pn));
      c.arrays.vertex.enabled = true;
      set_array(c, c.arrays.vertex, l->sv, F, s, at(l->pv)));
}
void glEnableClientState(GLenum cap) { NOW(c.client_state(cap, true)); }
void glDisableClientState(GLenum cap) { NOW(c.client_state(cap, false)); }

void glArrayElement(GLint i) {
  NOW(if (c.compiling()) { record_array_element(c, i); } else { c.array_element(i); });
}

void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  NOW(
      if (!c.compiling()) return c.draw_arrays(mode, first, count);
      // In a display list the arrays are read now.
      if (mode > GL_POLYGON) return c.error(GL_INVALID_ENUM);
      if (count < 0 || first < 0) return c.error(GL_INVALID_VALUE);
      c.record_draw([&] {
        glBegin(mode);
        for (int64_t i = first; i < int64_t(first) + count && i <= INT32_MAX; ++i) record_array_element(c, GLint(i));
        glEnd();
      }));
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid* indices) {
  NOW(
      if (!c.compiling()) return c.draw_elements(mode, count, type, indices);
      if (mode > GL_POLYGON) return c.error(GL_INVALID_ENUM);
      if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
          return c.error(GL_INVALID_ENUM);
      if (count < 0) return c.error(GL_INVALID_VALUE);
      const uint8_t* p = c.element_indices(count, type, indices);  // (buffer_objects.cpp)
      if (!p) return;
      c.record_draw([&] {
        glBegin(mode);
        for (GLsizei k = 0; k < count; ++k) {
          uint32_t i = 0;
          if (type == GL_UNSIGNED_BYTE) i = p[k];
          else if (type == GL_UNSIGNED_SHORT) { uint16_t s; std::memcpy(&s, p + 2 * size_t(k), 2); i = s; }
          else std::memcpy(&i, p + 4 * size_t(k), 4);
          if (i <= 0x7fffffffu) record_array_element(c, GLint(i));
        }
        glEnd();
      }));
}

// GL 1.2: glDrawElements with a promise that every index lies in [start, end]. The
// promise only helps a driver that copies vertices ahead; pGL reads the arrays per
// index either way, so an index outside the range is drawn as glDrawElements would.
void glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const GLvoid* indices) {
  Context* c = current();
  if (!c) return;
  if (end < start) return c->error(GL_INVALID_VALUE);
  glDrawElements(mode, count, type, indices);
}

// GL 1.4's multi-draws: one glDrawArrays / glDrawElements per entry (each recorded into
// a list being compiled, as those are).
void glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  Context* c = current();
  if (!c) return;
  if (drawcount < 0) return c->error(GL_INVALID_VALUE);
  if (drawcount > 0 && (!first || !count)) return;
  if (mode > GL_POLYGON) return c->error(GL_INVALID_ENUM);
  for (GLsizei i = 0; i < drawcount; ++i)  // a bad entry draws none of them
    if (count[i] < 0) return c->error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < drawcount; ++i) glDrawArrays(mode, first[i], count[i]);
}

void glMultiDrawElements(GLenum mode, const GLsizei* count, GLenum type, const GLvoid* const* indices, GLsizei drawcount) {
  Context* c = current();
  if (!c) return;
  if (drawcount < 0) return c->error(GL_INVALID_VALUE);
  if (drawcount > 0 && (!count || !indices)) return;
  if (mode > GL_POLYGON) return c->error(GL_INVALID_ENUM);
  for (GLsizei i = 0; i < drawcount; ++i)
    if (count[i] < 0) return c->error(GL_INVALID_VALUE);
  for (GLsizei i = 0; i < drawcount; ++i) glDrawElements(mode, count[i], type, indices[i]);
}

// --- display lists --------------------------------------------------------------

GLuint glGenLists(GLsizei range) {
  GLuint r = 0;
  NOW(r = c.gen_lists(range));
  return r;
}
void glNewList(GLuint list, GLenum mode) { NOW(c.new_list(list, mode)); }
void glEndList(void) { NOW(c.end_list()); }
void glCallList(GLuint list) { LIST(c.call_list(list)); }
void glCallLists(GLsizei n, GLenum type, const GLvoid* lists) {
  NOW(
      if (n < 0) return c.error(GL_INVALID_VALUE);
      size_t size;
      switch (type) {
        case GL_BYTE: case GL_UNSIGNED_BYTE: size = 1; break;
        case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: size = 2; break;
        case GL_3_BYTES: size = 3; break;
        case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: size = 4; break;
        default: return c.error(GL_INVALID_ENUM);
      }
      if (!lists) return;
      const auto* p = static_cast<const uint8_t*>(lists);
      for (GLsizei k = 0; k < n; ++k) {
        const uint8_t* e = p + size_t(k) * size;
        int64_t id = 0;
        switch (type) {
          case GL_BYTE: id = int8_t(e[0]); break;
          case GL_UNSIGNED_BYTE: id = e[0]; break;
          case GL_SHORT: { int16_t s; std::memcpy(&s, e, 2); id = s; break; }
          case GL_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, e, 2); id = s; break; }
          case GL_INT: { int32_t s; std::memcpy(&s, e, 4); id = s; break; }
          case GL_UNSIGNED_INT: { uint32_t s; std::memcpy(&s, e, 4); id = s; break; }
          case GL_FLOAT: { float f; std::memcpy(&f, e, 4); id = std::isfinite(f) ? int64_t(std::fmod(double(f), 4294967296.0)) : 0; break; }
          case GL_2_BYTES: id = e[0] * 256 + e[1]; break;
          case GL_3_BYTES: id = (e[0] * 256 + e[1]) * 256 + e[2]; break;
          default: id = ((int64_t(e[0]) * 256 + e[1]) * 256 + e[2]) * 256 + e[3]; break;
        }
        // The list base is added when the call runs (GL), so glListBase may follow.
        const GLuint offset = GLuint(uint64_t(id));
        compiled([=](Context& x) { x.call_list(x.list_base() + offset); });
      });
}
void glDeleteLists(GLuint list, GLsizei range) { NOW(c.delete_lists(list, range)); }
GLboolean glIsList(GLuint list) {
  GLboolean r = GL_FALSE;
  NOW(if (c.in_begin_error()) return; r = c.is_list(list) ? GL_TRUE : GL_FALSE);
  return r;
}
void glListBase(GLuint base) { LIST(if (!c.in_begin_error()) c.set_list_base(base)); }

// --- queries, read-back, synchronisation ------------------------------------------

GLenum glGetError(void) {
  Context* c = current();
  if (!c) return GL_NO_ERROR;
  // Between glBegin and glEnd the call itself is the error: it is recorded (unless an
  // earlier one is) and 0 returned, as Mesa does; the first glGetError after glEnd
  // reports it, once.
  if (c->in_begin_error()) return GL_NO_ERROR;
  return c->take_error();
}


void glGetBooleanv(GLenum pname, GLboolean* params) {
  get_values(pname, params, [](double v, int) { return GLboolean(v != 0 ? GL_TRUE : GL_FALSE); });
}
void glGetIntegerv(GLenum pname, GLint* params) {
  get_values(pname, params, [](double v, int kind) {
    if (!(v == v)) return GLint(0);  // NaN
    if (kind == 1) return GLint(std::llround(std::clamp(v, -1.0, 1.0) * 2147483647.0));
    return GLint(std::llround(std::clamp(v, -2147483648.0, 2147483647.0)));
  });
}
void glGetFloatv(GLenum pname, GLfloat* params) {
  get_values(pname, params, [](double v, int) { return GLfloat(v); });
}
void glGetDoublev(GLenum pname, GLdouble* params) {
  get_values(pname, params, [](double v, int) { return v; });
}

const GLubyte* glGetString(GLenum name) {
  Context* c = current();
  if (!c) return nullptr;
  if (c->in_begin_error()) return nullptr;
  const char* s = nullptr;
  switch (name) {
    case GL_VENDOR: s = "Velocity"; break;
    case GL_RENDERER: s = "Velocity pGL (software, tile rasterizer)"; break;
    case GL_VERSION: s = "1.5 Velocity pGL 0.1 (a subset: docs/gl.md)"; break;
    // The extensions whose whole functionality pGL has: token-only ones (GL_ADD, NPOT
    // sizes, BGR/BGRA pixels, GL_RESCALE_NORMAL, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT,
    // GL 1.4's blending and multi-draws) and GL 1.5's buffer objects and occlusion
    // queries under their ARB names (api_buffers.cpp); GL 1.2's 3-D textures under
    // GL_EXT_texture3D's names (api_texture_3d.cpp).
    // Framebuffer objects and their blit (api_framebuffer.cpp): a line of its own.
    case GL_EXTENSIONS:
      s = "GL_ARB_texture_env_add GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two GL_EXT_bgra "
          "GL_EXT_rescale_normal GL_EXT_texture_edge_clamp GL_EXT_texture_env_add GL_IBM_texture_mirrored_repeat "
          "GL_SGIS_texture_edge_clamp GL_EXT_blend_color GL_EXT_blend_minmax GL_EXT_blend_subtract "
          "GL_EXT_blend_func_separate GL_EXT_multi_draw_arrays GL_ARB_vertex_buffer_object GL_ARB_occlusion_query "
          "GL_ARB_multitexture "  // a space after each, as Mesa's (piglit's glinfo relies on it)
          "GL_EXT_framebuffer_object GL_EXT_framebuffer_blit "  // (not ARB: docs/gl.md)
          // (multisample.cpp: the default framebuffer's packed depth and stencil pixels)
          "GL_EXT_packed_depth_stencil "
          "GL_EXT_texture3D "
          "GL_ARB_window_pos GL_ARB_texture_border_clamp "  // glWindowPos's ARB names (api_pixels.cpp), GL_CLAMP_TO_BORDER
          // GL 1.3's GL_COMBINE environment (tex_combine.cpp): EXT's names are the same
          "GL_ARB_texture_env_combine GL_ARB_texture_env_dot3 GL_EXT_texture_env_combine ";
      break;
    default: c->error(GL_INVALID_ENUM); return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

void glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, GLvoid* pixels) {
  NOW(c.read_pixels(x, y, w, h, format, type, pixels));
}
void glFinish(void) { NOW(c.finish()); }
void glFlush(void) { NOW(c.finish()); }

// --- OSMesa ---------------------------------------------------------------------

OSMesaContext OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits, GLint accumBits,
                                     OSMesaContext sharelist) {
  if (sharelist) return nullptr;  // shared lists and textures: not supported (docs/gl.md)
  if (format != OSMESA_RGBA && format != OSMESA_BGRA && format != OSMESA_ARGB && format != OSMESA_RGB &&
      format != OSMESA_BGR)
    return nullptr;
  try {
    return new osmesa_context(format, depthBits, stencilBits, accumBits);
  } catch (const std::exception&) {
    return nullptr;
  }
}

OSMesaContext OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

void OSMesaDestroyContext(OSMesaContext ctx) {
  if (!ctx) return;
  if (g_osmesa == ctx) {
    g_osmesa = nullptr;
    velocity::gl::set_current(nullptr);
  }
  delete ctx;
}

GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type, GLsizei width, GLsizei height) {
  try {
    if (g_osmesa && g_osmesa != ctx) g_osmesa->gl.release();
    if (!ctx) {
      g_osmesa = nullptr;
      velocity::gl::set_current(nullptr);
      return GL_TRUE;
    }
    if (!ctx->gl.make_current(buffer, type, width, height)) return GL_FALSE;
  } catch (const std::exception&) {
    return GL_FALSE;
  }
  g_osmesa = ctx;
  velocity::gl::set_current(&ctx->gl);
  return GL_TRUE;
}

OSMesaContext OSMesaGetCurrentContext(void) { return g_osmesa; }

void OSMesaPixelStore(GLint pname, GLint value) {
  if (!g_osmesa) return;
  Context& c = g_osmesa->gl;
  if (pname == OSMESA_Y_UP) {
    c.release();
    c.y_up = value != 0;
  } else if (pname == OSMESA_ROW_LENGTH) {
    if (value < 0) return c.error(GL_INVALID_VALUE);
    c.release();
    c.row_length = value;
  } else {
    c.error(GL_INVALID_ENUM);
  }
}

void OSMesaGetIntegerv(GLint pname, GLint* value) {
  if (!value) return;
  Context* c = g_osmesa ? &g_osmesa->gl : nullptr;
  switch (pname) {
    case OSMESA_WIDTH: *value = c ? c->width() : 0; break;
    case OSMESA_HEIGHT: *value = c ? c->height() : 0; break;
    case OSMESA_FORMAT: *value = c ? GLint(c->format()) : 0; break;
    case OSMESA_TYPE: *value = GL_UNSIGNED_BYTE; break;
    case OSMESA_MAX_WIDTH: case OSMESA_MAX_HEIGHT: *value = velocity::gl::kMaxViewport; break;
    case OSMESA_Y_UP: *value = c ? c->y_up : 1; break;
    case OSMESA_ROW_LENGTH: *value = c ? c->row_length : 0; break;
    default: if (c) c->error(GL_INVALID_ENUM); break;
  }
}

GLboolean OSMesaGetDepthBuffer(OSMesaContext ctx, GLint* width, GLint* height, GLint* bytesPerValue, void** buffer) {
  if (!ctx) return GL_FALSE;
  try {
    return ctx->gl.depth_buffer(width, height, bytesPerValue, buffer) ? GL_TRUE : GL_FALSE;
  } catch (const std::exception&) {
    return GL_FALSE;
  }
}

// The buffer OSMesaMakeCurrent gave the context, as Mesa's: GL_FALSE (and zeros) before.
GLboolean OSMesaGetColorBuffer(OSMesaContext ctx, GLint* width, GLint* height, GLint* format, void** buffer) {
  const bool has = ctx && ctx->gl.buffer();
  if (width) *width = has ? ctx->gl.width() : 0;
  if (height) *height = has ? ctx->gl.height() : 0;
  if (format) *format = has ? GLint(ctx->gl.format()) : 0;
  if (buffer) *buffer = has ? ctx->gl.buffer() : nullptr;
  return has ? GL_TRUE : GL_FALSE;
}

// Mesa clamps a float buffer's colours only when asked; pGL's buffers are 8 bits a
// channel (OSMESA_TYPE GL_UNSIGNED_BYTE), whose colours are clamped either way, as
// Mesa's are: nothing to change.
void OSMesaColorClamp(GLboolean enable) { (void)enable; }

// The gl* and OSMesa* functions this library exports, by name (its own dynamic symbol
// table, so every entry point is found without a second list of them); NULL for
// any other name, GLU's included.
OSMESAproc OSMesaGetProcAddress(const char* name) {
  if (!name) return nullptr;
  const bool gl = std::strncmp(name, "gl", 2) == 0 && std::strncmp(name, "glu", 3) != 0;
  if (!gl && std::strncmp(name, "OSMesa", 6) != 0) return nullptr;
  Dl_info self;
  if (!dladdr(reinterpret_cast<void*>(&OSMesaGetProcAddress), &self) || !self.dli_fname) return nullptr;
  void* library = dlopen(self.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  if (!library) return nullptr;
  void* function = dlsym(library, name);
  dlclose(library);  // (RTLD_NOLOAD took a reference of the loaded library; it stays loaded)
  return reinterpret_cast<OSMESAproc>(function);
}

}  // extern "C"
