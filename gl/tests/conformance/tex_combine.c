/* GL 1.3's GL_COMBINE texture environment (ARB_texture_env_combine, _dot3): each
 * function of GL_COMBINE_RGB and GL_COMBINE_ALPHA on an RGBA texture of uneven colours
 * and alphas, smooth primary colours and a constant colour; every source and operand;
 * the scales; the texture's colour per base format (ALPHA, LUMINANCE, INTENSITY, RGB);
 * GL_PREVIOUS and GL_PRIMARY_COLOR on a second unit. Then glGetTexEnv (every pname, per
 * unit, after glPopAttrib), glGetTexParameter (every parameter, 1-D, 2-D, 3-D) and
 * the errors of all three. */
#define GL_GLEXT_PROTOTYPES 1 /* GL 1.3's functions in the system headers */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

/* An 8x8 texture of uneven colours and alphas in `internal` format. */
static void texture(GLenum internal) {
  static GLubyte texels[8 * 8 * 4];
  int x, y;
  for (y = 0; y < 8; ++y)
    for (x = 0; x < 8; ++x) {
      GLubyte* t = texels + 4 * (y * 8 + x);
      t[0] = (GLubyte)(30 + 28 * x), t[1] = (GLubyte)(220 - 25 * y), t[2] = (GLubyte)((x * y * 9) & 255);
      t[3] = (GLubyte)(40 + 20 * ((x + 2 * y) % 10));
    }
  glTexImage2D(GL_TEXTURE_2D, 0, internal, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* Cell i of a 4x4 grid of 64x64 cells: a 56x56 quad of smooth primary colours. */
static void cell(int i) {
  const float x0 = (float)(i % 4) * 64 + 2, y0 = (float)(i / 4) * 64 + 2, x1 = x0 + 56, y1 = y0 + 56; /* 7 pixels a texel: no pixel centre on a texel edge */
  glBegin(GL_QUADS);
  glColor4f(0.9f, 0.2f, 0.4f, 0.3f);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glColor4f(0.1f, 0.8f, 0.3f, 0.9f);
  glTexCoord2f(1, 0);
  glVertex2f(x1, y0);
  glColor4f(0.3f, 0.4f, 0.95f, 0.6f);
  glTexCoord2f(1, 1);
  glVertex2f(x1, y1);
  glColor4f(0.7f, 0.7f, 0.1f, 0.05f);
  glTexCoord2f(0, 1);
  glVertex2f(x0, y1);
  glEnd();
}

/* The combine state's initial values on the active unit (GL_TEXTURE_ENV_MODE GL_COMBINE). */
static void reset(void) {
  static const GLfloat constant[4] = {0.25f, 0.6f, 0.85f, 0.4f};
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PREVIOUS);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1);
}

/* One function with its three sources and operands, for RGB and alpha alike. */
static void combine(GLenum rgb, GLenum alpha, GLenum s0, GLenum s1, GLenum s2, GLenum o0, GLenum o1, GLenum o2) {
  reset();
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, s0);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, s1);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, s2);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, s2);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, s0);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, s1);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, o0);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, o1);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, o2);
  /* the alpha operands: SRC_ALPHA or its complement, as the RGB one is a complement */
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, o1 == GL_ONE_MINUS_SRC_COLOR || o1 == GL_ONE_MINUS_SRC_ALPHA ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, o0 == GL_ONE_MINUS_SRC_COLOR || o0 == GL_ONE_MINUS_SRC_ALPHA ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, o2 == GL_ONE_MINUS_SRC_COLOR || o2 == GL_ONE_MINUS_SRC_ALPHA ? GL_ONE_MINUS_SRC_ALPHA : GL_SRC_ALPHA);
}

static const GLenum tex_env_pnames[] = {
    GL_TEXTURE_ENV_MODE, GL_COMBINE_RGB,    GL_COMBINE_ALPHA,  GL_SOURCE0_RGB,    GL_SOURCE1_RGB,    GL_SOURCE2_RGB,
    GL_SOURCE0_ALPHA,    GL_SOURCE1_ALPHA,  GL_SOURCE2_ALPHA,  GL_OPERAND0_RGB,   GL_OPERAND1_RGB,   GL_OPERAND2_RGB,
    GL_OPERAND0_ALPHA,   GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA, GL_RGB_SCALE,      GL_ALPHA_SCALE};

/* Every glGetTexEnv value of the active unit, as "PREFIX_<i>" (integers) and the colour. */
static void env_values(const char* prefix) {
  char name[64];
  GLfloat f[4];
  GLint v[4];
  unsigned i;
  for (i = 0; i < sizeof tex_env_pnames / sizeof tex_env_pnames[0]; ++i) {
    glGetTexEnviv(GL_TEXTURE_ENV, tex_env_pnames[i], v);
    snprintf(name, sizeof name, "%s_%u", prefix, i);
    conf_value(name, v[0]);
    glGetTexEnvfv(GL_TEXTURE_ENV, tex_env_pnames[i], f);
    snprintf(name, sizeof name, "%s_%u_f", prefix, i);
    conf_value(name, f[0]);
  }
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
  for (i = 0; i < 4; ++i) {
    snprintf(name, sizeof name, "%s_color_%u", prefix, i);
    conf_value(name, f[i]);
  }
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
  snprintf(name, sizeof name, "%s_color_i", prefix);
  conf_value(name, v[1] / 65536); /* (the top bits: [0, 1] mapped to [0, 2^31 - 1]) */
}

