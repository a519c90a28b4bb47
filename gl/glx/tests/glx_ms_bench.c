/* The frame cost of multisample configurations: the same frame (a lit, depth-tested
 * sphere of 2 x 64 x 32 quads in immediate mode, cleared each frame, glFinish) drawn
 * FRAMES times in a WIDTHxHEIGHT pbuffer on the configuration without samples and on
 * those with 4, 9 and 16, with the CPU time of each run (getrusage: every thread of the
 * process) and its ratio to the first. Run with __GLX_VENDOR_LIBRARY_NAME=velocity:
 *   glx_ms_bench [FRAMES [WIDTH HEIGHT]] */
#include <GL/gl.h>
#include <GL/glx.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

static double cpu_seconds(void) {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return (double)u.ru_utime.tv_sec + (double)u.ru_stime.tv_sec + 1e-6 * (double)(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

static void sphere(void) {
  const int slices = 64, stacks = 32;
  int i, j;
  for (j = 0; j < stacks; ++j) {
    const double a0 = M_PI * j / stacks - M_PI / 2, a1 = M_PI * (j + 1) / stacks - M_PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= slices; ++i) {
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
  const int frames = argc > 1 ? atoi(argv[1]) : 50;
  const int w = argc > 3 ? atoi(argv[2]) : 640, h = argc > 3 ? atoi(argv[3]) : 480;
  const int wanted[] = {0, 4, 9, 16};
  double base = 0;
  int k;
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) return 2;
  for (k = 0; k < 4; ++k) {
    const int list[] = {GLX_SAMPLE_BUFFERS, wanted[k] > 0, GLX_SAMPLES, wanted[k], GLX_DEPTH_SIZE, 1, None};
    const int size[] = {GLX_PBUFFER_WIDTH, w, GLX_PBUFFER_HEIGHT, h, None};
    int n = 0, f, samples = -1;
    GLXFBConfig* c = glXChooseFBConfig(dpy, DefaultScreen(dpy), list, &n);
    if (!c || n == 0) return 1;
    GLXPbuffer pb = glXCreatePbuffer(dpy, c[0], size);
    GLXContext ctx = glXCreateNewContext(dpy, c[0], GLX_RGBA_TYPE, NULL, True);
    XFree(c);
    if (!pb || !ctx || !glXMakeContextCurrent(dpy, pb, pb, ctx)) return 1;
    glGetIntegerv(GL_SAMPLES, &samples);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -3);
    glFinish();
    const double t0 = cpu_seconds();
    for (f = 0; f < frames; ++f) {
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glRotatef(3, 0.3f, 1, 0);
      sphere();
      glFinish();
    }
    const double ms = 1000 * (cpu_seconds() - t0) / frames;
    if (k == 0) base = ms;
    printf("GL_SAMPLES %2d: %.2f ms CPU a frame, %.2fx\n", samples, ms, ms / base);
    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, ctx);
    glXDestroyPbuffer(dpy, pb);
  }
  XCloseDisplay(dpy);
  return 0;
}
