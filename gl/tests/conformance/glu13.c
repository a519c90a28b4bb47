/* GLU's image, mipmap and picking calls (libGLU's, drawing through pGL):
 * gluBuild2DMipmapLevels building levels 1-3 of a 16x8 image from level 1 up, drawn
 * at each level; gluScaleImage (bytes to bytes, shorts to floats, the pack and
 * unpack state); gluPickMatrix in selection mode and drawing; gluCheckExtension;
 * gluUnProject4; GLU_VERSION_1_3 and gluGetString; GLU's errors (GLU_INVALID_ENUM,
 * GLU_INVALID_VALUE). */
#include "harness.h"

static void textured_quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(x0, y0);
  glTexCoord2f(1, 0), glVertex2f(x1, y0);
  glTexCoord2f(1, 1), glVertex2f(x1, y1);
  glTexCoord2f(0, 1), glVertex2f(x0, y1);
  glEnd();
}

int main(int argc, char** argv) {
  GLubyte line[4 * 3] = {0}, image[16 * 8 * 4], small[5 * 3 * 3], scaled[7 * 4 * 3 + 8];
  GLushort shorts[3 * 2 * 2];
  GLfloat floats[4 * 3 * 2];
  GLuint select[64];
  GLint view[4] = {0, 0, 128, 128}, iv[4], hits, i;
  GLdouble model[16], proj[16], obj[4];
  conf_init(argc, argv, 128, 128);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
#ifdef GLU_VERSION_1_3
  conf_value("glu_version_1_3", 1);
#endif
  conf_value("glu_version_minor", atoi((const char*)gluGetString(GLU_VERSION) + 2));
  conf_ortho();

  /* (gluBuild1DMipmaps and gluBuild1DMipmapLevels build nothing on pGL yet: libGLU
   * uploads 1-D levels as GL_UNSIGNED_SHORT, a type pGL's glTexImage1D does not take
   * (GL_INVALID_ENUM; docs/gl.md). Only their argument errors are compared below.) */
  /* gluBuild2DMipmapLevels: a 16x8 image as level 1 of a texture whose levels 1-3 exist. */
  for (i = 0; i < 16 * 8; ++i) {
    const int x = i % 16, y = i / 16;
    image[4 * i] = (GLubyte)(x * 16), image[4 * i + 1] = (GLubyte)(y * 32);
    image[4 * i + 2] = (GLubyte)((x + y) % 2 * 200), image[4 * i + 3] = 255;
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  conf_value("build2d_levels",
             gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 1, 1, 3, image));
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, iv);
  conf_value("build2d_width1", iv[0]);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_HEIGHT, iv);
  conf_value("build2d_height3", iv[0]);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 4, GL_TEXTURE_WIDTH, iv);
  conf_value("build2d_width4", iv[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  textured_quad(2, 40, 66, 72);  /* level 1, magnified */
  textured_quad(70, 40, 78, 44); /* level 2 */
  textured_quad(82, 40, 86, 42); /* level 3 */
  glDisable(GL_TEXTURE_2D);
  conf_value("gl_error_mipmaps", glGetError());

  /* gluPickMatrix: drawn through a pick region around (40, 20), 24 x 16 pixels, which
   * fills the viewport's lower left quarter. */
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPickMatrix(40, 20, 24, 16, view);
  glOrtho(0, 128, 0, 128, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 0.5f, 0);
  glRectf(30, 10, 45, 25);
  glColor3f(0, 0.7f, 1);
  glRectf(45, 18, 60, 40);
  glViewport(0, 0, 128, 128);
  conf_frame("drawn");

  /* Selection through a pick matrix: which of three rectangles fall in a 4x4 region. */
  glSelectBuffer(64, select);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(0);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPickMatrix(50, 50, 4, 4, view);
  glOrtho(0, 128, 0, 128, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadName(1);
  glRectf(40, 40, 52, 60);
  glLoadName(2);
  glRectf(53, 40, 70, 60);
  glLoadName(3);
  glRectf(60, 40, 70, 60);
  hits = glRenderMode(GL_RENDER);
  conf_value("pick_hits", hits);
  conf_value("pick_first_name", hits > 0 ? select[3] : 0);
  conf_value("pick_second_name", hits > 1 ? select[7] : 0);
  gluPickMatrix(1, 1, 0, 4, view); /* a zero size: ignored */
  conf_value("pick_zero_error", glGetError());

  /* gluScaleImage: 5x3 RGB bytes with pack alignment 1 to 7x4, and shorts to floats. */
  for (i = 0; i < 5 * 3 * 3; ++i) small[i] = (GLubyte)(i * 37 % 256);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  conf_value("scale_bytes", gluScaleImage(GL_RGB, 5, 3, GL_UNSIGNED_BYTE, small, 7, 4, GL_UNSIGNED_BYTE, scaled));
  conf_value("scaled_0", scaled[0]);
  conf_value("scaled_10", scaled[10]);
  conf_value("scaled_40", scaled[40]);
  conf_value("scaled_83", scaled[83]);
  for (i = 0; i < 12; ++i) shorts[i] = (GLushort)(i * 5000 + 700);
  conf_value("scale_shorts", gluScaleImage(GL_LUMINANCE_ALPHA, 3, 2, GL_UNSIGNED_SHORT, shorts, 4, 3, GL_FLOAT, floats));
  conf_value("scaled_float_0", floats[0]);
  conf_value("scaled_float_9", floats[9]);
  conf_value("scaled_float_23", floats[23]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);

  /* gluCheckExtension: whole names only. */
  conf_value("check_found", gluCheckExtension((const GLubyte*)"GL_EXT_bgra", (const GLubyte*)"GL_EXT_abgr GL_EXT_bgra"));
  conf_value("check_prefix", gluCheckExtension((const GLubyte*)"GL_EXT_bg", (const GLubyte*)"GL_EXT_abgr GL_EXT_bgra"));
  conf_value("check_gl", gluCheckExtension((const GLubyte*)"GL_EXT_bgra", glGetString(GL_EXTENSIONS)));

  /* gluUnProject4 of a point through an asymmetric frustum. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 2, -1.5, 1, 1, 20);
  glGetDoublev(GL_PROJECTION_MATRIX, proj);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0.5f, -0.25f, -3);
  glRotatef(30, 0, 1, 0);
  glGetDoublev(GL_MODELVIEW_MATRIX, model);
  conf_value("unproject4", gluUnProject4(30, 90, 0.4, 2, model, proj, view, 0, 1, &obj[0], &obj[1], &obj[2], &obj[3]));
  conf_value("unproject4_x", obj[0]);
  conf_value("unproject4_y", obj[1]);
  conf_value("unproject4_z", obj[2]);
  conf_value("unproject4_w", obj[3]);

  /* GLU's errors, returned (GL's error untouched). */
  conf_value("build1d_bad_width", gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGB, 0, GL_RGB, GL_UNSIGNED_BYTE, line));
  conf_value("build1d_bad_format", gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGB, 4, GL_TEXTURE_2D, GL_UNSIGNED_BYTE, line));
  conf_value("build2d_levels_bad",
             gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, 1, 3, 1, image));
  conf_value("scale_bad_type", gluScaleImage(GL_RGB, 5, 3, GL_RGB, small, 7, 4, GL_UNSIGNED_BYTE, scaled));
  conf_value("scale_bad_size", gluScaleImage(GL_RGB, -5, 3, GL_UNSIGNED_BYTE, small, 7, 4, GL_UNSIGNED_BYTE, scaled));
  conf_value("gl_error_after", glGetError());
  return conf_end();
}
