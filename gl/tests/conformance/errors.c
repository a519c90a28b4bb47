/* glGetError's codes for misuse, glGet's values for the state, and glReadPixels,
 * compared as values with Mesa's. */
#include "harness.h"

static void err(const char* what) { conf_value(what, (double)glGetError()); }

/* glGetIntegerv(pname) into a variable preset to -7: no error and the variable set, and
 * with `exact`, its first value as Mesa's. (Without: limits of features Velocity lacks,
 * 0 there, and sizes it draws differently; docs/gl.md.) */
static void query(const char* name, GLenum pname, int exact) {
  GLint v[2] = {-7, -7};
  char n[96];
  glGetIntegerv(pname, v);
  snprintf(n, sizeof n, "%s_error", name);
  err(n);
  snprintf(n, sizeof n, "%s_set", name);
  conf_value(n, v[0] != -7);
  if (exact) conf_value(name, v[0]);
}

int main(int argc, char** argv) {
  GLint iv[4];
  GLfloat fv[16];
  GLboolean bv[4];
  GLdouble dv[4];
  GLubyte px[4 * 4 * 4];
  GLfloat depth[4];
  int i;
  conf_init(argc, argv, 64, 48);

  err("initial");
  glBegin(GL_TRIANGLES);
  glBegin(GL_TRIANGLES);
  glEnd();
  err("begin_in_begin");
  glEnd();
  err("end_without_begin");
  glBegin(GL_TRIANGLES);
  glEnable(GL_DEPTH_TEST);
  glEnd();
  err("enable_in_begin");
  /* glGetError between glBegin and glEnd: the call is the error and returns 0, so a
   * loop that drains the errors there ends; glEnd's glGetError reports it once. */
  glBegin(GL_TRIANGLES);
  err("geterror_in_begin");
  for (i = 0; i < 8 && glGetError() != GL_NO_ERROR; ++i) continue;
  conf_value("geterror_in_begin_drained", i);
  glEnd();
  err("geterror_after_begin");
  err("geterror_after_begin_again");
  glEnable(0x1234);
  glBegin(GL_POINTS);
  err("geterror_in_begin_keeps_earlier");
  glEnd();
  err("geterror_earlier_after_end");
  err("geterror_earlier_after_end_again");
  glEnable(0x1234);
  err("bad_enable");
  glBegin(0x20);
  err("bad_mode");
  glDepthFunc(GL_TRIANGLES);
  err("bad_depth_func");
  glViewport(0, 0, -1, 10);
  err("negative_viewport");
  glScissor(0, 0, 5, -5);
  err("negative_scissor");
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  err("projection_underflow");
  for (i = 0; i < 40; ++i) glPushMatrix();
  err("projection_overflow");
  glGetIntegerv(GL_PROJECTION_STACK_DEPTH, iv);
  conf_value("projection_depth_full", iv[0] >= 2);
  for (i = 0; i < 40; ++i) glPopMatrix();
  err("pops_after_overflow");
  glMatrixMode(GL_MODELVIEW);
  glMatrixMode(GL_LINE);
  err("bad_matrix_mode");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("teximage_negative");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("teximage_border");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, NULL);
  err("teximage_type");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_REPEAT);
  err("texparam_bad");
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR);
  err("texenv_bad");
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_SRC_ALPHA_SATURATE);
  err("blend_dst_saturate");
  glNewList(0, GL_COMPILE);
  err("newlist_zero");
  glEndList();
  err("endlist_without_newlist");
  glNewList(1, 0x1234);
  err("newlist_bad_mode");
  glGenLists(-1);
  err("genlists_negative");
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 120);
  err("spot_cutoff_range");
  glMaterialf(GL_FRONT, GL_SHININESS, 200);
  err("shininess_range");
  glPointSize(0);
  err("point_size_zero");
  glLineWidth(-1);
  err("line_width_negative");
  glDrawArrays(GL_TRIANGLES, 0, -1);
  err("drawarrays_negative");
  glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, NULL);
  err("drawelements_type");
  glGetIntegerv(0x9999, iv);
  err("get_bad");
  glClear(0x80000000u);
  err("clear_bad_bits");
  glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, px);
  err("readpixels_type");

  /* glGet of state set above and of defaults. */
  glGetIntegerv(GL_VIEWPORT, iv);
  for (i = 0; i < 4; ++i) conf_value("viewport", iv[i]);
  glGetIntegerv(GL_MATRIX_MODE, iv);
  conf_value("matrix_mode", iv[0]);
  glGetBooleanv(GL_DEPTH_TEST, bv);
  conf_value("depth_test", bv[0]);
  glGetIntegerv(GL_DEPTH_FUNC, iv);
  conf_value("depth_func", iv[0]);
  glGetIntegerv(GL_MAX_LIGHTS, iv);
  conf_value("max_lights", iv[0]);
  glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, iv);
  conf_value("modelview_depth", iv[0]);
  /* GL_EXTENSIONS names each extension pGL has (token-only ones, all in Mesa's list
   * too); GLU 1.1's gluGetString. */
  {
    static const char* const names[] = {"GL_ARB_texture_env_add", "GL_ARB_texture_mirrored_repeat",
                                        "GL_ARB_texture_non_power_of_two", "GL_EXT_bgra", "GL_EXT_rescale_normal",
                                        "GL_EXT_texture_edge_clamp", "GL_EXT_texture_env_add",
                                        "GL_IBM_texture_mirrored_repeat", "GL_SGIS_texture_edge_clamp"};
    const char* ext = (const char*)glGetString(GL_EXTENSIONS);
    const char* glu_version = (const char*)gluGetString(GLU_VERSION);
    for (i = 0; i < 9; ++i) conf_value(names[i], ext && strstr(ext, names[i]) != NULL);
#ifdef GLU_VERSION_1_1
    conf_value("glu_version_1_1", 1);
#endif
    conf_value("glu_version_major", glu_version ? atoi(glu_version) : -1);
    conf_value("glu_extensions", gluGetString(GLU_EXTENSIONS) != NULL);
    conf_value("glu_get_string_bad", gluGetString(GL_VENDOR) == NULL);
  }
  /* The framebuffer's and the implementation's values that answered GL_INVALID_ENUM
   * (the context has no stencil or accumulation buffer, as conf_init asks Mesa). */
  query("stencil_bits", GL_STENCIL_BITS, 1);
  query("accum_red_bits", GL_ACCUM_RED_BITS, 1);
  query("accum_green_bits", GL_ACCUM_GREEN_BITS, 1);
  query("accum_blue_bits", GL_ACCUM_BLUE_BITS, 1);
  query("accum_alpha_bits", GL_ACCUM_ALPHA_BITS, 1);
  query("aux_buffers", GL_AUX_BUFFERS, 1);
  query("index_bits", GL_INDEX_BITS, 1);
  query("rgba_mode", GL_RGBA_MODE, 1);
  query("index_mode", GL_INDEX_MODE, 1);
  query("stereo", GL_STEREO, 1);
  query("doublebuffer", GL_DOUBLEBUFFER, 1);
  query("draw_buffer", GL_DRAW_BUFFER, 1);
  query("read_buffer", GL_READ_BUFFER, 1);
  query("sample_buffers", GL_SAMPLE_BUFFERS, 1);
  query("samples", GL_SAMPLES, 1);
  query("subpixel_bits", GL_SUBPIXEL_BITS, 1);
  query("max_list_nesting", GL_MAX_LIST_NESTING, 1);
  query("point_size_range", GL_POINT_SIZE_RANGE, 1);
  query("line_width_range", GL_LINE_WIDTH_RANGE, 1);
  query("aliased_point_size_range", GL_ALIASED_POINT_SIZE_RANGE, 1);
  query("aliased_line_width_range", GL_ALIASED_LINE_WIDTH_RANGE, 1);
  query("point_size_granularity", GL_POINT_SIZE_GRANULARITY, 0);
  query("line_width_granularity", GL_LINE_WIDTH_GRANULARITY, 0);
  query("max_texture_units", GL_MAX_TEXTURE_UNITS, 0);
  query("num_compressed_texture_formats", GL_NUM_COMPRESSED_TEXTURE_FORMATS, 0);
  query("max_clip_planes", GL_MAX_CLIP_PLANES, 0);
  query("max_eval_order", GL_MAX_EVAL_ORDER, 0);
  query("max_attrib_stack_depth", GL_MAX_ATTRIB_STACK_DEPTH, 0);
  query("max_client_attrib_stack_depth", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 0);
  query("max_name_stack_depth", GL_MAX_NAME_STACK_DEPTH, 0);
  query("max_pixel_map_table", GL_MAX_PIXEL_MAP_TABLE, 0);
  glTranslatef(1, 2, 3);
  glRotatef(90, 0, 0, 1);
  glScalef(2, 2, 2);
  glGetFloatv(GL_MODELVIEW_MATRIX, fv);
  for (i = 0; i < 16; ++i) conf_value("modelview", fv[i]);
  glLoadIdentity();
  glClearColor(0.25f, 0.5f, 0.75f, 1);
  glGetDoublev(GL_COLOR_CLEAR_VALUE, dv);
  for (i = 0; i < 4; ++i) conf_value("clear_color", dv[i]);
  glGetFloatv(GL_CURRENT_COLOR, fv);
  for (i = 0; i < 4; ++i) conf_value("current_color", fv[i]);
  glGetIntegerv(GL_SHADE_MODEL, iv);
  conf_value("shade_model", iv[0]);
  glGetIntegerv(GL_CULL_FACE_MODE, iv);
  conf_value("cull_face_mode", iv[0]);
  glGetIntegerv(GL_FRONT_FACE, iv);
  conf_value("front_face", iv[0]);
  glGetIntegerv(GL_BLEND_SRC, iv);
  conf_value("blend_src", iv[0]);
  glGetIntegerv(GL_BLEND_DST, iv);
  conf_value("blend_dst", iv[0]);
  glGetFloatv(GL_FOG_DENSITY, fv);
  conf_value("fog_density", fv[0]);
  glGetIntegerv(GL_FOG_MODE, iv);
  conf_value("fog_mode", iv[0]);
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, fv);
  for (i = 0; i < 4; ++i) conf_value("light0_diffuse", fv[i]);
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, fv);
  for (i = 0; i < 4; ++i) conf_value("light1_diffuse", fv[i]);
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, fv);
  for (i = 0; i < 4; ++i) conf_value("material_ambient", fv[i]);
  conf_value("is_enabled_lighting", glIsEnabled(GL_LIGHTING));
  err("after_gets");

  /* gluProject / gluUnProject with the matrices read back by glGetDoublev. */
  {
    GLdouble model[16], proj[16], wx, wy, wz, ox, oy, oz;
    GLint view[4];
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, 4.0 / 3.0, 0.5, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(1, 2, 6, 0, 0.5, 0, 0, 1, 0);
    glRotatef(30, 0, 1, 0);
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    glGetIntegerv(GL_VIEWPORT, view);
    conf_value("glu_project_ok", gluProject(0.5, -0.25, 1.0, model, proj, view, &wx, &wy, &wz));
    conf_value("glu_project_x", wx);
    conf_value("glu_project_y", wy);
    conf_value("glu_project_z", wz);
    conf_value("glu_unproject_ok", gluUnProject(wx, wy, wz, model, proj, view, &ox, &oy, &oz));
    conf_value("glu_unproject_x", ox);
    conf_value("glu_unproject_y", oy);
    conf_value("glu_unproject_z", oz);
    glLoadIdentity();
  }

  /* glReadPixels: a cleared frame with two coloured rectangles. */
  glClearColor(0.2f, 0.4f, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 48, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glRectf(0, 0, 2, 2);
  glColor3f(0, 1, 0);
  glBegin(GL_QUADS);
  glVertex3f(10, 10, 0.5f);
  glVertex3f(20, 10, 0.5f);
  glVertex3f(20, 20, 0.5f);
  glVertex3f(10, 20, 0.5f);
  glEnd();
  glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
  for (i = 0; i < 4 * 4 * 4; i += 5) conf_value("readpixels_rgba", px[i]);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(12, 12, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
  for (i = 0; i < 6; ++i) conf_value("readpixels_rgb", px[i]);
  glReadPixels(12, 12, 1, 1, GL_RGBA, GL_FLOAT, fv);
  for (i = 0; i < 4; ++i) conf_value("readpixels_float", fv[i]);
  glReadPixels(12, 12, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_value("readpixels_depth", depth[0] > 0.2f && depth[0] < 0.3f);
  glReadPixels(40, 40, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  conf_value("readpixels_depth_clear", depth[0]);
  err("after_readpixels");
  conf_frame("readpixels");
  return conf_end();
}
