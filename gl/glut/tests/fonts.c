/* GLUT's fonts: every bitmap font's printable characters (glutBitmapString with
 * newlines, glutBitmapCharacter, Latin-1 characters above 127) in colours, both stroke
 * fonts scaled, turned and with newlines (glutStrokeString, glutStrokeCharacter), and
 * the widths, lengths and heights. Built against Velocity's GLUT and against freeglut
 * (on Mesa's GLX): each run writes its frames and values.txt into the folder it is
 * given, and velocity_gl_compare holds them side by side (shapes_test.py). */
#include <GL/glut.h>
#ifndef VELOCITY_GL
#include <GL/freeglut.h> /* freeglut declares glutBitmapString and the rest there */
#endif
#include <stdio.h>
#include <stdlib.h>

enum { kWidth = 400, kHeight = 300 };
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
    fprintf(stderr, "fonts: cannot write %s\n", path);
    exit(1);
  }
  fprintf(f, "P6\n%d %d\n255\n", kWidth, kHeight);
  for (y = kHeight - 1; y >= 0; --y) fwrite(pixels + (size_t)y * kWidth * 3, 1, kWidth * 3, f);
  fclose(f);
}

static void value(const char* name, double v) {
  char path[1024];
  FILE* f;
  snprintf(path, sizeof path, "%s/values.txt", out_dir);
  f = fopen(path, "a");
  if (!f) exit(1);
  fprintf(f, "%s %.6g\n", name, v);
  fclose(f);
}

static void* const bitmap_fonts[7] = {GLUT_BITMAP_8_BY_13,      GLUT_BITMAP_9_BY_15,      GLUT_BITMAP_TIMES_ROMAN_10,
                                      GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
                                      GLUT_BITMAP_HELVETICA_18};

static void bitmaps(void) {
  static const unsigned char latin1[] = {0xC0, 0xE9, 0xF1, 0xFC, 0xDF, 0xA9, 0xB0, 0xBD, 0};
  unsigned char line[100];
  int i, c, y = kHeight - 16;
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 7; ++i) {
    /* The printable characters, 48 a line, the rest after a newline. */
    int n = 0;
    for (c = 32; c < 127; ++c) {
      line[n++] = (unsigned char)c;
      if (c == 79) line[n++] = '\n';
    }
    line[n] = 0;
    glColor3f(1.0f - 0.12f * (float)i, 0.4f + 0.08f * (float)i, 0.3f + 0.1f * (float)i);
    glRasterPos2i(4 + 3 * i, y);
    glutBitmapString(bitmap_fonts[i], line);
    y -= 2 * glutBitmapHeight(bitmap_fonts[i]) + 2;
  }
  /* Characters one at a time, Latin-1 ones, and a raster position that moves off the
   * left edge and back (a glyph there is clipped, the advance still counts). */
  glColor3f(1, 1, 0);
  glRasterPos2i(250, 20);
  for (i = 0; latin1[i]; ++i) glutBitmapCharacter(GLUT_BITMAP_HELVETICA_18, latin1[i]);
  glRasterPos2i(2, 6);
  glBitmap(0, 0, 0, 0, -10, 0, NULL);
  glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char*)"edge");
  /* The unpack state a program set is put back. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glutBitmapCharacter(GLUT_BITMAP_8_BY_13, 'A');
  {
    GLint a, r;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &a);
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &r);
    value("unpack_alignment_after", a);
    value("unpack_row_length_after", r);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

static void strokes(void) {
  glClearColor(0.05f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glTranslatef(6, 250, 0);
  glScalef(0.15f, 0.15f, 1);
  glColor3f(1, 0.8f, 0.3f);
  glutStrokeString(GLUT_STROKE_ROMAN, (const unsigned char*)"The quick brown fox\njumps over 12,345 lazy dogs!");
  glPopMatrix();
  glPushMatrix();
  glTranslatef(10, 120, 0);
  glRotatef(12, 0, 0, 1);
  glScalef(0.12f, 0.2f, 1);
  glColor3f(0.4f, 0.9f, 1);
  glutStrokeString(GLUT_STROKE_MONO_ROMAN, (const unsigned char*)"MONO {[(<~`'\"|\\/>)]} @#$%^&*");
  glPopMatrix();
  glPushMatrix();
  glTranslatef(20, 40, 0);
  glScalef(0.3f, 0.3f, 1);
  glColor3f(0.9f, 0.4f, 1);
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 'G');
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 'l');
  glutStrokeCharacter(GLUT_STROKE_MONO_ROMAN, 'u');
  glutStrokeCharacter(GLUT_STROKE_MONO_ROMAN, 't');
  glutStrokeCharacter(GLUT_STROKE_ROMAN, 200); /* none: nothing drawn, no advance */
  glutStrokeCharacter(GLUT_STROKE_ROMAN, '!');
  glPopMatrix();
}

