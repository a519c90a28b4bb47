/* Framebuffer objects (GL_ARB_framebuffer_object / GL_EXT_framebuffer_object) and
 * glBlitFramebuffer.
 *
 * Frames: a 64x32 texture drawn into through an FBO with a depth renderbuffer
 * (overlapping triangles under the depth test, a scissored clear), then sampled onto the
 * window; a render-to-texture loop that draws each of two textures into the other six
 * times (blended); glGenerateMipmap of a rendered texture drawn minified; glDrawPixels,
 * glCopyPixels, glCopyTexSubImage2D and glBitmap inside an FBO; glTexSubImage2D into the
 * texture while it is attached and bound, drawn over after, and glGetTexImage of it
 * while still bound; a 1-D texture level as the
 * colour attachment; a packed depth-stencil renderbuffer (stencil test in an FBO);
 * glBlitFramebuffer from an FBO to the window (nearest: scaled, mirrored, scissored;
 * linear: enlarged), from the window to an FBO, and depth and stencil between two
 * FBOs. Values: glCheckFramebufferStatus for complete and incomplete framebuffers,
 * glGetRenderbufferParameteriv, glGetFramebufferAttachmentParameteriv (types, names,
 * levels, the channels' sizes, component types, GL_DEPTH_STENCIL_ATTACHMENT), the bindings,
 * glIs*, glReadPixels of colour, depth and stencil from FBOs (and from the
 * GL_READ_FRAMEBUFFER while another is drawn into), and the errors. Compared with Mesa. */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#define W 96
#define H 64

static void err(const char* name) { conf_value(name, (double)glGetError()); }

static void ortho(int w, int h) {
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void tri(float x0, float y0, float x1, float y1, float x2, float y2, float z) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x2, y2, z);
  glEnd();
}

/* A texture of w x h, RGBA, nearest filtering, contents undefined (NULL). */
static GLuint new_texture(int w, int h) {
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  return t;
}

