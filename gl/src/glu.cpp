// The GLU subset: camera matrices, projection helpers and gluBuild2DMipmaps, on top of
// the GL entry points (as GLU is on any OpenGL).
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "context.hpp"
#include "pixels.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;

// GLU works in double (its arguments and results), column-major: the product and the
// transform of gluProject and gluUnProject.
void multiply(const double* a, const double* b, double* r) {  // r = a * b
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
      r[c * 4 + row] = s;
    }
}
void transform(const double* m, const double* in, double* out) {
  for (int row = 0; row < 4; ++row)
    out[row] = m[row] * in[0] + m[4 + row] * in[1] + m[8 + row] * in[2] + m[12 + row] * in[3];
}
// The engine's inverse (velocity::invert: false for a singular matrix, as GLU's), refined
// once in double, which GLU's arguments and results are.
bool invert(const double* m, double* out) {
  velocity::Mat4 inv;
  if (!velocity::invert(velocity::gl::load_column_major(m), inv)) return false;
  double x[16], ax[16], r[16];
  velocity::gl::store_column_major(inv, x);
  multiply(m, x, ax);
  for (int i = 0; i < 16; ++i) r[i] = (i % 5 == 0 ? 2.0 : 0.0) - ax[i];  // 2I - A X
  multiply(x, r, out);
  return true;
}

// GLU's rounding of a size to a power of two (3 -> 4, 5 -> 4, 6 -> 8).
int nearest_power(int v) {
  int i = 1;
  for (;;) {
    if (v == 1) return i;
    if (v == 3) return i * 4;
    v >>= 1;
    i *= 2;
  }
}

// Box-filter resampling of RGBA8 texels (each output texel averages its footprint), to
// bring level 0 to power-of-two sides.
std::vector<uint32_t> scale(const std::vector<uint32_t>& in, int w, int h, int nw, int nh) {
  std::vector<uint32_t> out(size_t(nw) * nh);
  const double sx = double(w) / nw, sy = double(h) / nh;
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      const double x0 = x * sx, x1 = (x + 1) * sx, y0 = y * sy, y1 = (y + 1) * sy;
      double acc[4] = {0, 0, 0, 0}, total = 0;
      for (int yy = int(y0); yy < int(std::ceil(y1)) && yy < h; ++yy)
        for (int xx = int(x0); xx < int(std::ceil(x1)) && xx < w; ++xx) {
          const double wx = std::min(x1, xx + 1.0) - std::max(x0, double(xx));
          const double wy = std::min(y1, yy + 1.0) - std::max(y0, double(yy));
          const double wgt = wx * wy;
          if (wgt <= 0) continue;
          const uint32_t p = in[size_t(yy) * w + xx];
          for (int c = 0; c < 4; ++c) acc[c] += wgt * double((p >> (8 * c)) & 0xff);
          total += wgt;
        }
      uint32_t o = 0;
      for (int c = 0; c < 4; ++c) o |= uint32_t(std::lround(total > 0 ? acc[c] / total : 0)) << (8 * c);
      out[size_t(y) * nw + x] = o;
    }
  return out;
}
}  // namespace

extern "C" {

// The matrices of gluPerspective and gluLookAt are the engine's (velocity::perspective,
// velocity::look_at: the same formulas, in float).
void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) {
  if (zFar == zNear || std::sin(fovy / 2 * kPi / 180) == 0 || aspect == 0) return;  // GLU: the matrix unchanged
  GLfloat m[16];
  velocity::gl::store_column_major(
      velocity::perspective(float(fovy * kPi / 180), float(aspect), float(zNear), float(zFar)), m);
  glMultMatrixf(m);
}

void gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
  glOrtho(left, right, bottom, top, -1, 1);
}

void gluLookAt(GLdouble ex, GLdouble ey, GLdouble ez, GLdouble cx, GLdouble cy, GLdouble cz, GLdouble ux,
               GLdouble uy, GLdouble uz) {
  GLfloat m[16];
  velocity::gl::store_column_major(velocity::look_at({float(ex), float(ey), float(ez)}, {float(cx), float(cy), float(cz)},
                                                     {float(ux), float(uy), float(uz)}),
                                   m);
  glMultMatrixf(m);
}

GLint gluProject(GLdouble ox, GLdouble oy, GLdouble oz, const GLdouble* model, const GLdouble* proj, const GLint* view,
                 GLdouble* wx, GLdouble* wy, GLdouble* wz) {
  if (!model || !proj || !view || !wx || !wy || !wz) return GL_FALSE;
  const double in[4] = {ox, oy, oz, 1};
  double eye[4], clip[4];
  transform(model, in, eye);
  transform(proj, eye, clip);
  if (clip[3] == 0) return GL_FALSE;
  for (int i = 0; i < 3; ++i) clip[i] = clip[i] / clip[3] * 0.5 + 0.5;
  *wx = view[0] + clip[0] * view[2];
  *wy = view[1] + clip[1] * view[3];
  *wz = clip[2];
  return GL_TRUE;
}

