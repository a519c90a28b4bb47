/* State set after drawing changes only what is drawn after it: glViewport, glDepthRange,
 * glPointSize and glLineWidth between primitives of one kind (which a renderer batches
 * together), with nothing flushed in between. */
#include "harness.h"

static void rect(float r, float g, float b, float z) {
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  glVertex3f(-0.8f, -0.8f, z);
  glVertex3f(0.8f, -0.8f, z);
  glVertex3f(0.8f, 0.8f, z);
  glVertex3f(-0.8f, 0.8f, z);
  glEnd();
}

/* One pixel's red, green and blue as values NAME_r, NAME_g, NAME_b. */
static void pixel(const char* name, int x, int y) {
  GLubyte px[4];
  char n[64];
  int i;
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  for (i = 0; i < 3; ++i) {
    snprintf(n, sizeof n, "%s_%c", name, "rgb"[i]);
    conf_value(n, px[i]);
  }
}

int main(int argc, char** argv) {
  GLfloat depth;
  conf_init(argc, argv, 80, 40);
  glClearColor(0, 0, 0, 1);

  /* A red rectangle in the left viewport, then a green one in the right. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glViewport(0, 0, 40, 40);
  rect(1, 0, 0, 0);
  glViewport(40, 0, 40, 40);
  rect(0, 1, 0, 0);
  conf_frame("viewports");
  pixel("viewports_left", 20, 20);
  pixel("viewports_right", 60, 20);

  /* The same viewport set again between them, then a viewport with nothing drawn in
   * it before the frame ends. */
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(0, 0, 40, 40);
  rect(0, 0, 1, 0);
  glViewport(0, 0, 40, 40);
  rect(1, 1, 0, 0.5f);
  glViewport(40, 0, 20, 20);
  conf_frame("viewport_same");
  pixel("viewport_same_left", 20, 20);
  pixel("viewport_same_right", 60, 20);

  /* Depth ranges: red at z = 0 in [0, 0.5] (window depth 0.25), then green nearer in
   * object space (z = -0.9) but in [0.5, 1] (window depth 0.525): the depth test keeps red. */
  glViewport(0, 0, 80, 40);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDepthRange(0, 0.5);
  rect(1, 0, 0, 0);
  glDepthRange(0.5, 1);
  rect(0, 1, 0, -0.9f);
  conf_frame("depth_range");
  pixel("depth_range_centre", 40, 20);
  glReadPixels(40, 20, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  conf_value("depth_range_depth", depth > 0.24f && depth < 0.26f);
  glDepthRange(0, 1);
  glDisable(GL_DEPTH_TEST);

  /* A size-1 point, then a size-5 point; a 1-pixel line, then a 5-pixel line. */
  glMatrixMode(GL_PROJECTION);
  gluOrtho2D(0, 80, 0, 40);
  glMatrixMode(GL_MODELVIEW);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glPointSize(1);
  glBegin(GL_POINTS);
  glVertex2f(10.5f, 30.5f);
  glEnd();
  glPointSize(5);
  glBegin(GL_POINTS);
  glVertex2f(30.5f, 30.5f);
  glEnd();
  glLineWidth(1);
  glBegin(GL_LINES);
  glVertex2f(5.5f, 10.5f);
  glVertex2f(35.5f, 10.5f);
  glEnd();
  glLineWidth(5);
  glBegin(GL_LINES);
  glVertex2f(45.5f, 10.5f);
  glVertex2f(75.5f, 10.5f);
  glEnd();
  glPointSize(3);
  glLineWidth(3);
  conf_frame("sizes");
  pixel("point1_beside", 11, 30);
  pixel("point5_beside", 31, 30);
  pixel("line1_above", 20, 11);
  pixel("line5_above", 60, 11);
  return conf_end();
}
