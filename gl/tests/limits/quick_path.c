/* pGL's quick path (gl/src/context.hpp: independent triangles under the usual lighting,
 * glBegin(GL_TRIANGLES) and glDrawElements(GL_TRIANGLES), taken without Vertex records)
 * against its general path, byte for byte: each scene is drawn once as a program draws
 * it, and once inside glNewList(GL_COMPILE_AND_EXECUTE), where pGL takes the general
 * path (no quick path while a list is compiled), into the same framebuffer. The scenes:
 * smooth and flat shading; back, front, both and no faces culled, either front face;
 * triangles crossing the eye plane (facing from the clip-space determinant); a
 * glMaterial between a triangle's vertices (leaving one or two lit vertices for the next
 * run, after a first glDrawElements of 3073 indices); more vertices than one run (3072) and a
 * count that is not a multiple of 3; glDrawElements with vertices shared inside and
 * across runs, a stride, a disabled normal array and an index past the arrays' cache.
 * Mesa is not needed: the two paths must agree exactly, which a wrong facing, culling,
 * flat colour, batch or shared vertex breaks. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 160
#define H 120
#define COLS 40
#define ROWS 30
#define VERTS ((ROWS + 1) * (COLS + 1))

/* Positions and normals interleaved with a stride (7 floats: x y z, pad, nx ny nz). */
static float mesh[VERTS][7];
static unsigned mesh_index[ROWS * COLS * 6 + 2];
static int index_count;

static void make_mesh(void) {
  int i, j, k = 0;
  for (i = 0; i <= ROWS; ++i)
    for (j = 0; j <= COLS; ++j) {
      const float th = 3.14159265f * i / ROWS, ph = 6.2831853f * j / COLS;
      float* v = mesh[i * (COLS + 1) + j];
      v[4] = sinf(th) * cosf(ph), v[5] = cosf(th), v[6] = sinf(th) * sinf(ph);
      v[0] = 1.5f * v[4], v[1] = 1.5f * v[5], v[2] = 1.5f * v[6], v[3] = 0;
    }
  for (i = 0; i < ROWS; ++i)
    for (j = 0; j < COLS; ++j) {
      const unsigned a = i * (COLS + 1) + j, b = a + 1, c = a + COLS + 1, d = c + 1;
      mesh_index[k++] = a, mesh_index[k++] = c, mesh_index[k++] = b;
      mesh_index[k++] = b, mesh_index[k++] = c, mesh_index[k++] = d;
    }
  mesh_index[k++] = 5, mesh_index[k++] = 6; /* two left over: dropped */
  index_count = k;
}

/* Immediate mode: every triangle of the mesh, a glMaterial between the first and second
 * vertex of triangle 1500 (past the first run), and one vertex left over. */
static void immediate(int material_inside) {
  static const GLfloat red[4] = {0.9f, 0.2f, 0.1f, 1}, blue[4] = {0.2f, 0.3f, 0.9f, 1};
  int k;
  glBegin(GL_TRIANGLES);
  for (k = 0; k < ROWS * COLS * 6; ++k) {
    /* (After a triangle's second vertex: two lit vertices wait for the next run.) */
    if (material_inside && k == 2) glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    if (material_inside && k == 3 * 1500 + 1) glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glNormal3fv(&mesh[mesh_index[k]][4]);
    glVertex3fv(mesh[mesh_index[k]]);
  }
  glNormal3f(0, 0, 1);
  glVertex3f(0, 0, 0);
  glEnd();
}

static void elements(int normals, int count) {
  glVertexPointer(3, GL_FLOAT, sizeof mesh[0], mesh);
  glNormalPointer(GL_FLOAT, sizeof mesh[0], &mesh[0][4]);
  glEnableClientState(GL_VERTEX_ARRAY);
  if (normals) glEnableClientState(GL_NORMAL_ARRAY);
  glNormal3f(0.3f, 0.4f, 0.866f);
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, mesh_index);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
}

static int failures = 0;
static unsigned char clear_px[4]; /* the clear colour as the buffer holds it */

/* Does the buffer hold anything but the clear colour? */
static int drawn(const unsigned char* buffer) {
  int i;
  for (i = 0; i < W * H * 4; i += 4)
    if (memcmp(buffer + i, clear_px, 4)) return 1;
  return 0;
}