GLint gluUnProject(GLdouble wx, GLdouble wy, GLdouble wz, const GLdouble* model, const GLdouble* proj,
                   const GLint* view, GLdouble* ox, GLdouble* oy, GLdouble* oz) {
  if (!model || !proj || !view || !ox || !oy || !oz || view[2] == 0 || view[3] == 0) return GL_FALSE;
  double pm[16], inv[16];
  multiply(proj, model, pm);
  if (!invert(pm, inv)) return GL_FALSE;
  const double in[4] = {(wx - view[0]) / view[2] * 2 - 1, (wy - view[1]) / view[3] * 2 - 1, wz * 2 - 1, 1};
  double out[4];
  transform(inv, in, out);
  if (out[3] == 0) return GL_FALSE;
  *ox = out[0] / out[3], *oy = out[1] / out[3], *oz = out[2] / out[3];
  return GL_TRUE;
}

GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLenum format, GLenum type,
                        const void* data) {
  if (target != GL_TEXTURE_2D) return GLU_INVALID_ENUM;
  if (width < 1 || height < 1 || width > 65536 || height > 65536) return GLU_INVALID_VALUE;
  if (!velocity::gl::Context::base_format(internalFormat)) return GLU_INVALID_VALUE;
  // The caller's unpack state reads `data`; GLU's own uploads are tightly packed, with
  // the caller's state put back after (as Mesa's GLU does).
  static const GLenum kUnpack[6] = {GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
                                    GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST};
  GLint saved[6] = {4, 0, 0, 0, 0, 0};
  for (int i = 0; i < 6; ++i) glGetIntegerv(kUnpack[i], &saved[i]);
  velocity::gl::PixelStore store;
  store.alignment = saved[0], store.row_length = saved[1], store.skip_rows = saved[2], store.skip_pixels = saved[3];
  store.swap_bytes = saved[4] != 0;
  try {
    auto texels = velocity::gl::unpack_rgba(format, type, width, height, store, data);
    if (!texels) return GLU_INVALID_ENUM;
    const int w = std::min(nearest_power(width), velocity::gl::kMaxTextureSize);
    const int h = std::min(nearest_power(height), velocity::gl::kMaxTextureSize);
    velocity::Texture::Level level{w, h, std::move(*texels)};
    if (w != width || h != height) level.texels = scale(level.texels, width, height, w, h);
    static const GLint kPacked[6] = {4, 0, 0, 0, 0, 0};
    for (int i = 0; i < 6; ++i) glPixelStorei(kUnpack[i], kPacked[i]);
    // Below level 0 the sides are powers of two, each level exactly half the one above:
    // the box filter over each 2x2 block is the engine's mip-map builder.
    for (int l = 0;; ++l) {
      glTexImage2D(GL_TEXTURE_2D, l, internalFormat, level.width, level.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   level.texels.data());
      if (level.width == 1 && level.height == 1) break;
      level = velocity::next_mip_level(level);
    }
    for (int i = 0; i < 6; ++i) glPixelStorei(kUnpack[i], saved[i]);
  } catch (const std::exception&) {
    return GLU_OUT_OF_MEMORY;
  }
  return 0;
}

// GLU 1.1's: the version (1.3: the tessellator, NURBS and 1.3's calls are Debian's
// libGLU, linked with pGL) and no GLU extensions.
const GLubyte* gluGetString(GLenum name) {
  const char* s;
  switch (name) {
    case GLU_VERSION: s = "1.3 Velocity pGL (with libGLU: docs/gl.md)"; break;
    case GLU_EXTENSIONS: s = ""; break;
    default: return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

const GLubyte* gluErrorString(GLenum error) {
  const char* s;
  switch (error) {
    case GL_NO_ERROR: s = "no error"; break;
    case GL_INVALID_ENUM: s = "invalid enumerant"; break;
    case GL_INVALID_VALUE: s = "invalid value"; break;
    case GL_INVALID_OPERATION: s = "invalid operation"; break;
    case GL_STACK_OVERFLOW: s = "stack overflow"; break;
    case GL_STACK_UNDERFLOW: s = "stack underflow"; break;
    case GL_OUT_OF_MEMORY: s = "out of memory"; break;
    case GLU_INVALID_ENUM: s = "invalid enumerant"; break;
    case GLU_INVALID_VALUE: s = "invalid value"; break;
    case GLU_OUT_OF_MEMORY: s = "out of memory"; break;
    case GLU_INCOMPATIBLE_GL_VERSION: s = "incompatible gl version"; break;
    case GLU_INVALID_OPERATION: s = "invalid operation"; break;
    default: return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

}  // extern "C"
