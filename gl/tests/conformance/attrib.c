/* glPushAttrib / glPopAttrib and glPushClientAttrib / glPopClientAttrib: each group
 * restores its own state and nothing else (a value outside the group keeps what was set
 * after the push), nested pushes, a push in a display list, the stack limits and their
 * errors, and a frame drawn with state that a pop brought back. */
#include "harness.h"

static void get(const char* name, GLenum pname) {
  GLint v[4] = {-7, -7, -7, -7};
  char n[96];
  int i;
  glGetIntegerv(pname, v);
  for (i = 0; i < 4; ++i) {
    snprintf(n, sizeof n, "%s_%d", name, i);
    conf_value(n, v[i]);
  }
}

static void getf(const char* name, GLenum pname) {
  GLfloat v[4] = {-7, -7, -7, -7};
  char n[96];
  int i;
  glGetFloatv(pname, v);
  for (i = 0; i < 4; ++i) {
    snprintf(n, sizeof n, "%s_%d", name, i);
    conf_value(n, v[i]);
  }
}

static void error(const char* name) { conf_value(name, glGetError()); }

/* Changes state in every group the program checks. */
static void change_everything(void) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glClearDepth(0.25);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 3, 0x0f);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 2, 3, 4);
  glViewport(5, 6, 7, 8);
  glDepthRange(0.2, 0.7);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glClearColor(0.5f, 0.25f, 0.75f, 1);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  glShadeModel(GL_FLAT);
  glPointSize(4);
  glLineWidth(3);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glFrontFace(GL_CW);
  glEnable(GL_FOG);
  glFogf(GL_FOG_DENSITY, 0.5f);
  glMatrixMode(GL_PROJECTION);
  glEnable(GL_NORMALIZE);
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.5f);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glHint(GL_FOG_HINT, GL_NICEST);
  glListBase(7);
}

/* GL's initial values of what change_everything changes. (Not a glPushAttrib around
 * each case: Mesa 22 loses changes made under a nested push to groups the inner push
 * did not save, so nesting is only tested where nothing else changes.) */
static void reset_everything(void) {
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearDepth(1);
  glDisable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDisable(GL_SCISSOR_TEST);
  glScissor(0, 0, 64, 64);
  glViewport(0, 0, 64, 64);
  glDepthRange(0, 1);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0, 0, 0, 0);
  glDisable(GL_LIGHTING);
  glDisable(GL_LIGHT3);
  glShadeModel(GL_SMOOTH);
  glPointSize(1);
  glLineWidth(1);
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_FOG);
  glFogf(GL_FOG_DENSITY, 1);
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_NORMALIZE);
  glColor4f(1, 1, 1, 1);
  glDisable(GL_ALPHA_TEST);
  glAlphaFunc(GL_ALWAYS, 0);
  glDisable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glHint(GL_FOG_HINT, GL_DONT_CARE);
  glListBase(0);
}

