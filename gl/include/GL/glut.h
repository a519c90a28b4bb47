/* GLUT for pGL: the subset of the OpenGL Utility Toolkit that classic windowed GL 1.x
 * programs use (one window, its callbacks, the main loop, timers), on Velocity's SDL2
 * window (present/). Names, types and values are GLUT's (as freeglut defines them).
 *
 *   cc demo.c $(pkg-config --cflags --libs velocity-glut) -lm
 *
 * The window's pixels are an OSMesa buffer that pGL renders into; glutSwapBuffers shows
 * it with vertical sync. One window per program. A function GLUT has and this library
 * lacks is not declared here (see docs/gl.md), so a program using one fails to build
 * rather than run without it.
 *
 * For tests and recordings (no person at the keyboard), environment variables:
 *   VELOCITY_GLUT_SCRIPT=FILE   timed key presses and mouse events (the format of
 *                               `velocity view --script`, docs in present/runtime/script.hpp)
 *   VELOCITY_GLUT_FRAMES=N      glutMainLoop returns after N frames (glutSwapBuffers
 *                               calls, wherever made; a single-buffered window's display
 *                               callbacks; a display callback's repeated
 *                               glutPostRedisplay); a program that makes another without
 *                               returning to the main loop ends there (exit status 0)
 *   VELOCITY_GLUT_RECORD=DIR    every frame shown is also written as DIR/frame_NNNNN.png,
 *                               at most N frames (VELOCITY_GLUT_FRAMES) or else 1000
 * With SDL_VIDEODRIVER=dummy no display is needed. SIGINT and SIGTERM end the program
 * wherever it is, by the signal, as they end freeglut's. */
#ifndef VELOCITY_GL_GLUT_H
#define VELOCITY_GL_GLUT_H

#include <GL/gl.h>
#include <GL/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

/* glutInitDisplayMode */
#define GLUT_RGB 0x0000
#define GLUT_RGBA 0x0000
#define GLUT_INDEX 0x0001
#define GLUT_SINGLE 0x0000
#define GLUT_DOUBLE 0x0002
#define GLUT_ACCUM 0x0004
#define GLUT_ALPHA 0x0008
#define GLUT_DEPTH 0x0010
#define GLUT_STENCIL 0x0020
#define GLUT_MULTISAMPLE 0x0080

/* glutSpecialFunc keys */
#define GLUT_KEY_F1 0x0001
#define GLUT_KEY_F2 0x0002
#define GLUT_KEY_F3 0x0003
#define GLUT_KEY_F4 0x0004
#define GLUT_KEY_F5 0x0005
#define GLUT_KEY_F6 0x0006
#define GLUT_KEY_F7 0x0007
#define GLUT_KEY_F8 0x0008
#define GLUT_KEY_F9 0x0009
#define GLUT_KEY_F10 0x000A
#define GLUT_KEY_F11 0x000B
#define GLUT_KEY_F12 0x000C
#define GLUT_KEY_LEFT 0x0064
#define GLUT_KEY_UP 0x0065
#define GLUT_KEY_RIGHT 0x0066
#define GLUT_KEY_DOWN 0x0067
#define GLUT_KEY_PAGE_UP 0x0068
#define GLUT_KEY_PAGE_DOWN 0x0069
#define GLUT_KEY_HOME 0x006A
#define GLUT_KEY_END 0x006B
#define GLUT_KEY_INSERT 0x006C

/* glutMouseFunc */
#define GLUT_LEFT_BUTTON 0x0000
#define GLUT_MIDDLE_BUTTON 0x0001
#define GLUT_RIGHT_BUTTON 0x0002
#define GLUT_DOWN 0x0000
#define GLUT_UP 0x0001

/* glutGetModifiers */
#define GLUT_ACTIVE_SHIFT 0x0001
#define GLUT_ACTIVE_CTRL 0x0002
#define GLUT_ACTIVE_ALT 0x0004

/* glutGet */
#define GLUT_WINDOW_X 0x0064
#define GLUT_WINDOW_Y 0x0065
#define GLUT_WINDOW_WIDTH 0x0066
#define GLUT_WINDOW_HEIGHT 0x0067
#define GLUT_WINDOW_DOUBLEBUFFER 0x0073
#define GLUT_SCREEN_WIDTH 0x00C8
#define GLUT_SCREEN_HEIGHT 0x00C9
#define GLUT_INIT_WINDOW_WIDTH 0x01F6
#define GLUT_INIT_WINDOW_HEIGHT 0x01F7
#define GLUT_INIT_DISPLAY_MODE 0x01F8
#define GLUT_ELAPSED_TIME 0x02BC
#define GLUT_MENU_NUM_ITEMS 0x012C

/* Initialisation */
void glutInit(int *argcp, char **argv);
void glutInitDisplayMode(unsigned int mode);
void glutInitWindowSize(int width, int height);
void glutInitWindowPosition(int x, int y);

