/* Gears, written for this project: three lit gears, each a display list of quad strips
 * and quads (faces, teeth, outer and inner walls) with flat shading, spun over frames. */
#include <math.h>

#include "harness.h"

/* A gear of `teeth` teeth between radii r0 (hole) and r1 (root), teeth reaching r2,
 * `width` thick, centred on z = 0. */
static void gear(float r0, float r1, float r2, float width, int teeth) {
  const float pi = 3.14159265f, half = width * 0.5f;
  const float step = 2 * pi / teeth, q = step / 4;
  int i;
  glShadeModel(GL_FLAT);
  glNormal3f(0, 0, 1);
  /* Front face (a ring) and the front of the teeth. */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; ++i) {
    const float a = i * step;
    glVertex3f(r0 * cosf(a), r0 * sinf(a), half);
    glVertex3f(r1 * cosf(a), r1 * sinf(a), half);
    if (i < teeth) {
      glVertex3f(r0 * cosf(a), r0 * sinf(a), half);
      glVertex3f(r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q), half);
    }
  }
  glEnd();
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; ++i) {
    const float a = i * step;
    glVertex3f(r1 * cosf(a), r1 * sinf(a), half);
    glVertex3f(r2 * cosf(a + q), r2 * sinf(a + q), half);
    glVertex3f(r2 * cosf(a + 2 * q), r2 * sinf(a + 2 * q), half);
    glVertex3f(r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q), half);
  }
  glEnd();
  /* Back face and the back of the teeth. */
  glNormal3f(0, 0, -1);
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; ++i) {
    const float a = i * step;
    glVertex3f(r1 * cosf(a), r1 * sinf(a), -half);
    glVertex3f(r0 * cosf(a), r0 * sinf(a), -half);
    if (i < teeth) {
      glVertex3f(r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q), -half);
      glVertex3f(r0 * cosf(a), r0 * sinf(a), -half);
    }
  }
  glEnd();
  glBegin(GL_QUADS);
  for (i = 0; i < teeth; ++i) {
    const float a = i * step;
    glVertex3f(r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q), -half);
    glVertex3f(r2 * cosf(a + 2 * q), r2 * sinf(a + 2 * q), -half);
    glVertex3f(r2 * cosf(a + q), r2 * sinf(a + q), -half);
    glVertex3f(r1 * cosf(a), r1 * sinf(a), -half);
  }
  glEnd();
  /* The outside: tooth flanks, tops and the roots between teeth. */
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i < teeth; ++i) {
    const float a = i * step;
    const float pts[4][2] = {{r1 * cosf(a), r1 * sinf(a)},
                             {r2 * cosf(a + q), r2 * sinf(a + q)},
                             {r2 * cosf(a + 2 * q), r2 * sinf(a + 2 * q)},
                             {r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q)}};
    int k;
    for (k = 0; k < 4; ++k) {
      const float* p = pts[k];
      const float* n = pts[(k + 1) % 4];
      float dx = n[0] - p[0], dy = n[1] - p[1];
      const float len = sqrtf(dx * dx + dy * dy);
      if (k == 3) {
        const float b = (i + 1) * step;
        dx = r1 * cosf(b) - p[0], dy = r1 * sinf(b) - p[1];
      }
      glVertex3f(p[0], p[1], half);
      glVertex3f(p[0], p[1], -half);
      if (len > 0) glNormal3f(dy / len, -dx / len, 0);
    }
  }
  glVertex3f(r1, 0, half);
  glVertex3f(r1, 0, -half);
  glEnd();
  /* The hole's wall, smooth. */
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth; ++i) {
    const float a = i * step;
    glNormal3f(-cosf(a), -sinf(a), 0);
    glVertex3f(r0 * cosf(a), r0 * sinf(a), -half);
    glVertex3f(r0 * cosf(a), r0 * sinf(a), half);
  }
  glEnd();
}

int main(int argc, char** argv) {
  const GLfloat light_pos[4] = {5, 5, 10, 0};
  const GLfloat red[4] = {0.8f, 0.1f, 0, 1}, green[4] = {0, 0.8f, 0.2f, 1}, blue[4] = {0.2f, 0.2f, 1, 1};
  GLuint g1, g2, g3;
  int frame;
  conf_init(argc, argv, 300, 300);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);

  g1 = glGenLists(1);
  glNewList(g1, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
  gear(1.0f, 3.0f, 4.0f, 1.0f, 20);
  glEndList();
  g2 = glGenLists(1);
  glNewList(g2, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  gear(0.5f, 1.5f, 2.5f, 2.0f, 10);
  glEndList();
  g3 = glGenLists(1);
  glNewList(g3, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
  gear(1.3f, 1.5f, 2.5f, 0.5f, 10);
  glEndList();
  glEnable(GL_NORMALIZE);

  glViewport(0, 0, 300, 300);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 5, 60);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -40);

  for (frame = 0; frame < 3; ++frame) {
    const float angle = 7.0f * frame;
    char name[32];
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(20, 1, 0, 0);
    glRotatef(30 + 10.0f * frame, 0, 1, 0);
    glPushMatrix();
    glTranslatef(-3, -2, 0);
    glRotatef(angle, 0, 0, 1);
    glCallList(g1);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(3.1f, -2, 0);
    glRotatef(-2 * angle - 9, 0, 0, 1);
    glCallList(g2);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(-3.1f, 4.2f, 0);
    glRotatef(-2 * angle - 25, 0, 0, 1);
    glCallList(g3);
    glPopMatrix();
    glPopMatrix();
    snprintf(name, sizeof name, "gears%d", frame);
    conf_frame(name);
  }
  return conf_end();
}