static void state(const char* prefix) {
  char n[48];
#define S(name, pname) snprintf(n, sizeof n, "%s_%s", prefix, name), get(n, pname)
#define F(name, pname) snprintf(n, sizeof n, "%s_%s", prefix, name), getf(n, pname)
  S("blend", GL_BLEND);
  S("blend_src", GL_BLEND_SRC);
  S("depth_test", GL_DEPTH_TEST);
  S("depth_func", GL_DEPTH_FUNC);
  S("depth_mask", GL_DEPTH_WRITEMASK);
  F("clear_depth", GL_DEPTH_CLEAR_VALUE);
  S("stencil_test", GL_STENCIL_TEST);
  S("stencil_func", GL_STENCIL_FUNC);
  S("stencil_ref", GL_STENCIL_REF);
  S("stencil_fail", GL_STENCIL_FAIL);
  S("scissor_test", GL_SCISSOR_TEST);
  S("scissor", GL_SCISSOR_BOX);
  S("viewport", GL_VIEWPORT);
  F("depth_range", GL_DEPTH_RANGE);
  S("color_mask", GL_COLOR_WRITEMASK);
  F("clear_color", GL_COLOR_CLEAR_VALUE);
  S("lighting", GL_LIGHTING);
  /* (Not under GL_ENABLE_BIT: Mesa 22 leaves GL_LIGHTi as it is there; pGL restores
   * it, as GL 1.5's table 6.11 puts it in the enable group too.) */
  if (!strstr(prefix, "enable")) S("light3", GL_LIGHT3);
  S("shade_model", GL_SHADE_MODEL);
  F("point_size", GL_POINT_SIZE);
  F("line_width", GL_LINE_WIDTH);
  S("cull", GL_CULL_FACE);
  S("cull_mode", GL_CULL_FACE_MODE);
  S("front_face", GL_FRONT_FACE);
  S("fog", GL_FOG);
  F("fog_density", GL_FOG_DENSITY);
  S("matrix_mode", GL_MATRIX_MODE);
  S("normalize", GL_NORMALIZE);
  F("color", GL_CURRENT_COLOR);
  S("alpha_test", GL_ALPHA_TEST);
  S("alpha_func", GL_ALPHA_TEST_FUNC);
  S("texture_2d", GL_TEXTURE_2D);
  S("fog_hint", GL_FOG_HINT);
  S("list_base", GL_LIST_BASE);
  S("depth", GL_ATTRIB_STACK_DEPTH);
#undef S
#undef F
}

