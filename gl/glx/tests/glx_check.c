/* The GLX vendor library used as any GLX program uses the system's libGL (this file
 * is built against the system's <GL/glx.h> and libglvnd's libGL, never against pGL):
 * run with __GLX_VENDOR_LIBRARY_NAME=velocity under an X server (glx_test.py).
 * Visuals and FBConfigs say what exists (depth, stencil, alpha, accumulation); a double-buffered
 * window shows at glXSwapBuffers exactly what GL drew, its front buffer drawn into at
 * glFlush, a single-buffered one at glFlush; contexts are created, made current, destroyed and created again;
 * GLX_ARB_create_context gives what pGL is and refuses the rest with X errors;
 * glXGetProcAddress and swap control work; pbuffers hold pixels; misuse gives GLX's
 * errors. Prints "ok ..." per check, exits 1 at the first failure. */
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static Display* dpy;
static int x_errors, last_error;

static int count_errors(Display* d, XErrorEvent* e) {
  (void)d;
  ++x_errors;
  last_error = e->error_code;
  return 0;
}

#define CHECK(cond, ...)                                    \
  do {                                                      \
    if (!(cond)) {                                          \
      printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); \
      printf(__VA_ARGS__);                                  \
      printf("\n");                                         \
      exit(1);                                              \
    }                                                       \
  } while (0)

/* The window's pixel at (x, y), y down, as 0xRRGGBB. */
static unsigned long window_pixel(Window w, int x, int y) {
  XImage* image = XGetImage(dpy, w, x, y, 1, 1, AllPlanes, ZPixmap);
  CHECK(image, "XGetImage");
  const unsigned long p = XGetPixel(image, 0, 0) & 0xffffff;
  XDestroyImage(image);
  return p;
}

static Window open_window(XVisualInfo* vis, int w, int h) {
  XSetWindowAttributes a;
  memset(&a, 0, sizeof a);
  a.colormap = XCreateColormap(dpy, RootWindow(dpy, vis->screen), vis->visual, AllocNone);
  a.background_pixel = 0x808080;
  Window win = XCreateWindow(dpy, RootWindow(dpy, vis->screen), 0, 0, (unsigned)w, (unsigned)h, 0, vis->depth,
                             InputOutput, vis->visual, CWColormap | CWBackPixel, &a);
  XMapWindow(dpy, win);
  XSync(dpy, False);
  return win;
}

/* Blue background, red top-left quarter, green bottom-right quarter (GL's y is up). */
static void draw_quarters(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRecti(0, h / 2, w / 2, h);
  glColor3f(0, 1, 0);
  glRecti(w / 2, 0, w, h / 2);
}

/* Every pixel of the window equals what glReadPixels returns of the frame. */
static void check_window_is_frame(Window win, int w, int h, const unsigned char* frame) {
  XImage* image = XGetImage(dpy, win, 0, 0, (unsigned)w, (unsigned)h, AllPlanes, ZPixmap);
  CHECK(image, "XGetImage");
  int differ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned long p = XGetPixel(image, x, y);
      const unsigned char* f = frame + ((h - 1 - y) * w + x) * 4;
      const unsigned long want = ((unsigned long)f[0] << 16) | ((unsigned long)f[1] << 8) | f[2];
      differ += (p & 0xffffff) != want;
    }
  XDestroyImage(image);
  CHECK(differ == 0, "%d of %d pixels differ from glReadPixels (top-left %06lx, frame %02x%02x%02x)", differ, w * h,
        window_pixel(win, 0, 0), frame[(h - 1) * w * 4], frame[(h - 1) * w * 4 + 1], frame[(h - 1) * w * 4 + 2]);
}

static int config_attribute(GLXFBConfig c, int attribute) {
  int v = -1;
  CHECK(glXGetFBConfigAttrib(dpy, c, attribute, &v) == Success, "attribute 0x%x", attribute);
  return v;
}

/* A scene with edges at every slope: a triangle and a thin line on black, drawn in an
 * ortho projection of 0..40 x 0..24 whatever the viewport. */
static void draw_edges(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 40, 0, 24, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0.25f);
  glVertex2f(3.3f, 2.1f);
  glVertex2f(36.7f, 7.4f);
  glVertex2f(13.2f, 22.6f);
  glEnd();
}

