/* glDrawBuffer and glReadBuffer on OSMesa's single colour buffer (the front): the names
 * that select it (GL_FRONT, GL_LEFT, GL_FRONT_LEFT, GL_FRONT_AND_BACK), those of buffers
 * it does not have (right and auxiliary buffers: GL_INVALID_OPERATION), bad
 * enums, GL_NONE (nothing drawn into colour, depth and stencil still written; reading
 * colour is GL_INVALID_OPERATION, depth and stencil still read), glGet of both, the
 * attribute stacks, display lists, and the calls between glBegin and glEnd. */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

static void get(const char* name, GLenum pname) {
  GLint v = -12345;
  glGetIntegerv(pname, &v);
  conf_value(name, v);
}

int main(int argc, char** argv) {
  /* (GL_BACK and GL_BACK_LEFT are not compared: Mesa 22's OSMesa takes them on its single
   * buffer, where GL and pGL raise GL_INVALID_OPERATION.) */
  static const GLenum draw_names[] = {GL_FRONT, GL_FRONT_LEFT, GL_LEFT, GL_FRONT_AND_BACK, GL_NONE, GL_RIGHT,
                                      GL_FRONT_RIGHT, GL_BACK_RIGHT, GL_AUX0, GL_AUX3, GL_TEXTURE_2D, GL_ZERO + 1};
  static const char* labels[] = {"front", "front_left", "left", "front_and_back", "none", "right",
                                 "front_right", "back_right", "aux0", "aux3", "texture_2d", "one"};
  char name[64];
  unsigned i;
  GLubyte px[4] = {0, 0, 0, 0};
  GLubyte s = 0;
  GLfloat z = 0;
  GLuint list;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 64, 48);
  conf_ortho();

  get("draw_initial", GL_DRAW_BUFFER);
  get("read_initial", GL_READ_BUFFER);
  get("doublebuffer", GL_DOUBLEBUFFER);
  get("aux_buffers", GL_AUX_BUFFERS);

  /* Every name, each way: the error, and what glGet says after it. */
  for (i = 0; i < sizeof draw_names / sizeof draw_names[0]; ++i) {
    glDrawBuffer(GL_FRONT);
    glReadBuffer(GL_FRONT);
    glDrawBuffer(draw_names[i]);
    snprintf(name, sizeof name, "draw_%s", labels[i]);
    error(name);
    snprintf(name, sizeof name, "draw_%s_get", labels[i]);
    get(name, GL_DRAW_BUFFER);
    glReadBuffer(draw_names[i]);
    snprintf(name, sizeof name, "read_%s", labels[i]);
    error(name);
    snprintf(name, sizeof name, "read_%s_get", labels[i]);
    get(name, GL_READ_BUFFER);
  }
  glBegin(GL_POINTS);
  glDrawBuffer(GL_FRONT);
  glEnd();
  error("draw_in_begin");
  glBegin(GL_POINTS);
  glReadBuffer(GL_FRONT);
  glEnd();
  error("read_in_begin");

  /* GL_NONE: colour is not written, depth and stencil are. */
  glDrawBuffer(GL_FRONT);
  glReadBuffer(GL_FRONT);
  glClearColor(0.2f, 0.4f, 0.6f, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 7, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glDrawBuffer(GL_NONE);
  glColor3f(1, 0, 0);
  conf_quad(8, 8, 40, 30, 0.5f);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_FRONT_AND_BACK);
  glColor3f(0, 1, 0);
  conf_quad(20, 16, 56, 40, 0.2f); /* behind the first where they overlap: depth test */
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  conf_frame("none_then_both");
  glReadPixels(12, 12, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  conf_value("none_r", px[0]), conf_value("none_g", px[1]), conf_value("none_b", px[2]);
  glReadPixels(12, 12, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  conf_value("none_stencil", s);
  glReadPixels(12, 12, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  conf_value("none_depth", z);

  /* Reading from GL_NONE: colour is an error, depth and stencil are not. */
  glReadBuffer(GL_NONE);
  glReadPixels(12, 12, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  error("read_none_rgba");
  glReadPixels(12, 12, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  error("read_none_stencil");
  conf_value("read_none_stencil_value", s);
  glRasterPos2i(0, 0);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  error("copy_none_color");
  glReadBuffer(GL_FRONT);

  /* The attribute stacks: glDrawBuffer with the colour buffer's group, glReadBuffer with
   * the pixel mode's. */
  glDrawBuffer(GL_FRONT_LEFT);
  glReadBuffer(GL_LEFT);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_FRONT);
  glPopAttrib();
  get("pop_color_draw", GL_DRAW_BUFFER);
  get("pop_color_read", GL_READ_BUFFER);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_FRONT);
  glReadBuffer(GL_NONE);
  glPopAttrib();
  get("pop_pixel_draw", GL_DRAW_BUFFER);
  get("pop_pixel_read", GL_READ_BUFFER);
  error("pop_error");

  /* Display lists: both are compiled, and run when the list is called. */
  glDrawBuffer(GL_FRONT);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_FRONT_LEFT);
  glEndList();
  get("list_compiled_draw", GL_DRAW_BUFFER);
  glCallList(list);
  get("list_called_draw", GL_DRAW_BUFFER);
  get("list_called_read", GL_READ_BUFFER);
  glColor3f(0, 0, 1);
  conf_quad(0, 0, 64, 48, 0);
  glDrawBuffer(GL_FRONT);
  glColor3f(1, 0, 1);
  conf_quad(40, 2, 60, 12, 0);
  conf_frame("list");
  error("final_error");
  return conf_end();
}
