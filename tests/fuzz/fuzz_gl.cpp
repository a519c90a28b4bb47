// Fuzz target: pGL's API (libvelocity-gl) driven by random call sequences with random
// arguments (GLU's quadrics, the raster position and pixel rectangles, user clip planes
// and, where libvelocity-glut is built, GLUT's shapes among them: they need no window).
// The input's bytes choose a context (1..96 pixels a side, any OSMesa format, with or
// without depth and stencil), then up to 512 calls among ~190 GL, GLU and OSMesa entry
// points (GL 1.5's buffer objects and occlusion queries, 1-D textures and
// evaluators, GL 1.4's secondary colour and fog coordinates, GL 1.3's multitexture
// among them; framebuffer objects, renderbuffers and glBlitFramebuffer; GL 1.3's
// GL_COMBINE environment, glGetTexEnv and glGetTexParameter),
// with enums drawn from valid and invalid values and numbers that are often NaN,
// infinite, huge or negative; glBegin/glEnd nesting, display lists
// compiled, nested and called inside themselves, textures of odd sizes, vertex arrays
// with indices inside the arrays (the caller's contract), read-back.
//
// Properties: no sanitizer report, no crash, glGetError only ever returns GL's codes,
// the caller's colour buffer is never written outside its size (ASan), and after
// the sequence the context still draws and reads back.
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#ifdef VELOCITY_FUZZ_GLUT_SHAPES
#include <GL/glut.h>
#endif

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "fuzz_util.hpp"

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : p_(data), n_(size) {}
  bool empty() const { return n_ == 0; }
  uint8_t u8() {
    if (n_ == 0) return 0;
    --n_;
    return *p_++;
  }
  uint16_t u16() { return uint16_t(u8() | (u8() << 8)); }
  uint32_t u32() { return uint32_t(u16()) | (uint32_t(u16()) << 16); }
  int below(int n) { return int(u8() % n); }
  float number() {
    const uint8_t k = u8();
    if (k < 160) return float(int8_t(u8())) / 32.0f;
    if (k < 200) return float(int16_t(u16())) / 16.0f;
    if (k < 230) {
      static const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, std::numeric_limits<float>::quiet_NaN(),
                                      std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                                      1e30f, -1e30f, 1e-30f, 3.4e38f, 1e7f, 180.0f, 90.0f, 128.0f};
      return special[k % 16];
    }
    const uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  int integer() {
    const uint8_t k = u8();
    if (k < 200) return int(int8_t(u8()));
    if (k < 240) return int(int16_t(u16()));
    return int(u32());
  }
  // An enum: mostly one that some call takes, sometimes anything.
  GLenum enumerant() {
    static const GLenum e[] = {
        GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_LINE_STRIP, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
        GL_QUAD_STRIP, GL_POLYGON, GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE, GL_DEPTH_TEST, GL_CULL_FACE, GL_LIGHTING,
        GL_LIGHT0, GL_LIGHT1, GL_LIGHT7, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_COLOR_MATERIAL, GL_TEXTURE_2D, GL_BLEND,
        GL_ALPHA_TEST, GL_FOG, GL_SCISSOR_TEST, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT,
        GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS, GL_ZERO, GL_ONE,
        GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_COLOR, GL_SRC_ALPHA_SATURATE, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK,
        GL_CW, GL_CCW, GL_POINT, GL_LINE, GL_FILL, GL_FLAT, GL_SMOOTH, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR,
        GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
        GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE,
        GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FOG_MODE, GL_FOG_DENSITY,
        GL_FOG_START, GL_FOG_END, GL_FOG_COLOR, GL_LINEAR, GL_EXP, GL_EXP2, GL_NEAREST, GL_NEAREST_MIPMAP_NEAREST,
        GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_NEAREST, GL_TEXTURE_MIN_FILTER,
        GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE,
        GL_GENERATE_MIPMAP, GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR,
        GL_MODULATE, GL_REPLACE, GL_DECAL, GL_RGB, GL_RGBA, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA, GL_BGRA,
        GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, GL_SHORT, GL_INT, GL_DOUBLE, GL_BYTE,
        GL_COMPILE, GL_COMPILE_AND_EXECUTE, GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_TEXTURE_COORD_ARRAY,
        GL_VIEWPORT, GL_MODELVIEW_MATRIX, GL_PROJECTION_STACK_DEPTH, GL_CURRENT_COLOR, GL_DEPTH_COMPONENT,
        GL_UNPACK_ALIGNMENT, GL_PACK_ALIGNMENT, GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST, GL_VERSION, 0, 1, 0xFFFF,
        GL_STENCIL_TEST, GL_KEEP, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP, GL_STENCIL_INDEX,
        GL_STENCIL_REF, GL_STENCIL_WRITEMASK, GL_STENCIL_BITS, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA,
        GL_FUNC_SUBTRACT, GL_MIN, GL_MAX, GL_BLEND_COLOR, GL_BLEND_EQUATION, GL_ATTRIB_STACK_DEPTH,
        GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_RENDER, GL_SELECT, GL_EDGE_FLAG_ARRAY,
        GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL};
    if (u8() < 240) return e[u8() % (sizeof e / sizeof e[0])];
    return GLenum(u32());
  }

 private:
  const uint8_t* p_;
  size_t n_;
};

int quadric_errors = 0;
void GLAPIENTRY count_quadric_error(GLenum e) {
  fuzz_check(e == GLU_INVALID_ENUM || e == GLU_INVALID_VALUE);
  ++quadric_errors;
}

// GLU quadric calls on `q` (possibly null) with random state and sizes. The counts stay
// below 31 (-2 and below: the error paths): the work is proportional to them, as the
// caller asks, and at 253 x 253 one input ran for seconds, so the fuzzer barely moved
// (a "slow unit" in 30 s of fuzzing: 38 inputs).
void quadric_call(Bytes& in, GLUquadric*& q, float a, float b, float c, float d, GLenum e1) {
  const int n1 = in.below(33) - 2, n2 = in.below(33) - 2;
  switch (in.below(12)) {
    case 0: gluDeleteQuadric(q), q = gluNewQuadric(); break;
    case 1: gluQuadricDrawStyle(q, in.u8() & 1 ? GLU_POINT + GLenum(in.below(4)) : e1); break;
    case 2: gluQuadricNormals(q, in.u8() & 1 ? GLU_SMOOTH + GLenum(in.below(3)) : e1); break;
    case 3: gluQuadricOrientation(q, in.u8() & 1 ? GLU_OUTSIDE + GLenum(in.below(2)) : e1); break;
    case 4: gluQuadricTexture(q, GLboolean(in.u8())); break;
    case 5:
      gluQuadricCallback(q, in.u8() & 1 ? GLU_ERROR : e1,
                         in.u8() & 1 ? reinterpret_cast<_GLUfuncptr>(count_quadric_error) : nullptr);
      break;
    case 6: gluSphere(q, a, n1, n2); break;
    case 7: gluCylinder(q, a, b, c, n1, n2); break;
    case 8: gluDisk(q, a, b, n1, n2); break;
    case 9: gluPartialDisk(q, a, b, n1, n2, c, d); break;
    case 10: gluDeleteQuadric(q), q = nullptr; break;
    default: gluSphere(nullptr, a, n1, n2), gluQuadricDrawStyle(nullptr, e1); break;
  }
}

