/* A GLUT program that never returns from its display callback: it loops there,
 * drawing and calling glutSwapBuffers (double-buffered) or glFlush (single-buffered),
 * and glutPostRedisplay, as some classic demos do. The tests stop it with
 * VELOCITY_GLUT_FRAMES and with SIGTERM and SIGINT.
 *
 *   glut_loop swap|post */
#include <GL/glut.h>
#include <stdio.h>
#include <string.h>

static int swap = 1;

static void display(void) {
  int turn = 0;
  for (;;) {
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glRotatef(3, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.5f, 0.2f);
    glVertex2f(-0.7f, -0.6f);
    glVertex2f(0.7f, -0.6f);
    glVertex2f(0, 0.7f);
    glEnd();
    if (swap) {
      glutSwapBuffers();
    } else {
      glFlush();
    }
    glutPostRedisplay();
    if (++turn == 1) {
      printf("looping\n");
      fflush(stdout);
    }
  }
}

int main(int argc, char** argv) {
  swap = !(argc > 1 && strcmp(argv[1], "post") == 0);
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB | (swap ? GLUT_DOUBLE : GLUT_SINGLE));
  glutInitWindowSize(32, 24);
  glutCreateWindow("loop");
  glutDisplayFunc(display);
  glutMainLoop();
  printf("main loop left\n"); /* not reached: the display callback never returns */
  return 3;
}
