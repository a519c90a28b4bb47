/* pGL's benchmark (not a test): one C program built against Velocity (gl_bench) and
 * against Mesa's OSMesa (gl_bench_mesa), timing whole frames — clear, draw, glFinish —
 * of the same GL calls. scripts/bench_gl.sh runs both and prints the ratios.
 *
 *   gl_bench SCENE WIDTHxHEIGHT FRAMES [OUT.ppm]
 *   SCENE: gears            three lit gears from display lists (quad strips)
 *          mesh-immediate   a lit 100,352-triangle sphere, glBegin/glNormal/glVertex
 *          mesh-arrays      the same mesh through glDrawElements (vertex arrays)
 * Prints: "scene=... size=... frames=... median_ms=..."; with OUT.ppm, the last frame's
 * colour goes there too (to compare two builds' images byte for byte). */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SEGS 224 /* 224 x 224 x 2 = 100,352 triangles */

static float* positions;
static float* normals;
static unsigned* indices;
static int index_count;

static void make_mesh(void) {
  int i, j, k = 0;
  const int rings = SEGS / 2 + 1, cols = 2 * SEGS + 1;
  positions = malloc(sizeof(float) * 3 * rings * cols);
  normals = malloc(sizeof(float) * 3 * rings * cols);
  indices = malloc(sizeof(unsigned) * 6 * (rings - 1) * (cols - 1));
  for (i = 0; i < rings; ++i)
    for (j = 0; j < cols; ++j) {
      const float th = 3.14159265f * i / (rings - 1), ph = 6.2831853f * j / (cols - 1);
      float* p = positions + 3 * (i * cols + j);
      float* n = normals + 3 * (i * cols + j);
      n[0] = sinf(th) * cosf(ph), n[1] = cosf(th), n[2] = sinf(th) * sinf(ph);
      p[0] = n[0], p[1] = n[1], p[2] = n[2];
    }
  for (i = 0; i + 1 < rings; ++i)
    for (j = 0; j + 1 < cols; ++j) {
      const unsigned a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
      indices[k++] = a, indices[k++] = c, indices[k++] = b;
      indices[k++] = b, indices[k++] = c, indices[k++] = d;
    }
  index_count = k;
}

