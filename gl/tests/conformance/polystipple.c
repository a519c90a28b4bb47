/* Polygon stipple: an asymmetric 32x32 pattern over smooth filled triangles and quads
 * (tiled from the window's origin), given with the default unpack state and with
 * GL_UNPACK_LSB_FIRST, a row length and skips; what it does not apply to (lines,
 * points, polygon-mode outlines, glDrawPixels); a display list; glGetPolygonStipple
 * (default and LSB_FIRST packing), glIsEnabled, glPushAttrib (GL_POLYGON_STIPPLE_BIT,
 * GL_ENABLE_BIT) and the error inside glBegin/glEnd. */
#include "harness.h"

#define W 128
#define H 96

static GLubyte pattern[32 * 4], wide[40 * 8];

static void shapes(void) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0), glVertex2f(4, 4);
  glColor3f(0, 1, 0), glVertex2f(70, 10);
  glColor3f(0, 0, 1), glVertex2f(30, 90);
  glEnd();
  /* (Colours affine in x and y: a quad's four unrelated colours interpolate
   * differently from Mesa, stippled or not.) */
  glBegin(GL_QUADS);
  glColor3f(60.0f / 128, 40.0f / 96, 0.5f), glVertex2f(60, 40);
  glColor3f(124.0f / 128, 44.0f / 96, 0.5f), glVertex2f(124, 44);
  glColor3f(120.0f / 128, 92.0f / 96, 0.5f), glVertex2f(120, 92);
  glColor3f(64.0f / 128, 86.0f / 96, 0.5f), glVertex2f(64, 86);
  glEnd();
}

int main(int argc, char** argv) {
  static GLubyte image[8 * 6 * 3];
  GLubyte back[32 * 4 + 8];
  int i, y;
  conf_init(argc, argv, W, H);
  conf_ortho();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  for (i = 0; i < 32 * 4; ++i) pattern[i] = (GLubyte)((i * 37 + (i >> 2) * 11) ^ 0x5a);
  for (i = 0; i < 40 * 8; ++i) wide[i] = (GLubyte)(i * 29 + 7);
  for (i = 0; i < 8 * 6 * 3; ++i) image[i] = (GLubyte)(i * 5);

  /* The pattern over filled polygons. */
  glClear(GL_COLOR_BUFFER_BIT);
  glPolygonStipple(pattern);
  glEnable(GL_POLYGON_STIPPLE);
  shapes();
  conf_frame("filled");

  /* Not stippled: lines, points, polygon-mode outlines and pixel rectangles. */
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_LINES);
  glColor3f(1, 1, 1), glVertex2f(2.5f, 50.5f), glVertex2f(125.5f, 60.5f);
  glEnd();
  glPointSize(3);
  glBegin(GL_POINTS);
  for (i = 0; i < 10; ++i) glVertex2f(10.5f + 11 * i, 30.5f);
  glEnd();
  glPointSize(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  shapes();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glRasterPos2i(90, 5);
  glPixelZoom(3, 3);
  glDrawPixels(8, 6, GL_RGB, GL_UNSIGNED_BYTE, image);
  glPixelZoom(1, 1);
  conf_frame("not_stippled");

  /* Unpacked with LSB_FIRST, a row length of 40 bits (8 bytes a row at alignment 8),
   * skipping 5 pixels and 2 rows; from a display list, under a translation (the
   * pattern stays in window space). */
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glNewList(1, GL_COMPILE);
  glPolygonStipple(wide);
  glTranslatef(3, -2, 0);
  shapes();
  glEndList();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glCallList(1);
  glLoadIdentity();
  conf_frame("unpacked_list");

  /* glGetPolygonStipple: the pattern back, as given and LSB first. */
  glPolygonStipple(pattern);
  memset(back, 0, sizeof back);
  glGetPolygonStipple(back);
  for (y = 0; y < 32; y += 5) {
    char k[40];
    snprintf(k, sizeof k, "row%d", y);
    conf_value(k, back[4 * y] | back[4 * y + 1] << 8 | back[4 * y + 2] << 16 | (unsigned)back[4 * y + 3] << 24);
  }
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glGetPolygonStipple(back);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
  conf_value("lsb_row3", back[12] | back[13] << 8 | back[14] << 16 | (unsigned)back[15] << 24);

  /* The attribute groups and glIsEnabled. */
  conf_value("enabled", glIsEnabled(GL_POLYGON_STIPPLE));
  glPushAttrib(GL_POLYGON_STIPPLE_BIT | GL_ENABLE_BIT);
  glPolygonStipple(wide);
  glDisable(GL_POLYGON_STIPPLE);
  glPopAttrib();
  glGetPolygonStipple(back);
  conf_value("pop_row7", back[28] | back[29] << 8 | back[30] << 16 | (unsigned)back[31] << 24);
  conf_value("pop_enabled", glIsEnabled(GL_POLYGON_STIPPLE));
  glPushAttrib(GL_POLYGON_BIT);
  glDisable(GL_POLYGON_STIPPLE);
  glPopAttrib();
  conf_value("pop_polygon_enabled", glIsEnabled(GL_POLYGON_STIPPLE));
  conf_value("error_none", glGetError());
  glBegin(GL_TRIANGLES);
  glPolygonStipple(wide);
  glEnd();
  conf_value("error_in_begin", glGetError());
  return conf_end();
}