static void measures(void) {
  static const unsigned char text[] = "Width of this\nand of a longer line";
  char name[64];
  int i;
  for (i = 0; i < 7; ++i) {
    snprintf(name, sizeof name, "bitmap%d_height", i);
    value(name, glutBitmapHeight(bitmap_fonts[i]));
    snprintf(name, sizeof name, "bitmap%d_width_W", i);
    value(name, glutBitmapWidth(bitmap_fonts[i], 'W'));
    snprintf(name, sizeof name, "bitmap%d_width_i", i);
    value(name, glutBitmapWidth(bitmap_fonts[i], 'i'));
    snprintf(name, sizeof name, "bitmap%d_width_e_acute", i);
    value(name, glutBitmapWidth(bitmap_fonts[i], 0xE9));
    snprintf(name, sizeof name, "bitmap%d_length", i);
    value(name, glutBitmapLength(bitmap_fonts[i], text));
  }
  value("bitmap_width_0", glutBitmapWidth(GLUT_BITMAP_9_BY_15, 0));
  value("bitmap_width_256", glutBitmapWidth(GLUT_BITMAP_9_BY_15, 256));
  value("stroke_height", glutStrokeHeight(GLUT_STROKE_ROMAN));
  value("stroke_mono_height", glutStrokeHeight(GLUT_STROKE_MONO_ROMAN));
  value("stroke_width_W", glutStrokeWidth(GLUT_STROKE_ROMAN, 'W'));
  value("stroke_widthf_W", glutStrokeWidthf(GLUT_STROKE_ROMAN, 'W'));
  value("stroke_widthf_i", glutStrokeWidthf(GLUT_STROKE_ROMAN, 'i'));
  value("stroke_mono_widthf_i", glutStrokeWidthf(GLUT_STROKE_MONO_ROMAN, 'i'));
  value("stroke_width_200", glutStrokeWidth(GLUT_STROKE_ROMAN, 200));
  value("stroke_length", glutStrokeLength(GLUT_STROKE_ROMAN, text));
  value("stroke_lengthf", glutStrokeLengthf(GLUT_STROKE_ROMAN, text));
  value("stroke_mono_lengthf", glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, text));
}

static void display(void) {
  glViewport(0, 0, kWidth, kHeight);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  bitmaps();
  save("bitmap_fonts");
  strokes();
  save("stroke_fonts");
  measures();
  exit(0);
}

int main(int argc, char** argv) {
  char path[1024];
  FILE* f;
  if (argc > 1) out_dir = argv[1];
  snprintf(path, sizeof path, "%s/values.txt", out_dir);
  f = fopen(path, "w");
  if (f) fclose(f);
  glutInit(&argc, argv);
  glutInitDisplayMode(GLUT_RGB | GLUT_SINGLE);
  glutInitWindowSize(kWidth, kHeight);
  glutCreateWindow("fonts");
  glutDisplayFunc(display);
  glutMainLoop();
  return 1;
}