static const GLenum tex_parameter_pnames[] = {
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S,     GL_TEXTURE_WRAP_T,
    GL_TEXTURE_WRAP_R,     GL_TEXTURE_PRIORITY,   GL_TEXTURE_RESIDENT,   GL_TEXTURE_MIN_LOD,
    GL_TEXTURE_MAX_LOD,    GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL,  GL_GENERATE_MIPMAP};

static void parameter_values(GLenum target, const char* prefix) {
  char name[64];
  GLfloat f[4];
  GLint v[4];
  unsigned i;
  for (i = 0; i < sizeof tex_parameter_pnames / sizeof tex_parameter_pnames[0]; ++i) {
    glGetTexParameteriv(target, tex_parameter_pnames[i], v);
    snprintf(name, sizeof name, "%s_%u", prefix, i);
    conf_value(name, tex_parameter_pnames[i] == GL_TEXTURE_PRIORITY ? v[0] / 65536 : v[0]);
    glGetTexParameterfv(target, tex_parameter_pnames[i], f);
    snprintf(name, sizeof name, "%s_%u_f", prefix, i);
    conf_value(name, f[0]);
  }
  glGetTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, f);
  for (i = 0; i < 4; ++i) {
    snprintf(name, sizeof name, "%s_border_%u", prefix, i);
    conf_value(name, f[i]);
  }
  glGetTexParameteriv(target, GL_TEXTURE_BORDER_COLOR, v);
  snprintf(name, sizeof name, "%s_border_i", prefix);
  conf_value(name, v[2] / 65536);
  error(prefix);
}