/* GLX_ARB_multisample: configurations with 4, 9 and 16 samples; a context on one draws
 * k x k samples a pixel and reads (and shows) their mean. The oracle: the box filter of
 * the same scene drawn without samples at k times the size. */
static void check_multisample(int screen) {
  const char* extensions = glXQueryExtensionsString(dpy, screen);
  CHECK(extensions && strstr(extensions, "GLX_ARB_multisample"), "GLX_ARB_multisample in %s", extensions);
  int n = 0;
  const int want4[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 2, GLX_DOUBLEBUFFER, True, None};
  GLXFBConfig* c4 = glXChooseFBConfig(dpy, screen, want4, &n);
  CHECK(c4 && n == 3 && config_attribute(c4[0], GLX_SAMPLES) == 4 && config_attribute(c4[0], GLX_SAMPLE_BUFFERS) == 1 &&
            config_attribute(c4[1], GLX_SAMPLES) == 9 && config_attribute(c4[2], GLX_SAMPLES) == 16,
        "%d configs for 2 samples", n);
  const int want6[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 6, None};
  GLXFBConfig* c9 = glXChooseFBConfig(dpy, screen, want6, &n);
  CHECK(c9 && n == 4 && config_attribute(c9[0], GLX_SAMPLES) == 9, "%d configs for 6 samples", n);
  XFree(c9);
  const int want32[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 32, None};
  CHECK(!glXChooseFBConfig(dpy, screen, want32, &n) && n == 0, "32 samples offered");
  int vis_attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 9, None};
  XVisualInfo* vis9 = glXChooseVisual(dpy, screen, vis_attributes);
  int v = 0;
  CHECK(vis9 && glXGetConfig(dpy, vis9, GLX_SAMPLES, &v) == 0 && v == 9, "glXChooseVisual 9 samples: %d", v);
  XFree(vis9);

  {
    /* 16 samples where the sample buffer fits the renderer's 16384 a side; a drawable
     * 6000 wide gets 2 x 2. */
    const int wide_size[] = {GLX_PBUFFER_WIDTH, 6000, GLX_PBUFFER_HEIGHT, 4, None};
    GLXPbuffer wide = glXCreatePbuffer(dpy, c4[2], wide_size);
    GLXContext wide_ctx = glXCreateNewContext(dpy, c4[2], GLX_RGBA_TYPE, NULL, True);
    unsigned char corner[4] = {0, 0, 0, 0};
    GLint samples = 0;
    CHECK(wide && wide_ctx && glXMakeContextCurrent(dpy, wide, wide, wide_ctx), "a 6000-pixel pbuffer");
    glGetIntegerv(GL_SAMPLES, &samples);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(5999, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, corner);
    CHECK(samples == 4 && corner[1] == 255, "6000 wide: GL_SAMPLES %d, green %d", samples, corner[1]);
    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, wide_ctx);
    glXDestroyPbuffer(dpy, wide);
  }
  const GLXFBConfig ms = c4[1];  /* 9 samples: k = 3 */
  const int k = 3, w = 40, h = 24;
  XFree(c4);
  const int plain_list[] = {GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 1, None};
  GLXFBConfig* plain = glXChooseFBConfig(dpy, screen, plain_list, &n);
  CHECK(plain && config_attribute(plain[0], GLX_SAMPLES) == 0, "a configuration without samples");
  /* The oracle: the scene at k times the size, one sample a pixel, box-filtered. */
  const int big_size[] = {GLX_PBUFFER_WIDTH, k * w, GLX_PBUFFER_HEIGHT, k * h, None};
  GLXPbuffer big = glXCreatePbuffer(dpy, plain[0], big_size);
  GLXContext plain_ctx = glXCreateNewContext(dpy, plain[0], GLX_RGBA_TYPE, NULL, True);
  XFree(plain);
  CHECK(big && plain_ctx && glXMakeContextCurrent(dpy, big, big, plain_ctx), "the oracle's pbuffer");
  GLint iv[2] = {-1, -1};
  glGetIntegerv(GL_SAMPLE_BUFFERS, iv);
  glGetIntegerv(GL_SAMPLES, iv + 1);
  CHECK(iv[0] == 0 && iv[1] == 0, "no samples: GL_SAMPLE_BUFFERS %d GL_SAMPLES %d", iv[0], iv[1]);
  draw_edges(k * w, k * h);
  static unsigned char large[3 * 40 * 3 * 24 * 4], want[40 * 24 * 4], got[40 * 24 * 4];
  glReadPixels(0, 0, k * w, k * h, GL_RGBA, GL_UNSIGNED_BYTE, large);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) sum += large[((y * k + j) * k * w + x * k + i) * 4 + c];
        want[(y * w + x) * 4 + c] = (unsigned char)((sum + k * k / 2) / (k * k));
      }

  /* A window on the multisample configuration: drawn, read, swapped. */
  XVisualInfo* mvis = glXGetVisualFromFBConfig(dpy, ms);
  CHECK(mvis, "a visual for the multisample configuration");
  Window mwin = open_window(mvis, w, h);
  GLXContext mctx = glXCreateNewContext(dpy, ms, GLX_RGBA_TYPE, NULL, True);
  CHECK(mctx && glXMakeCurrent(dpy, mwin, mctx), "multisample context");
  glGetIntegerv(GL_SAMPLE_BUFFERS, iv);
  glGetIntegerv(GL_SAMPLES, iv + 1);
  CHECK(iv[0] == 1 && iv[1] == 9, "GL_SAMPLE_BUFFERS %d GL_SAMPLES %d", iv[0], iv[1]);
  draw_edges(w, h);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, got);
  int worst = 0, partial = 0;
  for (int i = 0; i < w * h * 4; ++i) {
    const int d = abs(got[i] - want[i]);
    if (d > worst) worst = d;
    if (i % 4 == 0 && got[i] > 0 && got[i] < 255) ++partial;
  }
  CHECK(worst <= 1, "resolved colour differs from the box filter by %d", worst);
  CHECK(partial >= 40, "%d edge pixels partly covered", partial);
  glXSwapBuffers(dpy, mwin);
  check_window_is_frame(mwin, w, h, got);
  printf("ok multisample: 9 samples, resolved = box filter of 3x the size (%d edge pixels, within %d)\n", partial, worst);

  /* Pixel operations act on every sample of a pixel: a scissored clear, glDrawPixels
   * of colour and depth, read back exactly; depth and stencil read one value a pixel. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(5, 3, 7, 4);
  glClearColor(0.2f, 0.4f, 0.6f, 1);
  glClearStencil(0x5a);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  unsigned char px[4 * 9];
  glReadPixels(4, 2, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, px);
  CHECK(px[0] == got[(2 * w + 4) * 4] && px[4 * 4] == 51 && px[4 * 4 + 1] == 102 && px[4 * 4 + 2] == 153,
        "scissored clear: %d %d %d", px[4 * 4], px[4 * 4 + 1], px[4 * 4 + 2]);
  unsigned char st[12];  /* rows of 3, 4-byte aligned */
  glReadPixels(4, 2, 3, 3, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
  CHECK(st[0] == 0 && st[5] == 0x5a && st[10] == 0x5a, "stencil %d %d %d", st[0], st[5], st[10]);
  const float depths[4] = {0.25f, 0.5f, 0.75f, 0.125f};
  const unsigned char colours[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 99, 199, 255};
  glRasterPos2f(20.25f, 10.25f); /* pixel (20, 10) in draw_edges' projection */
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, colours);
  unsigned char back[16];
  float dback[4];
  glReadPixels(20, 10, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, back);
  CHECK(memcmp(back, colours, 16) == 0, "glDrawPixels colour %d %d %d", back[12], back[13], back[14]);
  glEnable(GL_DEPTH_TEST);  /* (depth is written only with the test on) */
  glDepthFunc(GL_ALWAYS);
  glDrawPixels(2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, depths);  /* (and the raster colour) */
  glDisable(GL_DEPTH_TEST);
  glReadPixels(20, 10, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, dback);
  for (int i = 0; i < 4; ++i) CHECK(fabsf(dback[i] - depths[i]) < 1e-6f, "depth %d: %f", i, dback[i]);
  printf("ok multisample pixel operations: clear, glDrawPixels, depth and stencil reads\n");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, mctx);
  glXDestroyContext(dpy, plain_ctx);
  glXDestroyPbuffer(dpy, big);
  XDestroyWindow(dpy, mwin);
  XFree(mvis);
}

