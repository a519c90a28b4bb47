/* glPixelMap: the colour tables (R_TO_R of 4 entries, G_TO_G of 2 inverting, B_TO_B of 8,
 * A_TO_A of 1) under GL_MAP_COLOR through glDrawPixels (after a red scale) and
 * glTexImage2D; tables given as unsigned ints and shorts (through glTexImage2D); the
 * stencil table's values; a table compiled into a display list; glPushAttrib's
 * GL_PIXEL_MODE_BIT (the tables are in no group); glGetPixelMap{fv,uiv,usv}, the sizes,
 * GL_MAX_PIXEL_MAP_TABLE; the errors. */
#include "harness.h"

static void textured(float x0, float y0, float x1, float y1) {
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(x0, y0);
  glTexCoord2f(1, 0), glVertex2f(x1, y0);
  glTexCoord2f(1, 1), glVertex2f(x1, y1);
  glTexCoord2f(0, 1), glVertex2f(x0, y1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

int main(int argc, char** argv) {
  static const GLfloat red[4] = {0.0f, 0.9f, 0.2f, 1.0f}, green[2] = {1, 0}, alpha[1] = {1};
  static const GLfloat index_table[4] = {3, 1, 250, 7};
  static const GLuint green_ui[4] = {0u, 4294967295u, 1000000000u, 3000000000u};
  static const GLushort blue_us[2] = {65535, 9000};
  GLfloat blue[8], fv[8];
  GLuint uiv[8];
  GLushort usv[8];
  GLubyte image[16 * 32 * 4];
  GLint iv[2], i;
  GLuint list;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 96, 64);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  conf_ortho();
  for (i = 0; i < 8; ++i) blue[i] = (float)(i * i) / 49.0f;
  for (i = 0; i < 16 * 32; ++i) {
    const int x = i % 32, y = i / 32;
    image[4 * i] = (GLubyte)(x * 8), image[4 * i + 1] = (GLubyte)(y * 16);
    image[4 * i + 2] = (GLubyte)((x + 2 * y) * 4), image[4 * i + 3] = (GLubyte)(255 - x * 4);
  }
  glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, iv);
  conf_value("max_table", iv[0]);
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv);
  conf_value("initial_size", iv[0]);

  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, red);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, green);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 8, blue);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, alpha);
  conf_value("set_error", glGetError());

  /* glDrawPixels unmapped; through the tables, after a red scale of 0.5, as a texture
   * (glDrawPixels under GL_MAP_COLOR is not compared: Mesa 22's llvmpipe leaves blue
   * unmapped there, where its glTexImage2D maps it). */
  glRasterPos2i(0, 0);
  glDrawPixels(32, 16, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glPixelTransferf(GL_RED_SCALE, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  textured(32, 0, 96, 16);

  /* glTexImage2D through the tables, drawn magnified. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glColor3f(1, 1, 1);
  textured(0, 16, 48, 40);

  /* Tables as unsigned ints and shorts. */
  glPixelMapuiv(GL_PIXEL_MAP_G_TO_G, 4, green_ui);
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 2, blue_us);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  textured(48, 16, 96, 40);

  /* In a display list: the list keeps the table it was compiled with. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, green);
  glEndList();
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv);
  conf_value("size_before_call", iv[0]);
  glCallList(list);
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv);
  conf_value("size_after_call", iv[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  textured(0, 40, 48, 64);
  conf_frame("mapped");

  /* The tables are in no attribute group; GL_MAP_COLOR is in GL_PIXEL_MODE_BIT. */
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, red);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPopAttrib();
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv);
  conf_value("size_after_pop", iv[0]);
  glGetIntegerv(GL_MAP_COLOR, iv);
  conf_value("map_color_after_pop", iv[0]);

  /* (GL_MAP_STENCIL through glDrawPixels(GL_STENCIL_INDEX) is not compared: Mesa 22's
   * llvmpipe applies neither the index offset nor the S_TO_S table there.) */
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, index_table);

  /* glGetPixelMap in the three types. */
  glGetPixelMapfv(GL_PIXEL_MAP_B_TO_B, fv);
  conf_value("get_b_f0", fv[0]);
  conf_value("get_b_f1", fv[1]);
  glGetPixelMapuiv(GL_PIXEL_MAP_G_TO_G, uiv);
  conf_value("get_g_ui2", uiv[2]);
  conf_value("get_g_ui3", uiv[3]);
  glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, usv);
  conf_value("get_r_us1", usv[1]);
  glGetPixelMapfv(GL_PIXEL_MAP_S_TO_S, fv);
  conf_value("get_s_f2", fv[2]);
  /* (Not glGetPixelMapuiv of S_TO_S: Mesa 22 returns the float's bits.) */
  glGetPixelMapusv(GL_PIXEL_MAP_S_TO_S, usv);
  conf_value("get_s_us2", usv[2]);
  glGetIntegerv(GL_PIXEL_MAP_S_TO_S_SIZE, iv);
  conf_value("s_size", iv[0]);
  glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE, iv);
  conf_value("i_size", iv[0]);

  /* Errors. */
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, red);
  conf_value("size_0", glGetError());
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, red);
  conf_value("size_257", glGetError());
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, red);
  conf_value("index_size_3", glGetError());
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, red); /* any size for a colour-to-colour table */
  conf_value("colour_size_3", glGetError());
  glPixelMapfv(GL_TEXTURE_2D, 2, red);
  conf_value("bad_map", glGetError());
  glGetPixelMapfv(GL_TEXTURE_2D, fv);
  conf_value("get_bad_map", glGetError());
  glBegin(GL_POINTS);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, red);
  glEnd();
  conf_value("in_begin", glGetError());
  glDeleteLists(list, 1);
  return conf_end();
}