/* The window */
int glutCreateWindow(const char *title);
void glutDestroyWindow(int window);
int glutGetWindow(void);
void glutSetWindowTitle(const char *title);
void glutReshapeWindow(int width, int height);
void glutFullScreen(void);
void glutPostRedisplay(void);
void glutSwapBuffers(void);

/* Callbacks */
void glutDisplayFunc(void (*callback)(void));
void glutReshapeFunc(void (*callback)(int width, int height));
void glutKeyboardFunc(void (*callback)(unsigned char key, int x, int y));
void glutKeyboardUpFunc(void (*callback)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*callback)(int key, int x, int y));
void glutSpecialUpFunc(void (*callback)(int key, int x, int y));
void glutMouseFunc(void (*callback)(int button, int state, int x, int y));
void glutMotionFunc(void (*callback)(int x, int y));
void glutPassiveMotionFunc(void (*callback)(int x, int y));
void glutIdleFunc(void (*callback)(void));
void glutTimerFunc(unsigned int milliseconds, void (*callback)(int value), int value);

/* Pop-up menus: drawn over the window's frame, opened by the attached mouse button;
 * choosing an entry calls the menu's callback with its value. A call naming a menu or
 * an item that does not exist prints what was wrong and ends the program (exit(1)). */
int glutCreateMenu(void (*callback)(int value));
void glutDestroyMenu(int menu);
int glutGetMenu(void);
void glutSetMenu(int menu);
void glutAddMenuEntry(const char *label, int value);
void glutAddSubMenu(const char *label, int submenu);
void glutChangeToMenuEntry(int item, const char *label, int value);
void glutChangeToSubMenu(int item, const char *label, int submenu);
void glutRemoveMenuItem(int item);
void glutAttachMenu(int button);
void glutDetachMenu(int button);

/* The main loop: never returns, except after glutLeaveMainLoop (freeglut's) or
 * VELOCITY_GLUT_FRAMES frames. Closing the window ends the program (exit(0)); SIGINT and
 * SIGTERM end it by the signal. */
void glutMainLoop(void);
void glutLeaveMainLoop(void);

/* Shapes, as freeglut draws them. */
void glutSolidSphere(double radius, GLint slices, GLint stacks);
void glutWireSphere(double radius, GLint slices, GLint stacks);
void glutSolidCone(double base, double height, GLint slices, GLint stacks);
void glutWireCone(double base, double height, GLint slices, GLint stacks);
void glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings);
void glutSolidCube(double size);
void glutWireCube(double size);
void glutSolidDodecahedron(void);
void glutWireDodecahedron(void);
void glutSolidIcosahedron(void);
void glutWireIcosahedron(void);
void glutSolidOctahedron(void);
void glutWireOctahedron(void);
void glutSolidTetrahedron(void);
void glutWireTetrahedron(void);
void glutSolidTeapot(double size);
void glutWireTeapot(double size);

/* Fonts, freeglut's glyphs (gl/glut/fonts.cpp): bitmap fonts drawn with glBitmap at
 * the raster position, stroke fonts as line strips in model space, 152.38 units high. */
extern void *glutStrokeRoman, *glutStrokeMonoRoman, *glutBitmap9By15, *glutBitmap8By13, *glutBitmapTimesRoman10,
    *glutBitmapTimesRoman24, *glutBitmapHelvetica10, *glutBitmapHelvetica12, *glutBitmapHelvetica18;
#define GLUT_STROKE_ROMAN ((void *)&glutStrokeRoman)
#define GLUT_STROKE_MONO_ROMAN ((void *)&glutStrokeMonoRoman)
#define GLUT_BITMAP_9_BY_15 ((void *)&glutBitmap9By15)
#define GLUT_BITMAP_8_BY_13 ((void *)&glutBitmap8By13)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void *)&glutBitmapTimesRoman10)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void *)&glutBitmapTimesRoman24)
#define GLUT_BITMAP_HELVETICA_10 ((void *)&glutBitmapHelvetica10)
#define GLUT_BITMAP_HELVETICA_12 ((void *)&glutBitmapHelvetica12)
#define GLUT_BITMAP_HELVETICA_18 ((void *)&glutBitmapHelvetica18)
void glutBitmapCharacter(void *font, int character);
void glutBitmapString(void *font, const unsigned char *string);
int glutBitmapWidth(void *font, int character);
int glutBitmapLength(void *font, const unsigned char *string);
int glutBitmapHeight(void *font);
void glutStrokeCharacter(void *font, int character);
void glutStrokeString(void *font, const unsigned char *string);
int glutStrokeWidth(void *font, int character);
GLfloat glutStrokeWidthf(void *font, int character);
int glutStrokeLength(void *font, const unsigned char *string);
GLfloat glutStrokeLengthf(void *font, const unsigned char *string);
GLfloat glutStrokeHeight(void *font);

/* State */
int glutGet(GLenum what);
int glutGetModifiers(void);

#ifdef __cplusplus
}
#endif

#endif /* VELOCITY_GL_GLUT_H */
