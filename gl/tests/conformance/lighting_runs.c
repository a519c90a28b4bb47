/* GL lighting under the usual state — directional lights only, no spot, no local
 * viewer, one side, no colour material, no texture — which pGL transforms and lights a
 * run of vertices at a time (SIMD) rather than one by one: three coloured directional
 * lights with their own ambient, an emissive material with a highlight and without,
 * GL_NORMALIZE under a non-uniform scale, one glBegin of over 3072 vertices (pGL
 * assembles independent triangles in parts), glMaterial between vertices inside
 * glBegin/glEnd (each vertex lit with the material current when it was given), the
 * same mesh through glDrawElements, and flat-shaded quads. */
#include <math.h>

#include "harness.h"

#define COLS 48
#define ROWS 36

static float mesh_position[(ROWS + 1) * (COLS + 1)][3], mesh_normal[(ROWS + 1) * (COLS + 1)][3];
static unsigned mesh_index[ROWS * COLS * 6];

static void make_mesh(void) {
  int i, j, k = 0;
  for (i = 0; i <= ROWS; ++i)
    for (j = 0; j <= COLS; ++j) {
      const float th = 3.14159265f * i / ROWS, ph = 6.2831853f * j / COLS;
      float* n = mesh_normal[i * (COLS + 1) + j];
      float* p = mesh_position[i * (COLS + 1) + j];
      n[0] = sinf(th) * cosf(ph), n[1] = cosf(th), n[2] = sinf(th) * sinf(ph);
      p[0] = n[0], p[1] = n[1], p[2] = n[2];
    }
  for (i = 0; i < ROWS; ++i)
    for (j = 0; j < COLS; ++j) {
      const unsigned a = i * (COLS + 1) + j, b = a + 1, c = a + COLS + 1, d = c + 1;
      mesh_index[k++] = a, mesh_index[k++] = c, mesh_index[k++] = b;
      mesh_index[k++] = b, mesh_index[k++] = c, mesh_index[k++] = d;
    }
}

/* The mesh as independent triangles in one glBegin (10,368 vertices). */
static void mesh_immediate(void) {
  int k;
  glBegin(GL_TRIANGLES);
  for (k = 0; k < ROWS * COLS * 6; ++k) {
    glNormal3fv(mesh_normal[mesh_index[k]]);
    glVertex3fv(mesh_position[mesh_index[k]]);
  }
  glEnd();
}

/* A band of quads whose diffuse colour changes every two columns, by glMaterial
 * between the vertices. */
static void striped_band(void) {
  static const GLfloat stripes[5][4] = {
      {0.9f, 0.1f, 0.1f, 1}, {0.1f, 0.9f, 0.1f, 1}, {0.1f, 0.2f, 0.9f, 1}, {0.9f, 0.9f, 0.1f, 1}, {0.8f, 0.2f, 0.8f, 1}};
  int j;
  glBegin(GL_QUAD_STRIP);
  for (j = 0; j <= 10; ++j) {
    const float x = -1 + 0.2f * j, z = 0.3f * sinf(0.6f * j);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, stripes[(j / 2) % 5]);
    glNormal3f(-0.3f * cosf(0.6f * j), 0, 1);
    glVertex3f(x, 0.35f, z);
    glVertex3f(x, -0.35f, z);
  }
  glEnd();
}

int main(int argc, char** argv) {
  const GLfloat key[4] = {0.5f, 0.7f, 1, 0}, fill[4] = {-1, 0.2f, 0.4f, 0}, rim[4] = {0, -1, 0.3f, 0};
  const GLfloat warm[4] = {1, 0.85f, 0.6f, 1}, cool[4] = {0.2f, 0.3f, 0.9f, 1}, green[4] = {0.1f, 0.6f, 0.2f, 1};
  const GLfloat dim[4] = {0.08f, 0.02f, 0.05f, 1}, none[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1};
  const GLfloat model_ambient[4] = {0.15f, 0.1f, 0.2f, 1};
  int frame;
  make_mesh();
  conf_init(argc, argv, 240, 180);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40, 240.0 / 180.0, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
  glLoadIdentity();
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT1, GL_POSITION, fill);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, cool);
  glLightfv(GL_LIGHT1, GL_AMBIENT, dim);
  glEnable(GL_LIGHT2);
  glLightfv(GL_LIGHT2, GL_POSITION, rim);
  glLightfv(GL_LIGHT2, GL_DIFFUSE, green);
  glLightfv(GL_LIGHT2, GL_SPECULAR, cool);
  glVertexPointer(3, GL_FLOAT, 0, mesh_position);
  glNormalPointer(GL_FLOAT, 0, mesh_normal);

  for (frame = 0; frame < 3; ++frame) {
    char name[32];
    const GLfloat amb[4] = {0.3f, 0.2f, 0.25f, 1}, dif[4] = {0.8f, 0.75f, 0.6f, 1}, spec[4] = {0.7f, 0.7f, 0.7f, 1};
    const GLfloat emis[4] = {0.06f, 0, 0.03f, 1};
    glClearColor(0.05f, 0.05f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0, 0, -6);
    glRotatef(25.0f * frame, 0.3f, 1, 0);
    glShadeModel(frame == 2 ? GL_FLAT : GL_SMOOTH);
    glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, frame == 1 ? none : spec);
    glMaterialfv(GL_FRONT, GL_EMISSION, emis);
    glMaterialf(GL_FRONT, GL_SHININESS, frame == 1 ? 0 : 24);

    /* Left: the mesh in immediate mode, squashed (normals renormalised). (Its
     * triangles wind clockwise seen from outside.) */
    glFrontFace(GL_CW);
    glEnable(GL_NORMALIZE);
    glPushMatrix();
    glTranslatef(-1.3f, 0.5f, 0);
    glScalef(1.1f, 0.7f, 0.9f);
    mesh_immediate();
    glPopMatrix();
    glDisable(GL_NORMALIZE);

    /* Right: the same mesh from the arrays. */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glPushMatrix();
    glTranslatef(1.3f, 0.5f, 0);
    glScalef(0.9f, 0.9f, 0.9f);
    glDrawElements(GL_TRIANGLES, ROWS * COLS * 6, GL_UNSIGNED_INT, mesh_index);
    glPopMatrix();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glFrontFace(GL_CCW);

    /* Bottom: the band whose material changes between its vertices. */
    glPushMatrix();
    glTranslatef(0, -1.35f, 0);
    glScalef(2.2f, 1.4f, 1);
    striped_band();
    glPopMatrix();
    snprintf(name, sizeof name, "runs%d", frame);
    conf_frame(name);
  }
  return conf_end();
}