int main(int argc, char** argv) {
  static const struct {
    const char* name;
    GLbitfield bit;
  } groups[] = {{"current", GL_CURRENT_BIT},     {"point", GL_POINT_BIT},         {"line", GL_LINE_BIT},
                {"polygon", GL_POLYGON_BIT},     {"lighting", GL_LIGHTING_BIT},   {"fog", GL_FOG_BIT},
                {"depth", GL_DEPTH_BUFFER_BIT},  {"stencil", GL_STENCIL_BUFFER_BIT}, {"viewport", GL_VIEWPORT_BIT},
                {"transform", GL_TRANSFORM_BIT}, {"enable", GL_ENABLE_BIT},       {"color", GL_COLOR_BUFFER_BIT},
                {"hint", GL_HINT_BIT},           {"scissor", GL_SCISSOR_BIT},     {"texture", GL_TEXTURE_BIT},
                {"list", GL_LIST_BIT},           {"all", GL_ALL_ATTRIB_BITS}};
  unsigned i;
  GLint v;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 64, 64);
  get("max_depth", GL_MAX_ATTRIB_STACK_DEPTH);
  get("max_client_depth", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH);

  /* Each group alone: push it, change everything, pop, read everything back. */
  for (i = 0; i < sizeof groups / sizeof groups[0]; ++i) {
    GLuint list = glGenLists(1);
    char n[32];
    glPushAttrib(groups[i].bit);
    change_everything();
    glPopAttrib();
    state(groups[i].name);
    reset_everything();
    error(groups[i].name);
    /* The same, with the push compiled into a list. */
    glNewList(list, GL_COMPILE);
    glPushAttrib(groups[i].bit);
    glEndList();
    glCallList(list);
    change_everything();
    glPopAttrib();
    snprintf(n, sizeof n, "list_%s", groups[i].name);
    state(n);
    reset_everything();
    glDeleteLists(list, 1);
  }

  /* Nested: each pop restores its own push. */
  glPushAttrib(GL_CURRENT_BIT | GL_POINT_BIT);
  glColor3f(0, 1, 0);
  glPointSize(3);
  glPushAttrib(GL_CURRENT_BIT);
  glColor3f(1, 0, 0);
  glPopAttrib();
  state("nested_inner");
  glPopAttrib();
  state("nested_outer");

  /* Limits: overflow and underflow, and the depth counted. */
  for (i = 0; i < 20; ++i) glPushAttrib(GL_CURRENT_BIT);
  error("overflow");
  glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &v);
  conf_value("overflow_depth", v);
  for (i = 0; i < 20; ++i) glPopAttrib();
  error("underflow");
  glBegin(GL_POINTS);
  glPushAttrib(GL_CURRENT_BIT);
  glEnd();
  error("in_begin");
  glPopClientAttrib();
  error("client_underflow");

  /* The raster position (GL_CURRENT_BIT), the pixel zoom (GL_PIXEL_MODE_BIT), the user
   * clip planes (GL_TRANSFORM_BIT: equations and enables; GL_ENABLE_BIT: enables) and
   * the pack/unpack row lengths (GL_CLIENT_PIXEL_STORE_BIT). */
  {
    static const GLdouble plane_a[4] = {1, 0, 0, 0.5}, plane_b[4] = {0, -1, 0, 0.25};
    GLdouble eq[4];
    glRasterPos2f(0.25f, -0.5f);
    glPixelZoom(2, -1);
    glClipPlane(GL_CLIP_PLANE1, plane_a);
    glEnable(GL_CLIP_PLANE1);
    glPushAttrib(GL_CURRENT_BIT | GL_PIXEL_MODE_BIT | GL_TRANSFORM_BIT);
    glRasterPos2f(-0.75f, 0.5f);
    glPixelZoom(0.5f, 3);
    glClipPlane(GL_CLIP_PLANE1, plane_b);
    glDisable(GL_CLIP_PLANE1);
    glEnable(GL_CLIP_PLANE2);
    glPopAttrib();
    getf("raster_position", GL_CURRENT_RASTER_POSITION);
    getf("zoom_x", GL_ZOOM_X);
    getf("zoom_y", GL_ZOOM_Y);
    get("clip1", GL_CLIP_PLANE1);
    get("clip2", GL_CLIP_PLANE2);
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    conf_value("clip1_a", eq[0]);
    conf_value("clip1_d", eq[3]);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_CLIP_PLANE1);
    glClipPlane(GL_CLIP_PLANE1, plane_b);
    glPopAttrib();
    get("enable_clip1", GL_CLIP_PLANE1);
    glGetClipPlane(GL_CLIP_PLANE1, eq);
    conf_value("enable_clip1_kept_b", eq[1]);
    glDisable(GL_CLIP_PLANE1);
    glPixelZoom(1, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
    glPixelStorei(GL_PACK_SKIP_ROWS, 2);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
    glPixelStorei(GL_PACK_SKIP_ROWS, 5);
    glPopClientAttrib();
    get("client_unpack_row_length", GL_UNPACK_ROW_LENGTH);
    get("client_pack_skip_rows", GL_PACK_SKIP_ROWS);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    error("pixels_and_planes");
  }

  /* Client state: the pixel store and the vertex arrays. */
  {
    static const GLfloat tri[6] = {-1, -1, 1, -1, 0, 1};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glEnableClientState(GL_VERTEX_ARRAY);
    glPopClientAttrib();
    get("client_unpack", GL_UNPACK_ALIGNMENT);
    get("client_array_kept", GL_VERTEX_ARRAY);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_SHORT, 6, tri);
    glPopClientAttrib();
    get("client_array", GL_VERTEX_ARRAY);
    get("client_array_size", GL_VERTEX_ARRAY_SIZE);
    get("client_array_type", GL_VERTEX_ARRAY_TYPE);
    get("client_depth", GL_CLIENT_ATTRIB_STACK_DEPTH);
    /* A frame drawn with what the pop brought back. */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glPushAttrib(GL_CURRENT_BIT | GL_ENABLE_BIT);
    glColor3f(0, 1, 0);
    glPushAttrib(GL_CURRENT_BIT);
    glColor3f(1, 0, 0);
    glPopAttrib();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glPopAttrib();
    glDisableClientState(GL_VERTEX_ARRAY);
    conf_frame("drawn");
    error("end");
  }
  return conf_end();
}
