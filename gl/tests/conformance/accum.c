/* The accumulation buffer (a context asked for 16 accumulation bits): a motion blur of
 * five frames summed with GL_ACCUM; GL_LOAD, GL_MULT and GL_ADD on a smooth-shaded
 * image returned with a scale above 1 (clamped); glClearAccum and glClear of the
 * buffer and glAccum under the scissor box, GL_RETURN under a colour mask with
 * blending and the depth test enabled (neither applies to it); glAccum in a display
 * list; the queries (bits, clear value clamped to [-1, 1]), glPushAttrib's
 * GL_ACCUM_BUFFER_BIT, the errors, and a context without the buffer. */
#include "harness.h"

#define W 96
#define H 64

static void triangle(float dx) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.3f, 0.1f), glVertex2f(10 + dx, 8);
  glColor3f(0.2f, 1, 0.4f), glVertex2f(40 + dx, 14);
  glColor3f(0.1f, 0.5f, 1), glVertex2f(22 + dx, 56);
  glEnd();
}

/* (Colours affine in x and y, so that the quad's two triangles agree with Mesa's.) */
static void shaded_quad(void) {
  glBegin(GL_QUADS);
  glColor4f(0.0f, 0.2f, 0.9f, 1.0f), glVertex2f(0, 0);
  glColor4f(0.9f, 0.2f, 0.45f, 0.6f), glVertex2f(W, 0);
  glColor4f(0.9f, 0.8f, 0.15f, 0.2f), glVertex2f(W, H);
  glColor4f(0.0f, 0.8f, 0.6f, 0.6f), glVertex2f(0, H);
  glEnd();
}

static void pixel_values(const char* prefix, int x, int y) {
  GLfloat c[4];
  char name[64];
  int k;
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_FLOAT, c);
  for (k = 0; k < 4; ++k) {
    snprintf(name, sizeof name, "%s_%d_%d_%c", prefix, x, y, "rgba"[k]);
    conf_value(name, c[k]);
  }
}

int main(int argc, char** argv) {
  GLint bits[4];
  GLfloat clear[4];
  GLuint list;
  int i;
  conf_accum_bits = 16;
  conf_init(argc, argv, W, H);
  conf_ortho();

  /* Motion blur: five positions, each a fifth. */
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  glClearColor(0.1f, 0.1f, 0.2f, 1);
  for (i = 0; i < 5; ++i) {
    glClear(GL_COLOR_BUFFER_BIT);
    triangle(8.0f * i);
    glAccum(GL_ACCUM, 0.2f);
  }
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  conf_frame("motion");
  pixel_values("motion", 30, 20);
  pixel_values("motion", 70, 30);

  /* Load, multiply, add, returned scaled up (and clamped at 1). */
  glClear(GL_COLOR_BUFFER_BIT);
  shaded_quad();
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_MULT, 1.5f);
  glAccum(GL_ADD, -0.1f);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_RETURN, 1.6f);
  conf_frame("load_mult_add");
  pixel_values("load", 5, 60);
  pixel_values("load", 90, 3);

  /* The scissor box bounds glClear's and glAccum's pixels; GL_RETURN writes through the
   * colour mask and neither blends nor tests depth. */
  glClearColor(0.4f, 0.4f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glClearAccum(0.5f, -0.25f, 0.4f, 0.25f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(12, 6, 50, 40);
  glClearAccum(0.4f, 0.1f, 0.2f, 0.25f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glScissor(30, 20, 60, 40);
  triangle(30);
  glAccum(GL_ACCUM, 0.5f);
  glScissor(0, 0, 80, 56);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ZERO, GL_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glAccum(GL_RETURN, 0.8f);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
  conf_frame("scissor_mask");
  pixel_values("scissor", 20, 10);
  pixel_values("scissor", 70, 50);
  pixel_values("scissor", 90, 60);

  /* A display list holds glClearAccum and glAccum. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearAccum(0.25f, 0.5f, 0.125f, 0.375f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  glEndList();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  triangle(50);
  glCallList(list);
  conf_frame("list");
  pixel_values("list", 62, 20);

  /* Queries, the attribute stack, errors. */
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
  glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
  glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
  glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
  conf_value("accum_bits_positive", bits[0] >= 16 && bits[1] == bits[0] && bits[2] == bits[0] && bits[3] == bits[0]);
  glClearAccum(2, -3, 0.5f, 0.25f);
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, clear);
  for (i = 0; i < 4; ++i) {
    char name[32];
    snprintf(name, sizeof name, "clear_value_%d", i);
    conf_value(name, clear[i]);
  }
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(0, 0, 0, 0);
  glPopAttrib();
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, clear);
  conf_value("popped_clear_red", clear[0]);
  conf_value("popped_clear_green", clear[1]);
  while (glGetError() != GL_NO_ERROR) {
  }
  glAccum(GL_ONE, 1.0f);
  conf_value("error_bad_op", glGetError());
  glBegin(GL_TRIANGLES);
  glAccum(GL_ACCUM, 1.0f);
  glEnd();
  conf_value("error_in_begin", glGetError());
  glBegin(GL_TRIANGLES);
  glClearAccum(0, 0, 0, 0);
  glEnd();
  conf_value("error_clear_in_begin", glGetError());

  /* A context without an accumulation buffer. */
  {
    static unsigned char other[16 * 16 * 4];
    OSMesaContext none = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!none || !OSMesaMakeCurrent(none, other, GL_UNSIGNED_BYTE, 16, 16)) conf_fail("a second context");
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
    conf_value("none_bits", bits[0]);
    glAccum(GL_ACCUM, 1.0f);
    conf_value("none_error", glGetError());
    glClear(GL_ACCUM_BUFFER_BIT);
    conf_value("none_clear_error", glGetError());
    OSMesaMakeCurrent(conf_ctx, conf_buffer, GL_UNSIGNED_BYTE, W, H);
    OSMesaDestroyContext(none);
  }
  return conf_end();
}
