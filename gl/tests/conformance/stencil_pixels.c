/* Stencil indices in pixel rectangles: glDrawPixels(GL_STENCIL_INDEX) from unsigned and
 * signed bytes, shorts (byte-swapped), ints and floats, under the unpack
 * state, zoomed and mirrored, through the write mask and the scissor box but not the
 * stencil or depth test, never into colour; glCopyPixels(GL_STENCIL) (overlapping,
 * zoomed); in a display list; the errors. The stencil values are read back
 * and compared, and shown as colours. (GL_BITMAP indices are not compared: Mesa 22's
 * OSMesa loops without end on them, printing "Unsupported format/type".) */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

/* The stencil values of a grid over the 80 x 60 window, and a checksum of all. */
static void stencil_values(const char* name) {
  static GLubyte s[80 * 60];
  char n[64];
  int i, j;
  unsigned long sum = 0;
  glReadPixels(0, 0, 80, 60, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  for (i = 0; i < 80 * 60; ++i) sum = (sum * 31 + s[i]) % 1000003;
  snprintf(n, sizeof n, "%s_sum", name);
  conf_value(n, (double)sum);
  for (j = 0; j < 12; ++j)
    for (i = 0; i < 16; ++i) {
      snprintf(n, sizeof n, "%s_%d_%d", name, i, j);
      conf_value(n, s[(j * 5 + 2) * 80 + i * 5 + 2]);
    }
}

int main(int argc, char** argv) {
  GLubyte ub[12 * 10];
  GLbyte sb[6 * 4];
  GLushort us[7 * 5];
  GLint iv[5 * 3];
  GLfloat fv[4 * 4];
  GLuint list;
  int i;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 80, 60);
  conf_ortho();
  for (i = 0; i < 12 * 10; ++i) ub[i] = (GLubyte)(i * 7 + 1);
  for (i = 0; i < 6 * 4; ++i) sb[i] = (GLbyte)(-3 * i);
  for (i = 0; i < 7 * 5; ++i) us[i] = (GLushort)((i * 37 + 5) << 4 | 0x8000);
  for (i = 0; i < 5 * 3; ++i) iv[i] = 1000 * i - 7000;
  for (i = 0; i < 4 * 4; ++i) fv[i] = 2.75f * (float)i + 0.5f;

  glClearColor(0, 0, 0, 1);
  glClearStencil(0x40);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  /* The stencil and depth tests do not apply to these writes. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xff);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glColor3f(1, 0, 0);

  glRasterPos2i(2, 3);
  glDrawPixels(12, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  error("ubyte");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); /* (rows of 6 bytes and of 14: not padded) */
  glRasterPos2i(20, 3);
  glDrawPixels(6, 4, GL_STENCIL_INDEX, GL_BYTE, sb);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glRasterPos2i(30, 3);
  glDrawPixels(7, 5, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, us);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glRasterPos2i(40, 3);
  glDrawPixels(5, 3, GL_STENCIL_INDEX, GL_INT, iv);
  glRasterPos2i(50, 3);
  glDrawPixels(4, 4, GL_STENCIL_INDEX, GL_FLOAT, fv);
  error("types");

  /* Row length and skips, the write mask, a zoom (mirrored), the scissor box. */
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glStencilMask(0x0f);
  glRasterPos2i(2, 20);
  glDrawPixels(6, 5, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glStencilMask(0xff);
  glPixelZoom(2.0f, -1.5f);
  glRasterPos2i(14, 30);
  glDrawPixels(5, 4, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  glPixelZoom(1, 1);
  glEnable(GL_SCISSOR_TEST);
  glScissor(30, 18, 6, 6);
  glRasterPos2i(28, 16);
  glDrawPixels(12, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  glDisable(GL_SCISSOR_TEST);
  error("state");

  /* glCopyPixels(GL_STENCIL): overlapping, and zoomed. (Pixels from outside the window
   * are undefined: Mesa writes 0, pGL skips them.) */
  glRasterPos2i(44, 22);
  glCopyPixels(40, 18, 14, 12, GL_STENCIL);
  glPixelZoom(1, 2);
  glRasterPos2i(60, 40);
  glCopyPixels(0, 2, 16, 8, GL_STENCIL);
  glPixelZoom(1, 1);
  error("copy");

  /* In a display list: the indices unpacked when compiled. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glRasterPos2i(2, 40);
  glDrawPixels(12, 10, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  glEndList();
  for (i = 0; i < 12 * 10; ++i) ub[i] = 3;
  glCallList(list);
  error("list");

  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  stencil_values("drawn");
  conf_show_stencil("shown", 80, 60);

  /* Errors: a packed type, an unknown type, GL_BITMAP with a colour format, between
   * glBegin and glEnd. */
  glRasterPos2i(0, 0);
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT_5_6_5, us);
  error("packed_type");
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_RGBA, us);
  error("bad_type");
  glDrawPixels(2, 2, GL_RGBA, GL_BITMAP, us);
  error("bitmap_rgba");
  glDrawPixels(-1, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, us);
  error("negative");
  glCopyPixels(0, 0, 2, 2, GL_STENCIL_INDEX);
  error("copy_bad_type");
  glBegin(GL_POINTS);
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ub);
  glEnd();
  error("in_begin");
  glBegin(GL_POINTS);
  glCopyPixels(0, 0, 2, 2, GL_STENCIL);
  glEnd();
  error("copy_in_begin");
  return conf_end();
}