int main(void) {
  dpy = XOpenDisplay(NULL);
  if (!dpy) {
    printf("no X display\n");
    return 2;
  }
  XSetErrorHandler(count_errors);
  const int screen = DefaultScreen(dpy);

  /* --- configurations: what exists, and nothing that does not */
  int n = 0;
  GLXFBConfig* all = glXGetFBConfigs(dpy, screen, &n);
  CHECK(all && n == 10, "%d configs", n);
  XFree(all);
  const int with_stencil[] = {GLX_STENCIL_SIZE, 1, None};
  GLXFBConfig* stencil = glXChooseFBConfig(dpy, screen, with_stencil, &n);
  CHECK(stencil && n == 8 && config_attribute(stencil[0], GLX_STENCIL_SIZE) == 8 &&
            config_attribute(stencil[0], GLX_DEPTH_SIZE) == 24,
        "%d configs with a stencil buffer", n);
  XFree(stencil);
  const int too_much_stencil[] = {GLX_STENCIL_SIZE, 9, None};
  GLXFBConfig* none = glXChooseFBConfig(dpy, screen, too_much_stencil, &n);
  CHECK(!none && n == 0, "a 9-bit stencil buffer is offered");
  const int with_accum[] = {GLX_ACCUM_RED_SIZE, 1, GLX_ACCUM_ALPHA_SIZE, 16, None};
  GLXFBConfig* accum = glXChooseFBConfig(dpy, screen, with_accum, &n);
  CHECK(accum && n == 8 && config_attribute(accum[0], GLX_ACCUM_GREEN_SIZE) == 16 &&
            config_attribute(accum[0], GLX_STENCIL_SIZE) == 8,
        "%d configs with an accumulation buffer", n);
  XFree(accum);
  const int too_much_accum[] = {GLX_ACCUM_BLUE_SIZE, 17, None};
  none = glXChooseFBConfig(dpy, screen, too_much_accum, &n);
  CHECK(!none && n == 0, "a 17-bit accumulation buffer is offered");
  const int wanted[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_DOUBLEBUFFER, True,
                        GLX_RED_SIZE, 8, GLX_ALPHA_SIZE, 1, GLX_DEPTH_SIZE, 16, None};
  GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, wanted, &n);
  CHECK(configs && n == 4 && config_attribute(configs[0], GLX_SAMPLES) == 0, "%d double-buffered configs with depth", n);
  GLXFBConfig config = configs[0];
  XFree(configs);
  CHECK(config_attribute(config, GLX_DEPTH_SIZE) == 24, "depth");
  CHECK(config_attribute(config, GLX_ALPHA_SIZE) == 8, "alpha");
  CHECK(config_attribute(config, GLX_STENCIL_SIZE) == 8, "stencil");
  CHECK(config_attribute(config, GLX_DOUBLEBUFFER) == 1, "double");
  CHECK(config_attribute(config, GLX_VISUAL_ID) != 0, "visual");
  const int single_no_depth[] = {GLX_DOUBLEBUFFER, False, None};
  configs = glXChooseFBConfig(dpy, screen, single_no_depth, &n);
  CHECK(configs && n == 5 && config_attribute(configs[0], GLX_DEPTH_SIZE) == 0, "smaller depth first");
  XFree(configs);
  printf("ok configs: 10, depth 24, stencil 8 and accumulation 16 or none, alpha 8, 4, 9 or 16 samples\n");

  int rgba_only[] = {GLX_RED_SIZE, 1, None};
  CHECK(!glXChooseVisual(dpy, screen, rgba_only), "a colour-index visual");
  int double_depth[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 1, GLX_DEPTH_SIZE, 1, None};
  XVisualInfo* vis = glXChooseVisual(dpy, screen, double_depth);
  CHECK(vis, "glXChooseVisual");
  int v = 0;
  CHECK(glXGetConfig(dpy, vis, GLX_DOUBLEBUFFER, &v) == 0 && v == 1, "GLX_DOUBLEBUFFER");
  CHECK(glXGetConfig(dpy, vis, GLX_DEPTH_SIZE, &v) == 0 && v == 24, "GLX_DEPTH_SIZE");
  CHECK(glXGetConfig(dpy, vis, GLX_STENCIL_SIZE, &v) == 0 && v == 8, "GLX_STENCIL_SIZE");
  CHECK(glXGetConfig(dpy, vis, GLX_USE_GL, &v) == 0 && v == 1, "GLX_USE_GL");
  printf("ok glXChooseVisual, glXGetConfig\n");

  /* --- a double-buffered window: the swap shows exactly the frame */
  const int w = 70, h = 46;
  Window win = open_window(vis, w, h);
  GLXContext ctx = glXCreateContext(dpy, vis, NULL, True);
  CHECK(ctx, "glXCreateContext");
  CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent");
  CHECK(strstr((const char*)glGetString(GL_RENDERER), "Velocity"), "renderer %s", glGetString(GL_RENDERER));
  GLint iv[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, iv);
  CHECK(iv[2] == w && iv[3] == h, "viewport %d %d", iv[2], iv[3]);
  glGetIntegerv(GL_DOUBLEBUFFER, iv);
  CHECK(iv[0] == 1, "GL_DOUBLEBUFFER %d", iv[0]);
  glGetIntegerv(GL_DRAW_BUFFER, iv);
  CHECK(iv[0] == GL_BACK, "GL_DRAW_BUFFER 0x%x", iv[0]);
  glGetIntegerv(GL_DEPTH_BITS, iv);
  CHECK(iv[0] == 24, "GL_DEPTH_BITS %d", iv[0]);
  glGetIntegerv(GL_STENCIL_BITS, iv);
  CHECK(iv[0] == 8, "GL_STENCIL_BITS %d", iv[0]);
  draw_quarters(w, h);
  static unsigned char frame[70 * 46 * 4];
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, frame);
  const unsigned long before = window_pixel(win, 5, 5);
  CHECK(before == 0x808080, "the back buffer showed before the swap: %06lx", before);
  glXSwapBuffers(dpy, win);
  check_window_is_frame(win, w, h, frame);
  CHECK(window_pixel(win, 5, 5) == 0xff0000 && window_pixel(win, w - 5, h - 5) == 0x00ff00 &&
            window_pixel(win, w - 5, 5) == 0x0000ff,
        "quarters");
  printf("ok double-buffered window: shown at glXSwapBuffers, exactly the frame\n");

  /* --- front and back buffers: drawing into the front shows at glFlush and leaves the
   * back alone; the swap copies the back to the front; each reads back */
  unsigned char fb[4] = {0, 0, 0, 0};
  glDrawBuffer(GL_FRONT);
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  CHECK(window_pixel(win, 5, 5) == 0xff00ff, "the front drawn, shown at glFlush: %06lx", window_pixel(win, 5, 5));
  glReadBuffer(GL_BACK);
  glReadPixels(5, h - 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, fb);
  CHECK(fb[0] == 255 && fb[1] == 0 && fb[2] == 0, "the back kept its frame: %d %d %d", fb[0], fb[1], fb[2]);
  glReadBuffer(GL_FRONT);
  glReadPixels(5, h - 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, fb);
  CHECK(fb[0] == 255 && fb[1] == 0 && fb[2] == 255, "the front reads back: %d %d %d", fb[0], fb[1], fb[2]);
  glDrawBuffer(GL_BACK);
  glClearColor(0, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  CHECK(window_pixel(win, 5, 5) == 0xff00ff, "the back showed before the swap: %06lx", window_pixel(win, 5, 5));
  glXSwapBuffers(dpy, win);
  CHECK(window_pixel(win, 5, 5) == 0x00ffff, "the swap shows the back: %06lx", window_pixel(win, 5, 5));
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, fb);
  CHECK(fb[0] == 0 && fb[1] == 255 && fb[2] == 255, "the front is the back after the swap: %d %d %d", fb[0], fb[1], fb[2]);
  glDrawBuffer(GL_FRONT_AND_BACK);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 0, 1);
  glRecti(0, 0, 10, 10);
  glFlush();
  CHECK(window_pixel(win, 20, 20) == 0xffff00 && window_pixel(win, 5, h - 5) == 0x0000ff, "both drawn, the front shown");
  glReadBuffer(GL_BACK);
  glReadPixels(20, 20, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, fb);
  CHECK(fb[0] == 255 && fb[1] == 255 && fb[2] == 0, "both drawn, the back: %d %d %d", fb[0], fb[1], fb[2]);
  glGetIntegerv(GL_DRAW_BUFFER, iv);
  CHECK(iv[0] == GL_FRONT_AND_BACK, "GL_DRAW_BUFFER 0x%x", iv[0]);
  glDrawBuffer(GL_BACK);
  CHECK(glGetError() == GL_NO_ERROR, "errors");
  printf("ok front and back buffers: the front shown at glFlush, the swap a copy\n");

  /* --- destroyed and created again, from an FBConfig this time */
  CHECK(glXMakeCurrent(dpy, None, NULL), "release");
  glXDestroyContext(dpy, ctx);
  ctx = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, NULL, True);
  CHECK(ctx, "glXCreateNewContext");
  CHECK(glXMakeContextCurrent(dpy, win, win, ctx), "glXMakeContextCurrent");
  CHECK(glXGetCurrentContext() == ctx && glXGetCurrentDrawable() == win, "current");
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, win);
  CHECK(window_pixel(win, 5, 5) == 0xffff00, "second context: %06lx", window_pixel(win, 5, 5));
  printf("ok contexts destroyed and created again\n");

  /* --- glXGetProcAddress: GL and GLX functions */
  PFNGLXCREATECONTEXTATTRIBSARBPROC create_attribs =
      (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddress((const GLubyte*)"glXCreateContextAttribsARB");
  void (*clear_color)(GLfloat, GLfloat, GLfloat, GLfloat) =
      (void (*)(GLfloat, GLfloat, GLfloat, GLfloat))glXGetProcAddress((const GLubyte*)"glClearColor");
  CHECK(create_attribs && clear_color, "glXGetProcAddress");
  clear_color(0, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, win);
  CHECK(window_pixel(win, 5, 5) == 0x00ffff, "glClearColor by address");
  const char* extensions = glXQueryExtensionsString(dpy, screen);
  CHECK(extensions && strstr(extensions, "GLX_ARB_create_context") && strstr(extensions, "GLX_EXT_swap_control"),
        "extensions %s", extensions ? extensions : "(none)");
  printf("ok glXGetProcAddress\n");

  /* --- GLX_ARB_create_context: compatibility 1.x; 3.2 core and bad attributes refused */
  const int v14[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 4,
                     GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB, None};
  GLXContext c14 = create_attribs(dpy, config, NULL, True, v14);
  CHECK(c14, "a 1.4 context");
  XSync(dpy, False);
  x_errors = 0;
  /* GL 1.5 (buffer objects, occlusion queries) is the newest pGL gives: a 1.5
   * context is made, its GL_VERSION says so, and its functions are found. */
  const int v15[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5, None};
  GLXContext c15 = create_attribs(dpy, config, NULL, True, v15);
  CHECK(c15, "a 1.5 context");
  CHECK(glXMakeCurrent(dpy, win, c15), "make the 1.5 context current");
  CHECK(strncmp((const char*)glGetString(GL_VERSION), "1.5", 3) == 0, "GL_VERSION %s", (const char*)glGetString(GL_VERSION));
  CHECK(glXGetProcAddress((const GLubyte*)"glGenBuffers") && glXGetProcAddress((const GLubyte*)"glBeginQueryARB") &&
            glXGetProcAddress((const GLubyte*)"glTexImage1D"),
        "GL 1.5's and 1-D textures' functions");
  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, c15);
  XSync(dpy, False);
  const int v32[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2,
                     GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
  CHECK(!create_attribs(dpy, config, NULL, True, v32), "a 3.2 core context");
  XSync(dpy, False);
  CHECK(x_errors == 1 && last_error == BadMatch, "3.2: %d errors, last %d", x_errors, last_error);
  const int bad[] = {0x7777, 1, None};
  CHECK(!create_attribs(dpy, config, NULL, True, bad), "an unknown attribute");
  XSync(dpy, False);
  CHECK(x_errors == 2 && last_error == BadValue, "unknown attribute: %d errors, last %d", x_errors, last_error);
  CHECK(glXMakeCurrent(dpy, win, c14), "make the 1.4 context current");
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, win);
  CHECK(window_pixel(win, 5, 5) == 0xff00ff, "1.4 context draws");
  printf("ok GLX_ARB_create_context\n");

  /* --- swap control */
  PFNGLXSWAPINTERVALEXTPROC swap_interval =
      (PFNGLXSWAPINTERVALEXTPROC)glXGetProcAddress((const GLubyte*)"glXSwapIntervalEXT");
  CHECK(swap_interval, "glXSwapIntervalEXT");
  unsigned interval = 99, most = 0;
  glXQueryDrawable(dpy, win, GLX_SWAP_INTERVAL_EXT, &interval);
  CHECK(interval == 0, "default interval %u", interval);
  swap_interval(dpy, win, 2);
  glXQueryDrawable(dpy, win, GLX_SWAP_INTERVAL_EXT, &interval);
  glXQueryDrawable(dpy, win, GLX_MAX_SWAP_INTERVAL_EXT, &most);
  CHECK(interval == 2 && most >= 2, "interval %u max %u", interval, most);
  PFNGLXSWAPINTERVALMESAPROC interval_mesa =
      (PFNGLXSWAPINTERVALMESAPROC)glXGetProcAddress((const GLubyte*)"glXSwapIntervalMESA");
  PFNGLXGETSWAPINTERVALMESAPROC get_interval_mesa =
      (PFNGLXGETSWAPINTERVALMESAPROC)glXGetProcAddress((const GLubyte*)"glXGetSwapIntervalMESA");
  CHECK(interval_mesa && get_interval_mesa && get_interval_mesa() == 2, "MESA interval");
  CHECK(interval_mesa(0) == 0 && get_interval_mesa() == 0, "MESA interval 0");
  x_errors = 0;
  swap_interval(dpy, win, -1);
  XSync(dpy, False);
  CHECK(x_errors == 1 && last_error == BadValue, "interval -1: %d errors", x_errors);
  printf("ok swap control\n");

  /* --- a single-buffered window shows at glFlush */
  int single[] = {GLX_RGBA, GLX_RED_SIZE, 1, None};
  XVisualInfo* svis = glXChooseVisual(dpy, screen, single);
  CHECK(svis && svis->visualid != vis->visualid, "single-buffered visual");
  CHECK(glXGetConfig(dpy, svis, GLX_DOUBLEBUFFER, &v) == 0 && v == 0, "single");
  Window swin = open_window(svis, 33, 21);
  GLXContext sctx = glXCreateContext(dpy, svis, NULL, True);
  CHECK(sctx && glXMakeCurrent(dpy, swin, sctx), "single-buffered context");
  glGetIntegerv(GL_DRAW_BUFFER, iv);
  CHECK(iv[0] == GL_FRONT, "GL_DRAW_BUFFER 0x%x", iv[0]);
  draw_quarters(33, 21);
  glFlush();
  CHECK(window_pixel(swin, 2, 2) == 0xff0000 && window_pixel(swin, 30, 18) == 0x00ff00, "flush shows");
  printf("ok single-buffered window: shown at glFlush\n");

  /* --- a pbuffer */
  const int pb_attributes[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 8, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, pb_attributes);
  CHECK(pb, "glXCreatePbuffer");
  CHECK(glXMakeContextCurrent(dpy, pb, pb, c14), "pbuffer current");
  unsigned pw = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &pw);
  CHECK(pw == 16, "pbuffer width %u", pw);
  draw_quarters(16, 8);
  unsigned char px[4] = {0, 0, 0, 0};
  glReadPixels(15, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  CHECK(px[0] == 0 && px[1] == 255 && px[2] == 0, "pbuffer pixel %d %d %d", px[0], px[1], px[2]);
  printf("ok pbuffer\n");

  check_multisample(screen);

  /* --- misuse: GLX's errors, no crash */
  CHECK(glXMakeCurrent(dpy, None, NULL), "release");
  glXDestroyContext(dpy, c14);
  x_errors = 0;
  CHECK(!glXMakeContextCurrent(dpy, win, swin, ctx), "a different read drawable");
  XSync(dpy, False);
  CHECK(x_errors == 1 && last_error == BadMatch, "read != draw: %d errors %d", x_errors, last_error);
  glXDestroyPbuffer(dpy, pb);
  glXDestroyContext(dpy, ctx);
  glXDestroyContext(dpy, sctx);
  XFree(vis);
  XFree(svis);
  XCloseDisplay(dpy);
  printf("ok errors; all GLX checks passed\n");
  return 0;
}
