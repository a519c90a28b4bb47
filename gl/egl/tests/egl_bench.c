/* The same headless EGL program on whichever EGL vendor libEGL is pointed at: a lit,
 * depth-tested sphere of 2 x 256 x 128 triangles in immediate mode, cleared each frame,
 * glFinish, in a WIDTHxHEIGHT pbuffer; prints the median frame time of FRAMES frames
 * (after one to warm up). Not a test: compare Velocity's vendor with Mesa's, e.g.
 *   __EGL_VENDOR_LIBRARY_FILENAMES=build/gl/egl/60_velocity.json egl_bench 30 1920 1080
 *   __EGL_VENDOR_LIBRARY_FILENAMES=/usr/share/glvnd/egl_vendor.d/50_mesa.json egl_bench 30 1920 1080 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static void sphere(void) {
  const int slices = 256, stacks = 128;
  for (int j = 0; j < stacks; ++j) {
    const double a0 = M_PI * j / stacks - M_PI / 2, a1 = M_PI * (j + 1) / stacks - M_PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= slices; ++i) {
      const double b = 2 * M_PI * i / slices;
      glNormal3d(cos(a1) * cos(b), sin(a1), cos(a1) * sin(b));
      glVertex3d(cos(a1) * cos(b), sin(a1), cos(a1) * sin(b));
      glNormal3d(cos(a0) * cos(b), sin(a0), cos(a0) * sin(b));
      glVertex3d(cos(a0) * cos(b), sin(a0), cos(a0) * sin(b));
    }
    glEnd();
  }
}

int main(int argc, char** argv) {
  const int frames = argc > 1 ? atoi(argv[1]) : 30;
  const int width = argc > 3 ? atoi(argv[2]) : 1920, height = argc > 3 ? atoi(argv[3]) : 1080;
  if (frames < 1 || frames > 10000 || width < 1 || height < 1) return 2;
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (!eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) return fprintf(stderr, "no EGL display\n"), 1;
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_DEPTH_SIZE, 24,
                         EGL_NONE};
  EGLConfig config;
  EGLint n = 0;
  const EGLint size[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  if (!eglChooseConfig(dpy, want, &config, 1, &n) || n < 1) return fprintf(stderr, "no configuration\n"), 1;
  EGLSurface pbuffer = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (!pbuffer || !ctx || !eglMakeCurrent(dpy, pbuffer, pbuffer, ctx)) return fprintf(stderr, "no context\n"), 1;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.16 * width / height, 0.16 * width / height, -0.16, 0.16, 0.5, 10);
  glMatrixMode(GL_MODELVIEW);
  double* ms = malloc(sizeof(double) * (size_t)frames);
  for (int f = -1; f < frames; ++f) {
    const double t0 = now();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslated(0, 0, -3);
    glRotated(f * 3.0, 0.3, 1, 0);
    sphere();
    glFinish();
    if (f >= 0) ms[f] = 1e3 * (now() - t0);
  }
  qsort(ms, (size_t)frames, sizeof(double), by_value);
  printf("%s: %s, %dx%d, %d frames of %d triangles: median %.2f ms\n", eglQueryString(dpy, EGL_VENDOR),
         (const char*)glGetString(GL_RENDERER), width, height, frames, 2 * 256 * 128, ms[frames / 2]);
  free(ms);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglTerminate(dpy);
  return 0;
}
