/* Between glBegin and glEnd a command that takes the caller's memory (glDrawPixels,
 * glBitmap, glPolygonStipple, glTexImage1D/2D/3D, glTexSubImage1D/2D/3D) is
 * GL_INVALID_OPERATION and reads nothing: GL 1.5 section 2.6.3 says such a command is
 * not executed, and the unpack state there may not describe the memory, since
 * glPixelStore is refused too (a fuzzer found glDrawPixels reading past its buffer so).
 * Each call gets a pointer to a page that cannot be read: reading it would crash. Then,
 * after glEnd, the same glDrawPixels of a readable copy draws. Mesa is no oracle for a
 * crash, so this runs on Velocity alone. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <sys/mman.h>
#include <unistd.h>

static int failures = 0;

static void expect_error(const char* what, GLenum want) {
  const GLenum got = glGetError();
  if (got == want) return;
  fprintf(stderr, "begin_reads: %s gave error 0x%x, expected 0x%x\n", what, got, want);
  ++failures;
}

int main(void) {
  static unsigned char buffer[8 * 8 * 4];
  static const GLubyte red[4] = {255, 0, 0, 255};
  const size_t page = (size_t)sysconf(_SC_PAGESIZE);
  const GLubyte* locked = mmap(NULL, page, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  GLuint texture = 0;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (locked == MAP_FAILED || !ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 2;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glRasterPos2f(-1, -1);
  expect_error("setting up", GL_NO_ERROR);

  /* Each call alone in a glBegin/glEnd pair (glGetError there is itself the error). */
#define IN_BEGIN(call, what)    \
  glBegin(GL_TRIANGLES);        \
  call;                         \
  glEnd();                      \
  expect_error(what, GL_INVALID_OPERATION)
  IN_BEGIN(glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glDrawPixels in glBegin");
  IN_BEGIN(glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, locked), "glDrawPixels(GL_STENCIL_INDEX) in glBegin");
  IN_BEGIN(glBitmap(8, 8, 0, 0, 0, 0, locked), "glBitmap in glBegin");
  IN_BEGIN(glPolygonStipple(locked), "glPolygonStipple in glBegin");
  IN_BEGIN(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexImage1D in glBegin");
  IN_BEGIN(glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexSubImage1D in glBegin");
  IN_BEGIN(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexImage2D in glBegin");
  IN_BEGIN(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexSubImage2D in glBegin");
  IN_BEGIN(glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexImage3D in glBegin");
  IN_BEGIN(glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, locked), "glTexSubImage3D in glBegin");
  expect_error("glEnd", GL_NO_ERROR);

  /* Outside glBegin the same call draws. */
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glFinish();
  expect_error("glDrawPixels after glEnd", GL_NO_ERROR);
  if (buffer[0] != 255 || buffer[1] != 0 || buffer[3] != 255) {
    fprintf(stderr, "begin_reads: glDrawPixels after glEnd drew %d %d %d %d, expected 255 0 0 255\n", buffer[0],
            buffer[1], buffer[2], buffer[3]);
    ++failures;
  }
  OSMesaDestroyContext(ctx);
  munmap((void*)locked, page);
  return failures ? 1 : 0;
}
