/* What the GLX vendor needs of Xlib's internals (Xlibint.h, which is C only): GLX
 * errors raised by the client library itself (a bad attribute, an unsupported
 * version), delivered to the program's X error handler exactly as a server's error
 * would be, and a call when a display closes. */
#include <X11/Xlibint.h>

#include <GL/glxproto.h>

#include "xlib_internal.h"

_Static_assert(VGLX_GLXBadContext == GLXBadContext, "glxproto.h");
_Static_assert(VGLX_GLXBadDrawable == GLXBadDrawable, "glxproto.h");
_Static_assert(VGLX_GLXBadFBConfig == GLXBadFBConfig, "glxproto.h");
_Static_assert(VGLX_GLXBadPbuffer == GLXBadPbuffer, "glxproto.h");
_Static_assert(VGLX_GLXBadPixmap == GLXBadPixmap, "glxproto.h");
_Static_assert(VGLX_GLXBadProfileARB == GLXBadProfileARB, "glxproto.h");
_Static_assert(VGLX_GLXBadWindow == GLXBadWindow, "glxproto.h");
_Static_assert(VGLX_X_GLXChangeDrawableAttributes == X_GLXChangeDrawableAttributes, "glxproto.h");
_Static_assert(VGLX_X_GLXCopyContext == X_GLXCopyContext, "glxproto.h");
_Static_assert(VGLX_X_GLXCreateContext == X_GLXCreateContext, "glxproto.h");
_Static_assert(VGLX_X_GLXCreateContextAttribsARB == X_GLXCreateContextAttribsARB, "glxproto.h");
_Static_assert(VGLX_X_GLXCreateGLXPixmap == X_GLXCreateGLXPixmap, "glxproto.h");
_Static_assert(VGLX_X_GLXCreateNewContext == X_GLXCreateNewContext, "glxproto.h");
_Static_assert(VGLX_X_GLXCreatePbuffer == X_GLXCreatePbuffer, "glxproto.h");
_Static_assert(VGLX_X_GLXCreatePixmap == X_GLXCreatePixmap, "glxproto.h");
_Static_assert(VGLX_X_GLXCreateWindow == X_GLXCreateWindow, "glxproto.h");
_Static_assert(VGLX_X_GLXDestroyContext == X_GLXDestroyContext, "glxproto.h");
_Static_assert(VGLX_X_GLXDestroyGLXPixmap == X_GLXDestroyGLXPixmap, "glxproto.h");
_Static_assert(VGLX_X_GLXDestroyPbuffer == X_GLXDestroyPbuffer, "glxproto.h");
_Static_assert(VGLX_X_GLXDestroyPixmap == X_GLXDestroyPixmap, "glxproto.h");
_Static_assert(VGLX_X_GLXDestroyWindow == X_GLXDestroyWindow, "glxproto.h");
_Static_assert(VGLX_X_GLXGetDrawableAttributes == X_GLXGetDrawableAttributes, "glxproto.h");
_Static_assert(VGLX_X_GLXGetFBConfigs == X_GLXGetFBConfigs, "glxproto.h");
_Static_assert(VGLX_X_GLXGetVisualConfigs == X_GLXGetVisualConfigs, "glxproto.h");
_Static_assert(VGLX_X_GLXMakeContextCurrent == X_GLXMakeContextCurrent, "glxproto.h");
_Static_assert(VGLX_X_GLXSwapBuffers == X_GLXSwapBuffers, "glxproto.h");

void velocity_glx_error(Display* dpy, unsigned char code, unsigned long resource, unsigned char minor,
                        int core_error) {
  int opcode = 0, first_event = 0, first_error = 0;
  if (!XQueryExtension(dpy, "GLX", &opcode, &first_event, &first_error)) opcode = first_error = 0;
  xError error;
  LockDisplay(dpy);
  error.type = X_Error;
  error.errorCode = (CARD8)(core_error ? code : first_error + code);
  error.sequenceNumber = (CARD16)dpy->request;
  error.resourceID = (CARD32)resource;
  error.minorCode = minor;
  error.majorCode = (CARD8)opcode;
  _XError(dpy, &error);
  UnlockDisplay(dpy);
}

void velocity_glx_on_close(Display* dpy, int (*closing)(Display*, XExtCodes*)) {
  XExtCodes* codes = XAddExtension(dpy);
  if (codes) XESetCloseDisplay(dpy, codes->extension, closing);
}
