/* Velocity's GLU subset (pGL): the GLU calls libvelocity-gl implements. GLU_VERSION_1_1
 * is defined (gluGetString, 1.1's addition, exists); GLU_VERSION_1_2 and _1_3 are not,
 * as their additions (the gluTess* tessellator, gluCheckExtension, gluBuild*MipmapLevels,
 * gluUnProject4) do not exist here: a program guarded by them takes its fallback. */
#ifndef __glu_h__
#define __glu_h__

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLU_VERSION_1_1 1

#define GLU_FALSE 0
#define GLU_TRUE 1
#define GLU_INVALID_ENUM 100900
#define GLU_INVALID_VALUE 100901
#define GLU_OUT_OF_MEMORY 100902
#define GLU_VERSION 100800
#define GLU_EXTENSIONS 100801

/* Quadrics (gluNewQuadric and the calls taking a GLUquadric). */
#define GLU_SMOOTH 100000
#define GLU_FLAT 100001
#define GLU_NONE 100002
#define GLU_POINT 100010
#define GLU_LINE 100011
#define GLU_FILL 100012
#define GLU_SILHOUETTE 100013
#define GLU_OUTSIDE 100020
#define GLU_INSIDE 100021
#define GLU_ERROR 100103

typedef struct GLUquadric GLUquadric;
typedef GLUquadric GLUquadricObj;
typedef void(GLAPIENTRY *_GLUfuncptr)(void);

GLAPI void GLAPIENTRY gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar);
GLAPI void GLAPIENTRY gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top);
GLAPI void GLAPIENTRY gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX, GLdouble centerY,
                                GLdouble centerZ, GLdouble upX, GLdouble upY, GLdouble upZ);
GLAPI GLint GLAPIENTRY gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble *model,
                                  const GLdouble *proj, const GLint *view, GLdouble *winX, GLdouble *winY,
                                  GLdouble *winZ);
GLAPI GLint GLAPIENTRY gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble *model,
                                    const GLdouble *proj, const GLint *view, GLdouble *objX, GLdouble *objY,
                                    GLdouble *objZ);
GLAPI GLint GLAPIENTRY gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                         GLenum format, GLenum type, const void *data);
GLAPI const GLubyte *GLAPIENTRY gluErrorString(GLenum error);

GLAPI GLUquadric *GLAPIENTRY gluNewQuadric(void);
GLAPI void GLAPIENTRY gluDeleteQuadric(GLUquadric *quad);
GLAPI void GLAPIENTRY gluQuadricCallback(GLUquadric *quad, GLenum which, _GLUfuncptr callback);
GLAPI void GLAPIENTRY gluQuadricDrawStyle(GLUquadric *quad, GLenum draw);
GLAPI void GLAPIENTRY gluQuadricNormals(GLUquadric *quad, GLenum normal);
GLAPI void GLAPIENTRY gluQuadricOrientation(GLUquadric *quad, GLenum orientation);
GLAPI void GLAPIENTRY gluQuadricTexture(GLUquadric *quad, GLboolean texture);
GLAPI void GLAPIENTRY gluSphere(GLUquadric *quad, GLdouble radius, GLint slices, GLint stacks);
GLAPI void GLAPIENTRY gluCylinder(GLUquadric *quad, GLdouble base, GLdouble top, GLdouble height, GLint slices,
                                  GLint stacks);
GLAPI void GLAPIENTRY gluDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops);
GLAPI void GLAPIENTRY gluPartialDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices, GLint loops,
                                     GLdouble start, GLdouble sweep);
GLAPI const GLubyte *GLAPIENTRY gluGetString(GLenum name);

#ifdef __cplusplus
}
#endif

#endif /* __glu_h__ */
