/* Velocity's OSMesa (pGL): off-screen OpenGL 1.x contexts that render into a buffer the
 * program owns, with Mesa's OSMesa names and values, so that headless Mesa programs
 * relink against libvelocity-gl unchanged. */
#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSMESA_MAJOR_VERSION 11
#define OSMESA_MINOR_VERSION 2
#define OSMESA_PATCH_VERSION 0

/* Pixel formats of the colour buffer (type GL_UNSIGNED_BYTE) */
#define OSMESA_COLOR_INDEX GL_COLOR_INDEX
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4

/* OSMesaPixelStore */
#define OSMESA_ROW_LENGTH 0x10
#define OSMESA_Y_UP 0x11

/* OSMesaGetIntegerv */
#define OSMESA_WIDTH 0x20
#define OSMESA_HEIGHT 0x21
#define OSMESA_FORMAT 0x22
#define OSMESA_TYPE 0x23
#define OSMESA_MAX_WIDTH 0x24
#define OSMESA_MAX_HEIGHT 0x25

typedef struct osmesa_context *OSMesaContext;

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits,
                                                      GLint accumBits, OSMesaContext sharelist);
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width,
                                             GLsizei height);
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void);
GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value);
GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint *value);
GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint *width, GLint *height, GLint *bytesPerValue,
                                                void **buffer);
/* The colour buffer of a context made current (GL_FALSE before); OSMesaColorClamp (no
 * effect: the buffers are 8 bits a channel, clamped anyway); the address of a gl* or
 * OSMesa* function by name. */
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint *width, GLint *height, GLint *format,
                                                void **buffer);
GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable);
typedef void (*OSMESAproc)(void);
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char *funcName);

#ifdef __cplusplus
}
#endif

#endif /* OSMESA_H */
