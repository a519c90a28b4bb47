/* Selection: glRenderMode(GL_SELECT) with glSelectBuffer and the name stack (glInitNames,
 * glPushName, glPopName, glLoadName): points, lines and polygons inside, outside and
 * across the view volume, culled faces, a perspective view, a depth range; the hit
 * records (name count, depths, names) compared with Mesa's (the depths to 1/1000 of the
 * range), an overflowing buffer, the state's queries and GL's errors. */
#include "harness.h"

static GLuint buf[256];

static void error(const char* name) { conf_value(name, glGetError()); }

static void records(const char* name, GLint hits) {
  char n[64];
  GLint h, k, at = 0;
  snprintf(n, sizeof n, "%s_hits", name);
  conf_value(n, hits);
  for (h = 0; h < hits && at < 256; ++h) {
    const GLint count = (GLint)buf[at];
    snprintf(n, sizeof n, "%s_%d_count", name, h);
    conf_value(n, count);
    snprintf(n, sizeof n, "%s_%d_zmin", name, h);
    conf_value(n, (int)(buf[at + 1] / 4294967.295 + 0.5));
    snprintf(n, sizeof n, "%s_%d_zmax", name, h);
    conf_value(n, (int)(buf[at + 2] / 4294967.295 + 0.5));
    for (k = 0; k < count && at + 3 + k < 256; ++k) {
      snprintf(n, sizeof n, "%s_%d_name%d", name, h, k);
      conf_value(n, buf[at + 3 + k]);
    }
    at += 3 + count;
  }
}

int main(int argc, char** argv) {
  GLint v;
  conf_init(argc, argv, 64, 64);
  conf_value("mode", (glGetIntegerv(GL_RENDER_MODE, &v), v));
  glGetIntegerv(GL_MAX_NAME_STACK_DEPTH, &v);
  conf_value("max_names", v);
  conf_value("select_without_buffer", glRenderMode(GL_SELECT));
  error("select_without_buffer_error");
  glRenderMode(GL_RENDER); /* (Mesa enters select mode anyway) */

  /* Orthographic: a quad inside, one outside, one across the edge, a culled one, a
   * line across a corner, points in and out, under nested names. */
  glSelectBuffer(256, buf);
  glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &v);
  conf_value("buffer_size", v);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  conf_value("enter", glRenderMode(GL_SELECT));
  glInitNames();
  glPushName(10);
  conf_quad(-0.5f, -0.5f, 0.5f, 0.5f, 0.2f);
  glPushName(20);
  conf_quad(2, 2, 3, 3, 0); /* outside: no hit */
  glLoadName(21);
  glBegin(GL_TRIANGLES);
  glVertex3f(0.5f, 0, -0.4f);
  glVertex3f(1.5f, 0, 0.6f);
  glVertex3f(1.5f, 1, 0.6f);
  glEnd();
  glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
  conf_value("stack_depth", v);
  glPopName();
  glLoadName(30);
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES); /* clockwise: culled */
  glVertex2f(0, 0);
  glVertex2f(0, 0.5f);
  glVertex2f(0.5f, 0);
  glEnd();
  glDisable(GL_CULL_FACE);
  glLoadName(40);
  glBegin(GL_LINES);
  glVertex3f(0.4f, 1.5f, 0.8f);
  glVertex3f(1.5f, 0.4f, -0.8f);
  glVertex3f(0.8f, 0.6f, 0.9f);
  glVertex3f(1.8f, 0.6f, -0.1f);
  glEnd();
  glLoadName(50);
  glBegin(GL_POINTS);
  glVertex3f(0.25f, 0.25f, -0.5f);
  glVertex3f(5, 5, 0);
  glVertex3f(-0.25f, 0.75f, 0.75f);
  glEnd();
  glPopName();
  glPopName();
  error("pop_underflow");
  glLoadName(1);
  error("load_empty");
  records("ortho", glRenderMode(GL_RENDER));
  error("ortho_error");

  /* Perspective, a depth range, a quad cut by the near plane. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glDepthRange(0.2, 0.9);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(7);
  conf_quad(-1, -1, 1, 1, -5);
  glLoadName(8);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, 0);
  glVertex3f(1, -1, 0);
  glVertex3f(1, 1, -6);
  glVertex3f(-1, 1, -6);
  glEnd();
  records("perspective", glRenderMode(GL_RENDER));
  glDepthRange(0, 1);

  /* Overflow: -1, and glSelectBuffer in select mode. */
  glSelectBuffer(5, buf);
  glRenderMode(GL_SELECT);
  glSelectBuffer(5, buf);
  error("buffer_in_select");
  glPushName(1);
  glPushName(2);
  glPushName(3);
  conf_quad(-1, -1, 1, 1, -5);
  conf_value("overflow", glRenderMode(GL_RENDER));
  glRenderMode(GL_FEEDBACK + 100);
  error("bad_mode");
  glPushName(1); /* in GL_RENDER: ignored */
  error("render_push");
  glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
  conf_value("render_depth", v);
  /* Drawing again after selection. */
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0.5f, 0);
  conf_quad(-1, -1, 1, 1, -5);
  conf_frame("after");
  return conf_end();
}