int main(int argc, char** argv) {
  static const GLenum formats[] = {GL_ALPHA, GL_LUMINANCE, GL_INTENSITY, GL_RGB, GL_LUMINANCE_ALPHA, GL_RGBA};
  GLuint tex[2];
  GLfloat f[4];
  GLint v = 0;
  int i;
  conf_init(argc, argv, 256, 256);
  conf_ortho();
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  texture(GL_RGBA);
  glEnable(GL_TEXTURE_2D);

  /* Defaults, before any glTexEnv. */
  env_values("initial");
  error("initial_error");

  /* The functions, sources and operands. */
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  combine(GL_REPLACE, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(0);
  combine(GL_REPLACE, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_ONE_MINUS_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(1);
  combine(GL_REPLACE, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_ALPHA, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(2);
  combine(GL_REPLACE, GL_REPLACE, GL_PRIMARY_COLOR, GL_TEXTURE, GL_CONSTANT, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(3);
  combine(GL_MODULATE, GL_MODULATE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA);
  cell(4);
  combine(GL_ADD, GL_ADD, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(5);
  combine(GL_ADD_SIGNED, GL_ADD_SIGNED, GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_ALPHA, GL_SRC_ALPHA);
  cell(6);
  combine(GL_INTERPOLATE, GL_INTERPOLATE, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(7);
  combine(GL_INTERPOLATE, GL_INTERPOLATE, GL_PREVIOUS, GL_CONSTANT, GL_TEXTURE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR);
  cell(8);
  combine(GL_SUBTRACT, GL_SUBTRACT, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(9);
  combine(GL_SUBTRACT, GL_SUBTRACT, GL_CONSTANT, GL_TEXTURE, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(10);
  combine(GL_DOT3_RGB, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(11);
  combine(GL_DOT3_RGBA, GL_REPLACE, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(12);
  combine(GL_MODULATE, GL_MODULATE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4);
  cell(13);
  combine(GL_ADD_SIGNED, GL_ADD, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2);
  cell(14);
  combine(GL_DOT3_RGB, GL_MODULATE, GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
  cell(15);
  conf_frame("functions");
  /* The alpha of the same frame, as grey (the frames keep RGB only). */
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ZERO); /* white times the alpha below */
  combine(GL_REPLACE, GL_MODULATE, GL_CONSTANT, GL_PREVIOUS, GL_TEXTURE, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_ALPHA);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (const GLfloat[]){1, 1, 1, 0});
  cell(0); /* one minus the primary alpha times the texture's */
  combine(GL_DOT3_RGBA, GL_REPLACE, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(1); /* the dot product in alpha too */
  combine(GL_INTERPOLATE, GL_INTERPOLATE, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  cell(2);
  combine(GL_ADD_SIGNED, GL_ADD_SIGNED, GL_TEXTURE, GL_PRIMARY_COLOR, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_ALPHA, GL_SRC_ALPHA);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2);
  cell(3);
  glDisable(GL_BLEND);
  conf_frame("alphas");

  /* The texture's colour per base format: REPLACE of the texture (row 0), and of
   * one minus it (row 1), then ALPHA's RGB and the others' alpha through the blend. */
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 6; ++i) {
    texture(formats[i]);
    combine(GL_REPLACE, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
    cell(i < 4 ? i : i + 4);
    combine(GL_ADD, GL_REPLACE, GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_COLOR, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_COLOR);
    cell(i < 4 ? i + 4 : i + 8);
  }
  conf_frame("formats");
  texture(GL_RGBA);

  /* Two units: unit 1 combines unit 0's result (PREVIOUS) with PRIMARY_COLOR. */
  glClear(GL_COLOR_BUFFER_BIT);
  combine(GL_MODULATE, GL_MODULATE, GL_TEXTURE, GL_CONSTANT, GL_PREVIOUS, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  texture(GL_LUMINANCE);
  glEnable(GL_TEXTURE_2D);
  combine(GL_INTERPOLATE, GL_ADD, GL_PREVIOUS, GL_PRIMARY_COLOR, GL_TEXTURE, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_COLOR);
  cell(5);
  combine(GL_SUBTRACT, GL_REPLACE, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_TEXTURE, GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_COLOR);
  cell(6);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE); /* unit 1 plain, unit 0 combined */
  cell(9);
  env_values("unit1");
  glActiveTexture(GL_TEXTURE0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL); /* unit 0 plain, unit 1 modulate */
  cell(10);
  env_values("unit0");
  conf_frame("units");
  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  /* glPushAttrib(GL_TEXTURE_BIT) keeps each unit's combine state. */
  combine(GL_DOT3_RGBA, GL_ADD_SIGNED, GL_CONSTANT, GL_PRIMARY_COLOR, GL_TEXTURE, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4);
  glActiveTexture(GL_TEXTURE1);
  combine(GL_SUBTRACT, GL_INTERPOLATE, GL_PRIMARY_COLOR, GL_TEXTURE, GL_CONSTANT, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_COLOR, GL_SRC_COLOR);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2);
  glPushAttrib(GL_TEXTURE_BIT);
  reset();
  glActiveTexture(GL_TEXTURE0);
  reset();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  glPopAttrib();
  glGetIntegerv(GL_ACTIVE_TEXTURE, &v);
  conf_value("popped_active", v);
  env_values("popped_unit1");
  glActiveTexture(GL_TEXTURE0);
  env_values("popped_unit0");
  error("attrib_error");

  /* glTexEnv's errors. */
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DECAL);
  error("combine_rgb_decal");
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);
  error("combine_alpha_dot3");
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGBA);
  error("combine_alpha_dot3_rgba");
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_SRC_COLOR);
  error("source_src_color");
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_SRC_ALPHA);
  error("source_alpha_bad");
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR);
  error("operand_alpha_src_color");
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_COLOR);
  error("operand_alpha_one_minus_src_color");
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ZERO);
  error("operand_rgb_zero");
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3);
  error("rgb_scale_3");
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f);
  error("alpha_scale_half");
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 8);
  error("rgb_scale_8");
  env_values("after_errors");
  glBegin(GL_POINTS);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD);
  glEnd();
  error("tex_env_inside_begin");

  /* glGetTexEnv's errors. */
  f[0] = -7;
  glGetTexEnvfv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, f);
  error("get_tex_env_bad_target");
  conf_value("get_tex_env_bad_target_untouched", f[0]);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, f);
  error("get_tex_env_bad_pname");
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, f);
  error("get_tex_env_filter_control_bad_pname");
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, f);
  conf_value("lod_bias", f[0]);
  glBegin(GL_POINTS);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  glEnd();
  error("get_tex_env_inside_begin");

  /* glGetTexParameter on each target, initial and set. */
  parameter_values(GL_TEXTURE_2D, "param_2d_initial");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, (const GLfloat[]){0.2f, 0.4f, 0.75f, 1});
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 5);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  parameter_values(GL_TEXTURE_2D, "param_2d");
  glBindTexture(GL_TEXTURE_1D, tex[1]);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  parameter_values(GL_TEXTURE_1D, "param_1d");
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_MIRRORED_REPEAT);
  glTexParameterf(GL_TEXTURE_3D, GL_TEXTURE_MAX_LOD, 2);
  parameter_values(GL_TEXTURE_3D, "param_3d_default");
  glGetTexParameterfv(GL_TEXTURE_ENV, GL_TEXTURE_MIN_FILTER, f);
  error("get_tex_parameter_bad_target");
  glGetTexParameterfv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
  error("get_tex_parameter_proxy");
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &v);
  error("get_tex_parameter_bad_pname");
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &v);
  error("get_tex_parameter_level_pname");
  glBegin(GL_POINTS);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
  glEnd();
  error("get_tex_parameter_inside_begin");

  glDeleteTextures(2, tex);
  return conf_end();
}
