/* What the GLX vendor needs of Xlib's internals (xlib_internal.c). */
#ifndef VELOCITY_XLIB_INTERNAL_H
#define VELOCITY_XLIB_INTERNAL_H
#include <X11/Xlib.h>
/* The GLX protocol's error codes and request numbers (GL/glxproto.h's values, which
 * glx_error.c checks; that header is C only): an error names the request that failed,
 * as the server's would. */
enum {
  VGLX_GLXBadContext = 0,
  VGLX_GLXBadDrawable = 2,
  VGLX_GLXBadFBConfig = 9,
  VGLX_GLXBadPbuffer = 10,
  VGLX_GLXBadPixmap = 3,
  VGLX_GLXBadProfileARB = 13,
  VGLX_GLXBadWindow = 12,
  VGLX_X_GLXChangeDrawableAttributes = 30,
  VGLX_X_GLXCopyContext = 10,
  VGLX_X_GLXCreateContext = 3,
  VGLX_X_GLXCreateContextAttribsARB = 34,
  VGLX_X_GLXCreateGLXPixmap = 13,
  VGLX_X_GLXCreateNewContext = 24,
  VGLX_X_GLXCreatePbuffer = 27,
  VGLX_X_GLXCreatePixmap = 22,
  VGLX_X_GLXCreateWindow = 31,
  VGLX_X_GLXDestroyContext = 4,
  VGLX_X_GLXDestroyGLXPixmap = 15,
  VGLX_X_GLXDestroyPbuffer = 28,
  VGLX_X_GLXDestroyPixmap = 23,
  VGLX_X_GLXDestroyWindow = 32,
  VGLX_X_GLXGetDrawableAttributes = 29,
  VGLX_X_GLXGetFBConfigs = 21,
  VGLX_X_GLXGetVisualConfigs = 14,
  VGLX_X_GLXMakeContextCurrent = 26,
  VGLX_X_GLXSwapBuffers = 11,
};

#ifdef __cplusplus
extern "C" {
#endif
/* Reports a GLX (or, with core_error, a core X) error to the program's X error
 * handler, as if the server had sent it. */
void velocity_glx_error(Display* dpy, unsigned char code, unsigned long resource, unsigned char minor,
                        int core_error);
/* Calls `closing` when XCloseDisplay closes dpy (before the connection goes). */
void velocity_glx_on_close(Display* dpy, int (*closing)(Display*, XExtCodes*));
#ifdef __cplusplus
}
#endif
#endif