/* The bound 2-D texture over the window rectangle (x0, y0)-(x1, y1), replacing. */
static void draw_texture(float x0, float y0, float x1, float y1) {
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(x0, y0);
  glTexCoord2f(1, 0), glVertex2f(x1, y0);
  glTexCoord2f(1, 1), glVertex2f(x1, y1);
  glTexCoord2f(0, 1), glVertex2f(x0, y1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

static void read_values(const char* name, int x, int y) {
  GLubyte p[4];
  char n[64];
  int i;
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  for (i = 0; i < 4; ++i) {
    snprintf(n, sizeof n, "%s_%d", name, i);
    conf_value(n, p[i]);
  }
}

static void errors_and_queries(void) {
  GLuint fb, rb[3], tex;
  GLint v = -1;
  glGenFramebuffers(1, &fb);
  conf_value("is_fb_unbound", glIsFramebuffer(fb));
  glBindFramebuffer(GL_TEXTURE_2D, fb);
  err("bind_bad_target");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  err("attach_to_window");
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  err("query_window_bad");
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  conf_value("window_front_type", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &v);
  conf_value("window_depth_size", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &v);
  conf_value("window_stencil_size", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_FRONT_LEFT, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, &v);
  conf_value("window_green_size", v);
  err("query_window");
  conf_value("status_window", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  conf_value("is_fb", glIsFramebuffer(fb));
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
  conf_value("fb_binding", v == (GLint)fb);
  conf_value("status_empty", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glClear(GL_COLOR_BUFFER_BIT);
  err("clear_incomplete");
  glCheckFramebufferStatus(GL_RENDERBUFFER);
  err("status_bad_target");

  tex = new_texture(16, 8);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, -1);
  err("level_negative");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 7777, 0);
  err("no_such_texture");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_ACCUM, GL_TEXTURE_2D, tex, 0);
  err("bad_attachment");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_1D, tex, 0);
  err("textarget_mismatch");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 1);
  conf_value("status_missing_level", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  err("attach_ok");
  conf_value("status_colour", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  conf_value("att_type", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
  conf_value("att_name", v == (GLint)tex);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  conf_value("att_level", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  conf_value("att_depth_none", v);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER_WIDTH, &v);
  err("att_bad_pname");

  glGenRenderbuffers(3, rb);
  conf_value("is_rb_unbound", glIsRenderbuffer(rb[0]));
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  err("storage_rb0");
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  conf_value("is_rb", glIsRenderbuffer(rb[0]));
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &v);
  conf_value("rb_binding", v == (GLint)rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_BGRA, 4, 4);
  err("storage_bad_format");
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, -1, 4);
  err("storage_negative");
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 20, 6);
  err("storage_ok");
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
  conf_value("rb_width", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_HEIGHT, &v);
  conf_value("rb_height", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v);
  conf_value("rb_format", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
  conf_value("rb_depth_bits", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &v);
  conf_value("rb_depth_red_bits", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, 0x1234, &v);
  err("rb_bad_pname");
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, rb[0]);
  err("rb_bad_target");
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[0]);
  err("rb_attach");
  conf_value("status_sizes_differ", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  conf_value("status_depth_as_colour", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
  conf_value("status_no_colour", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glDrawBuffer(GL_BACK);
  err("drawbuffer_back");
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  err("buffers_none");
  conf_value("status_depth_only", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glGetIntegerv(GL_DEPTH_BITS, &v);
  conf_value("depth_bits_fbo", v);

  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 8, 8);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v);
  conf_value("ds_depth_bits", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v);
  conf_value("ds_stencil_bits", v);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_GREEN_SIZE, &v);
  conf_value("rgba8_green_bits", v);
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &v);
  conf_value("rgba8_alpha_bits", v);

  glGenerateMipmap(GL_TEXTURE_ENV);
  err("mipmap_bad_target");
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  err("blit_depth_linear");
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
  err("blit_bad_filter");
  glBlitFramebuffer(0, 0, 1, 1, 0, 0, 1, 1, 0x8000, GL_NEAREST);
  err("blit_bad_mask");

  glDeleteFramebuffers(1, &fb);
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
  conf_value("binding_after_delete", v);
  conf_value("is_fb_deleted", glIsFramebuffer(fb));
  glDeleteRenderbuffers(3, rb);
  glGetIntegerv(GL_RENDERBUFFER_BINDING, &v);
  conf_value("rb_binding_after_delete", v);
  glDeleteTextures(1, &tex);
  err("deletes");
}

/* Draws into a 64x32 texture with a depth renderbuffer, samples it onto the window. */
static void render_to_texture(void) {
  GLuint fb, depth, tex;
  GLfloat z[2];
  tex = new_texture(64, 32);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 64, 32);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  conf_value("rtt_status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  ortho(64, 32);
  glClearColor(0.1f, 0.2f, 0.5f, 1);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0.5f, 0);
  tri(3, 2, 60, 6, 20, 30, 0.2f);
  glColor3f(0, 0.9f, 0.3f);
  tri(10, 28, 5, 4, 62, 20, -0.3f);  /* in front */
  glColor3f(0.8f, 0.1f, 0.9f);
  tri(40, 1, 63, 1, 50, 31, 0.6f);   /* partly behind */
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(2, 20, 9, 7);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  read_values("rtt_read_a", 30, 10);
  read_values("rtt_read_b", 5, 22);
  glReadPixels(30, 10, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z[0]);
  glReadPixels(63, 31, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z[1]);
  conf_value("rtt_depth_front", z[0]);
  conf_value("rtt_depth_clear", z[1]);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBindTexture(GL_TEXTURE_2D, tex);
  draw_texture(4, 6, 68, 38);  /* texel for pixel */
  draw_texture(70, 40, 92, 62);  /* smaller */
  conf_frame("render_to_texture");
  err("rtt_errors");
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &depth);
  glDeleteTextures(1, &tex);
}

