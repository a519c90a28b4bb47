/* A classic GLUT program, written for this project: a lit, spinning cube in a
 * double-buffered window with a depth buffer, and every callback the tests check.
 * Arrow keys turn the cube, 'p' pauses the spin, Esc or 'q' quits; it prints what each
 * callback receives, one line each, so that a test can follow it.
 *
 *   glut_demo [DUMP.ppm FREEZE_FRAME]
 *
 * With DUMP and FREEZE_FRAME, the spin stops at frame FREEZE_FRAME, and that frame, as
 * glReadPixels returns it, is written to DUMP (a binary PPM, top row first): the test
 * compares it with what the window shows. */
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>

static float angle = 20, turn = 0;
static int frame = 0, paused = 0, freeze = -1, dumped = 0;
static const char* dump_path = NULL;

static void cube(void) {
  static const float p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  /* Each face's corners counter-clockwise seen from outside, its normal and colour. */
  static const int face[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
  static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  static const float c[6][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.9f},
                                {0.9f, 0.8f, 0.2f}, {0.8f, 0.3f, 0.8f}, {0.3f, 0.8f, 0.8f}};
  int f, k;
  glBegin(GL_QUADS);
  for (f = 0; f < 6; ++f) {
    glColor3fv(c[f]);
    glNormal3fv(n[f]);
    for (k = 0; k < 4; ++k) glVertex3fv(p[face[f][k]]);
  }
  glEnd();
}

static void write_dump(void) {
  int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT), y;
  unsigned char* rgb = malloc((size_t)w * h * 3);
  FILE* f = fopen(dump_path, "wb");
  if (!rgb || !f) {
    fprintf(stderr, "glut_demo: cannot write %s\n", dump_path);
    exit(2);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (y = h - 1; y >= 0; --y) fwrite(rgb + (size_t)y * w * 3, 1, (size_t)w * 3, f); /* GL's rows are bottom-up */
  fclose(f);
  free(rgb);
  printf("dumped frame %d\n", frame);
  fflush(stdout);
}

static void display(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(angle, 0.3f, 1, 0.2f);
  glRotatef(turn, 1, 0, 0);
  cube();
  glPopMatrix();
  if (frame == freeze && dump_path && !dumped) {
    write_dump();
    dumped = 1;
  }
  glutSwapBuffers();
  ++frame;
}

static void reshape(int w, int h) {
  printf("reshape %d %d\n", w, h);
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(40, (double)w / h, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -7);
}

static void keyboard(unsigned char key, int x, int y) {
  printf("key %d %d %d\n", key, x, y);
  fflush(stdout);
  if (key == 27 || key == 'q') exit(0);
  if (key == 'p') paused = !paused;
}

static void special(int key, int x, int y) {
  printf("special %d %d %d\n", key, x, y);
  if (key == GLUT_KEY_LEFT) angle -= 10;
  if (key == GLUT_KEY_RIGHT) angle += 10;
  if (key == GLUT_KEY_UP) turn -= 10;
  if (key == GLUT_KEY_DOWN) turn += 10;
  glutPostRedisplay();
}

static void mouse(int button, int state, int x, int y) { printf("mouse %d %d %d %d\n", button, state, x, y); }

static void idle(void) {
  if (!paused && frame != freeze) angle += 2;
  if (frame <= freeze || freeze < 0) glutPostRedisplay();
}

static void timer(int value) {
  printf("timer %d after %d ms\n", value, glutGet(GLUT_ELAPSED_TIME));
  fflush(stdout);
}

int main(int argc, char** argv) {
  static const float light[4] = {0.3f, 0.5f, 1, 0};
  glutInit(&argc, argv);
  if (argc == 3) dump_path = argv[1], freeze = atoi(argv[2]);
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(320, 240);
  glutInitWindowPosition(0, 0);
  glutCreateWindow("glut_demo");
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glutDisplayFunc(display);
  glutReshapeFunc(reshape);
  glutKeyboardFunc(keyboard);
  glutSpecialFunc(special);
  glutMouseFunc(mouse);
  glutIdleFunc(idle);
  glutTimerFunc(100, timer, 7);
  glutMainLoop();
  printf("main loop left after %d frames\n", frame);
  return 0;
}