static void materials(void) {
  static const GLfloat grey[4] = {0.8f, 0.7f, 0.6f, 1}, spec[4] = {0.6f, 0.6f, 0.6f, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT, GL_SHININESS, 12);
}

/* Draws scene `s` both ways and compares; returns whether anything was drawn. (Seen
 * from inside the sphere, every triangle of it faces one way: one culling state draws
 * nothing there.) */
static int check(const char* what, int s, unsigned char* buffer, unsigned char* first, int may_be_empty) {
  int pass;
  for (pass = 0; pass < 2; ++pass) {
    materials(); /* (scene 1 changes the material inside glBegin/glEnd) */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (pass == 1) glNewList(1, GL_COMPILE_AND_EXECUTE);
    if (s == 0) immediate(0);
    else if (s == 1) immediate(1);
    else if (s == 4) elements(1, 3073), immediate(1); /* (the context's first quick draws) */
    else elements(s == 2, index_count);
    if (pass == 1) glEndList();
    glFinish();
    if (glGetError() != GL_NO_ERROR) {
      fprintf(stderr, "quick_path: %s: a GL error\n", what);
      ++failures;
    }
    if (pass == 0) memcpy(first, buffer, (size_t)W * H * 4);
  }
  if (memcmp(first, buffer, (size_t)W * H * 4)) {
    int i, differ = 0;
    for (i = 0; i < W * H * 4; ++i) differ += first[i] != buffer[i];
    fprintf(stderr, "quick_path: %s: %d bytes differ from the general path\n", what, differ);
    ++failures;
  } else if (!drawn(buffer) && !may_be_empty) { /* (or the comparison says nothing) */
    fprintf(stderr, "quick_path: %s: nothing drawn\n", what);
    ++failures;
  }
  return drawn(buffer);
}

int main(void) {
  static const GLenum culls[4] = {0, GL_BACK, GL_FRONT, GL_FRONT_AND_BACK};
  static const GLfloat light[4] = {0.4f, 0.6f, 1, 0}, spec[4] = {0.6f, 0.6f, 0.6f, 1};
  unsigned char* buffer = malloc((size_t)W * H * 4);
  unsigned char* first = malloc((size_t)W * H * 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  int s, c, f, shade, near, drawn_near = 0;
  if (!buffer || !first || !ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 2;
  make_mesh();
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  memcpy(clear_px, buffer, 4);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.1, 0.1, -0.075, 0.075, 0.1, 20);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0, 0, -5);
  check("first draws: 3073 elements, then a run after two lit vertices", 4, buffer, first, 0);
  for (near = 0; near < 2; ++near)
    for (shade = 0; shade < 2; ++shade)
      for (c = 0; c < 4; ++c)
        for (f = 0; f < 2; ++f)
          for (s = 0; s < 4; ++s) {
            char what[96];
            if (c == 3 && s > 0) continue; /* (everything culled: nothing drawn) */
            materials();
            glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
            if (culls[c]) glEnable(GL_CULL_FACE), glCullFace(culls[c]);
            else glDisable(GL_CULL_FACE);
            glFrontFace(f ? GL_CW : GL_CCW);
            glLoadIdentity();
            /* Far: the whole sphere in view. Near: the eye inside it, w < 0 behind. */
            glTranslatef(0.3f, -0.2f, near ? -0.5f : -5);
            glRotatef(30, 0.3f, 1, 0.1f);
            snprintf(what, sizeof what, "scene %d, %s, %s, cull %d, front face %s", s, near ? "near" : "far",
                     shade ? "flat" : "smooth", c, f ? "cw" : "ccw");
            if (c == 3) {
              /* Everything culled: both paths leave the clear colour. */
              glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
              immediate(0);
              glFinish();
              if (drawn(buffer)) {
                fprintf(stderr, "quick_path: %s: drew a culled triangle\n", what);
                ++failures;
              }
              continue;
            }
            drawn_near += check(what, s, buffer, first, near) && near;
          }
  if (drawn_near < 16) {
    fprintf(stderr, "quick_path: only %d scenes from inside the sphere drew anything\n", drawn_near);
    ++failures;
  }
  OSMesaDestroyContext(ctx);
  free(buffer);
  free(first);
  if (failures) return 1;
  printf("quick_path: the quick and general paths drew the same bytes\n");
  return 0;
}
