/* Polygon offset (glPolygonOffset, GL_POLYGON_OFFSET_FILL / LINE / POINT): a red
 * polygon, then a blue one at the same place pushed behind or pulled in front by one
 * unit of the minimum resolvable difference, in every pair of fill, line and point
 * modes (piglit's polygon-offset); tilted quads offset by their depth slope (factor),
 * behind an unoffset copy; the depth read back from offset quads. Values: the state,
 * the depths. Compared with Mesa. */
#include "harness.h"

static void rect(float x, float y, float w, float h, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x, y, z);
  glVertex3f(x + w, y, z);
  glVertex3f(x + w, y + h, z);
  glVertex3f(x, y + h, z);
  glEnd();
}

/* A quad tilted in depth: z from z0 on the left to z1 on the right, and down by dzy. */
static void tilted(float x, float y, float w, float h, float z0, float z1, float dzy) {
  glBegin(GL_QUADS);
  glVertex3f(x, y, z0);
  glVertex3f(x + w, y, z1);
  glVertex3f(x + w, y + h, z1 + dzy);
  glVertex3f(x, y + h, z0 + dzy);
  glEnd();
}

int main(int argc, char** argv) {
  static const GLenum modes[3] = {GL_FILL, GL_LINE, GL_POINT};
  GLfloat f = 0, depth[3];
  int over, a, b, i = 0;
  conf_init(argc, argv, 220, 160);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 220, 0, 160, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_FLAT);
  glLineWidth(4);
  glPointSize(4);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_POLYGON_OFFSET_LINE);
  glEnable(GL_POLYGON_OFFSET_POINT);
  conf_value("enabled_line", glIsEnabled(GL_POLYGON_OFFSET_LINE));

  /* Rows 0-1: blue behind (units +1), then in front (units -1), 9 mode pairs each. */
  for (over = 0; over < 2; ++over)
    for (a = 0; a < 3; ++a)
      for (b = 0; b < 3; ++b, ++i) {
        const float x = 4.0f + 24 * (float)(i % 9), y = 4.0f + 24 * (float)(i / 9);
        glPolygonOffset(0, 0);
        glColor3f(1, 0, 0);
        glPolygonMode(GL_FRONT_AND_BACK, modes[a]);
        rect(x, y, 16, 16, 0.125f);
        glPolygonOffset(0, over ? -1.0f : 1.0f);
        glColor3f(0, 0, 1);
        glPolygonMode(GL_FRONT_AND_BACK, modes[b]);
        rect(x, y, 16, 16, 0.125f);
      }
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

  /* Row 2: tilted quads, the second pulled in front by its slope (factor -1, -2) or
   * pushed behind (factor 1.5), units 0. */
  {
    static const float factors[4] = {-1, -2, 1.5f, -1};
    for (a = 0; a < 4; ++a) {
      const float x = 4.0f + 52 * (float)a;
      const float dz = a == 3 ? 0.0f : 0.6f, dzy = a == 3 ? -0.5f : 0.2f * (float)a;
      glPolygonOffset(0, 0);
      glColor3f(1, 1, 0);
      tilted(x, 56, 44, 40, -0.3f, -0.3f + dz, dzy);
      glPolygonOffset(factors[a], 0);
      glColor3f(0, 1, 0);
      tilted(x, 56, 44, 40, -0.3f, -0.3f + dz, dzy);
    }
  }

  /* Row 3: flat quads offset by units 1000 and -1000 (and none); their depths read back. */
  glDepthFunc(GL_ALWAYS);
  for (a = 0; a < 3; ++a) {
    glPolygonOffset(0, a == 0 ? 0.0f : a == 1 ? 1000.0f : -1000.0f);
    glColor3f(0.3f * (float)a, 0.5f, 1);
    rect(4.0f + 30 * (float)a, 110, 24, 24, 0.25f);
  }
  for (a = 0; a < 3; ++a) glReadPixels(16 + 30 * a, 122, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth[a]);
  conf_value("depth_plain", depth[0]);
  conf_value("depth_units_behind", depth[1] - depth[0]);
  conf_value("depth_units_front", depth[0] - depth[2]);

  glGetFloatv(GL_POLYGON_OFFSET_UNITS, &f);
  conf_value("units", f);
  glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &f);
  conf_value("factor", f);
  glBegin(GL_TRIANGLES);
  glPolygonOffset(1, 1);
  glEnd();
  conf_value("offset_in_begin", glGetError());
  conf_frame("polyoffset");
  return conf_end();
}