/* Each of two textures drawn into the other, six times, blended with a moving shape. */
static void ping_pong(void) {
  GLuint fb, tex[2];
  int i;
  tex[0] = new_texture(48, 40);
  tex[1] = new_texture(48, 40);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  ortho(48, 40);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 6; ++i) {
    const GLuint from = tex[i % 2], to = tex[(i + 1) % 2];
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, to, 0);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, from);
    glColor4f(1, 1, 1, 1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.9f, 0.8f, 0.95f, 1);
    glBegin(GL_QUADS); /* the other texture, shifted by 3 pixels and darkened */
    glTexCoord2f(0, 0), glVertex2f(3, 1);
    glTexCoord2f(1, 0), glVertex2f(51, 1);
    glTexCoord2f(1, 1), glVertex2f(51, 41);
    glTexCoord2f(0, 1), glVertex2f(3, 41);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(i % 3 == 0 ? 1.0f : 0.2f, i % 3 == 1 ? 1.0f : 0.3f, i % 3 == 2 ? 1.0f : 0.1f, 0.7f);
    tri(2 + 5 * i, 3, 12 + 5 * i, 4, 6 + 4 * i, 14 + 3 * i, 0);
    glDisable(GL_BLEND);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  draw_texture(2, 2, 50, 42);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  draw_texture(50, 20, 94, 56);
  conf_frame("ping_pong");
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(2, tex);
}

