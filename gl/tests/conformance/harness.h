/* The conformance programs' harness. Each program in this folder is one C source built
 * twice — against Velocity (gl/include, libvelocity-gl) and against Mesa (the system's
 * <GL/gl.h>, libOSMesa, libGLU) — and run with an output folder: every conf_frame()
 * writes the frame as NAME.ppm, every conf_value() a line "NAME VALUE" to values.txt.
 * compare.cpp then holds the two runs' outputs side by side. */
#ifndef VELOCITY_GL_CONFORMANCE_HARNESS_H
#define VELOCITY_GL_CONFORMANCE_HARNESS_H

#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static OSMesaContext conf_ctx;
static unsigned char* conf_buffer;
static int conf_width, conf_height;
static const char* conf_dir = ".";
static int conf_stencil_bits = 0; /* set before conf_init for a context with a stencil buffer */
static int conf_accum_bits = 0;   /* and with an accumulation buffer */

static void conf_fail(const char* what) {
  fprintf(stderr, "conformance: %s\n", what);
  exit(1);
}

/* An RGBA context with a depth buffer (and conf_stencil_bits of stencil) rendering into
 * a width x height buffer. */
static void conf_init(int argc, char** argv, int width, int height) {
  if (argc > 1) conf_dir = argv[1];
  conf_width = width, conf_height = height;
  conf_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, conf_stencil_bits, conf_accum_bits, NULL);
  if (!conf_ctx) conf_fail("OSMesaCreateContextExt failed");
  conf_buffer = (unsigned char*)calloc((size_t)width * height, 4);
  if (!conf_buffer) conf_fail("out of memory");
  if (!OSMesaMakeCurrent(conf_ctx, conf_buffer, GL_UNSIGNED_BYTE, width, height)) conf_fail("OSMesaMakeCurrent failed");
  {
    char path[1024];
    FILE* f;
    snprintf(path, sizeof path, "%s/values.txt", conf_dir);
    f = fopen(path, "w");
    if (!f) conf_fail("cannot write values.txt");
    fclose(f);
  }
}

/* glFinish, then the buffer (bottom row first, OSMesa's Y_UP) as NAME.ppm, top row first. */
static void conf_frame(const char* name) {
  char path[1024];
  FILE* f;
  int y;
  glFinish();
  snprintf(path, sizeof path, "%s/%s.ppm", conf_dir, name);
  f = fopen(path, "wb");
  if (!f) conf_fail("cannot write a frame");
  fprintf(f, "P6\n%d %d\n255\n", conf_width, conf_height);
  for (y = conf_height - 1; y >= 0; --y) {
    const unsigned char* row = conf_buffer + (size_t)y * conf_width * 4;
    int x;
    for (x = 0; x < conf_width; ++x) fwrite(row + 4 * x, 1, 3, f);
  }
  fclose(f);
}

static void conf_value(const char* name, double value) __attribute__((unused));
static void conf_value(const char* name, double value) {
  char path[1024];
  FILE* f;
  snprintf(path, sizeof path, "%s/values.txt", conf_dir);
  f = fopen(path, "a");
  if (!f) conf_fail("cannot write values.txt");
  fprintf(f, "%s %.6g\n", name, value);
  fclose(f);
}

/* Window coordinates as the projection: one unit a pixel of the conf_init size, origin at
 * the bottom left, for programs that place primitives on exact pixels. */
static void conf_ortho(void) __attribute__((unused));
static void conf_ortho(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, conf_width, 0, conf_height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* An axis-aligned quad at depth z, counter-clockwise from (x0, y0). */
static void conf_quad(float x0, float y0, float x1, float y1, float z) __attribute__((unused));
static void conf_quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

/* The stencil buffer shown as a frame: where a value's low three bits are v, a colour
 * made of v's bits, over the rectangle (0, 0) - (w, h). */
static void conf_show_stencil(const char* name, float w, float h) __attribute__((unused));
static void conf_show_stencil(const char* name, float w, float h) {
  int v;
  glPushAttrib(GL_ENABLE_BIT | GL_STENCIL_BUFFER_BIT | GL_CURRENT_BIT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (v = 0; v < 8; ++v) {
    glStencilFunc(GL_EQUAL, v, 0x07);
    glColor3f((v & 1) ? 1.0f : 0.2f, (v & 2) ? 1.0f : 0.2f, (v & 4) ? 1.0f : 0.2f);
    glRectf(0, 0, w, h);
  }
  glPopAttrib();
  conf_frame(name);
}

static int conf_end(void) {
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(conf_ctx);
  free(conf_buffer);
  return 0;
}

#endif
