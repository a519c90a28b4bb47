/* GLUT's menus, driven by a script (glut_test.py menus): a menu with a sub-menu on the
 * right button, changed, shortened and re-filled before the main loop; each choice
 * printed with the menu current in its callback and sets the clear colour; the left
 * button stays the program's. Prints the root menu's width as GLUT draws it (the
 * labels' Helvetica 12 widths), so that the script can reach into the sub-menu. */
#include <GL/glut.h>
#include <stdio.h>
#include <string.h>

static int root, more;
static float colour[3] = {0.2f, 0.2f, 0.2f};

static void choose(int value) {
  printf("menu %d current %s items %d\n", value, glutGetMenu() == root ? "root" : glutGetMenu() == more ? "more" : "?",
         glutGet(GLUT_MENU_NUM_ITEMS));
  colour[0] = value == 1, colour[1] = value == 2, colour[2] = value == 3;
  glutPostRedisplay();
}

static void display(void) {
  glClearColor(colour[0], colour[1], colour[2], 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glutSwapBuffers();
}

static void mouse(int button, int state, int x, int y) {
  printf("mouse %d %d %d %d\n", button, state, x, y);
  fflush(stdout);
}

static void tick(int value) {
  glutPostRedisplay();
  glutTimerFunc(30, tick, value);
}

static int width(const char* label) { return glutBitmapLength(GLUT_BITMAP_HELVETICA_12, (const unsigned char*)label); }

int main(int argc, char** argv) {
  int w, spare;
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
  glutInitWindowSize(200, 150);
  glutCreateWindow("menus");
  glutDisplayFunc(display);
  glutMouseFunc(mouse);
  more = glutCreateMenu(choose);
  glutAddMenuEntry("Blue", 3);
  spare = glutCreateMenu(choose);
  glutAddMenuEntry("gone", 7);
  glutDestroyMenu(spare);
  root = glutCreateMenu(choose);
  glutAddMenuEntry("Red", 1);
  glutAddMenuEntry("Yellow", 5);
  glutAddMenuEntry("Removed", 6);
  printf("items %d\n", glutGet(GLUT_MENU_NUM_ITEMS));
  glutRemoveMenuItem(3);
  glutChangeToMenuEntry(2, "Green", 2);
  glutAddSubMenu("More", more);
  printf("items %d current %d\n", glutGet(GLUT_MENU_NUM_ITEMS), glutGetMenu() == root);
  glutAttachMenu(GLUT_RIGHT_BUTTON);
  w = width("Red");
  if (width("Green") > w) w = width("Green");
  if (width("More") + 14 > w) w = width("More") + 14;
  printf("root_width %d\n", w + 16);
  fflush(stdout);
  glutTimerFunc(30, tick, 0);
  glutMainLoop();
  return 0;
}