// The raster position and pixel rectangles: glRasterPos, glWindowPos, glBitmap,
// glDrawPixels (any format and type, packed ones included), glCopyPixels, glPixelZoom
// and glPixelStore with random unpack state. Sizes, skips and row lengths stay inside
// `image` (the caller's contract); zooms and positions are anything.
void pixel_call(Bytes& in, const std::vector<float>& image, float a, float b, float c, float d, GLenum e1, GLenum e2) {
  static const GLenum formats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA,
                                   GL_RED, GL_GREEN, GL_BLUE, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_COLOR_INDEX};
  static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT,
                                 GL_FLOAT, GL_BITMAP, GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_BYTE_2_3_3_REV,
                                 GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT_5_6_5_REV, GL_UNSIGNED_SHORT_4_4_4_4,
                                 GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_UNSIGNED_SHORT_5_5_5_1,
                                 GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_UNSIGNED_INT_8_8_8_8, GL_UNSIGNED_INT_8_8_8_8_REV,
                                 GL_UNSIGNED_INT_10_10_10_2, GL_UNSIGNED_INT_2_10_10_10_REV};
  GLenum format = in.u8() < 230 ? formats[in.below(13)] : e1;
  GLenum type = in.u8() < 230 ? types[in.below(20)] : e2;
  // GL_EXT_packed_depth_stencil's GL_DEPTH_STENCIL_EXT and GL_UNSIGNED_INT_24_8_EXT,
  // paired or with another type or format (4 bytes a pixel: inside `image`).
  if (const uint8_t pick = in.u8(); pick < 24) format = 0x84F9, type = pick < 16 ? 0x84FA : type;
  else if (pick < 32) type = 0x84FA;
  // At most 16 x 16 pixels of 16 bytes, with skips and row lengths below 16: inside the
  // 64 x 64 x 16-byte image.
  const int w = in.below(18) - 1, h = in.below(18) - 1;
  switch (in.below(10)) {
    case 0: glRasterPos4f(a, b, c, d); break;
    case 1: glRasterPos2i(in.integer(), in.integer()); break;
    case 2:
      if (in.u8() & 1) glWindowPos3f(a, b, c);
      else glWindowPos3dARB(a, b, c);  // GL_ARB_window_pos's name for the same call
      break;
    case 3: glBitmap(w, h, a, b, c, d, in.u8() & 1 ? reinterpret_cast<const GLubyte*>(image.data()) : nullptr); break;
    case 4: glDrawPixels(w, h, format, type, in.u8() & 1 ? image.data() : nullptr); break;
    case 5: glCopyPixels(in.integer() % 128, in.integer() % 128, w * (1 + in.below(8)), h, in.u8() & 1 ? GL_COLOR : e1); break;
    case 6: {
      // The polygon stipple through the random unpack state (48 rows of 8 bytes at
      // most: inside `image`); read back into 32 rows of at most 8 bytes.
      glPixelZoom(a, b);
      glPolygonStipple(in.u8() & 1 ? reinterpret_cast<const GLubyte*>(image.data()) : nullptr);
      (in.u8() & 1 ? glEnable : glDisable)(GL_POLYGON_STIPPLE);
      GLubyte back[32 * 8];
      glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
      glPixelStorei(GL_PACK_ROW_LENGTH, 0), glPixelStorei(GL_PACK_SKIP_ROWS, 0), glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
      glPixelStorei(GL_PACK_ALIGNMENT, 1 << in.below(4));
      glPixelStorei(GL_PACK_LSB_FIRST, in.u8() & 1);
      glGetPolygonStipple(back);
      glPopClientAttrib();
      break;
    }
    case 7: {
      static const GLenum counts[] = {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS};
      glPixelStorei(counts[in.below(3)], in.below(18) - 1);
      break;
    }
    case 8: {
      // Any value for the names that cannot move a read past `image` (and a bad name).
      static const GLenum names[] = {GL_UNPACK_ALIGNMENT, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_PACK_SWAP_BYTES,
                                     GL_UNPACK_IMAGE_HEIGHT, GL_RGBA};
      glPixelStoref(names[in.below(6)], in.u8() & 1 ? float(in.below(10) - 1) : a);
      break;
    }
    default: glRasterPos3f(a, b, c), glBitmap(w, h, 0, 0, a, b, reinterpret_cast<const GLubyte*>(image.data())); break;
  }
}

// User clip planes: any equation (NaN and infinities too), any plane name, enabled and
// disabled between and inside glBegin/glEnd, read back.
void clip_call(Bytes& in, float a, float b, float c, float d) {
  const GLenum plane = GL_CLIP_PLANE0 + GLenum(in.below(8)) - (in.u8() & 1);
  switch (in.below(3)) {
    case 0: {
      const GLdouble eq[4] = {a, b, c, d};
      glClipPlane(plane, in.u8() & 1 ? eq : nullptr);
      break;
    }
    case 1: (in.u8() & 1 ? glEnable : glDisable)(plane); break;
    default: {
      GLdouble eq[4];
      glGetClipPlane(plane, eq);
      glIsEnabled(plane);
      break;
    }
  }
}

// Texture coordinate generation: any coordinate, name, mode and plane (NaN too) in
// every form, enabled and disabled, read back; a textured triangle drawn with it.
void tex_gen_call(Bytes& in, float a, float b, float c, float d, GLenum e1) {
  static const GLenum names[] = {GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE, GL_TEXTURE_ENV_MODE};
  static const GLenum modes[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_NORMAL_MAP, GL_REFLECTION_MAP};
  const GLenum coord = GL_S + GLenum(in.below(5)) - (in.u8() & 1);
  const GLenum pname = in.u8() & 1 ? names[in.below(4)] : e1;
  const float fv[4] = {a, b, c, d};
  const GLint iv[4] = {GLint(in.below(8)) - 3, GLint(modes[in.below(5)]), 0, 1};
  const GLdouble dv[4] = {d, c, b, a};
  switch (in.below(7)) {
    case 0: glTexGeni(coord, pname, GLint(modes[in.below(5)])); break;
    case 1: glTexGenf(coord, pname, in.u8() & 1 ? a : float(modes[in.below(5)])); break;
    case 2: glTexGenfv(coord, pname, in.u8() & 1 ? fv : nullptr); break;
    case 3: glTexGeniv(coord, pname, iv); break;
    case 4: glTexGendv(coord, pname, dv); break;
    case 5: (in.u8() & 1 ? glEnable : glDisable)(GL_TEXTURE_GEN_S + GLenum(in.below(5))); break;
    default: {
      GLfloat f[4];
      GLint i[4];
      GLdouble g[4];
      glGetTexGenfv(coord, pname, f);
      glGetTexGeniv(coord, pname, i);
      glGetTexGendv(coord, pname, g);
      glEnable(GL_TEXTURE_2D);
      glBegin(GL_TRIANGLES);
      glNormal3f(a, b, c), glVertex3f(a, b, 0), glVertex3f(b, c, d), glVertex3f(d, a, c);
      glEnd();
      break;
    }
  }
}

// GL 1.5's buffer objects and occlusion queries: any target, name, size, offset,
// usage and access; arrays and indices pointed into buffers at any offset (the
// library bounds its reads by the buffer), drawn, mapped, written, read back.
void buffer_call(Bytes& in, std::vector<float>& scratch, GLuint* names, GLenum e1, GLenum e2) {
  static const GLenum targets[] = {GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER};
  const GLenum target = in.u8() < 230 ? targets[in.below(2)] : e1;
  const GLuint name = names[in.below(4)] + GLuint(in.below(3));
  // Sizes and offsets within `scratch` (64 x 64 x 4 floats) or just past it.
  const GLsizeiptr size = GLsizeiptr(in.below(4)) * GLsizeiptr(in.u16() % 4096) - 1;
  const GLintptr offset = GLintptr(in.u16() % 600) - 8;
  switch (in.below(12)) {
    case 0: glGenBuffers(in.below(5) - 1, names); break;
    case 1: glBindBuffer(target, name); break;
    case 2: glDeleteBuffers(in.below(5) - 1, names); break;
    case 3:
      glBufferData(target, size, in.u8() & 1 ? scratch.data() : nullptr,
                   in.u8() < 230 ? GL_STREAM_DRAW + GLenum(in.below(11)) : e2);
      break;
    case 4: glBufferSubData(target, offset, size, scratch.data()); break;
    case 5: glGetBufferSubData(target, offset, size, scratch.data()); break;
    case 6: {
      void* p = glMapBuffer(target, in.u8() < 230 ? GL_READ_ONLY + GLenum(in.below(3)) : e2);
      GLint bytes = 0;
      glGetBufferParameteriv(target, GL_BUFFER_SIZE, &bytes);
      if (p && bytes > 0) static_cast<uint8_t*>(p)[in.u16() % bytes] = in.u8();  // inside the mapping
      if (in.u8() & 1) glUnmapBuffer(target);
      break;
    }
    case 7: {
      GLint v;
      void* p;
      glGetBufferParameteriv(target, e2, &v);
      glGetBufferPointerv(target, in.u8() & 1 ? GL_BUFFER_MAP_POINTER : e2, &p);
      glGetPointerv(e1, &p);
      glIsBuffer(name);
      break;
    }
    case 8:
    case 9: {
      // Every array at an offset in the buffer bound to GL_ARRAY_BUFFER (offsets are
      // only given with one bound: without, they would be the caller's addresses); any
      // elements drawn, any indices from the element buffer.
      GLint array_buffer = 0, element_buffer = 0;
      glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer);
      glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &element_buffer);
      if (array_buffer == 0) break;
      const auto* at = reinterpret_cast<const void*>(uintptr_t(in.u16() % 2048));
      const GLsizei stride = GLsizei(in.below(40));
      glVertexPointer(2 + in.below(3), in.u8() & 1 ? GL_FLOAT : GL_SHORT, stride, at);
      glColorPointer(3 + in.below(2), in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT, stride, at);
      glNormalPointer(in.u8() & 1 ? GL_BYTE : GL_FLOAT, stride, at);
      glTexCoordPointer(1 + in.below(4), GL_FLOAT, stride, at);
      glEdgeFlagPointer(stride, at);
      if (in.u8() & 1) glDrawArrays(e1, in.below(64), in.below(300));
      if (element_buffer)
        glDrawElements(e1, in.below(300), GL_UNSIGNED_BYTE + 2 * GLenum(in.below(3)),
                       reinterpret_cast<const void*>(uintptr_t(in.u16() % 4096)));
      break;
    }
    case 10: {
      GLuint ids[2] = {names[0], names[1]};
      if (in.u8() & 1) glGenQueries(in.below(3) - 1, ids);
      if (in.u8() & 1) glBeginQuery(in.u8() < 230 ? GL_SAMPLES_PASSED : e1, ids[in.below(2)] + GLuint(in.below(2)));
      glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
      if (in.u8() & 1) glEndQuery(in.u8() < 230 ? GL_SAMPLES_PASSED : e1);
      GLuint r;
      GLint iv;
      glGetQueryObjectuiv(ids[in.below(2)], in.u8() & 1 ? GL_QUERY_RESULT : GL_QUERY_RESULT_AVAILABLE, &r);
      glGetQueryObjectiv(ids[in.below(2)], e2, &iv);
      glGetQueryiv(in.u8() & 1 ? GL_SAMPLES_PASSED : e1, in.u8() & 1 ? GL_CURRENT_QUERY : e2, &iv);
      if (in.u8() & 1) glDeleteQueries(in.below(3) - 1, ids);
      glIsQuery(ids[0]);
      break;
    }
    default: glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT), glBindBuffer(target, name), glPopClientAttrib(); break;
  }
}

