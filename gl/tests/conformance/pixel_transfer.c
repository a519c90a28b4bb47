/* glPixelTransfer: the scale and bias of each colour component through glDrawPixels
 * (unsigned bytes, floats beyond [0, 1], luminance) and glTexImage2D / glTexSubImage2D
 * (RGBA, RGB from floats, luminance), depth scale and bias under the depth test,
 * GL_MAP_COLOR set in a display list, glPushAttrib's pixel-mode group, the queries and
 * the errors. */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

static void getf(const char* name, GLenum pname) {
  GLfloat v = -12345;
  glGetFloatv(pname, &v);
  conf_value(name, v);
}

static void identity(void) {
  static const GLenum names[] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE, GL_DEPTH_SCALE};
  static const GLenum biases[] = {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS, GL_DEPTH_BIAS};
  int i;
  for (i = 0; i < 5; ++i) glPixelTransferf(names[i], 1), glPixelTransferf(biases[i], 0);
  glPixelTransferi(GL_MAP_COLOR, 0), glPixelTransferi(GL_MAP_STENCIL, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 0), glPixelTransferi(GL_INDEX_OFFSET, 0);
}

static void textured_square(float x, float y) {
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(x, y);
  glTexCoord2f(1, 0), glVertex2f(x + 16, y);
  glTexCoord2f(1, 1), glVertex2f(x + 16, y + 16);
  glTexCoord2f(0, 1), glVertex2f(x, y + 16);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) {
  GLubyte rgba[8 * 8 * 4], lum[8 * 8];
  GLfloat frgb[4 * 4 * 3], depth[8 * 8];
  GLuint tex[3], list;
  int i;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 96, 64);
  conf_ortho();
  for (i = 0; i < 64; ++i) {
    rgba[4 * i] = (GLubyte)(i * 4), rgba[4 * i + 1] = (GLubyte)(255 - i * 3), rgba[4 * i + 2] = (GLubyte)(i * 2 + 40),
    rgba[4 * i + 3] = (GLubyte)(200 - i);
    lum[i] = (GLubyte)(i * 3 + 20);
    depth[i] = (float)i / 64.0f;
  }
  for (i = 0; i < 48; ++i) frgb[i] = (float)i / 24.0f - 0.5f; /* beyond [0, 1] both ways */

  getf("red_scale", GL_RED_SCALE);
  getf("depth_bias", GL_DEPTH_BIAS);
  getf("map_color", GL_MAP_COLOR);
  getf("index_shift", GL_INDEX_SHIFT);

  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  /* glDrawPixels: scale and bias on each component. */
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_SCALE, -1.0f);
  glPixelTransferf(GL_GREEN_BIAS, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.25f);
  glPixelTransferf(GL_ALPHA_SCALE, 2.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos2i(2, 2);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glDisable(GL_BLEND);
  glRasterPos2i(12, 2);
  glDrawPixels(4, 4, GL_RGB, GL_FLOAT, frgb);
  glRasterPos2i(18, 2);
  glDrawPixels(8, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  getf("red_scale_set", GL_RED_SCALE);
  getf("green_bias_set", GL_GREEN_BIAS);

  /* glTexImage2D and glTexSubImage2D under the same transfer. */
  glGenTextures(3, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_FLOAT, frgb);
  glPixelTransferf(GL_RED_BIAS, 0.3f);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGB, GL_FLOAT, frgb);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 8, 8, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  identity();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  textured_square(30, 2);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  textured_square(48, 2);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  textured_square(66, 2);

  /* Depth scale and bias, under the depth test: a far square, then pixels whose depth
   * the transfer moves in front of it or behind it. */
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 0, 1);
  glRectf(2, 24, 40, 40);
  glPixelTransferf(GL_DEPTH_SCALE, 2.0f);
  glPixelTransferf(GL_DEPTH_BIAS, -0.3f);
  glColor3f(1, 1, 0);
  glRasterPos2i(4, 26);
  glDrawPixels(8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glDisable(GL_DEPTH_TEST);
  identity();

  /* GL_MAP_COLOR compiled into a list; glPushAttrib restores it and the scales. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glEndList();
  getf("map_color_compiled", GL_MAP_COLOR);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glCallList(list);
  getf("map_color_called", GL_MAP_COLOR);
  /* (Not drawn with it: GL's default maps, one entry of 0, make every component 0,
   * as pGL draws; Mesa 22's llvmpipe keeps blue.) */
  glPixelTransferf(GL_BLUE_SCALE, 3);
  glPopAttrib();
  getf("map_color_popped", GL_MAP_COLOR);
  getf("blue_scale_popped", GL_BLUE_SCALE);
  glRasterPos2i(54, 26);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, rgba);

  /* (Stencil indices' shift, offset and GL_MAP_STENCIL are not compared: Mesa 22's
   * llvmpipe leaves glDrawPixels' indices unchanged by them.) */
  conf_frame("transfer");

  /* Errors. */
  glPixelTransferf(GL_ZOOM_X, 1);
  error("bad_pname");
  glBegin(GL_POINTS);
  glPixelTransferf(GL_RED_SCALE, 1);
  glEnd();
  error("in_begin");
  error("final");
  return conf_end();
}
