/* GL lighting: several lights (directional and positional, attenuation, spot), the
 * light model (ambient, two-sided, local viewer), materials, colour material, flat and
 * smooth shading of a lit sphere-like mesh and a plane seen from both sides. */
#include <math.h>

#include "harness.h"

static void sphere(float radius, int slices, int stacks) {
  int i, j;
  for (i = 0; i < stacks; ++i) {
    const float a0 = 3.14159265f * (-0.5f + (float)i / stacks), a1 = 3.14159265f * (-0.5f + (float)(i + 1) / stacks);
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= slices; ++j) {
      const float b = 6.2831853f * j / slices;
      const float x = cosf(b), y = sinf(b);
      glNormal3f(x * cosf(a1), y * cosf(a1), sinf(a1));
      glVertex3f(radius * x * cosf(a1), radius * y * cosf(a1), radius * sinf(a1));
      glNormal3f(x * cosf(a0), y * cosf(a0), sinf(a0));
      glVertex3f(radius * x * cosf(a0), radius * y * cosf(a0), radius * sinf(a0));
    }
    glEnd();
  }
}

static void plane(int n) {
  int i, j;
  for (i = 0; i < n; ++i) {
    glBegin(GL_TRIANGLE_STRIP);
    for (j = 0; j <= n; ++j) {
      glNormal3f(0, 0, 1);
      glVertex3f(-1 + 2.0f * j / n, -1 + 2.0f * (i + 1) / n, 0);
      glVertex3f(-1 + 2.0f * j / n, -1 + 2.0f * i / n, 0);
    }
    glEnd();
  }
}

int main(int argc, char** argv) {
  const GLfloat white[4] = {1, 1, 1, 1}, red[4] = {1, 0.2f, 0.2f, 1}, blue[4] = {0.2f, 0.3f, 1, 1};
  const GLfloat dir[4] = {0.5f, 0.7f, 1, 0}, point_pos[4] = {-2, 1, 2, 1}, spot_pos[4] = {0, 0, 3, 1};
  const GLfloat spot_dir[3] = {0, 0, -1}, dim[4] = {0.1f, 0.1f, 0.1f, 1};
  int frame;
  conf_init(argc, argv, 200, 150);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40, 200.0 / 150.0, 1, 20);
  glMatrixMode(GL_MODELVIEW);

  for (frame = 0; frame < 4; ++frame) {
    char name[32];
    glClearColor(0.05f, 0.05f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    /* Lights are placed in eye space (identity modelview) except light 2, which moves
     * with the scene. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, frame == 3 ? dim : white);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_POSITION, point_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, red);
    glLightfv(GL_LIGHT1, GL_SPECULAR, white);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.5f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    glTranslatef(0, 0, -6);
    if (frame >= 1) {
      glEnable(GL_LIGHT2);
      glLightfv(GL_LIGHT2, GL_POSITION, spot_pos);
      glLightfv(GL_LIGHT2, GL_DIFFUSE, blue);
      glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, spot_dir);
      glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 25);
      glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 8);
    } else {
      glDisable(GL_LIGHT2);
    }
    {
      const GLfloat amb[4] = {0.1f, 0.15f, 0.1f, 1};
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
      glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, frame == 2);
      glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, frame >= 2);
    }
    glShadeModel(frame == 1 ? GL_FLAT : GL_SMOOTH);

    /* Left: a sphere with a shiny material. */
    {
      const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1}, dif[4] = {0.8f, 0.7f, 0.5f, 1}, spec[4] = {0.9f, 0.9f, 0.9f, 1};
      const GLfloat emis[4] = {0.05f, 0, 0.05f, 1};
      glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
      glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
      glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emis);
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
    }
    glPushMatrix();
    glTranslatef(-1.2f, 0, 0);
    glRotatef(20.0f * frame, 0, 1, 0);
    sphere(0.9f, 24, 16);
    glPopMatrix();

    /* Right: a scaled sphere with colour material (diffuse from glColor), normals
     * renormalised. */
    glEnable(frame == 3 ? GL_RESCALE_NORMAL : GL_NORMALIZE); /* a uniform scale: both give unit normals */
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, frame == 3 ? GL_AMBIENT_AND_DIFFUSE : GL_DIFFUSE);
    glColor3f(0.3f, 0.9f, 0.4f);
    glPushMatrix();
    glTranslatef(1.2f, 0.4f, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    sphere(1.2f, 20, 12);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_NORMALIZE);
    glDisable(GL_RESCALE_NORMAL);

    /* Bottom: a plane tilted so that its back shows in two frames (two-sided lighting),
     * with a different back material. */
    {
      const GLfloat back[4] = {0.9f, 0.2f, 0.9f, 1}, front[4] = {0.6f, 0.6f, 0.6f, 1}, none[4] = {0, 0, 0, 1};
      glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
      glMaterialfv(GL_BACK, GL_DIFFUSE, back);
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
      glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, none);
    }
    glPushMatrix();
    glTranslatef(0, -1.3f, -0.5f);
    glRotatef(frame >= 2 ? 100.0f : -70.0f, 1, 0, 0);
    glScalef(1.5f, 0.8f, 1);
    plane(8);
    glPopMatrix();
    snprintf(name, sizeof name, "lit%d", frame);
    conf_frame(name);
  }
  return conf_end();
}