// 1-D textures: images of any width up to 64 (`pixels` holds 64 RGBA floats a row),
// levels, offsets and targets; copies from the framebuffer; bound, enabled, drawn.
void texture_1d_call(Bytes& in, const std::vector<float>& pixels, GLuint* names, float a, float b, GLenum e1) {
  const GLenum target = in.u8() < 230 ? GL_TEXTURE_1D : e1;
  const GLint level = in.below(9) - 1;
  const GLsizei w = in.below(67) - 2;
  switch (in.below(7)) {
    case 0: glBindTexture(in.u8() & 1 ? GL_TEXTURE_1D : GL_TEXTURE_2D, names[in.below(4)] + GLuint(in.below(2))); break;
    case 1:
      glTexImage1D(target, level, in.u8() & 1 ? GL_RGBA : GLint(in.enumerant()), w, in.below(3) - 1,
                   in.u8() & 1 ? GL_RGBA : in.enumerant(), in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT,
                   in.u8() & 1 ? pixels.data() : nullptr);
      break;
    case 2:
      glTexSubImage1D(target, level, in.integer(), w, GL_RGBA, in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT, pixels.data());
      break;
    case 3: glCopyTexImage1D(target, level, GL_RGB, in.integer() % 128, in.integer() % 128, w, in.below(3) - 1); break;
    case 4: glCopyTexSubImage1D(target, level, in.integer() % 70, in.integer() % 128, in.integer() % 128, w); break;
    case 5: {
      GLint v;
      glGetTexLevelParameteriv(target, level, in.u8() & 1 ? GL_TEXTURE_WIDTH : e1, &v);
      std::vector<float> back(64 * 4);
      if (target == GL_TEXTURE_1D) glGetTexImage(target, level, GL_RGBA, GL_FLOAT, back.data());  // at most 64 texels
      glTexParameterf(target, in.u8() & 1 ? GL_TEXTURE_MIN_FILTER : e1, float(in.u8() & 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST));
      break;
    }
    default:
      (in.u8() & 1 ? glEnable : glDisable)(GL_TEXTURE_1D);
      glBegin(GL_TRIANGLES);
      glTexCoord2f(a, b), glVertex2f(-1, -1), glTexCoord2f(b, a), glVertex2f(1, -0.5f), glVertex2f(a, b);
      glEnd();
      break;
  }
}

// 3-D textures: images of any size up to 8x8x8 (`pixels` holds 64 * 64 RGBA floats;
// the pixel store reset around the calls that read or write client memory), levels,
// offsets and targets, proxies, copies from the framebuffer; bound, enabled, drawn.
void texture_3d_call(Bytes& in, const std::vector<float>& pixels, std::vector<float>& out, GLuint* names, float a,
                     float b, float c, GLenum e1) {
  const GLenum target = in.u8() < 230 ? GL_TEXTURE_3D : in.u8() & 1 ? GL_PROXY_TEXTURE_3D : e1;
  const GLint level = in.below(6) - 1;
  const GLsizei w = in.below(11) - 2, h = in.below(11) - 2, d = in.below(11) - 2;
  auto reset_store = [] {
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    for (GLenum p : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_IMAGE_HEIGHT,
                     GL_UNPACK_SKIP_IMAGES, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                     GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES})
      glPixelStorei(p, 0);
  };
  switch (in.below(7)) {
    case 0: glBindTexture(in.u8() & 1 ? GL_TEXTURE_3D : GL_TEXTURE_2D, names[in.below(4)] + GLuint(in.below(2))); break;
    case 1:
      reset_store();
      glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, in.below(3) ? 0 : 8), glPixelStorei(GL_UNPACK_SKIP_IMAGES, in.below(3));
      glTexImage3D(target, level, in.u8() & 1 ? GL_RGBA : GLint(in.enumerant()), w, h, d, in.below(3) - 1,
                   in.u8() & 1 ? GL_RGBA : in.enumerant(), in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT,
                   in.u8() & 1 ? pixels.data() : nullptr);
      glPopClientAttrib();
      break;
    case 2:
      reset_store();
      glTexSubImage3D(target, level, in.integer() % 10, in.integer() % 10, in.integer() % 10, w, h, d, GL_RGBA,
                      in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT, in.u8() & 1 ? pixels.data() : nullptr);
      glPopClientAttrib();
      break;
    case 3:
      glCopyTexSubImage3D(target, level, in.integer() % 10, in.integer() % 10, in.integer() % 10, in.integer() % 128,
                          in.integer() % 128, w, h);
      break;
    case 4: {
      GLint v;
      glGetTexLevelParameteriv(target, level, in.u8() & 1 ? GL_TEXTURE_DEPTH : e1, &v);
      reset_store();
      glPixelStorei(GL_PACK_IMAGE_HEIGHT, in.below(3) ? 0 : 8), glPixelStorei(GL_PACK_SKIP_IMAGES, in.below(3));
      // A level is at most 8x8x8 here (glTexImage3D's sizes): 8 * 10 images of 8 rows fit in out.
      if (target == GL_TEXTURE_3D) glGetTexImage(target, level, GL_RGBA, GL_FLOAT, out.data());
      glPopClientAttrib();
      break;
    }
    case 5:
      glTexParameterf(target, in.u8() & 1 ? GL_TEXTURE_WRAP_R : GL_TEXTURE_MIN_FILTER,
                      float(in.u8() & 1 ? GL_LINEAR_MIPMAP_LINEAR : in.u8() & 1 ? GL_CLAMP_TO_EDGE : e1));
      break;
    default:
      (in.u8() & 1 ? glEnable : glDisable)(GL_TEXTURE_3D);
      glBegin(GL_TRIANGLES);
      glTexCoord3f(a, b, c), glVertex2f(-1, -1), glTexCoord4f(b, a, c, a), glVertex2f(1, -0.5f), glVertex2f(a, b);
      glEnd();
      break;
  }
}