static void gear(float r0, float r1, float r2, float width, int teeth) {
  const float step = 6.2831853f / teeth, q = step / 4, half = width / 2;
  int i;
  glShadeModel(GL_FLAT);
  for (i = 0; i < 2; ++i) {
    const float z = i ? -half : half;
    int k;
    glNormal3f(0, 0, i ? -1.0f : 1.0f);
    glBegin(GL_QUAD_STRIP);
    for (k = 0; k <= teeth; ++k) {
      const float a = k * step;
      glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
      glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
    }
    glEnd();
    glBegin(GL_QUADS);
    for (k = 0; k < teeth; ++k) {
      const float a = k * step;
      glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
      glVertex3f(r2 * cosf(a + q), r2 * sinf(a + q), z);
      glVertex3f(r2 * cosf(a + 2 * q), r2 * sinf(a + 2 * q), z);
      glVertex3f(r1 * cosf(a + 3 * q), r1 * sinf(a + 3 * q), z);
    }
    glEnd();
  }
  glBegin(GL_QUAD_STRIP);
  for (i = 0; i <= teeth * 4; ++i) {
    const float a = i * q;
    const float r = (i % 4 == 1 || i % 4 == 2) ? r2 : r1;
    glNormal3f(cosf(a), sinf(a), 0);
    glVertex3f(r * cosf(a), r * sinf(a), half);
    glVertex3f(r * cosf(a), r * sinf(a), -half);
  }
  glEnd();
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

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int compare(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

int main(int argc, char** argv) {
  const GLfloat light[4] = {5, 5, 10, 0}, red[4] = {0.8f, 0.1f, 0, 1}, green[4] = {0, 0.8f, 0.2f, 1};
  const GLfloat blue[4] = {0.2f, 0.2f, 1, 1}, grey[4] = {0.8f, 0.7f, 0.6f, 1};
  int w = 1920, h = 1080, frames = 30, f, mode;
  GLuint lists = 0;
  double* times;
  unsigned char* buffer;
  OSMesaContext ctx;
  if (argc < 2 || (strcmp(argv[1], "gears") && strcmp(argv[1], "mesh-immediate") && strcmp(argv[1], "mesh-arrays"))) {
    fprintf(stderr, "usage: %s gears|mesh-immediate|mesh-arrays [WxH] [FRAMES]\n", argv[0]);
    return 2;
  }
  mode = !strcmp(argv[1], "gears") ? 0 : !strcmp(argv[1], "mesh-immediate") ? 1 : 2;
  if (argc > 2 && sscanf(argv[2], "%dx%d", &w, &h) != 2) return 2;
  if (argc > 3) frames = atoi(argv[3]);
  if (w < 1 || h < 1 || w > 8192 || h > 8192 || frames < 1 || frames > 10000) return 2;
  ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  buffer = malloc((size_t)w * h * 4);
  times = malloc(sizeof(double) * frames);
  if (!ctx || !buffer || !times || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, w, h)) return 1;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, (double)w / h, 1, 100);
  glMatrixMode(GL_MODELVIEW);
  if (mode == 0) {
    lists = glGenLists(3);
    glNewList(lists, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    gear(1.0f, 3.0f, 4.0f, 1.0f, 20);
    glEndList();
    glNewList(lists + 1, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    gear(0.5f, 1.5f, 2.5f, 2.0f, 10);
    glEndList();
    glNewList(lists + 2, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    gear(1.3f, 1.5f, 2.5f, 0.5f, 10);
    glEndList();
  } else {
    make_mesh();
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
  }
  for (f = 0; f < frames; ++f) {
    const double t0 = now_ms();
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    if (mode == 0) {
      glTranslatef(0, 0, -20);
      glRotatef(20, 1, 0, 0);
      glRotatef(30 + f, 0, 1, 0);
      glPushMatrix();
      glTranslatef(-3, -2, 0);
      glRotatef(2.0f * f, 0, 0, 1);
      glCallList(lists);
      glPopMatrix();
      glPushMatrix();
      glTranslatef(3.1f, -2, 0);
      glRotatef(-4.0f * f - 9, 0, 0, 1);
      glCallList(lists + 1);
      glPopMatrix();
      glPushMatrix();
      glTranslatef(-3.1f, 4.2f, 0);
      glRotatef(-4.0f * f - 25, 0, 0, 1);
      glCallList(lists + 2);
      glPopMatrix();
    } else {
      glTranslatef(0, 0, -3);
      glRotatef(360.0f * f / frames, 0, 1, 0);
      if (mode == 2) {
        glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, indices);
      } else {
        int k;
        glBegin(GL_TRIANGLES);
        for (k = 0; k < index_count; ++k) {
          glNormal3fv(normals + 3 * indices[k]);
          glVertex3fv(positions + 3 * indices[k]);
        }
        glEnd();
      }
    }
    glFinish();
    times[f] = now_ms() - t0;
  }
  if (argc > 4) {
    FILE* out = fopen(argv[4], "wb");
    int y;
    if (!out) return 1;
    fprintf(out, "P6\n%d %d\n255\n", w, h);
    for (y = h - 1; y >= 0; --y) /* the buffer's rows are bottom first */
      for (f = 0; f < w; ++f) fwrite(buffer + 4 * ((size_t)y * w + f), 1, 3, out);
    if (fclose(out)) return 1;
  }
  qsort(times, frames, sizeof(double), compare);
  printf("scene=%s size=%dx%d frames=%d median_ms=%.2f\n", argv[1], w, h, frames, times[frames / 2]);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
  free(buffer);
  free(times);
  return 0;
}
