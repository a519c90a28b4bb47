/* The logic op (GL_COLOR_LOGIC_OP): each of the 16 operations, as a rectangle of one
 * exact 8-bit colour drawn over stripes of others (every bit combination of source and
 * destination meets), with blending also enabled (the logic op takes its place) and a
 * colour mask; triangles, lines and points under XOR; glDrawPixels and
 * glCopyPixels through it (the piglit xor tests' pattern); glPushAttrib / glPopAttrib,
 * the queries and the errors. */
#include "harness.h"

#define W 128
#define H 96

static const GLenum ops[16] = {GL_CLEAR, GL_AND,  GL_AND_REVERSE, GL_COPY,         GL_AND_INVERTED, GL_NOOP,
                               GL_XOR,   GL_OR,   GL_NOR,         GL_EQUIV,        GL_INVERT,       GL_OR_REVERSE,
                               GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND, GL_SET};

/* Vertical stripes of exact colours across the window. */
static void stripes(void) {
  static const GLubyte colors[6][4] = {{0x00, 0xff, 0x35, 0xff}, {0xff, 0x00, 0xca, 0x80}, {0x5a, 0xa5, 0x0f, 0x00},
                                       {0xc3, 0x3c, 0xf0, 0x7f}, {0x81, 0x7e, 0x18, 0xe7}, {0xff, 0xff, 0xff, 0x12}};
  int i;
  glDisable(GL_COLOR_LOGIC_OP);
  for (i = 0; i < 32; ++i) {
    glColor4ubv(colors[i % 6]);
    glRecti(i * 4, 0, i * 4 + 4, H);
  }
}

/* The 16 operations in a 4 x 4 grid of cells, each a rectangle of colour `c`. */
static void grid(const GLubyte* c) {
  int k;
  glEnable(GL_COLOR_LOGIC_OP);
  glColor4ubv(c);
  for (k = 0; k < 16; ++k) {
    int x = (k % 4) * 32, y = (k / 4) * 24;
    glLogicOp(ops[k]);
    glRecti(x + 3, y + 3, x + 29, y + 21);
  }
  glDisable(GL_COLOR_LOGIC_OP);
}

int main(int argc, char** argv) {
  static const GLubyte c1[4] = {0x96, 0x3c, 0xf5, 0x69}, c2[4] = {0x0f, 0xf0, 0x55, 0xaa};
  static GLubyte image[16 * 12 * 4];
  GLint iv[1];
  int i;
  conf_init(argc, argv, W, H);
  conf_ortho();
  glShadeModel(GL_FLAT);

  stripes();
  grid(c1);
  conf_frame("ops");

  /* Blending enabled too: the logic op takes its place. A colour mask keeps green and
   * alpha. */
  stripes();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  grid(c2);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
  conf_frame("ops_blend_mask");

  /* Flat triangles, lines and points under XOR, twice over in part (XOR twice is the
   * identity). Flat: an interpolated colour a rounding apart would differ in many bits
   * after the XOR. */
  stripes();
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  for (i = 0; i < 2; ++i) {
    glBegin(GL_TRIANGLES);
    glColor3ub(255, 0, 0), glVertex2i(10, 10);
    glColor3ub(0, 255, 0), glVertex2i(100 - 40 * i, 20);
    glColor3ub(0, 0, 255), glVertex2i(40, 85);
    glEnd();
  }
  glBegin(GL_LINES);
  for (i = 0; i < 8; ++i) glColor3ub(0xff, 0xaa, 0x55), glVertex2f(64.3f, 48.7f), glVertex2f(64.6f + 10.3f * i - 35, 90.4f);
  glEnd();
  glPointSize(3);
  glBegin(GL_POINTS);
  for (i = 0; i < 10; ++i) glColor3ub((GLubyte)(i * 25), 0xf0, 0x0f), glVertex2f(8.5f + 11 * i, 5.5f);
  glEnd();
  glDisable(GL_COLOR_LOGIC_OP);
  conf_frame("xor_primitives");

  /* glDrawPixels and glCopyPixels through XOR and AND_REVERSE. */
  stripes();
  for (i = 0; i < 16 * 12; ++i) {
    image[4 * i] = (GLubyte)(i * 7), image[4 * i + 1] = (GLubyte)(255 - i), image[4 * i + 2] = (GLubyte)(i * 13 + 5);
    image[4 * i + 3] = (GLubyte)(i * 3);
  }
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glRasterPos2i(5, 7);
  glPixelZoom(2, 3);
  glDrawPixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glPixelZoom(1, 1);
  glLogicOp(GL_AND_REVERSE);
  glRasterPos2i(70, 40);
  glCopyPixels(0, 0, 40, 30, GL_COLOR);
  glLogicOp(GL_XOR);
  glRasterPos2i(60, 2);
  glCopyPixels(60, 2, 30, 20, GL_COLOR); /* onto itself: zero */
  glDisable(GL_COLOR_LOGIC_OP);
  conf_frame("pixels");

  /* State: queries, the attribute groups, errors. */
  glLogicOp(GL_NAND);
  glGetIntegerv(GL_LOGIC_OP_MODE, iv);
  conf_value("mode", iv[0]);
  conf_value("enabled_off", glIsEnabled(GL_COLOR_LOGIC_OP));
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_OR);
  glPopAttrib();
  glGetIntegerv(GL_LOGIC_OP_MODE, iv);
  conf_value("pop_color_mode", iv[0]);
  conf_value("pop_color_enabled", glIsEnabled(GL_COLOR_LOGIC_OP));
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_OR);
  conf_value("enabled_on", glIsEnabled(GL_COLOR_LOGIC_OP));
  glPopAttrib();
  glGetIntegerv(GL_LOGIC_OP_MODE, iv);
  conf_value("pop_enable_mode", iv[0]);
  conf_value("pop_enable_enabled", glIsEnabled(GL_COLOR_LOGIC_OP));
  conf_value("error_none", glGetError());
  glLogicOp(GL_SET + 1);
  conf_value("error_op_high", glGetError());
  glLogicOp(GL_CLEAR - 1);
  conf_value("error_op_low", glGetError());
  glBegin(GL_POINTS);
  glLogicOp(GL_XOR);
  glEnd();
  conf_value("error_in_begin", glGetError());
  glGetIntegerv(GL_LOGIC_OP_MODE, iv);
  conf_value("mode_after_errors", iv[0]);
  return conf_end();
}