// Sized and generic compressed internal formats with every pixel type (the packed
// ones of GL 1.2 with any format, swapped or not), into 2-D, 1-D and 3-D images and
// copies; the level's sizes queried. Images at most 8x8 (x8) of 4-byte groups.
void texture_format_call(Bytes& in, const std::vector<float>& pixels, GLenum e1) {
  static const GLenum formats[] = {GL_ALPHA4,     GL_LUMINANCE16_ALPHA16, GL_INTENSITY12, GL_R3_G3_B2, GL_RGB10,
                                   GL_RGBA2,      GL_RGB10_A2,            GL_RGBA16,      GL_LUMINANCE6_ALPHA2,
                                   GL_COMPRESSED_RGB, GL_COMPRESSED_INTENSITY};
  static const GLenum types[] = {GL_UNSIGNED_BYTE_3_3_2,      GL_UNSIGNED_SHORT_5_6_5_REV, GL_UNSIGNED_SHORT_4_4_4_4,
                                 GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_UNSIGNED_INT_8_8_8_8,    GL_UNSIGNED_INT_2_10_10_10_REV,
                                 GL_BYTE, GL_SHORT, GL_UNSIGNED_INT, GL_FLOAT};
  static const GLenum pixel_formats[] = {GL_RGB, GL_RGBA, GL_BGRA, GL_BGR, GL_LUMINANCE_ALPHA, GL_ALPHA};
  const GLint internal = in.u8() < 230 ? GLint(formats[in.below(sizeof formats / sizeof formats[0])]) : GLint(e1);
  const GLenum type = types[in.below(sizeof types / sizeof types[0])];
  const GLenum format = pixel_formats[in.below(sizeof pixel_formats / sizeof pixel_formats[0])];
  const GLsizei w = in.below(10) - 1, h = in.below(10) - 1;
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  for (GLenum p : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_IMAGE_HEIGHT,
                   GL_UNPACK_SKIP_IMAGES})
    glPixelStorei(p, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, in.u8() & 1);
  switch (in.below(5)) {
    case 0: glTexImage2D(GL_TEXTURE_2D, 0, internal, w, h, 0, format, type, pixels.data()); break;
    case 1: glTexImage1D(GL_TEXTURE_1D, 0, internal, w, 0, format, type, pixels.data()); break;
    case 2: glTexImage3D(GL_TEXTURE_3D, 0, internal, w, h, in.below(9), 0, format, type, pixels.data()); break;
    case 3: glTexSubImage2D(GL_TEXTURE_2D, 0, in.below(4), in.below(4), w, h, format, type, pixels.data()); break;
    default: glCopyTexImage2D(GL_TEXTURE_2D, 0, GLenum(internal), in.below(64), in.below(64), w, h, 0); break;
  }
  glPopClientAttrib();
  GLint v;
  for (GLenum q : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_COMPRESSED})
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, q, &v);
}

// One-dimensional evaluators: any target, domain (NaN too), stride and order (the
// points read stay inside `attrib`: order * stride at most 30 * 8 of its 512 floats),
// enabled, evaluated inside and outside glBegin/glEnd, on grids of any size below 300.
// Framebuffer objects and renderbuffers: any target, attachment, texture (1-D or 2-D,
// any level, possibly deleted), renderbuffer format and size (small: at most 70 a side),
// bound for drawing and reading in any combination, drawn into, cleared, read, blitted
// between with any rectangles and filters, mipmaps generated.
void framebuffer_call(Bytes& in, std::vector<float>& scratch, GLuint* textures, GLuint* fbs, GLuint* rbs, float a,
                      float b, GLenum e1, GLenum e2) {
  static const GLenum targets[] = {GL_FRAMEBUFFER, GL_DRAW_FRAMEBUFFER, GL_READ_FRAMEBUFFER};
  static const GLenum attachments[] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT,
                                       GL_DEPTH_STENCIL_ATTACHMENT, GL_COLOR_ATTACHMENT1};
  static const GLenum formats[] = {GL_RGBA8, GL_RGB, GL_RGBA4, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                   GL_DEPTH_COMPONENT32, GL_STENCIL_INDEX8, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL};
  const GLenum target = in.u8() < 230 ? targets[in.below(3)] : e1;
  const GLenum attachment = in.u8() < 230 ? attachments[in.below(5)] : e2;
  const GLuint fb = fbs[in.below(4)] + GLuint(in.below(2));
  const GLuint rb = rbs[in.below(4)] + GLuint(in.below(2));
  const GLuint tex = textures[in.below(4)] + GLuint(in.below(2));
  switch (in.below(12)) {
    case 0: glGenFramebuffers(in.below(5) - 1, fbs); break;
    case 1: glBindFramebuffer(target, fb); break;
    case 2: glDeleteFramebuffers(in.below(3), fbs); break;
    case 3: glGenRenderbuffers(in.below(5) - 1, rbs), glBindRenderbuffer(in.u8() < 230 ? GL_RENDERBUFFER : e1, rb); break;
    case 4:
      glRenderbufferStorage(in.u8() < 230 ? GL_RENDERBUFFER : e1, in.u8() < 230 ? formats[in.below(9)] : e2,
                            in.below(72) - 1, in.below(72) - 1);
      break;
    case 5: glFramebufferRenderbuffer(target, attachment, in.u8() < 230 ? GL_RENDERBUFFER : e1, rb); break;
    case 6:
      if (in.u8() & 1)
        glFramebufferTexture2D(target, attachment, in.u8() < 230 ? GL_TEXTURE_2D : e1, tex, in.below(15) - 1);
      else
        glFramebufferTexture1D(target, attachment, in.u8() < 230 ? GL_TEXTURE_1D : e1, tex, in.below(15) - 1);
      break;
    case 7: {
      GLint v[4];
      glCheckFramebufferStatus(target);
      glGetFramebufferAttachmentParameteriv(target, in.u8() & 1 ? attachment : GL_DEPTH, e1, v);
      glGetRenderbufferParameteriv(GL_RENDERBUFFER, e2, v);
      glIsFramebuffer(fb), glIsRenderbuffer(rb);
      glDeleteRenderbuffers(in.below(3), rbs);
      break;
    }
    case 8: glGenerateMipmap(in.u8() < 230 ? GL_TEXTURE_1D + GLenum(in.below(2)) : e1); break;
    case 9:
      glBlitFramebuffer(in.integer(), in.integer(), in.integer(), in.integer(), in.integer(), in.integer(),
                        in.integer(), in.integer(), GLbitfield(in.u8() < 230 ? in.below(8) << 8 : in.u16()),
                        in.u8() & 1 ? GL_NEAREST : GL_LINEAR);
      break;
    case 10:
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
      glRectf(a, b, b, a);
      glReadPixels(in.below(80) - 4, in.below(80) - 4, in.below(8), in.below(8),
                   in.u8() & 1 ? GL_RGBA : GL_DEPTH_COMPONENT, GL_FLOAT, scratch.data());
      break;
    default:
      glDrawBuffer(in.u8() & 1 ? GL_COLOR_ATTACHMENT0 : e1);
      glReadBuffer(in.u8() & 1 ? GL_COLOR_ATTACHMENT0 : e2);
      glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, in.below(70) - 2, in.below(70) - 2, in.below(40), in.below(40), 0);
      glDeleteTextures(in.below(2), textures);
      break;
  }
}

void evaluator_call(Bytes& in, const std::vector<float>& attrib, float a, float b, GLenum e1) {
  const GLenum target = in.u8() < 230 ? GL_MAP1_COLOR_4 + GLenum(in.below(9)) : e1;
  switch (in.below(6)) {
    case 0: glMap1f(target, a, b, in.below(10) - 1, in.below(33) - 1, attrib.data()); break;
    case 1: (in.u8() & 1 ? glEnable : glDisable)(target); break;
    case 2:
      glBegin(in.u8() & 1 ? GL_LINE_STRIP : GL_POINTS);
      for (int i = in.below(20); i >= 0; --i) glEvalCoord1f(a + float(i) * b);
      glEnd();
      break;
    case 3: glMapGrid1f(in.below(300) - 1, a, b); break;
    case 4:
      glEvalMesh1(in.u8() < 230 ? GL_POINT + GLenum(in.below(3)) : e1, in.below(300) - 10, in.below(300) - 10);
      glEvalPoint1(in.below(300) - 10);
      break;
    default: {
      GLfloat v[32 * 4];
      glGetMapfv(target, in.u8() < 230 ? GL_COEFF + GLenum(in.below(3)) : e1, v);
      break;
    }
  }
}

// Two-dimensional evaluators: any target, domains (NaN too), strides and orders (the
// points read stay inside `attrib`: at most 30 * 4 + 30 * 4 + 4 of its 512 floats),
// GL_AUTO_NORMAL, evaluated inside and outside glBegin/glEnd, meshes on grids below 40
// a side in the three modes (and a bad one), in a display list, under glPushAttrib.
void evaluator2_call(Bytes& in, const std::vector<float>& attrib, float a, float b, GLenum e1) {
  const GLenum target = in.u8() < 230 ? GL_MAP2_COLOR_4 + GLenum(in.below(9)) : e1;
  switch (in.below(7)) {
    case 0:
      glMap2f(target, a, b, in.below(6) - 1, in.below(33) - 1, b, a + 1, in.below(6) - 1, in.below(33) - 1,
              attrib.data());
      break;
    case 1: (in.u8() & 1 ? glEnable : glDisable)(in.u8() & 1 ? GLenum(GL_AUTO_NORMAL) : target); break;
    case 2:
      glBegin(in.u8() & 1 ? GL_TRIANGLE_STRIP : GL_POINTS);
      for (int i = in.below(20); i >= 0; --i) glEvalCoord2f(a + float(i) * b, b - float(i) * a);
      glEvalPoint2(in.below(60) - 10, in.below(60) - 10);
      glEnd();
      break;
    case 3: glMapGrid2f(in.below(40) - 1, a, b, in.below(40) - 1, b, a); break;
    case 4: {
      const bool listed = in.u8() & 1;
      if (listed) glNewList(1, GL_COMPILE_AND_EXECUTE);
      glEvalMesh2(in.u8() < 230 ? GL_POINT + GLenum(in.below(3)) : e1, in.below(40) - 5, in.below(40) - 5,
                  in.below(40) - 5, in.below(40) - 5);
      if (listed) glEndList();
      break;
    }
    case 5:
      glPushAttrib(in.u8() & 1 ? GL_EVAL_BIT : GL_ENABLE_BIT);
      glEnable(GL_MAP2_VERTEX_3);
      glPopAttrib();
      break;
    default: {
      static std::vector<GLfloat> v(30 * 30 * 4);
      glGetMapfv(target, in.u8() < 230 ? GL_COEFF + GLenum(in.below(3)) : e1, v.data());
      break;
    }
  }
}

