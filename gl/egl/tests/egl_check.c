/* The EGL vendor library used as a headless program uses the system's EGL: this file is
 * built against the system's <EGL/egl.h> and <GL/gl.h> and linked to libglvnd's libEGL
 * and libOpenGL, never to pGL; run with __EGL_VENDOR_LIBRARY_FILENAMES naming
 * Velocity's JSON file (egl_test.py). It checks what EGL 1.4 and the claimed extensions
 * say: the surfaceless platform's display, configurations and their order, pbuffers
 * that hold what GL drew (two of them in turn, one destroyed while drawn into), a
 * context without a surface drawing into a framebuffer object, multisample
 * configurations, a context current in one thread refused to another, eglTerminate with
 * a context current, and EGL's error for each misuse. Prints "ok ..." per check, exits 1
 * at the first failure. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(cond, ...)                                    \
  do {                                                      \
    if (!(cond)) {                                          \
      printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); \
      printf(__VA_ARGS__);                                  \
      printf("\n");                                         \
      exit(1);                                              \
    }                                                       \
  } while (0)

/* The call failed with `error`, and eglGetError said so once. */
#define CHECK_ERROR(call_failed, error)                                                    \
  do {                                                                                     \
    CHECK(call_failed, "succeeded");                                                       \
    const EGLint e_ = eglGetError();                                                       \
    CHECK(e_ == (error), "error 0x%x, expected 0x%x (%s)", e_, (error), #error);           \
    CHECK(eglGetError() == EGL_SUCCESS, "eglGetError did not reset");                      \
  } while (0)

static int has_word(const char* list, const char* word) {
  const size_t n = strlen(word);
  for (const char* p = list; p && (p = strstr(p, word)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
  return 0;
}

static EGLint attrib(EGLDisplay dpy, EGLConfig c, EGLint name) {
  EGLint v = -12345;
  CHECK(eglGetConfigAttrib(dpy, c, name, &v), "eglGetConfigAttrib 0x%x", name);
  return v;
}

/* The first configuration that matches `list`, or fails. */
static EGLConfig choose(EGLDisplay dpy, const EGLint* list) {
  EGLConfig c = NULL;
  EGLint n = 0;
  CHECK(eglChooseConfig(dpy, list, &c, 1, &n) && n == 1, "eglChooseConfig: n=%d error 0x%x", n, eglGetError());
  return c;
}

static unsigned pixel(int x, int y) {
  unsigned char p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return (unsigned)p[0] << 16 | (unsigned)p[1] << 8 | p[2];
}

static void clear(float r, float g, float b) {
  glClearColor(r, g, b, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* A red shape in the viewport: a triangle over its lower-left half, or a block over the
 * left half of its bottom quarter (asymmetric both ways: GL's row 0 is the bottom one). */
static void red(int block) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 0, 0);
  if (block) {
    glRectf(0, 0, 0.5f, 0.25f);
    return;
  }
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
}

struct other_thread {
  EGLDisplay dpy;
  EGLContext ctx;
  EGLSurface surface;
  EGLBoolean made;
  EGLint error;
};

static void* try_make_current(void* arg) {
  struct other_thread* t = arg;
  eglBindAPI(EGL_OPENGL_API);
  t->made = eglMakeCurrent(t->dpy, t->surface, t->surface, t->ctx);
  t->error = eglGetError();
  if (t->made) eglReleaseThread();
  return NULL;
}

int main(void) {
  /* --- the platform, the display -------------------------------------------------------- */
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  CHECK(has_word(client, "EGL_MESA_platform_surfaceless") && has_word(client, "EGL_EXT_platform_base"),
        "client extensions: %s", client ? client : "(null)");
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  CHECK(dpy != EGL_NO_DISPLAY, "eglGetPlatformDisplay(SURFACELESS): 0x%x", eglGetError());
  CHECK(eglGetDisplay(EGL_DEFAULT_DISPLAY) == dpy, "the default display is another");
  const EGLAttrib bad_display_list[] = {0x3333, 1, EGL_NONE};
  CHECK_ERROR(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, bad_display_list) ==
                  EGL_NO_DISPLAY,
              EGL_BAD_ATTRIBUTE);
  printf("ok display: the surfaceless platform's, also the default one\n");

  EGLint n = 0;
  CHECK_ERROR(!eglGetConfigs(dpy, NULL, 0, &n), EGL_NOT_INITIALIZED);
  CHECK_ERROR(eglQueryString(dpy, EGL_VENDOR) == NULL, EGL_NOT_INITIALIZED);
  EGLint major = 0, minor = 0;
  CHECK(eglInitialize(dpy, &major, &minor) && major == 1 && minor == 4, "eglInitialize: %d.%d", major, minor);
  CHECK(eglGetError() == EGL_SUCCESS, "error after success");
  CHECK(strcmp(eglQueryString(dpy, EGL_VENDOR), "Velocity") == 0, "vendor %s", eglQueryString(dpy, EGL_VENDOR));
  CHECK(strcmp(eglQueryString(dpy, EGL_CLIENT_APIS), "OpenGL") == 0, "APIs");
  CHECK(strncmp(eglQueryString(dpy, EGL_VERSION), "1.4", 3) == 0, "version");
  const char* ext = eglQueryString(dpy, EGL_EXTENSIONS);
  CHECK(has_word(ext, "EGL_KHR_create_context") && has_word(ext, "EGL_KHR_surfaceless_context"), "%s", ext);
  CHECK_ERROR(eglQueryString(dpy, 0x3333) == NULL, EGL_BAD_PARAMETER);
  printf("ok eglInitialize: EGL 1.4 by Velocity, OpenGL, %s\n", ext);

  /* --- configurations -------------------------------------------------------------------- */
  CHECK(eglGetConfigs(dpy, NULL, 0, &n) && n == 5, "%d configurations", n);
  EGLConfig all[8];
  CHECK(eglGetConfigs(dpy, all, 8, &n) && n == 5, "eglGetConfigs");
  for (int i = 0; i < n; ++i) {
    CHECK(attrib(dpy, all[i], EGL_RED_SIZE) == 8 && attrib(dpy, all[i], EGL_ALPHA_SIZE) == 8 &&
              attrib(dpy, all[i], EGL_BUFFER_SIZE) == 32,
          "colour of %d", i);
    CHECK(attrib(dpy, all[i], EGL_SURFACE_TYPE) & EGL_PBUFFER_BIT, "pbuffer bit");
    CHECK(!(attrib(dpy, all[i], EGL_SURFACE_TYPE) & (EGL_WINDOW_BIT | EGL_PIXMAP_BIT)), "no windows");
    CHECK(attrib(dpy, all[i], EGL_RENDERABLE_TYPE) == EGL_OPENGL_BIT, "desktop GL only");
  }
  CHECK_ERROR(!eglGetConfigAttrib(dpy, all[0], 0x3333, &n), EGL_BAD_ATTRIBUTE);
  CHECK_ERROR(!eglGetConfigAttrib(dpy, (EGLConfig)&n, EGL_RED_SIZE, &n), EGL_BAD_CONFIG);
  CHECK_ERROR(!eglGetConfigs(dpy, all, 8, NULL), EGL_BAD_PARAMETER);
  /* EGL's defaults ask for a window and OpenGL ES: none is either. */
  const EGLint defaults[] = {EGL_NONE};
  CHECK(eglChooseConfig(dpy, defaults, all, 8, &n) && n == 0, "%d configurations for EGL's defaults", n);
  const EGLint gl_pbuffer[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  CHECK(eglChooseConfig(dpy, gl_pbuffer, all, 8, &n) && n == 5, "%d", n);
  /* EGL's order: no samples first, then the smaller depth buffer. */
  CHECK(attrib(dpy, all[0], EGL_DEPTH_SIZE) == 0 && attrib(dpy, all[1], EGL_DEPTH_SIZE) == 24 &&
            attrib(dpy, all[1], EGL_SAMPLES) == 0 && attrib(dpy, all[2], EGL_SAMPLES) == 4 &&
            attrib(dpy, all[3], EGL_SAMPLES) == 9 && attrib(dpy, all[4], EGL_SAMPLES) == 16,
        "order");
  const EGLint depth24[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_DEPTH_SIZE, 24,
                            EGL_RED_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
  EGLConfig config = choose(dpy, depth24);
  CHECK(attrib(dpy, config, EGL_DEPTH_SIZE) == 24 && attrib(dpy, config, EGL_STENCIL_SIZE) == 8 &&
            attrib(dpy, config, EGL_SAMPLES) == 0,
        "depth 24");
  const EGLint samples4[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SAMPLES, 4,
                             EGL_NONE};
  EGLConfig ms_config = choose(dpy, samples4);
  CHECK(attrib(dpy, ms_config, EGL_SAMPLES) == 4 && attrib(dpy, ms_config, EGL_SAMPLE_BUFFERS) == 1, "samples");
  const EGLint by_id[] = {EGL_CONFIG_ID, 2, EGL_DEPTH_SIZE, 24, EGL_NONE};  /* the id overrides the rest */
  CHECK(attrib(dpy, choose(dpy, by_id), EGL_CONFIG_ID) == 2, "by id");
  const EGLint any[] = {EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_RENDERABLE_TYPE, EGL_DONT_CARE, EGL_NONE};
  CHECK(eglChooseConfig(dpy, any, NULL, 0, &n) && n == 5, "EGL_DONT_CARE: %d", n);
  const EGLint too_deep[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_DEPTH_SIZE, 32,
                             EGL_NONE};
  CHECK(eglChooseConfig(dpy, too_deep, all, 8, &n) && n == 0, "depth 32: %d", n);
  const EGLint unknown[] = {0x3333, 1, EGL_NONE};
  CHECK_ERROR(!eglChooseConfig(dpy, unknown, all, 8, &n), EGL_BAD_ATTRIBUTE);
  const EGLint level_dont_care[] = {EGL_LEVEL, EGL_DONT_CARE, EGL_NONE};
  CHECK_ERROR(!eglChooseConfig(dpy, level_dont_care, all, 8, &n), EGL_BAD_ATTRIBUTE);
  const EGLint negative_size[] = {EGL_RED_SIZE, -2, EGL_NONE};
  CHECK_ERROR(!eglChooseConfig(dpy, negative_size, all, 8, &n), EGL_BAD_ATTRIBUTE);
  CHECK_ERROR(!eglChooseConfig(dpy, gl_pbuffer, all, 8, NULL), EGL_BAD_PARAMETER);
  printf("ok configurations: 5, pbuffers and OpenGL, in EGL's order\n");

  /* --- surfaces ---------------------------------------------------------------------------- */
  CHECK_ERROR(eglCreateWindowSurface(dpy, config, 0, NULL) == EGL_NO_SURFACE, EGL_BAD_NATIVE_WINDOW);
  CHECK_ERROR(eglCreatePlatformWindowSurface(dpy, config, NULL, NULL) == EGL_NO_SURFACE, EGL_BAD_NATIVE_WINDOW);
  CHECK_ERROR(eglCreatePixmapSurface(dpy, config, 0, NULL) == EGL_NO_SURFACE, EGL_BAD_NATIVE_PIXMAP);
  CHECK_ERROR(eglCreatePbufferFromClientBuffer(dpy, EGL_OPENVG_IMAGE, NULL, config, NULL) == EGL_NO_SURFACE,
              EGL_BAD_PARAMETER);
  const EGLint size[] = {EGL_WIDTH, 64, EGL_HEIGHT, 48, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(dpy, config, size);
  CHECK(pbuffer != EGL_NO_SURFACE, "eglCreatePbufferSurface: 0x%x", eglGetError());
  EGLint v = 0;
  CHECK(eglQuerySurface(dpy, pbuffer, EGL_WIDTH, &v) && v == 64, "width %d", v);
  CHECK(eglQuerySurface(dpy, pbuffer, EGL_HEIGHT, &v) && v == 48, "height %d", v);
  CHECK(eglQuerySurface(dpy, pbuffer, EGL_CONFIG_ID, &v) && v == attrib(dpy, config, EGL_CONFIG_ID), "id");
  CHECK(eglQuerySurface(dpy, pbuffer, EGL_RENDER_BUFFER, &v) && v == EGL_BACK_BUFFER, "render buffer");
  CHECK(eglQuerySurface(dpy, pbuffer, EGL_LARGEST_PBUFFER, &v) && v == EGL_FALSE, "largest");
  CHECK_ERROR(!eglQuerySurface(dpy, pbuffer, 0x3333, &v), EGL_BAD_ATTRIBUTE);
  CHECK_ERROR(!eglQuerySurface(dpy, (EGLSurface)&v, EGL_WIDTH, &v), EGL_BAD_SURFACE);
  const EGLint negative[] = {EGL_WIDTH, -1, EGL_NONE};
  CHECK_ERROR(eglCreatePbufferSurface(dpy, config, negative) == EGL_NO_SURFACE, EGL_BAD_PARAMETER);
  CHECK_ERROR(eglCreatePbufferSurface(dpy, config, unknown) == EGL_NO_SURFACE, EGL_BAD_ATTRIBUTE);
  const EGLint texture[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET, EGL_TEXTURE_2D, EGL_NONE};
  CHECK_ERROR(eglCreatePbufferSurface(dpy, config, texture) == EGL_NO_SURFACE, EGL_BAD_MATCH);
  const EGLint huge[] = {EGL_WIDTH, 20000, EGL_HEIGHT, 2, EGL_NONE};
  CHECK_ERROR(eglCreatePbufferSurface(dpy, config, huge) == EGL_NO_SURFACE, EGL_BAD_ALLOC);
  const EGLint largest[] = {EGL_WIDTH, 20000, EGL_HEIGHT, 2, EGL_LARGEST_PBUFFER, EGL_TRUE, EGL_NONE};
  EGLSurface wide = eglCreatePbufferSurface(dpy, config, largest);
  CHECK(wide && eglQuerySurface(dpy, wide, EGL_WIDTH, &v) && v == 16384, "the largest pbuffer: %d", v);
  CHECK(eglDestroySurface(dpy, wide), "destroy");
  CHECK_ERROR(!eglDestroySurface(dpy, wide), EGL_BAD_SURFACE);
  CHECK_ERROR(!eglBindTexImage(dpy, pbuffer, EGL_BACK_BUFFER), EGL_BAD_MATCH);
  CHECK_ERROR(!eglCopyBuffers(dpy, pbuffer, 0), EGL_BAD_NATIVE_PIXMAP);
  printf("ok pbuffers: sizes, queries, errors; no windows or pixmaps on this platform\n");

  /* --- contexts ------------------------------------------------------------------------------ */
  /* OpenGL ES is eglBindAPI's default, and not what any configuration renders. */
  CHECK(eglQueryAPI() == EGL_OPENGL_ES_API, "the default API");
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT, EGL_BAD_CONFIG);
  CHECK(eglBindAPI(EGL_OPENGL_API), "eglBindAPI(EGL_OPENGL_API)");
  const EGLint gl15[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 5, EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, gl15);
  CHECK(ctx != EGL_NO_CONTEXT, "eglCreateContext 1.5: 0x%x", eglGetError());
  const EGLint gl2[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_NONE};
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, gl2) == EGL_NO_CONTEXT, EGL_BAD_MATCH);
  const EGLint gl16[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 6, EGL_NONE};
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, gl16) == EGL_NO_CONTEXT, EGL_BAD_MATCH);
  const EGLint bad_flag[] = {EGL_CONTEXT_FLAGS_KHR, 0x80, EGL_NONE};
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, bad_flag) == EGL_NO_CONTEXT, EGL_BAD_ATTRIBUTE);
  const EGLint forward[] = {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR, EGL_NONE};
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, forward) == EGL_NO_CONTEXT, EGL_BAD_MATCH);
  CHECK_ERROR(eglCreateContext(dpy, config, EGL_NO_CONTEXT, unknown) == EGL_NO_CONTEXT, EGL_BAD_ATTRIBUTE);
  CHECK_ERROR(eglCreateContext(dpy, config, ctx, NULL) == EGL_NO_CONTEXT, EGL_BAD_MATCH);  /* no sharing */
  CHECK_ERROR(eglCreateContext(dpy, config, (EGLContext)&v, NULL) == EGL_NO_CONTEXT, EGL_BAD_CONTEXT);
  CHECK_ERROR(eglCreateContext(dpy, (EGLConfig)&v, EGL_NO_CONTEXT, NULL) == EGL_NO_CONTEXT, EGL_BAD_CONFIG);
  const EGLint debug[] = {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                          EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};  /* (a profile is ignored below 3.2) */
  EGLContext debug_ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, debug);
  CHECK(debug_ctx && eglDestroyContext(dpy, debug_ctx), "a debug context");
  CHECK_ERROR(!eglDestroyContext(dpy, debug_ctx), EGL_BAD_CONTEXT);
  CHECK(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &v) && v == EGL_OPENGL_API, "client type");
  CHECK(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &v) && v == EGL_NONE, "not bound: %x", v);
  printf("ok contexts: OpenGL 1.0-1.5, the rest refused with EGL_KHR_create_context's errors\n");

  /* --- drawing into a pbuffer ------------------------------------------------------------- */
  EGLConfig no_depth = choose(dpy, gl_pbuffer);
  EGLSurface shallow = eglCreatePbufferSurface(dpy, no_depth, size);
  CHECK(shallow, "pbuffer");
  CHECK_ERROR(!eglMakeCurrent(dpy, shallow, shallow, ctx), EGL_BAD_MATCH);  /* not the context's buffers */
  CHECK_ERROR(!eglMakeCurrent(dpy, pbuffer, shallow, ctx), EGL_BAD_MATCH);  /* pGL reads where it draws */
  CHECK_ERROR(!eglMakeCurrent(dpy, (EGLSurface)&v, (EGLSurface)&v, ctx), EGL_BAD_SURFACE);
  CHECK(eglMakeCurrent(dpy, pbuffer, pbuffer, ctx), "eglMakeCurrent: 0x%x", eglGetError());
  CHECK(eglGetCurrentContext() == ctx && eglGetCurrentSurface(EGL_DRAW) == pbuffer, "current");
  CHECK(strcmp((const char*)glGetString(GL_VENDOR), "Velocity") == 0, "GL_VENDOR %s", glGetString(GL_VENDOR));
  GLint viewport[4], bits = 0, buffer = 0;
  glGetIntegerv(GL_VIEWPORT, viewport);
  CHECK(viewport[2] == 64 && viewport[3] == 48, "viewport %dx%d", viewport[2], viewport[3]);
  glGetIntegerv(GL_DEPTH_BITS, &bits);
  CHECK(bits == 24, "depth bits %d", bits);
  glGetIntegerv(GL_STENCIL_BITS, &bits);
  CHECK(bits == 8, "stencil bits %d", bits);
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  CHECK(buffer == GL_BACK, "draw buffer 0x%x", buffer);
  clear(0, 0, 1);
  red(1);
  CHECK(pixel(2, 2) == 0xff0000 && pixel(2, 45) == 0x0000ff && pixel(61, 2) == 0x0000ff, "%06x %06x %06x",
        pixel(2, 2), pixel(2, 45), pixel(61, 2));
  CHECK(eglSwapBuffers(dpy, pbuffer) && pixel(2, 2) == 0xff0000, "a pbuffer's swap changes nothing");
  CHECK(eglSwapInterval(dpy, 1), "eglSwapInterval");
  CHECK(eglQueryContext(dpy, ctx, EGL_RENDER_BUFFER, &v) && v == EGL_BACK_BUFFER, "bound");
  CHECK(glGetError() == GL_NO_ERROR, "GL error");
  printf("ok a pbuffer: GL_BACK, 24-bit depth, 8-bit stencil; the triangle where GL puts it\n");

  /* Two pbuffers of one size, in turn: each keeps what was drawn into it. */
  EGLSurface second = eglCreatePbufferSurface(dpy, config, size);
  CHECK(second && eglMakeCurrent(dpy, second, second, ctx), "second");
  clear(0, 1, 0);
  CHECK(pixel(2, 2) == 0x00ff00, "second: %06x", pixel(2, 2));
  CHECK(eglMakeCurrent(dpy, pbuffer, pbuffer, ctx), "first again");
  CHECK(pixel(2, 2) == 0xff0000 && pixel(2, 45) == 0x0000ff, "the first pbuffer kept %06x %06x", pixel(2, 2),
        pixel(2, 45));
  CHECK(eglMakeCurrent(dpy, second, second, ctx) && pixel(30, 30) == 0x00ff00, "the second kept %06x",
        pixel(30, 30));
  /* Another context made current on the first pbuffer finds what the first drew. */
  EGLContext other = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  CHECK(other && eglMakeCurrent(dpy, pbuffer, pbuffer, other), "another context");
  CHECK(pixel(2, 2) == 0xff0000 && pixel(2, 45) == 0x0000ff, "another context reads %06x %06x", pixel(2, 2),
        pixel(2, 45));
  CHECK(eglMakeCurrent(dpy, second, second, ctx) && eglDestroyContext(dpy, other), "back");
  /* Made current without a surface in between, the context finds the pbuffer's pixels. */
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx) && eglMakeCurrent(dpy, second, second, ctx),
        "second, via no surface");
  CHECK(pixel(30, 30) == 0x00ff00, "the second pbuffer after no surface: %06x", pixel(30, 30));
  /* Destroyed while drawn into: it stays until the context lets go. */
  CHECK(eglDestroySurface(dpy, second), "destroy current");
  CHECK_ERROR(!eglQuerySurface(dpy, second, EGL_WIDTH, &v), EGL_BAD_SURFACE);
  clear(1, 1, 0);
  CHECK(pixel(5, 5) == 0xffff00, "a destroyed current pbuffer still drawn into");
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT), "release");
  CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT, "released");
  printf("ok pbuffers in turn keep their pixels, for another context too; one destroyed while current lives until released\n");

  /* --- another thread ------------------------------------------------------------------------ */
  CHECK(eglMakeCurrent(dpy, pbuffer, pbuffer, ctx), "again");
  struct other_thread t = {dpy, ctx, pbuffer, EGL_TRUE, 0};
  pthread_t thread;
  CHECK(pthread_create(&thread, NULL, try_make_current, &t) == 0 && pthread_join(thread, NULL) == 0, "thread");
  CHECK(!t.made && t.error == EGL_BAD_ACCESS, "a context current here, made current there: 0x%x", t.error);
  EGLContext ctx2 = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  struct other_thread t2 = {dpy, ctx2, pbuffer, EGL_TRUE, 0};
  CHECK(pthread_create(&thread, NULL, try_make_current, &t2) == 0 && pthread_join(thread, NULL) == 0, "thread");
  CHECK(!t2.made && t2.error == EGL_BAD_ACCESS, "a surface drawn into here, bound there: 0x%x", t2.error);
  CHECK(eglGetError() == EGL_SUCCESS, "the other thread's error is its own");
  printf("ok threads: EGL_BAD_ACCESS for a context or surface current in another thread\n");

  /* --- without a surface: a framebuffer object ------------------------------------------- */
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx2), "surfaceless: 0x%x", eglGetError());
  glGetIntegerv(GL_VIEWPORT, viewport);
  CHECK(viewport[2] == 0 && viewport[3] == 0, "EGL_KHR_surfaceless_context's viewport: %dx%d", viewport[2],
        viewport[3]);
  PFNGLGENFRAMEBUFFERSEXTPROC gen_framebuffers = (PFNGLGENFRAMEBUFFERSEXTPROC)eglGetProcAddress("glGenFramebuffersEXT");
  PFNGLBINDFRAMEBUFFEREXTPROC bind_framebuffer = (PFNGLBINDFRAMEBUFFEREXTPROC)eglGetProcAddress("glBindFramebufferEXT");
  PFNGLGENRENDERBUFFERSEXTPROC gen_renderbuffers =
      (PFNGLGENRENDERBUFFERSEXTPROC)eglGetProcAddress("glGenRenderbuffersEXT");
  PFNGLBINDRENDERBUFFEREXTPROC bind_renderbuffer =
      (PFNGLBINDRENDERBUFFEREXTPROC)eglGetProcAddress("glBindRenderbufferEXT");
  PFNGLRENDERBUFFERSTORAGEEXTPROC renderbuffer_storage =
      (PFNGLRENDERBUFFERSTORAGEEXTPROC)eglGetProcAddress("glRenderbufferStorageEXT");
  PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC attach =
      (PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC)eglGetProcAddress("glFramebufferRenderbufferEXT");
  PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC status =
      (PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC)eglGetProcAddress("glCheckFramebufferStatusEXT");
  CHECK(gen_framebuffers && bind_framebuffer && gen_renderbuffers && bind_renderbuffer && renderbuffer_storage &&
            attach && status,
        "GL_EXT_framebuffer_object's functions");
  GLuint fbo = 0, colour = 0;
  gen_framebuffers(1, &fbo);
  bind_framebuffer(GL_FRAMEBUFFER_EXT, fbo);
  gen_renderbuffers(1, &colour);
  bind_renderbuffer(GL_RENDERBUFFER_EXT, colour);
  renderbuffer_storage(GL_RENDERBUFFER_EXT, GL_RGBA8, 32, 16);
  attach(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_RENDERBUFFER_EXT, colour);
  CHECK(status(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT, "incomplete");
  glViewport(0, 0, 32, 16);
  clear(0, 0, 1);
  red(1);
  CHECK(pixel(1, 1) == 0xff0000 && pixel(1, 14) == 0x0000ff && pixel(30, 1) == 0x0000ff, "the FBO: %06x %06x %06x",
        pixel(1, 1), pixel(1, 14), pixel(30, 1));
  CHECK(glGetError() == GL_NO_ERROR, "GL error");
  printf("ok without a surface: drawing into a framebuffer object\n");

  /* --- multisample ------------------------------------------------------------------------ */
  EGLContext ms_ctx = eglCreateContext(dpy, ms_config, EGL_NO_CONTEXT, NULL);
  EGLSurface ms_pbuffer = eglCreatePbufferSurface(dpy, ms_config, size);
  CHECK(ms_ctx && ms_pbuffer && eglMakeCurrent(dpy, ms_pbuffer, ms_pbuffer, ms_ctx), "multisample");
  glGetIntegerv(GL_SAMPLES, &bits);
  CHECK(bits == 4, "GL_SAMPLES %d", bits);
  clear(0, 0, 0);
  red(0);
  /* The diagonal's pixels are partly covered: some red, not all. */
  int partial = 0;
  for (int x = 0; x < 64; ++x) {
    const unsigned r = pixel(x, (47 - x * 48 / 64)) >> 16;
    partial += r > 0 && r < 255;
  }
  CHECK(partial > 10, "%d partly covered pixels on the edge", partial);
  printf("ok multisample: GL_SAMPLES 4, %d pixels of the edge partly covered\n", partial);

  /* --- eglTerminate with a context current ------------------------------------------------ */
  CHECK(eglTerminate(dpy), "eglTerminate");
  CHECK(eglGetCurrentContext() == ms_ctx, "still current");
  clear(0, 1, 1);
  CHECK(pixel(3, 3) == 0x00ffff, "still drawing after eglTerminate: %06x", pixel(3, 3));
  CHECK_ERROR(!eglQueryContext(dpy, ms_ctx, EGL_CONFIG_ID, &v), EGL_NOT_INITIALIZED);
  CHECK(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT), "release after terminate");
  CHECK(eglInitialize(dpy, NULL, NULL), "again");
  CHECK_ERROR(!eglQueryContext(dpy, ctx, EGL_CONFIG_ID, &v), EGL_BAD_CONTEXT);
  CHECK_ERROR(!eglQuerySurface(dpy, pbuffer, EGL_WIDTH, &v), EGL_BAD_SURFACE);
  CHECK(eglTerminate(dpy) && eglReleaseThread(), "the end");
  printf("ok eglTerminate: the current context draws until released; every handle is gone after\n");
  printf("all EGL checks passed\n");
  return 0;
}
