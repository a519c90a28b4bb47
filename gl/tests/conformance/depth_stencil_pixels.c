/* GL_EXT_packed_depth_stencil on the default framebuffer: glDrawPixels and glReadPixels
 * of GL_DEPTH_STENCIL_EXT / GL_UNSIGNED_INT_24_8_EXT words (24 bits of depth above 8 of
 * stencil), under the unpack and pack state (row length, skips; byte swapping when
 * packed), zoomed,
 * through the stencil write mask and the scissor box, never into colour;
 * glCopyPixels(GL_DEPTH_STENCIL_EXT); the errors of a format and type that do not
 * pair. The words read back, the depth and stencil read apart, and the frame (with the
 * stencil shown as colours) are compared with Mesa. */
#include "harness.h"

#ifndef GL_DEPTH_STENCIL_EXT
#define GL_DEPTH_STENCIL_EXT 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8_EXT
#define GL_UNSIGNED_INT_24_8_EXT 0x84FA
#endif

static void error(const char* name) { conf_value(name, glGetError()); }

/* A grid of words over the 64 x 48 window: depth (24 bits) and stencil apart, and the
 * depth as glReadPixels(GL_DEPTH_COMPONENT) gives it. */
static void words(const char* name) {
  static GLuint w[64 * 48];
  static GLfloat d[64 * 48];
  char n[64];
  int i, j;
  glReadPixels(0, 0, 64, 48, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, w);
  glReadPixels(0, 0, 64, 48, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  for (j = 0; j < 12; ++j)
    for (i = 0; i < 16; ++i) {
      const int at = (j * 4 + 1) * 64 + i * 4 + 2;
      snprintf(n, sizeof n, "%s_z_%d_%d", name, i, j);
      conf_value(n, (double)(w[at] >> 8));
      snprintf(n, sizeof n, "%s_s_%d_%d", name, i, j);
      conf_value(n, (double)(w[at] & 0xff));
      snprintf(n, sizeof n, "%s_d_%d_%d", name, i, j);
      conf_value(n, d[at]);
    }
}

int main(int argc, char** argv) {
  static GLuint image[13 * 9], small[2];
  GLuint back[6];
  int i;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 64, 48);
  conf_ortho();
  /* Depth rising to the right, stencil by position: no two rows alike. */
  for (i = 0; i < 13 * 9; ++i) {
    const GLuint z = (GLuint)((i % 13) * 1290000u + (i / 13) * 91u + 7u) & 0xffffffu;
    image[i] = z << 8 | (GLuint)((i * 29 + 3) & 0xff);
  }
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClearDepth(0.5);
  glClearStencil(0x11);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  error("clear");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);

  /* The whole image, then a part of it (row length 13, skipping 2 rows and 3 pixels). */
  glRasterPos2f(1.5f, 2.5f);
  glDrawPixels(13, 9, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  error("draw");
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 13);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glRasterPos2f(20.5f, 3.5f);
  glDrawPixels(7, 5, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  /* Zoomed, through a stencil write mask and the scissor box. (Not compared:
   * GL_UNPACK_SWAP_BYTES, which pGL applies to each word as GL 1.5's table 3.7 says
   * and Mesa 22's glDrawPixels(GL_DEPTH_STENCIL) ignores; glReadPixels' swap agrees.) */
  glStencilMask(0x0f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 20, 50, 20);
  glPixelZoom(2.0f, 3.0f);
  glRasterPos2f(3.5f, 17.5f);
  glDrawPixels(13, 9, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, image);
  glPixelZoom(1.0f, 1.0f);
  glDisable(GL_SCISSOR_TEST);
  glStencilMask(0xff);
  error("draw_zoomed");
  conf_frame("colour_untouched");
  words("drawn");

  /* Copied: depth and stencil, no colour. */
  glRasterPos2f(48.5f, 30.5f);
  glCopyPixels(1, 2, 13, 9, GL_DEPTH_STENCIL_EXT);
  error("copy");
  words("copied");

  /* Packed for reading: a row length and skips, and byte swapping. */
  for (i = 0; i < 6; ++i) back[i] = 0xdeadbeefu;
  glPixelStorei(GL_PACK_ROW_LENGTH, 3);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glReadPixels(2, 3, 2, 2, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, back);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  for (i = 0; i < 6; ++i) {
    char n[32];
    snprintf(n, sizeof n, "packed_%d_hi", i);
    conf_value(n, (double)(back[i] >> 16));
    snprintf(n, sizeof n, "packed_%d_lo", i);
    conf_value(n, (double)(back[i] & 0xffff));
  }

  /* Errors: the extension's format with another type, its type with another format. */
  glDrawPixels(1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT, small);
  error("draw_wrong_type");
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8_EXT, small);
  error("draw_wrong_format");
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL_EXT, GL_FLOAT, small);
  error("read_wrong_type");
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8_EXT, small);
  error("read_wrong_format");
  glDrawPixels(-1, 1, GL_DEPTH_STENCIL_EXT, GL_UNSIGNED_INT_24_8_EXT, small);
  error("draw_negative");
  conf_show_stencil("stencil_shown", 64, 48);
  return conf_end();
}