// glPixelMap: any table name, sizes around the limits (the values read stay inside
// `attrib`'s 512 floats; NaN and huge values included), read back in the three types,
// then used by glDrawPixels of colours and stencil indices with the maps on.
void pixel_map_call(Bytes& in, const std::vector<float>& attrib, GLenum e1) {
  const GLenum map = in.u8() < 230 ? GL_PIXEL_MAP_I_TO_I + GLenum(in.below(10)) : e1;
  const GLsizei size = GLsizei(in.below(260)) - 1;
  switch (in.below(3)) {
    case 0: glPixelMapfv(map, size, attrib.data()); break;
    case 1: glPixelMapuiv(map, size, reinterpret_cast<const GLuint*>(attrib.data())); break;
    default: glPixelMapusv(map, size, reinterpret_cast<const GLushort*>(attrib.data())); break;
  }
  static std::vector<GLuint> back(256);
  glGetPixelMapuiv(map, back.data());
  glGetPixelMapusv(map, reinterpret_cast<GLushort*>(back.data()));
  glGetPixelMapfv(map, reinterpret_cast<GLfloat*>(back.data()));
  glPixelTransferi(GL_MAP_COLOR, in.u8() & 1);
  glPixelTransferi(GL_MAP_STENCIL, in.u8() & 1);
  glPixelTransferi(GL_INDEX_OFFSET, int(in.below(600)) - 300);
  // 16 bytes: read with the default unpack state (the random one may reach past them).
  // Outside glBegin/glEnd, where glPixelStore works (inside, a list compiled with
  // GL_COMPILE_AND_EXECUTE would read the pixels under the random state).
  const GLubyte pixels[4 * 4] = {0, 64, 128, 255, 1, 2, 3, 4, 250, 7, 9, 200, 13, 17, 19, 23};
  glEnd();
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0), glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0), glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glRasterPos2f(0, 0);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glDrawPixels(4, 4, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, pixels);
  glPopClientAttrib();
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
}

#ifdef VELOCITY_FUZZ_GLUT_SHAPES
// GLUT's shapes with random sizes and counts (below 31, as the quadrics').
void shape_call(Bytes& in, float a, float b) {
  const int n1 = in.below(33) - 2, n2 = in.below(33) - 2;
  const bool wire = in.u8() & 1;
  switch (in.below(9)) {
    case 0: (wire ? glutWireSphere : glutSolidSphere)(a, n1, n2); break;
    case 1: (wire ? glutWireCone : glutSolidCone)(a, b, n1, n2); break;
    case 2: (wire ? glutWireTorus : glutSolidTorus)(a, b, n1, n2); break;
    case 3: (wire ? glutWireCube : glutSolidCube)(a); break;
    case 4: (wire ? glutWireTetrahedron : glutSolidTetrahedron)(); break;
    case 5: (wire ? glutWireOctahedron : glutSolidOctahedron)(); break;
    case 6: (wire ? glutWireDodecahedron : glutSolidDodecahedron)(); break;
    case 7: (wire ? glutWireTeapot : glutSolidTeapot)(a); break;
    default: (wire ? glutWireIcosahedron : glutSolidIcosahedron)(); break;
  }
}
#endif

// Colour buffers, the level-of-detail controls and glPixelTransfer: glDrawBuffer / glReadBuffer with
// every buffer name and any enum (OSMesa's single buffer: the back, right and
// auxiliary ones are errors), GL_NONE before drawing and reading; GL_TEXTURE_MIN_LOD,
// _MAX_LOD and both biases at any value (NaN, infinities), then a textured draw.
// GL 1.4's secondary colour and fog coordinates, GL 1.2's separate specular colour
// (gl/src/color_sum.cpp): their state at any values, their arrays inside `attrib` (64
// elements of any type fit), draws with the colour sum on, lit and textured or not.
void color_sum_call(Bytes& in, const std::vector<float>& attrib, float a, float b, float c, GLenum e1) {
  static const GLenum caps[] = {GL_COLOR_SUM, GL_SECONDARY_COLOR_ARRAY, GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY};
  static const GLenum types[] = {GL_FLOAT, GL_DOUBLE, GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_UNSIGNED_INT};
  const GLenum cap = in.u8() < 230 ? caps[in.below(4)] : e1;
  switch (in.below(6)) {
    case 0:
      glSecondaryColor3f(a, b, c);
      if (in.u8() & 1) glSecondaryColor3ub(in.u8(), in.u8(), in.u8());
      if (in.u8() & 1) glSecondaryColor3s(GLshort(in.integer()), GLshort(in.integer()), GLshort(in.integer()));
      if (in.u8() & 1) glSecondaryColor3i(in.integer(), in.integer(), in.integer());
      break;
    case 1:
      glFogCoordf(a);
      if (in.u8() & 1) glFogCoordd(b);
      glFogi(GL_FOG_COORD_SRC, in.u8() < 230 ? (in.u8() & 1 ? GL_FOG_COORD : GL_FRAGMENT_DEPTH) : e1);
      break;
    case 2:
      glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, in.u8() < 230 ? (in.u8() & 1 ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR) : e1);
      (in.u8() & 1 ? glEnable : glDisable)(cap);
      (in.u8() & 1 ? glEnableClientState : glDisableClientState)(cap);
      break;
    case 3: {
      const GLsizei stride = GLsizei(in.below(4) * 4) - (in.u8() < 240 ? 0 : 8);
      const GLenum type = in.u8() < 240 ? types[in.below(6)] : e1;
      glSecondaryColorPointer(in.u8() < 230 ? 3 : in.below(6), type, stride, attrib.data() + 16);
      glFogCoordPointer(in.u8() & 1 ? GL_FLOAT : type, stride, attrib.data() + 260);
      glIndexPointer(type, stride, attrib.data() + 8);
      break;
    }
    case 4: {
      static const GLenum queries[] = {GL_CURRENT_SECONDARY_COLOR, GL_CURRENT_FOG_COORD, GL_FOG_COORD_SRC,
                                       GL_LIGHT_MODEL_COLOR_CONTROL, GL_SECONDARY_COLOR_ARRAY_SIZE,
                                       GL_SECONDARY_COLOR_ARRAY_TYPE, GL_SECONDARY_COLOR_ARRAY_STRIDE,
                                       GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY_STRIDE, GL_INDEX_ARRAY_TYPE,
                                       GL_INDEX_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING,
                                       GL_FOG_COORD_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_BUFFER_BINDING};
      GLfloat v[16];
      GLvoid* p;
      glGetFloatv(queries[in.below(14)], v);
      glGetPointerv(in.u8() & 1 ? GL_SECONDARY_COLOR_ARRAY_POINTER : GL_FOG_COORD_ARRAY_POINTER, &p);
      glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
      glIsEnabled(cap);
      glPushAttrib(in.u8() & 1 ? GL_ALL_ATTRIB_BITS : GL_FOG_BIT | GL_CURRENT_BIT);
      glEnable(GL_COLOR_SUM);
      glPopAttrib();
      break;
    }
    default: {
      glEnable(GL_COLOR_SUM);
      if (in.u8() & 1) glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
      glBegin(in.u8() & 1 ? GL_TRIANGLES : GL_LINE_LOOP);
      glSecondaryColor3f(a, 0.5f, c), glFogCoordf(b), glVertex2f(a, b);
      glSecondaryColor3f(b, c, 1), glFogCoordf(c), glVertex2f(b, c);
      glSecondaryColor3f(0, a, b), glFogCoordf(a), glVertex2f(c, a);
      glEnd();
      glDrawArrays(GL_TRIANGLES, in.below(20), in.below(36));
      glDisable(GL_LIGHTING);
      break;
    }
  }
}

