/* GLUT's shapes (the teapot too), solid and wire, lit, each turned so that its asymmetries show: built
 * against Velocity's GLUT and against freeglut (on Mesa's GLX), each run writes its
 * frames (glReadPixels) as PPMs into the folder it is given, and velocity_gl_compare
 * holds them side by side (shapes_test.py). */
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>

enum { kWidth = 240, kHeight = 180 };
static const char* out_dir = ".";

static void save(const char* name) {
  static unsigned char pixels[kWidth * kHeight * 3];
  char path[1024];
  FILE* f;
  int y;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGB, GL_UNSIGNED_BYTE, pixels);
  snprintf(path, sizeof path, "%s/%s.ppm", out_dir, name);
  f = fopen(path, "wb");
  if (!f) {
    fprintf(stderr, "shapes: cannot write %s\n", path);
    exit(1);
  }
  fprintf(f, "P6\n%d %d\n255\n", kWidth, kHeight);
  for (y = kHeight - 1; y >= 0; --y) fwrite(pixels + (size_t)y * kWidth * 3, 1, kWidth * 3, f);
  fclose(f);
}

static void place(float x, float y) {
  glLoadIdentity();
  glTranslatef(x, y, -8);
  glRotatef(-55, 1, 0, 0);
  glRotatef(30, 0, 0, 1);
  glRotatef(10, 0, 1, 0);
}

static void frame(int wire) {
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glColor3f(1, 1, 1);
  place(-2.3f, 1.1f);
  (wire ? glutWireSphere : glutSolidSphere)(0.8, 13, 9);
  place(-0.6f, 0.9f);
  (wire ? glutWireCone : glutSolidCone)(0.7, 1.3, 11, 3);
  place(1.0f, 1.1f);
  (wire ? glutWireTorus : glutSolidTorus)(0.2, 0.6, 9, 14);
  place(2.5f, 1.1f);
  (wire ? glutWireCube : glutSolidCube)(1.1);
  place(-2.3f, -1.2f);
  (wire ? glutWireTetrahedron : glutSolidTetrahedron)();
  place(-0.7f, -1.2f);
  (wire ? glutWireOctahedron : glutSolidOctahedron)();
  place(0.9f, -1.2f);
  glScalef(0.45f, 0.45f, 0.45f);
  (wire ? glutWireDodecahedron : glutSolidDodecahedron)();
  place(2.5f, -1.2f);
  (wire ? glutWireIcosahedron : glutSolidIcosahedron)();
}

static void teapots(void) {
  static const unsigned char texels[4 * 4 * 3] = {255, 40,  40,  40, 255, 40,  40, 40,  255, 255, 255, 40,
                                                  40,  255, 255, 255, 40, 255, 200, 200, 200, 90,  90,  90,
                                                  255, 128, 0,   0,  128, 255, 128, 0,   255, 0,   255, 128,
                                                  250, 250, 250, 10, 10,  10,  128, 128, 128, 60,  200, 90};
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  place(-2.0f, 0.9f);
  glRotatef(70, 1, 0, 0);
  glutSolidTeapot(0.9);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  place(1.6f, 0.9f);
  glRotatef(40, 0, 0, 1);
  glRotatef(70, 1, 0, 0);
  glutSolidTeapot(0.9);
  glDisable(GL_TEXTURE_2D);
  place(-0.2f, -1.3f);
  glRotatef(70, 1, 0, 0);
  glutWireTeapot(1.0);
}

static void display(void) {
  const GLfloat pos[4] = {0.5f, 0.8f, 1.0f, 0}, diffuse[4] = {0.9f, 0.8f, 0.6f, 1};
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.55, 0.55, -0.41, 0.41, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  frame(0);
  save("solid");
  frame(1);
  save("wire_lit");
  glDisable(GL_LIGHTING);
  frame(1);
  save("wire");
  /* Teapots: solid (lit, then textured with its patches' coordinates) and wire. */
  glEnable(GL_LIGHTING);
  teapots();
  save("teapot");
  exit(0);
}

int main(int argc, char** argv) {
  if (argc > 1) out_dir = argv[1];
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
  glutInitWindowSize(kWidth, kHeight);
  glutCreateWindow("shapes");
  glutDisplayFunc(display);
  glutMainLoop();
  return 1;
}
