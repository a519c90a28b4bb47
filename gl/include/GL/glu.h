/* Velocity's GLU (pGL): the GLU calls libvelocity-gl implements, and GLU 1.2's polygon
 * tessellator (the gluTess* calls, gluBeginPolygon), which is Debian's libGLU: programs
 * that link velocity-gl link it too (CMake's target, pkg-config's velocity-gl), and its
 * GL calls reach libvelocity-gl, loaded before it. NURBS (gluNurbs*) is libGLU's too, drawing
 * with pGL's evaluators, and so are gluScaleImage, gluBuild1DMipmaps, gluPickMatrix and
 * GLU 1.3's additions but gluBuild3DMipmaps (GL 1.2's 3-D textures are not pGL's).
 * GLU_VERSION_1_1 to _1_3 are defined. */
#ifndef __glu_h__
#define __glu_h__

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLU_VERSION_1_1 1
#define GLU_VERSION_1_2 1
#define GLU_VERSION_1_3 1

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

/* GLU 1.1's and 1.3's image, mipmap, picking and projection calls that are libGLU's (its
 * GL calls reach pGL): gluScaleImage, gluBuild1DMipmaps, the *MipmapLevels forms,
 * gluPickMatrix, gluCheckExtension, gluUnProject4. */
#define GLU_INVALID_OPERATION 100904
#define GLU_INCOMPATIBLE_GL_VERSION 100903
GLAPI GLint GLAPIENTRY gluScaleImage(GLenum format, GLsizei wIn, GLsizei hIn, GLenum typeIn, const void *dataIn,
                                     GLsizei wOut, GLsizei hOut, GLenum typeOut, GLvoid *dataOut);
GLAPI GLint GLAPIENTRY gluBuild1DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLenum format,
                                         GLenum type, const void *data);
GLAPI GLint GLAPIENTRY gluBuild1DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLenum format,
                                              GLenum type, GLint level, GLint base, GLint max, const void *data);
GLAPI GLint GLAPIENTRY gluBuild2DMipmapLevels(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                                              GLenum format, GLenum type, GLint level, GLint base, GLint max,
                                              const void *data);
GLAPI void GLAPIENTRY gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint *viewport);
GLAPI GLboolean GLAPIENTRY gluCheckExtension(const GLubyte *extName, const GLubyte *extString);
GLAPI GLint GLAPIENTRY gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW,
                                     const GLdouble *model, const GLdouble *proj, const GLint *view,
                                     GLdouble nearVal, GLdouble farVal, GLdouble *objX, GLdouble *objY,
                                     GLdouble *objZ, GLdouble *objW);

/* The tessellator (libGLU's; GLU 1.2 section 5). */
#define GLU_TESS_BEGIN 100100
#define GLU_BEGIN 100100
#define GLU_TESS_VERTEX 100101
#define GLU_VERTEX 100101
#define GLU_TESS_END 100102
#define GLU_END 100102
#define GLU_TESS_ERROR 100103
#define GLU_TESS_EDGE_FLAG 100104
#define GLU_EDGE_FLAG 100104
#define GLU_TESS_COMBINE 100105
#define GLU_TESS_BEGIN_DATA 100106
#define GLU_TESS_VERTEX_DATA 100107
#define GLU_TESS_END_DATA 100108
#define GLU_TESS_ERROR_DATA 100109
#define GLU_TESS_EDGE_FLAG_DATA 100110
#define GLU_TESS_COMBINE_DATA 100111
#define GLU_CW 100120
#define GLU_CCW 100121
#define GLU_INTERIOR 100122
#define GLU_EXTERIOR 100123
#define GLU_UNKNOWN 100124
#define GLU_TESS_WINDING_ODD 100130
#define GLU_TESS_WINDING_NONZERO 100131
#define GLU_TESS_WINDING_POSITIVE 100132
#define GLU_TESS_WINDING_NEGATIVE 100133
#define GLU_TESS_WINDING_ABS_GEQ_TWO 100134
#define GLU_TESS_WINDING_RULE 100140
#define GLU_TESS_BOUNDARY_ONLY 100141
#define GLU_TESS_TOLERANCE 100142
#define GLU_TESS_ERROR1 100151
#define GLU_TESS_ERROR2 100152
#define GLU_TESS_ERROR3 100153
#define GLU_TESS_ERROR4 100154
#define GLU_TESS_ERROR5 100155
#define GLU_TESS_ERROR6 100156
#define GLU_TESS_ERROR7 100157
#define GLU_TESS_ERROR8 100158
#define GLU_TESS_MISSING_BEGIN_POLYGON 100151
#define GLU_TESS_MISSING_BEGIN_CONTOUR 100152
#define GLU_TESS_MISSING_END_POLYGON 100153
#define GLU_TESS_MISSING_END_CONTOUR 100154
#define GLU_TESS_COORD_TOO_LARGE 100155
#define GLU_TESS_NEED_COMBINE_CALLBACK 100156
#define GLU_TESS_MAX_COORD 1.0e150

typedef struct GLUtesselator GLUtesselator;
typedef GLUtesselator GLUtesselatorObj;
typedef GLUtesselator GLUtriangulatorObj;