/* glGenerateMipmap of a rendered texture, drawn minified with each level showing. */
static void mipmaps(void) {
  GLuint fb, tex;
  int i;
  tex = new_texture(64, 64);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  ortho(64, 64);
  glClearColor(0.0f, 0.0f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 8; ++i) { /* stripes of differing widths */
    glColor3f(i & 1 ? 1.0f : 0.2f, i & 2 ? 0.9f : 0.1f, i & 4 ? 0.8f : 0.0f);
    tri(8.0f * i, 0, 8.0f * i + 3 + i, 0, 8.0f * i, 64, 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, tex);
  glGenerateMipmap(GL_TEXTURE_2D);
  err("mipmap_errors");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_texture(2, 2, 34, 34);
  draw_texture(40, 2, 56, 18);
  draw_texture(60, 2, 68, 10);
  draw_texture(72, 2, 76, 6);
  conf_frame("mipmaps");
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

/* Pixel rectangles inside an FBO: glDrawPixels, glCopyPixels, glBitmap,
 * glCopyTexSubImage2D, and glTexSubImage2D into the attached texture while bound. */
static void pixels_in_fbo(void) {
  GLuint fb, tex, copy;
  GLubyte img[12 * 10 * 4], sub[6 * 5 * 4];
  static const GLubyte bits[8] = {0x81, 0x42, 0x24, 0x18, 0x18, 0x3c, 0x7e, 0xff};
  int i;
  for (i = 0; i < 12 * 10; ++i) {
    img[4 * i] = (GLubyte)(i * 7), img[4 * i + 1] = (GLubyte)(255 - i * 3), img[4 * i + 2] = (GLubyte)(i % 12 * 20);
    img[4 * i + 3] = 255;
  }
  for (i = 0; i < 6 * 5; ++i) sub[4 * i] = 250, sub[4 * i + 1] = (GLubyte)(i * 8), sub[4 * i + 2] = 30, sub[4 * i + 3] = 255;
  tex = new_texture(40, 30);
  copy = new_texture(16, 16);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glBindTexture(GL_TEXTURE_2D, tex);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  ortho(40, 30);
  glClearColor(0.2f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(3, 2);
  glDrawPixels(12, 10, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glRasterPos2i(20, 15);
  glCopyPixels(3, 2, 12, 10, GL_COLOR);
  glColor3f(0, 1, 1);
  glRasterPos2i(30, 3);
  glBitmap(8, 8, 0, 0, 0, 0, bits);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 31, 20, 6, 5, GL_RGBA, GL_UNSIGNED_BYTE, sub);
  glColor3f(1, 1, 0);
  tri(25, 18, 39, 29, 33, 29, 0); /* over the sub-image */
  glBindTexture(GL_TEXTURE_2D, copy);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 18, 13, 14, 12);
  read_values("pix_copied", 22, 17);
  read_values("pix_sub", 32, 21);
  { /* the attached texture read back while its FBO is bound: what was drawn */
    static GLubyte level[40 * 30 * 4];
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, level);
    for (i = 0; i < 4; ++i) {
      char n[32];
      snprintf(n, sizeof n, "pix_getteximage_%d", i);
      conf_value(n, level[(28 * 40 + 33) * 4 + i]); /* inside the yellow triangle */
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindTexture(GL_TEXTURE_2D, tex);
  draw_texture(2, 2, 42, 32);
  glBindTexture(GL_TEXTURE_2D, copy);
  draw_texture(50, 10, 82, 42);
  conf_frame("pixels_in_fbo");
  err("pixels_errors");
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
  glDeleteTextures(1, &copy);
}

/* A 1-D texture level drawn into (lines across a 32x1 framebuffer). */
static void one_d(void) {
  GLuint fb, tex;
  GLint v;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_1D, tex);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture1D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_1D, tex, 0);
  conf_value("oned_status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  conf_value("oned_type", v);
  ortho(32, 1);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0.5f, 0);
  glBegin(GL_QUADS);
  glVertex2f(5, 0), glVertex2f(19, 0), glVertex2f(19, 1), glVertex2f(5, 1);
  glEnd();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord1f(0), glVertex2f(4, 4);
  glTexCoord1f(1), glVertex2f(68, 4);
  glTexCoord1f(1), glVertex2f(68, 40);
  glTexCoord1f(0), glVertex2f(4, 40);
  glEnd();
  glDisable(GL_TEXTURE_1D);
  conf_frame("one_d");
  glDeleteFramebuffers(1, &fb);
  glDeleteTextures(1, &tex);
}

/* A packed depth-stencil renderbuffer: stencil written, then testing, in an FBO; a
 * second FBO's depth and stencil from the first by glBlitFramebuffer. */
static void depth_stencil_and_blits(void) {
  GLuint fb[2], colour[2], ds[2];
  GLubyte s[4];
  GLfloat z[3];
  int i;
  glGenFramebuffers(2, fb);
  glGenRenderbuffers(2, colour);
  glGenRenderbuffers(2, ds);
  for (i = 0; i < 2; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, fb[i]);
    glBindRenderbuffer(GL_RENDERBUFFER, colour[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 50, 40);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour[i]);
    glBindRenderbuffer(GL_RENDERBUFFER, ds[i]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 50, 40);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, ds[i]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds[i]);
    conf_value(i ? "ds_status_1" : "ds_status_0", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glClearColor(0, 0, 0, 1);
    glClearStencil(0);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  {
    static const struct { GLenum attachment, pname; const char* name; } q[] = {
        {GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, "att_ds_depth_size"},
        {GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, "att_ds_stencil_size"},
        {GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, "att_ds_type"},
        {GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE, "att_colour_red_size"},
        {GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE, "att_colour_alpha_size"},
        {GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, "att_colour_depth_size"},
        {GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, "att_colour_type"},
        {GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, "att_depth_level"},
    };
    GLint bits;
    unsigned k;
    char n[48];
    glGetIntegerv(GL_STENCIL_BITS, &bits);
    conf_value("ds_stencil_bits_fbo", bits);
    for (k = 0; k < sizeof q / sizeof q[0]; ++k) {
      bits = -1;
      glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, q[k].attachment, q[k].pname, &bits);
      conf_value(q[k].name, bits);
      snprintf(n, sizeof n, "%s_error", q[k].name);
      err(n);
    }
  }
  ortho(50, 40);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.4f, 0.4f, 0.9f);
  tri(2, 2, 45, 8, 10, 37, 0.25f);
  glStencilFunc(GL_EQUAL, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glColor3f(1, 0.8f, 0.1f);
  tri(20, 0, 50, 40, 0, 30, -0.5f);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glReadPixels(12, 12, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[0]);
  glReadPixels(4, 30, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[1]);
  conf_value("ds_stencil_both", s[0]);
  conf_value("ds_stencil_none", s[1]);

  /* Depth and stencil from FBO 0 to FBO 1, one to one. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
  glBlitFramebuffer(0, 0, 50, 40, 0, 0, 50, 40, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  err("blit_ds_error");
  glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
  glReadPixels(12, 12, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s[2]);
  glReadPixels(12, 12, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z[0]);
  glReadPixels(40, 5, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z[1]);
  glReadPixels(1, 38, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z[2]);
  conf_value("blit_stencil", s[2]);
  conf_value("blit_depth_a", z[0]);
  conf_value("blit_depth_b", z[1]);
  conf_value("blit_depth_clear", z[2]);
  /* FBO 1 draws where FBO 0's stencil and depth say (its colour stays black there). */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 6, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glColor3f(0.2f, 1, 0.4f);
  glBegin(GL_QUADS);
  glVertex2f(0, 0), glVertex2f(50, 0), glVertex2f(50, 40), glVertex2f(0, 40);
  glEnd();
  glDisable(GL_STENCIL_TEST);

  /* A read framebuffer other than the draw framebuffer. */
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  read_values("read_fb0", 12, 12);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  read_values("read_fb1", 30, 20);

  /* Colour to the window: nearest, enlarged and mirrored; scissored; linear. */
  ortho(W, H);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glBlitFramebuffer(0, 0, 50, 40, 0, 0, 50, 40, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBlitFramebuffer(0, 0, 50, 40, 95, 63, 55, 33, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  glEnable(GL_SCISSOR_TEST);
  glScissor(52, 0, 30, 25);
  glBlitFramebuffer(10, 5, 40, 30, 50, 0, 96, 31, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  err("blit_colour_error");
  conf_frame("blit_nearest");
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
  glBlitFramebuffer(4, 4, 28, 20, 0, 0, 96, 64, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  conf_frame("blit_linear");
  /* And the window into an FBO, shrunk, back out to look at it. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
  glBlitFramebuffer(0, 0, 96, 64, 0, 0, 48, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glBlitFramebuffer(0, 0, 50, 40, 20, 10, 70, 50, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  conf_frame("blit_from_window");
  err("blit_errors");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(2, fb);
  glDeleteRenderbuffers(2, colour);
  glDeleteRenderbuffers(2, ds);
}

/* Colour buffers of the luminance, alpha and intensity formats read back as RGBA
 * (luminance in red), drawn into and blended; the bits of an FBO just completed. */
static void formats(void) {
  static const GLenum bases[3] = {GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA};
  static const GLfloat texel[8] = {0.25f, 0.75f, 0.25f, 0.75f, 0.25f, 0.75f, 0.25f, 0.75f};
  GLuint fb, tex[3], depth;
  GLint v;
  GLfloat got[4];
  int i, k;
  char n[48];
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenTextures(3, tex);
  for (i = 0; i < 3; ++i) {
    glBindTexture(GL_TEXTURE_2D, tex[i]);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)bases[i], 2, 2, 0, bases[i], GL_FLOAT, texel);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[i], 0);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, got);
    for (k = 0; k < 4; ++k) snprintf(n, sizeof n, "fmt%d_read_%d", i, k), conf_value(n, (int)(got[k] * 255 + 0.5f));
    ortho(2, 2);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_DST_COLOR);
    glColor4f(0.25f, 0.5f, 0.75f, 0.5f);
    glBegin(GL_QUADS);
    glVertex2f(1, 0), glVertex2f(2, 0), glVertex2f(2, 2), glVertex2f(1, 2);
    glEnd();
    glDisable(GL_BLEND);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_FLOAT, got);
    for (k = 0; k < 4; ++k) snprintf(n, sizeof n, "fmt%d_blended_%d", i, k), conf_value(n, (int)(got[k] * 255 + 0.5f));
  }
  glGetIntegerv(GL_DEPTH_BITS, &v);
  conf_value("bits_depth_before", v);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, 2, 2);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  glGetIntegerv(GL_DEPTH_BITS, &v);
  conf_value("bits_depth_16", v);
  glGetIntegerv(GL_RED_BITS, &v);
  conf_value("bits_red", v);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &depth);
  glDeleteTextures(3, tex);
  err("formats_errors");
}

int main(int argc, char** argv) {
  conf_stencil_bits = 8;
  conf_init(argc, argv, W, H);
  errors_and_queries();
  render_to_texture();
  ping_pong();
  mipmaps();
  pixels_in_fbo();
  one_d();
  depth_stencil_and_blits();
  formats();
  err("final");
  return conf_end();
}