// GL 1.3's multitexture (gl/src/multitexture.cpp): units chosen (and bad ones), each
// unit's texture state, coordinates and array inside `attrib`, draws, the attribute
// stacks across a unit change.
void multitexture_call(Bytes& in, const std::vector<float>& attrib, GLuint* names, float a, float b, GLenum e1) {
  const GLenum unit = in.u8() < 230 ? GL_TEXTURE0 + GLenum(in.below(3)) : e1;
  switch (in.below(6)) {
    case 0: (in.u8() & 1 ? glActiveTexture : glActiveTextureARB)(unit); break;
    case 1: glClientActiveTexture(unit); break;
    case 2:
      glMultiTexCoord4f(unit, a, b, a, in.u8() & 1 ? 1.0f : b);
      if (in.u8() & 1) glMultiTexCoord2s(unit, GLshort(in.integer()), GLshort(in.integer()));
      if (in.u8() & 1) glMultiTexCoord1dARB(unit, double(a));
      break;
    case 3:
      glActiveTexture(unit);
      glBindTexture(in.u8() & 1 ? GL_TEXTURE_2D : GL_TEXTURE_1D, names[in.below(4)]);
      (in.u8() & 1 ? glEnable : glDisable)(in.u8() & 1 ? GL_TEXTURE_2D : GL_TEXTURE_1D);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, in.u8() & 1 ? GL_MODULATE : GL_ADD + GLint(in.below(3)) - 1);
      if (in.u8() & 1) (in.u8() & 1 ? glEnable : glDisable)(GL_TEXTURE_GEN_S + GLenum(in.below(4)));
      if (in.u8() & 1) glMatrixMode(GL_TEXTURE), glRotatef(a, 0, 0, 1), glMatrixMode(GL_MODELVIEW);
      break;
    case 4:
      glClientActiveTexture(unit);
      glTexCoordPointer(1 + in.below(4), in.u8() & 1 ? GL_FLOAT : GL_SHORT, GLsizei(in.below(3) * 4), attrib.data() + 20);
      (in.u8() & 1 ? glEnableClientState : glDisableClientState)(GL_TEXTURE_COORD_ARRAY);
      glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
      glClientActiveTexture(GL_TEXTURE0 + GLenum(in.below(2)));
      if (in.u8() & 1) glPopClientAttrib();
      break;
    default: {
      glPushAttrib(in.u8() & 1 ? GL_TEXTURE_BIT : GL_ENABLE_BIT | GL_CURRENT_BIT);
      glActiveTexture(unit);
      glBegin(in.u8() & 1 ? GL_QUADS : GL_LINE_STRIP);
      for (int k = 0; k < 4; ++k) {
        glMultiTexCoord2f(GL_TEXTURE0, a * float(k), b);
        glMultiTexCoord2f(GL_TEXTURE1, b, a * float(k));
        glVertex2f(k & 1 ? a : b, k & 2 ? b : a);
      }
      glEnd();
      glRasterPos2f(a, b);
      if (in.u8() & 1) glPopAttrib();
      break;
    }
  }
}

// GL 1.3's GL_COMBINE environment and the texture queries (gl/src/tex_combine.cpp):
// every combine parameter with its values, neighbours' and any; glGetTexEnv and
// glGetTexParameter with any target and name into a buffer of the largest answer's
// size (4); a draw through the combined units.
void tex_combine_call(Bytes& in, float a, float b, GLenum e1) {
  static const GLenum pnames[] = {GL_COMBINE_RGB,     GL_COMBINE_ALPHA,  GL_SOURCE0_RGB,    GL_SOURCE1_RGB,
                                  GL_SOURCE2_RGB,     GL_SOURCE0_ALPHA,  GL_SOURCE1_ALPHA,  GL_SOURCE2_ALPHA,
                                  GL_OPERAND0_RGB,    GL_OPERAND1_RGB,   GL_OPERAND2_RGB,   GL_OPERAND0_ALPHA,
                                  GL_OPERAND1_ALPHA,  GL_OPERAND2_ALPHA, GL_RGB_SCALE,      GL_ALPHA_SCALE,
                                  GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_R,
                                  GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_PRIORITY, GL_TEXTURE_RESIDENT, GL_TEXTURE_MIN_LOD,
                                  GL_GENERATE_MIPMAP, GL_TEXTURE_LOD_BIAS};
  static const GLenum values[] = {GL_COMBINE,    GL_REPLACE,       GL_MODULATE,      GL_ADD,
                                  GL_ADD_SIGNED, GL_INTERPOLATE,   GL_SUBTRACT,      GL_DOT3_RGB,
                                  GL_DOT3_RGBA,  GL_TEXTURE,       GL_CONSTANT,      GL_PRIMARY_COLOR,
                                  GL_PREVIOUS,   GL_SRC_COLOR,     GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                  GL_ONE_MINUS_SRC_ALPHA, GL_TEXTURE1, GL_ZERO, GL_ONE};
  static const GLenum targets[] = {GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_1D, GL_TEXTURE_2D,
                                   GL_TEXTURE_3D, GL_PROXY_TEXTURE_2D};
  const GLenum pname = in.u8() < 240 ? pnames[in.below(26)] : e1;
  const GLenum target = in.u8() < 240 ? targets[in.below(6)] : e1;
  switch (in.below(5)) {
    case 0: glTexEnvi(GL_TEXTURE_ENV, pname, GLint(in.u8() < 200 ? values[in.below(20)] : GLenum(in.integer()))); break;
    case 1: {
      const GLfloat v[4] = {a, b, float(in.below(6)), 0.5f};
      if (in.u8() & 1) glTexEnvfv(target, pname, v);
      else glTexEnviv(target, pname, reinterpret_cast<const GLint*>(values));
      break;
    }
    case 2: {
      GLfloat f[4] = {};
      GLint v[4] = {};
      (in.u8() & 1 ? glGetTexEnvfv : glGetTexParameterfv)(target, pname, f);
      (in.u8() & 1 ? glGetTexEnviv : glGetTexParameteriv)(target, pname, v);
      break;
    }
    case 3: {  // inside glBegin/glEnd: GL_INVALID_OPERATION, no change
      GLfloat f[4] = {};
      glBegin(GL_POINTS);
      glTexEnvi(GL_TEXTURE_ENV, pname, GL_ADD);
      glGetTexEnvfv(GL_TEXTURE_ENV, pname, f);
      glGetTexParameterfv(target, pname, f);
      glEnd();
      break;
    }
    default:
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
      glEnable(GL_TEXTURE_2D);
      glBegin(GL_TRIANGLES);
      glColor4f(a, b, 0.5f, a), glTexCoord2f(a, b), glVertex2f(a, b);
      glColor4f(b, 0.2f, a, 1), glTexCoord2f(b, 0), glVertex2f(b, -a);
      glColor4f(1, a, b, 0), glTexCoord2f(0, a), glVertex2f(-b, a);
      glEnd();
      break;
  }
}

void buffer_lod_call(Bytes& in, float a, float b, GLenum e1) {
  static const GLenum names[] = {GL_NONE, GL_FRONT_LEFT, GL_FRONT_RIGHT, GL_BACK_LEFT, GL_BACK_RIGHT, GL_FRONT,
                                 GL_BACK, GL_LEFT, GL_RIGHT, GL_FRONT_AND_BACK, GL_AUX0, GL_AUX3};
  const GLenum mode = in.u8() < 230 ? names[in.below(12)] : e1;
  switch (in.below(6)) {
    case 5: {
      // glPixelTransfer: every name (and a bad one) at any value, then pixels drawn
      // through it by the other calls.
      static const GLenum transfer[] = {GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE,
                                        GL_RED_BIAS, GL_GREEN_SCALE, GL_GREEN_BIAS, GL_BLUE_SCALE, GL_BLUE_BIAS,
                                        GL_ALPHA_SCALE, GL_ALPHA_BIAS, GL_DEPTH_SCALE, GL_DEPTH_BIAS};
      const GLenum pname = in.u8() < 240 ? transfer[in.below(14)] : e1;
      if (in.u8() & 1)
        glPixelTransferf(pname, a);
      else
        glPixelTransferi(pname, GLint(in.integer()));
      break;
    }
    case 0: glDrawBuffer(mode); break;
    case 1: glReadBuffer(mode); break;
    case 2: {
      static const GLenum lod[] = {GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD, GL_TEXTURE_LOD_BIAS};
      glTexParameterf(GL_TEXTURE_2D, lod[in.below(3)], a);
      glTexEnvf(in.u8() & 1 ? GL_TEXTURE_FILTER_CONTROL : e1, in.u8() & 1 ? GL_TEXTURE_LOD_BIAS : e1, b);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST + GLint(in.below(4)));
      break;
    }
    case 3: {
      // 64 bytes of texels: read with the default unpack state (the random one, with its
      // row lengths and skips, may reach past them; pixel_call gives it a larger image).
      const GLubyte texels[4 * 4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255};
      glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0), glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0), glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      glPopClientAttrib();
      glEnable(GL_TEXTURE_2D);
      glBegin(GL_TRIANGLES);
      glTexCoord2f(0, 0), glVertex2f(-1, -1);
      glTexCoord2f(a, 0), glVertex2f(1, -1);
      glTexCoord2f(0, b), glVertex2f(0, 1);
      glEnd();
      glDisable(GL_TEXTURE_2D);
      break;
    }
    default: {
      // Reading and copying whatever buffer is selected, GL_NONE included.
      uint8_t px[4 * 4 * 4];
      glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);  // 4 x 4 RGBA rows, nothing skipped
      glPixelStorei(GL_PACK_ROW_LENGTH, 0), glPixelStorei(GL_PACK_SKIP_ROWS, 0);
      glPixelStorei(GL_PACK_SKIP_PIXELS, 0), glPixelStorei(GL_PACK_ALIGNMENT, 4);
      glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
      glPopClientAttrib();
      glRasterPos2f(a, b);
      static const GLenum copies[] = {GL_COLOR, GL_DEPTH, GL_STENCIL};
      glCopyPixels(0, 0, 4, 4, copies[in.below(3)]);
      glAccum(GL_LOAD, 1);
      break;
    }
  }
}