GLAPI GLUtesselator *GLAPIENTRY gluNewTess(void);
GLAPI void GLAPIENTRY gluDeleteTess(GLUtesselator *tess);
GLAPI void GLAPIENTRY gluTessCallback(GLUtesselator *tess, GLenum which, _GLUfuncptr callback);
GLAPI void GLAPIENTRY gluTessProperty(GLUtesselator *tess, GLenum which, GLdouble data);
GLAPI void GLAPIENTRY gluGetTessProperty(GLUtesselator *tess, GLenum which, GLdouble *data);
GLAPI void GLAPIENTRY gluTessNormal(GLUtesselator *tess, GLdouble x, GLdouble y, GLdouble z);
GLAPI void GLAPIENTRY gluTessBeginPolygon(GLUtesselator *tess, GLvoid *data);
GLAPI void GLAPIENTRY gluTessBeginContour(GLUtesselator *tess);
GLAPI void GLAPIENTRY gluTessVertex(GLUtesselator *tess, GLdouble *location, GLvoid *data);
GLAPI void GLAPIENTRY gluTessEndContour(GLUtesselator *tess);
GLAPI void GLAPIENTRY gluTessEndPolygon(GLUtesselator *tess);
GLAPI void GLAPIENTRY gluBeginPolygon(GLUtesselator *tess);
GLAPI void GLAPIENTRY gluNextContour(GLUtesselator *tess, GLenum type);
GLAPI void GLAPIENTRY gluEndPolygon(GLUtesselator *tess);

/* NURBS (libGLU's, GLU 1.3 chapter 7: it draws through GL's evaluators, glMap1/glMap2,
 * glEvalMesh, or in GLU_NURBS_TESSELLATOR mode to the GLU_NURBS_* callbacks). */
#define GLU_AUTO_LOAD_MATRIX 100200
#define GLU_CULLING 100201
#define GLU_PARAMETRIC_TOLERANCE 100202
#define GLU_SAMPLING_TOLERANCE 100203
#define GLU_DISPLAY_MODE 100204
#define GLU_SAMPLING_METHOD 100205
#define GLU_U_STEP 100206
#define GLU_V_STEP 100207
#define GLU_OBJECT_PARAMETRIC_ERROR 100208
#define GLU_OBJECT_PATH_LENGTH 100209
#define GLU_PATH_LENGTH 100215
#define GLU_PARAMETRIC_ERROR 100216
#define GLU_DOMAIN_DISTANCE 100217
#define GLU_MAP1_TRIM_2 100210
#define GLU_MAP1_TRIM_3 100211
#define GLU_OUTLINE_POLYGON 100240
#define GLU_OUTLINE_PATCH 100241
#define GLU_NURBS_ERROR 100103
#define GLU_NURBS_MODE 100160
#define GLU_NURBS_TESSELLATOR 100161
#define GLU_NURBS_RENDERER 100162
#define GLU_NURBS_BEGIN 100164
#define GLU_NURBS_VERTEX 100165
#define GLU_NURBS_NORMAL 100166
#define GLU_NURBS_COLOR 100167
#define GLU_NURBS_TEXTURE_COORD 100168
#define GLU_NURBS_END 100169
#define GLU_NURBS_BEGIN_DATA 100170
#define GLU_NURBS_VERTEX_DATA 100171
#define GLU_NURBS_NORMAL_DATA 100172
#define GLU_NURBS_COLOR_DATA 100173
#define GLU_NURBS_TEXTURE_COORD_DATA 100174
#define GLU_NURBS_END_DATA 100175

typedef struct GLUnurbs GLUnurbs;
typedef GLUnurbs GLUnurbsObj;

GLAPI GLUnurbs *GLAPIENTRY gluNewNurbsRenderer(void);
GLAPI void GLAPIENTRY gluDeleteNurbsRenderer(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluNurbsProperty(GLUnurbs *nurb, GLenum property, GLfloat value);
GLAPI void GLAPIENTRY gluGetNurbsProperty(GLUnurbs *nurb, GLenum property, GLfloat *data);
GLAPI void GLAPIENTRY gluNurbsCallback(GLUnurbs *nurb, GLenum which, _GLUfuncptr callback);
GLAPI void GLAPIENTRY gluNurbsCallbackData(GLUnurbs *nurb, GLvoid *userData);
GLAPI void GLAPIENTRY gluLoadSamplingMatrices(GLUnurbs *nurb, const GLfloat *model, const GLfloat *perspective,
                                              const GLint *view);
GLAPI void GLAPIENTRY gluBeginSurface(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluEndSurface(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluNurbsSurface(GLUnurbs *nurb, GLint sKnotCount, GLfloat *sKnots, GLint tKnotCount,
                                      GLfloat *tKnots, GLint sStride, GLint tStride, GLfloat *control, GLint sOrder,
                                      GLint tOrder, GLenum type);
GLAPI void GLAPIENTRY gluBeginCurve(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluEndCurve(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluNurbsCurve(GLUnurbs *nurb, GLint knotCount, GLfloat *knots, GLint stride, GLfloat *control,
                                    GLint order, GLenum type);
GLAPI void GLAPIENTRY gluBeginTrim(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluEndTrim(GLUnurbs *nurb);
GLAPI void GLAPIENTRY gluPwlCurve(GLUnurbs *nurb, GLint count, GLfloat *data, GLint stride, GLenum type);

#ifdef __cplusplus
}
#endif

#endif /* __glu_h__ */
