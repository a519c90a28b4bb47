/* The stencil buffer (an 8-bit one: OSMesaCreateContextExt's stencilBits): glStencilFunc
 * with each comparison, value and write masks, glStencilOp's eight operations on stencil
 * fail, depth fail and depth pass, glClearStencil with the scissor and the write mask,
 * the stencil test after the alpha test, glReadPixels(GL_STENCIL_INDEX) in several
 * types, the state queries and GL's errors. The stencil values themselves are compared
 * (read back), as well as the frames. */
#include "harness.h"

/* The stencil values of an 8 x 8 grid over the window, as NAME_i values, and a
 * checksum of every pixel's. */
static void stencil_values(const char* name) {
  static GLubyte s[96 * 64];
  char n[64];
  int i, j;
  unsigned long sum = 0;
  glReadPixels(0, 0, 96, 64, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  for (i = 0; i < 96 * 64; ++i) sum = (sum * 31 + s[i]) % 1000003;
  snprintf(n, sizeof n, "%s_sum", name);
  conf_value(n, (double)sum);
  for (j = 0; j < 8; ++j)
    for (i = 0; i < 8; ++i) {
      snprintf(n, sizeof n, "%s_%d_%d", name, i, j);
      conf_value(n, s[(j * 8 + 4) * 96 + i * 12 + 6]);
    }
}

static void get(const char* name, GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  conf_value(name, v);
}

static void error(const char* name) { conf_value(name, glGetError()); }

int main(int argc, char** argv) {
  static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  static const GLenum ops[8] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
  int i;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 96, 64);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 96, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);

  /* The initial state and the buffer's size. */
  get("bits", GL_STENCIL_BITS);
  get("func", GL_STENCIL_FUNC);
  get("ref", GL_STENCIL_REF);
  get("value_mask", GL_STENCIL_VALUE_MASK);
  get("writemask", GL_STENCIL_WRITEMASK);
  get("fail", GL_STENCIL_FAIL);
  get("zfail", GL_STENCIL_PASS_DEPTH_FAIL);
  get("zpass", GL_STENCIL_PASS_DEPTH_PASS);
  get("clear", GL_STENCIL_CLEAR_VALUE);
  conf_value("enabled", glIsEnabled(GL_STENCIL_TEST));
  error("initial_error");

  /* Errors: unknown functions and operations, calls between glBegin and glEnd. */
  glStencilFunc(GL_ZERO + 3, 0, 0xff);
  error("bad_func");
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR + 7);
  error("bad_op");
  glStencilOp(0x1234, GL_KEEP, GL_KEEP);
  error("bad_op_first");
  glBegin(GL_TRIANGLES);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glEnd();
  error("in_begin");
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE + 100, NULL);
  error("bad_type");

  /* Set and read back: the reference clamps to the buffer's range, masks stay as set. */
  glStencilFunc(GL_LEQUAL, 300, 0x0f);
  get("ref_clamped", GL_STENCIL_REF);
  get("value_mask_set", GL_STENCIL_VALUE_MASK);
  glStencilFunc(GL_LEQUAL, -5, 0xff);
  get("ref_negative", GL_STENCIL_REF);
  glStencilMask(0x3c);
  get("writemask_set", GL_STENCIL_WRITEMASK);
  glStencilMask(~0u);
  glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT);
  get("fail_set", GL_STENCIL_FAIL);
  get("zfail_set", GL_STENCIL_PASS_DEPTH_FAIL);
  get("zpass_set", GL_STENCIL_PASS_DEPTH_PASS);
  glClearStencil(0x1ff);
  get("clear_set", GL_STENCIL_CLEAR_VALUE);
  error("set_error");

  /* A mask: a stencil of 1 inside a triangle (colour writes off), then red where it is
   * 1 and blue where it is not. */
  glClearColor(0, 0, 0, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glBegin(GL_TRIANGLES);
  glVertex2f(10, 5);
  glVertex2f(85, 20);
  glVertex2f(30, 60);
  glEnd();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glColor3f(1, 0, 0);
  conf_quad(0, 0, 96, 64, 0);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glColor3f(0, 0, 1);
  conf_quad(0, 0, 96, 64, 0);
  conf_frame("mask");
  stencil_values("mask");

  /* Each comparison: stencil values 0..7 in columns, then for each function a band of
   * rows drawn where ref 3 compares true against them. */
  glClear(GL_COLOR_BUFFER_BIT);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (i = 0; i < 8; ++i) {
    glStencilFunc(GL_ALWAYS, i, 0xff);
    conf_quad(i * 12.0f, 0, i * 12.0f + 12, 64, 0);
  }
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (i = 0; i < 8; ++i) {
    glStencilFunc(funcs[i], 3, 0xff);
    glColor3f((i & 1) ? 1.0f : 0.3f, (i & 2) ? 1.0f : 0.3f, (i & 4) ? 1.0f : 0.3f);
    conf_quad(0, i * 8.0f, 96, i * 8.0f + 8, 0);
  }
  conf_frame("funcs");
  stencil_values("funcs_columns");

  /* Each operation on stencil pass, over columns 0..7 with a second and third pass
   * where they overlap: increments and decrements clamp at 0 and 255, the wrap ones
   * wrap, invert flips the bits. */
  glClearStencil(0x80);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (i = 0; i < 8; ++i) {
    glStencilFunc(GL_ALWAYS, 0xfe, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, ops[i]);
    conf_quad(i * 12.0f, 0, i * 12.0f + 12, 40, 0);
    conf_quad(i * 12.0f, 20, i * 12.0f + 12, 50, 0);
    conf_quad(i * 12.0f, 30, i * 12.0f + 12, 64, 0);
  }
  stencil_values("ops_pass");
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (i = 0; i < 8; ++i) {
    glStencilOp(GL_KEEP, GL_KEEP, ops[i]);
    conf_quad(i * 12.0f, 0, i * 12.0f + 12, 32, 0);
    conf_quad(i * 12.0f, 16, i * 12.0f + 12, 64, 0);
  }
  stencil_values("ops_from_zero");
  glClearStencil(255);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (i = 0; i < 8; ++i) {
    glStencilOp(GL_KEEP, GL_KEEP, ops[i]);
    conf_quad(i * 12.0f, 0, i * 12.0f + 12, 32, 0);
  }
  stencil_values("ops_from_255");

  /* Stencil fail, depth fail, depth pass: a near quad, then a far one under three ops. */
  glEnable(GL_DEPTH_TEST);
  glClearStencil(5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0, 1, 0);
  conf_quad(20, 10, 60, 50, 0.5f); /* window depth 0.25 */
  glStencilFunc(GL_LESS, 2, 0xff); /* passes where 2 < stencil */
  glStencilOp(GL_ZERO, GL_INCR, GL_DECR);
  glClearStencil(1);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 30, 64);
  glClear(GL_STENCIL_BUFFER_BIT); /* the left 30 columns fail the stencil test */
  glDisable(GL_SCISSOR_TEST);
  glColor3f(1, 0, 1);
  conf_quad(10, 20, 80, 40, -0.5f); /* window depth 0.75: behind the green one */
  conf_frame("zfail");
  stencil_values("zfail");
  glDisable(GL_DEPTH_TEST);

  /* Masks: the value mask selects the bits compared, the write mask the bits written;
   * a clear under the write mask and the scissor. */
  glClearStencil(0xa5);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glStencilMask(0x0f);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
  conf_quad(0, 0, 48, 64, 0);
  glStencilMask(0xf0);
  glClearStencil(0x3c);
  glEnable(GL_SCISSOR_TEST);
  glScissor(24, 8, 48, 40);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glStencilMask(0xff);
  stencil_values("masks");
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_EQUAL, 0x0a, 0x0f); /* low nibble 0xa: where the invert flipped 5 */
  glColor3f(1, 1, 0);
  conf_quad(0, 0, 96, 32, 0);
  glStencilFunc(GL_EQUAL, 0x30, 0xf0); /* high nibble 3: the masked clear */
  glColor3f(0, 1, 1);
  conf_quad(0, 32, 96, 64, 0);
  conf_frame("masks");

  /* The alpha test comes first: fragments it discards leave the stencil alone. */
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  glBegin(GL_QUADS);
  glColor4f(1, 1, 1, 0);
  glVertex2f(0, 0);
  glColor4f(1, 1, 1, 1);
  glVertex2f(96, 0);
  glVertex2f(96, 64);
  glColor4f(1, 1, 1, 0);
  glVertex2f(0, 64);
  glEnd();
  glDisable(GL_ALPHA_TEST);
  conf_frame("alpha");
  stencil_values("alpha");

  /* Without the test enabled, the stencil is not touched. */
  glDisable(GL_STENCIL_TEST);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  conf_quad(0, 0, 96, 64, 0);
  stencil_values("disabled");

  /* glReadPixels in other types: indices, not scaled. */
  {
    GLfloat f[4];
    GLushort us[4];
    GLuint ui[4];
    glClearStencil(200);
    glClear(GL_STENCIL_BUFFER_BIT);
    glReadPixels(10, 10, 4, 1, GL_STENCIL_INDEX, GL_FLOAT, f);
    glReadPixels(10, 10, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, us);
    glReadPixels(10, 10, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, ui);
    conf_value("read_float", f[3]);
    conf_value("read_ushort", us[3]);
    conf_value("read_uint", ui[3]);
    error("read_error");
  }
  return conf_end();
}
