/* The texture wrap modes and the border colour: GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE,
 * GL_CLAMP_TO_BORDER and GL_MIRRORED_REPEAT, each with GL_NEAREST and GL_LINEAR, on a
 * 2-D texture (5x3, no two texels alike) with s and t wrapped by different modes, and
 * on a 1-D texture; projective texture coordinates (q != 1) through the same modes;
 * the raster position set by glWindowPos under its ARB names (GL_ARB_window_pos).
 * glReadPixels' GL_LUMINANCE_ALPHA and packed types. Values: the extensions named, the errors. Compared with Mesa. */
#define GL_GLEXT_PROTOTYPES 1 /* glWindowPos*ARB in the system headers */
#include <string.h>

#include "harness.h"

#ifndef GL_CLAMP_TO_BORDER
#define GL_CLAMP_TO_BORDER 0x812D
#endif

static const GLenum wraps[5] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};

/* A quad with s and t from -0.7 to 1.6 (divided by q where q is given per corner). */
static void quad(float x0, float y0, float x1, float y1, const float q[4]) {
  const float s[4] = {-0.7f, 1.6f, 1.6f, -0.7f}, t[4] = {-0.7f, -0.7f, 1.6f, 1.6f};
  const float x[4] = {x0, x1, x1, x0}, y[4] = {y0, y0, y1, y1};
  int i;
  glBegin(GL_QUADS);
  for (i = 0; i < 4; ++i) {
    glTexCoord4f(s[i] * q[i], t[i] * q[i], 0, q[i]);
    glVertex2f(x[i], y[i]);
  }
  glEnd();
}

static int has_extension(const char* name) {
  const char* e = (const char*)glGetString(GL_EXTENSIONS);
  const size_t n = strlen(name);
  while (e && (e = strstr(e, name)) != NULL) {
    if (e[n] == ' ' || e[n] == 0) return 1;
    e += n;
  }
  return 0;
}

int main(int argc, char** argv) {
  static const float flat[4] = {1, 1, 1, 1}, proj[4] = {1, 2.5f, 0.5f, 1.75f};
  static const GLfloat border[4] = {0.9f, 0.6f, 0.1f, 0.8f};
  GLubyte image[3 * 5 * 4], row[7 * 4];
  GLuint tex[2];
  int i, j;
  conf_init(argc, argv, 200, 160);
  conf_ortho();
  glClearColor(0.2f, 0.2f, 0.4f, 1);  /* exact in 8 bits: read back below */
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 15; ++i) {
    image[4 * i] = (GLubyte)(17 * i), image[4 * i + 1] = (GLubyte)(255 - 40 * (i % 5));
    image[4 * i + 2] = (GLubyte)(i / 5 * 120), image[4 * i + 3] = (GLubyte)(i % 2 ? 255 : 90);
  }
  for (i = 0; i < 7; ++i) {
    row[4 * i] = (GLubyte)(i * 40), row[4 * i + 1] = (GLubyte)(i % 2 ? 220 : 30);
    row[4 * i + 2] = (GLubyte)(250 - i * 30), row[4 * i + 3] = 255;
  }
  glGenTextures(2, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Rows 0-3 (2-D): s wrapped by mode i, t by mode 4 - i; nearest then linear, plain
   * then projective. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glEnable(GL_TEXTURE_2D);
  for (j = 0; j < 4; ++j) {
    const GLint filter = j % 2 ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    for (i = 0; i < 5; ++i) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wraps[i]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wraps[4 - i]);
      quad(2.0f + 39 * (float)i, 2.0f + 30 * (float)j, 38.0f + 39 * (float)i, 30.0f + 30 * (float)j, j < 2 ? flat : proj);
    }
  }
  glDisable(GL_TEXTURE_2D);

  /* Row 4 (1-D): each mode, nearest then linear, an integer border colour. */
  glBindTexture(GL_TEXTURE_1D, tex[1]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
  {
    const GLint iborder[4] = {0x7fffffff, 0, 0x3fffffff, 0x7fffffff};
    glTexParameteriv(GL_TEXTURE_1D, GL_TEXTURE_BORDER_COLOR, iborder);
  }
  glEnable(GL_TEXTURE_1D);
  for (i = 0; i < 10; ++i) {
    const GLint filter = i < 5 ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, (GLint)wraps[i % 5]);
    quad(2.0f + 19.5f * (float)i, 124, 20.0f + 19.5f * (float)i, 140, i % 2 ? proj : flat);
  }
  glDisable(GL_TEXTURE_1D);

  /* glWindowPos's ARB names: bitmaps and pixels placed in window coordinates, the
   * current colour taken unlit, z through the depth range. */
  {
    static const GLubyte bits[8] = {0xff, 0x81, 0xbd, 0xa5, 0xa5, 0xbd, 0x81, 0xff};
    GLfloat pos[4];
    glColor3f(1, 0.5f, 0);
    glWindowPos2iARB(150, 143);
    glBitmap(8, 8, 0, 0, 9, 0, bits);
    glWindowPos2fARB(170.5f, 143.25f);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    glColor3f(0.2f, 1, 1);
    glWindowPos2sARB(182, 150);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    glDepthRange(0.25, 0.75);
    {
      const GLdouble p[3] = {3, 144, 0.5};
      glWindowPos3dvARB(p);
    }
    glDrawPixels(7, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    conf_value("windowpos_x", pos[0]);
    conf_value("windowpos_y", pos[1]);
    conf_value("windowpos_z", pos[2]);
    {
      const GLint p[3] = {30, 145, 1};
      glWindowPos3ivARB(p);
    }
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    conf_value("windowpos_z_far", pos[2]);
    glDepthRange(0, 1);
    glBegin(GL_POINTS);
    glWindowPos2iARB(1, 1);
    glEnd();
    conf_value("windowpos_in_begin", glGetError());
  }

  /* glReadPixels' GL_LUMINANCE_ALPHA (texture-al reads it): L = R + G + B, and A. */
  {
    GLfloat la[4];
    glReadPixels(0, 0, 2, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, la);
    conf_value("read_la_l", la[0]);
    conf_value("read_la_a", la[1]);
    conf_value("read_la_l2", la[2]);
  }

  /* glReadPixels' packed types (triangle-rasterization reads GL_UNSIGNED_INT_8_8_8_8):
   * the clear colour and a bitmap's orange, each way; a swapped short; the errors. */
  {
    GLuint u[2] = {0, 0};
    GLushort s[2] = {0, 0};
    GLubyte b[2] = {0, 0};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &u[0]);
    glReadPixels(150, 143, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &u[1]);
    conf_value("read_8888", u[0]);
    conf_value("read_8888_rev", u[1]);
    glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s[0]);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    glReadPixels(150, 143, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, &s[1]);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    conf_value("read_565", s[0]);
    conf_value("read_4444_rev_swapped", s[1]);
    glReadPixels(150, 143, 2, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, b);
    conf_value("read_332", b[0]);
    conf_value("read_332_next", b[1]);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, s);
    conf_value("read_565_rgba", glGetError());
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8, u);
    conf_value("read_packed_depth", glGetError());
  }

  /* Values and errors. */
  conf_value("ext_window_pos", has_extension("GL_ARB_window_pos"));
  conf_value("ext_border_clamp", has_extension("GL_ARB_texture_border_clamp"));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER + 1);
  conf_value("wrap_bad_enum", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_LINEAR);
  conf_value("wrap_filter_enum", glGetError());
  conf_frame("texwrap");
  glDeleteTextures(2, tex);
  return conf_end();
}