bool valid_error(GLenum e) {
  return e == GL_NO_ERROR || (e >= GL_INVALID_ENUM && e <= GL_OUT_OF_MEMORY) || e == GL_INVALID_FRAMEBUFFER_OPERATION;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  static const GLenum formats[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR};
  const GLenum format = formats[in.below(5)];
  const int w = 1 + in.below(96), h = 1 + in.below(96);
  const int buffers = in.below(3);  // none, depth, depth and stencil
  OSMesaContext ctx = OSMesaCreateContextExt(format, buffers ? 24 : 0, buffers == 2 ? 8 : 0, buffers == 2 ? 16 : 0, nullptr);
  fuzz_check(ctx != nullptr);
  const size_t bpp = format == OSMESA_RGB || format == OSMESA_BGR ? 3 : 4;
  std::vector<uint8_t> buffer(size_t(w) * h * bpp);
  fuzz_check(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h));

  // Client memory the calls may point at: 64 vertices of every attribute, 64 indices
  // below 64, a 64x64 RGBA float image (large enough for any format and type).
  std::vector<float> attrib(64 * 4 * 2);
  for (float& f : attrib) f = in.number();
  std::vector<uint32_t> idx32(64);
  std::vector<uint16_t> idx16(64);
  std::vector<uint8_t> idx8(64);
  for (int i = 0; i < 64; ++i) idx32[size_t(i)] = idx16[size_t(i)] = idx8[size_t(i)] = uint8_t(in.below(64));
  std::vector<float> pixels(64 * 64 * 4);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 97) / 96.0f;
  std::vector<float> out(96 * 96 * 4 + 16);
  GLuint names[4] = {0, 0, 0, 0};
  GLuint buffer_names[4] = {0, 0, 0, 0};
  GLuint framebuffer_names[4] = {0, 0, 0, 0}, renderbuffer_names[4] = {0, 0, 0, 0};
  GLUquadric* quadric = gluNewQuadric();

  for (int call = 0; call < 512 && !in.empty(); ++call) {
    const GLenum e1 = in.enumerant(), e2 = in.enumerant();
    const float a = in.number(), b = in.number(), c = in.number(), d = in.number();
    const float v4[4] = {a, b, c, d};
    const GLint iv4[4] = {in.integer(), in.integer(), in.integer(), in.integer()};
    switch (in.below(69)) {
      case 63: glStencilFunc(e1, iv4[0], GLuint(iv4[1])); break;
      case 64:
        switch (in.below(5)) {
          case 0:
            glStencilOp(e1, e2, in.enumerant());
            glStencilMask(GLuint(iv4[2]));
            glClearStencil(iv4[3]);
            // The accumulation buffer (the context with every buffer has one).
            glClearAccum(a, b, c, d);
            glAccum(in.u8() & 1 ? GL_ACCUM + GLenum(in.below(5)) : e1, a * b);
            break;
          case 1: (in.u8() & 1 ? glPushAttrib(GLbitfield(iv4[0])) : glPopAttrib()); break;
          case 2: (in.u8() & 1 ? glPushClientAttrib(GLbitfield(iv4[0])) : glPopClientAttrib()); break;
          case 3: {
            // Edge flags, from glEdgeFlag and from an array inside `attrib`'s bytes.
            glEdgeFlag(GLboolean(in.u8() & 1));
            glEdgeFlagPointer(GLsizei(in.below(3)) - 1, attrib.data());
            (in.u8() & 1 ? glEnableClientState : glDisableClientState)(GL_EDGE_FLAG_ARRAY);
            break;
          }
          default:
            glBlendColor(a, b, c, d);
            glBlendEquation(e1);
            glBlendFuncSeparate(e2, in.enumerant(), in.enumerant(), in.enumerant());
            break;
        }
        break;
      case 66:
        // Selection: the buffer is `out`'s memory; names and modes from the input.
        if (in.u8() & 1) glSelectBuffer(in.below(64) - 1, reinterpret_cast<GLuint*>(out.data()));
        // Feedback: into `out` too, any size and type; the tokens while drawing.
        if (in.u8() & 1) glFeedbackBuffer(in.below(64) - 1, in.u8() & 1 ? GL_2D + GLenum(in.below(6)) : e1, out.data());
        if (in.u8() & 1) glPassThrough(a);
        glRenderMode(in.u8() & 1 ? (in.u8() & 1 ? GL_SELECT : GL_FEEDBACK) : e1);
        (in.u8() & 1 ? glPushName(GLuint(iv4[0])) : in.u8() & 1 ? glPopName() : glLoadName(GLuint(iv4[1])));
        if (in.u8() & 1) glInitNames();
        break;
      case 67: {
        // Copies from the colour buffer (any rectangle, partly outside or not) and the
        // level queries.
        const GLint level = in.below(4) - 1;
        const GLint x = in.integer() % 128, y = in.integer() % 128;
        const GLsizei cw = in.below(70) - 2, ch = in.below(70) - 2;
        if (in.u8() & 1)
          glCopyTexImage2D(in.u8() & 1 ? GL_TEXTURE_2D : e1, level, in.u8() & 1 ? GL_RGBA : e2, x, y, cw, ch,
                           in.below(3) - 1);
        else
          glCopyTexSubImage2D(GL_TEXTURE_2D, level, in.below(40) - 4, in.below(40) - 4, x, y, cw, ch);
        GLint v = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, in.u8() & 1 ? GL_TEXTURE_WIDTH : e1, &v);
        break;
      }
      case 65: {
        // Ranges inside the arrays' 56 elements, as case 50's.
        GLint firsts[3];
        GLsizei counts[3];
        for (int k = 0; k < 3; ++k) firsts[k] = in.below(56), counts[k] = in.below(57 - firsts[k]);
        glMultiDrawArrays(e1, firsts, counts, in.below(5) - 1);
        break;
      }
      case 0: glBegin(e1); break;
      case 1: glEnd(); break;
      case 2: glVertex3f(a, b, c); break;
      case 3: glVertex4fv(v4); break;
      case 4: glColor4f(a, b, c, d); break;
      case 5: glColor3ub(uint8_t(iv4[0]), uint8_t(iv4[1]), uint8_t(iv4[2])); break;
      case 6: glNormal3f(a, b, c); break;
      case 7: glTexCoord4f(a, b, c, d); break;
      case 8: glMatrixMode(e1); break;
      case 9: glLoadIdentity(); break;
      case 10: glPushMatrix(); break;
      case 11: glPopMatrix(); break;
      case 12: glRotatef(a, b, c, d); break;
      case 13: glTranslatef(a, b, c); break;
      case 14: glScalef(a, b, c); break;
      case 15: glOrtho(a, b, c, d, in.number(), in.number()); break;
      case 16: glFrustum(a, b, c, d, in.number(), in.number()); break;
      case 17: gluPerspective(a, b, c, d); break;
      case 18: gluLookAt(a, b, c, d, 0, 0, 0, 1, 0); break;
      case 19: glViewport(iv4[0], iv4[1], iv4[2], iv4[3]); break;
      case 20: glScissor(iv4[0], iv4[1], iv4[2], iv4[3]); break;
      case 21: glClear(GLbitfield(in.u32())); break;
      case 22: glClearColor(a, b, c, d); break;
      case 23: glEnable(e1); break;
      case 24: glDisable(e1); break;
      case 25: glDepthFunc(e1); break;
      case 26: glBlendFunc(e1, e2); break;
      case 27: glAlphaFunc(e1, a); break;
      case 28: glFogfv(e1, v4); break;
      case 29: glLightfv(GL_LIGHT0 + GLenum(in.below(9)), e1, v4); break;
      case 30: glLightModelfv(e1, v4); break;
      case 31: glMaterialfv(e1, e2, v4); break;
      case 32: glColorMaterial(e1, e2); break;
      case 33: glShadeModel(e1); break;
      case 34: glCullFace(e1); break;
      case 35: glFrontFace(e1); break;
      case 36: glPolygonMode(e1, e2); break;
      case 37: glPolygonOffset(a, b); break;
      case 38: glPointSize(a); break;
      case 39: glLineWidth(a); break;
      case 40: glGenTextures(in.below(5) - 1, names); break;
      case 41: glBindTexture(e1, names[in.below(4)] + GLuint(in.below(3))); break;
      case 42: glDeleteTextures(in.below(5) - 1, names); break;
      case 43: {
        const int tw = in.below(67) - 2, th = in.below(67) - 2;  // at most 64: `pixels` holds 64x64 RGBA floats
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1 << in.below(4));
        glTexImage2D(e1 == GL_TEXTURE ? GL_TEXTURE_2D : GL_TEXTURE_2D, in.below(9) - 1, GLint(in.enumerant()), tw, th,
                     in.below(3) - 1, in.enumerant(), in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT,
                     in.u8() & 1 ? pixels.data() : nullptr);
        break;
      }
      case 44: {
        const int tw = in.below(65), th = in.below(65);
        glTexSubImage2D(GL_TEXTURE_2D, in.below(3), in.integer(), in.integer(), tw, th, in.enumerant(),
                        in.u8() & 1 ? GL_UNSIGNED_BYTE : GL_FLOAT, pixels.data());
        break;
      }
      case 45: glTexParameterf(e1, e2, a); break;
      case 46: glTexEnvfv(e1, e2, v4); break;
      case 47: gluBuild2DMipmaps(GL_TEXTURE_2D, GLint(e1), 1 + in.below(64), 1 + in.below(64), e2, GL_UNSIGNED_BYTE,
                                 pixels.data());
        break;
      case 48: {
        // Arrays inside `attrib`: sizes and types whose 64 elements fit in it.
        const GLsizei stride = GLsizei(in.below(3) * 4);
        const int sz = 2 + in.below(3);
        glVertexPointer(sz, in.u8() & 1 ? GL_FLOAT : e1, stride, attrib.data());
        glColorPointer(3 + in.below(2), in.u8() & 1 ? GL_FLOAT : GL_UNSIGNED_BYTE, 0, attrib.data() + 4);
        glNormalPointer(GL_FLOAT, 0, attrib.data() + 8);
        glTexCoordPointer(1 + in.below(4), GL_FLOAT, 0, attrib.data() + 12);
        // Or the interleaved formats (one past the last too) over `out`, packed or not.
        if (in.u8() & 1) glInterleavedArrays(GL_V2F + GLenum(in.below(15)), GLsizei(in.below(18) * 4) - 4, out.data());
        break;
      }
      case 49: (in.u8() & 1 ? glEnableClientState : glDisableClientState)(e1); break;
      case 50: {
        const int first = in.below(70) - 3, count = in.below(70) - 3;
        glDrawArrays(e1, first, first >= 0 && first + count > 56 ? 56 - first : count);
        break;
      }
      case 51: {
        const int n = in.below(66) - 1;
        const int t = in.below(4);
        const void* p = t == 0 ? static_cast<const void*>(idx8.data()) : t == 1 ? static_cast<const void*>(idx16.data())
                                                                                 : static_cast<const void*>(idx32.data());
        const GLenum type = t == 0 ? GL_UNSIGNED_BYTE : t == 1 ? GL_UNSIGNED_SHORT : t == 2 ? GL_UNSIGNED_INT : e2;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);  // the indices are the client's, below 64
        if (in.u8() & 1)
          glDrawElements(e1, n > 64 ? 64 : n, type, p);
        else  // the range is advice: any, even a wrong or reversed one
          glDrawRangeElements(e1, GLuint(in.below(70)), GLuint(in.below(70)), n > 64 ? 64 : n, type, p);
        break;
      }
      case 52: glArrayElement(in.below(56)); break;
      case 53: glNewList(GLuint(in.below(6)), e1); break;
      case 54: glEndList(); break;
      case 55: glCallList(GLuint(in.below(6))); break;
      case 56: {
        const GLubyte lists[4] = {uint8_t(in.below(6)), uint8_t(in.below(6)), uint8_t(in.below(6)), uint8_t(in.below(6))};
        glListBase(GLuint(in.below(3)));
        glCallLists(in.below(6) - 1, GL_UNSIGNED_BYTE, lists);
        break;
      }
      case 57: glGenLists(in.below(6) - 1); break;
      case 58: glDeleteLists(GLuint(in.below(6)), in.below(6) - 1); break;
      case 59: {
        const int rw = in.below(12) - 1, rh = in.below(12) - 1;
        glPixelStorei(GL_PACK_ALIGNMENT, 1 << in.below(4));
        // Bytes, floats, or one of the packed types (at most 4 bytes a pixel, as a float's one component).
        static const GLenum read_types[5] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_INT_8_8_8_8,
                                             GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_BYTE_3_3_2};
        glReadPixels(in.integer() % 128, in.integer() % 128, rw, rh, e1, read_types[in.below(5)], out.data());
        // GL_EXT_packed_depth_stencil: 4 bytes a pixel, as GL_FLOAT's.
        if (in.u8() < 32) glReadPixels(in.integer() % 128, in.integer() % 128, rw, rh, 0x84F9, 0x84FA, out.data());
        break;
      }
      case 60: {
        GLdouble dv[16];
        GLint iv[16];
        GLboolean bv[16];
        glGetDoublev(e1, dv);
        glGetIntegerv(e1, iv);
        glGetBooleanv(e1, bv);
        glIsEnabled(e1);
        glGetString(e1);
        gluGetString(e1);
        break;
      }
      case 61: (in.u8() & 1 ? glFinish : glFlush)(); break;
      case 62:
        if (in.u8() & 1) glLogicOp(e1);
        if (in.u8() & 1) glLineStipple(in.integer(), GLushort(in.integer()));
        (in.u8() & 1 ? glEnable : glDisable)(GL_LINE_STIPPLE);
        (in.u8() & 1 ? glEnable : glDisable)(GL_COLOR_LOGIC_OP);
        glRectf(a, b, c, d);
        glBegin(in.u8() & 1 ? GL_LINE_LOOP : GL_LINES);
        glVertex3f(a, b, c), glVertex3f(c, d, a), glVertex4f(d, a, b, c), glVertex2f(b, d);
        glEnd();
        break;
      default: {
        GLint ww, hh, bytes;
        void* depth = nullptr;
        if (OSMesaGetDepthBuffer(ctx, &ww, &hh, &bytes, &depth) && depth) {
          fuzz_check(ww == w && hh == h && bytes == 4);
        }
        quadric_call(in, quadric, a, b, c, d, e1);
        pixel_call(in, pixels, a, b, c, d, e1, e2);
        clip_call(in, a, b, c, d);
        tex_gen_call(in, a, b, c, d, e1);
        buffer_call(in, pixels, buffer_names, e1, e2);
        texture_1d_call(in, pixels, names, a, b, e1);
        texture_3d_call(in, pixels, out, names, a, b, c, e1);
        texture_format_call(in, pixels, e1);
        evaluator_call(in, attrib, a, b, e1);
        evaluator2_call(in, attrib, a, b, e1);
        pixel_map_call(in, attrib, e1);
        buffer_lod_call(in, a, b, e1);
        color_sum_call(in, attrib, a, b, c, e1);
        multitexture_call(in, attrib, names, a, b, e1);
        tex_combine_call(in, a, b, e1);
        framebuffer_call(in, pixels, names, framebuffer_names, renderbuffer_names, a, b, e1, e2);
#ifdef VELOCITY_FUZZ_GLUT_SHAPES
        shape_call(in, a, b);
#endif
        break;
      }
    }
    fuzz_check(valid_error(glGetError()));
  }

  // Still a working context: finish any open primitive and list, draw, read back.
  glEnd();
  glEndList();
  // What is pending is drawn first: its errors (the GPU backend refuses user clip
  // planes, GL_OUT_OF_MEMORY) are the sequence's, not the final draw's.
  glFinish();
  glGetError();
  glViewport(0, 0, w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);  // (the sequence may have left a framebuffer object bound)
  // The sequence may have left colour reads and writes on no buffer (GL_NONE).
  glDrawBuffer(GL_FRONT);
  glReadBuffer(GL_FRONT);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  uint8_t px[4] = {0, 0, 0, 0};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  fuzz_check(glGetError() == GL_NO_ERROR);
  gluDeleteQuadric(quadric);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  return 0;
}
