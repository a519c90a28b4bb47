// pGL's context: the OpenGL 1.x state machine on Velocity's pipeline.
//
// The context does OpenGL's vertex work itself — modelview and projection transforms,
// GL lighting, texture matrix, fog coordinate, primitive assembly for the ten modes,
// face culling, polygon modes, flat shading with GL's provoking vertex — and hands the
// renderer clip-space points, lines and triangles with per-fragment state
// (velocity::PrimitiveBatch + PixelState). Consecutive primitives of one kind with the
// same per-fragment state, viewport, depth range, point size and line width go into one
// batch, which keeps the state it opened with; a batch is handed over when that changes.
// The renderer keeps a frame open until something needs the pixels (glFinish,
// glFlush, glReadPixels, OSMesaMakeCurrent, OSMesaGetDepthBuffer): then the frame runs
// on every core and the colour lands in the caller's buffer.
//
// The state is one struct per GL area (state.hpp); the methods are grouped by area
// below, each group in the file named beside it, as Mesa's src/mesa/main/ is:
//   context.cpp       OSMesa binding, errors, the current context
//   frame.cpp         batches to the renderer, frames, colour and depth out
//   vertex.cpp        glBegin/glEnd: transform, GL lighting, primitive assembly
//   transform.cpp     matrix stacks, viewport, depth range
//   lighting.cpp      lights, materials, colour material, shade model
//   raster_state.cpp  enables, depth, blend, alpha test, fog, scissor, masks, clears,
//                     culling, polygon mode and offset, point size, line width
//   texture.cpp       texture objects, images, parameters, environment
//   arrays.cpp        vertex arrays, glArrayElement, glDrawArrays, glDrawElements
//   lists.cpp         display lists
//   queries.cpp       glGet*, glIsEnabled
//   read_pixels.cpp   glReadPixels
//   attrib.cpp        glPushAttrib, glPopAttrib, glPushClientAttrib, glPopClientAttrib
//   copy_texture.cpp  glCopyTexImage2D, glCopyTexSubImage2D, glGetTexLevelParameter,
//                     glGetTexImage
//   select.cpp        selection: glRenderMode, glSelectBuffer, the name stack
//   feedback.cpp      feedback: glFeedbackBuffer, glPassThrough, the tokens
//   blend.cpp         GL 1.4's blending: glBlendFuncSeparate, glBlendEquation, glBlendColor;
//                     glLogicOp
//   stencil.cpp       the stencil buffer: glStencilFunc, glStencilOp, glStencilMask,
//                     glClearStencil, its queries and its part of PixelState
//   raster_pos.cpp    glRasterPos, glWindowPos
//   draw_pixels.cpp   glBitmap, glDrawPixels, glCopyPixels, glPixelZoom, glPixelStore
//   clip_planes.cpp   glClipPlane, GL_CLIP_PLANEi
//   tex_gen.cpp       glTexGen, GL_TEXTURE_GEN_S..Q
//   line_stipple.cpp  glLineStipple, GL_LINE_STIPPLE
//   polygon_stipple.cpp  glPolygonStipple, glGetPolygonStipple, GL_POLYGON_STIPPLE
//   accum.cpp         the accumulation buffer: glAccum, glClearAccum
//   buffer_objects.cpp  GL 1.5's buffer objects (arrays and indices read from them)
//   occlusion.cpp     GL 1.5's occlusion queries (GL_SAMPLES_PASSED)
//   api_buffers.cpp   their C entry points, glGetPointerv
//   texture_1d.cpp    1-D textures (height-1 images); api_texture_1d.cpp their C calls
//   evaluators.cpp    evaluators (1-D and 2-D); api_evaluators.cpp their C calls
//   color_sum.cpp     GL 1.4's secondary colour and fog coordinates, GL 1.2's separate
//                     specular colour; api_color_sum.cpp their C calls
//   multitexture.cpp  GL 1.3's texture units; api_multitexture.cpp their C calls
//   tex_combine.cpp   GL 1.3's GL_COMBINE environment, glGetTexEnv, glGetTexParameter
//                     (and their C calls)
//   framebuffer_objects.cpp  framebuffer objects and renderbuffers; api_framebuffer.cpp
//                     their C calls (and glBlitFramebuffer's, blit.cpp)
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "clip_planes.hpp"
#include "framebuffer_objects.hpp"
#include "pixel_ops.hpp"
#include "state.hpp"
#include "tex_gen.hpp"
#include "velocity/primitives.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace velocity::gl {

// A vertex after the vertex stage.
struct Vertex {
  Vec4 clip;
  Vec4 front, back;  // lit colours (back only with two-sided lighting)
  Vec4 tex;
  float fog = 0;
  bool edge = true;  // glEdgeFlag: does a polygon's boundary edge start here?
  float clip_distance[kMaxClipPlanes] = {};  // to the enabled user clip planes
};

class Context {
 public:
  Context(GLenum format, int depth_bits, int stencil_bits = 0, int accum_bits = 0);
  ~Context();

  // --- OSMesa (context.cpp)
  bool make_current(void* buffer, GLenum type, int width, int height);
  void release();  // no longer current: run what is pending
  bool depth_buffer(GLint* width, GLint* height, GLint* bytes_per_value, void** buffer);
  GLenum format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  void* buffer() const { return buffer_; }  // OSMesaGetColorBuffer's (null before make_current)
  bool y_up = true;
  int row_length = 0;

  // --- errors
  void error(GLenum e) {
    if (error_ == GL_NO_ERROR) error_ = e;
  }
  GLenum take_error() {
    GLenum e = error_;
    error_ = GL_NO_ERROR;
    return e;
  }
  // Records GL_INVALID_OPERATION and returns true between glBegin and glEnd.
  bool in_begin_error() {
    if (!in_begin_) return false;
    error(GL_INVALID_OPERATION);
    return true;
  }
  bool in_begin() const { return in_begin_; }
  // A command that reads the caller's memory (an image, a bitmap, a stipple) and runs now
  // between glBegin and glEnd: GL_INVALID_OPERATION, and true, so that nothing is read
  // (the unpack state may not describe the memory: glPixelStore is refused there too).
  // While a list is compiled the memory is read for the list, as GL says.
  bool refuses_in_begin() { return !compiling() && in_begin_error(); }

  // --- primitives (vertex.cpp)
  void begin(GLenum mode);
  void end();
  void vertex(Vec4 v);
  // glVertex's common case, inline in the entry points: inside a glBegin(GL_TRIANGLES)
  // that takes the quick path (quick_, vertex.cpp), only the position and the current
  // normal are kept. False: not taken (vertex() does the rest).
  bool quick_vertex(float x, float y, float z, float w) {
    if (!quick_) return false;
    // (Component by component: stored whole from the stack, the vector would be read
    // back whole from two halves, a store-forwarding stall.)
    Vec4& p = quick_position_[quick_count_];
    p.x = x, p.y = y, p.z = z, p.w = w;
    quick_normal_[quick_count_] = normal_;
    if (++quick_count_ == kQuickRun) quick_flush_checked();
    return true;
  }
  void set_color(Vec4 c);  // (lighting.cpp: it feeds GL_COLOR_MATERIAL)
  void set_normal(Vec3 n) { normal_ = n; }
  void set_texcoord(Vec4 t) { texcoord_ = t; }
  void set_edge_flag(bool e) { edge_flag_ = e; }
  bool edge_flag() const { return edge_flag_; }
  void rect(float x1, float y1, float x2, float y2);

  // --- transform (transform.cpp)
  void matrix_mode(GLenum mode);
  void load_identity() { load(Mat4{}); }
  void load(const Mat4& m);
  void multiply(const Mat4& m);
  void rotate(float degrees, float x, float y, float z);
  void translate(float x, float y, float z);
  void scale(float x, float y, float z);
  void frustum(double l, double r, double b, double t, double n, double f);
  void ortho(double l, double r, double b, double t, double n, double f);
  void push_matrix();
  void pop_matrix();
  void viewport(GLint x, GLint y, GLsizei w, GLsizei h);
  void depth_range(double n, double f);

  // --- raster state (raster_state.cpp)
  void enable(GLenum cap, bool on);
  void scissor(GLint x, GLint y, GLsizei w, GLsizei h);
  void clear(GLbitfield mask);
  void clear_color(Vec4 c) { raster_.clear_color = c; }
  void clear_depth(double d);
  void depth_func(GLenum f);
  void depth_mask(bool on);
  void color_mask(bool r, bool g, bool b, bool a);
  void blend_func(GLenum s, GLenum d);
  void blend_func_separate(GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha);  // blend.cpp
  void blend_equation(GLenum mode);
  void blend_color(Vec4 c);
  void logic_op(GLenum op);  // blend.cpp
  bool get_blend(GLenum pname, std::vector<double>& out, int& kind) const;
  void alpha_func(GLenum f, float ref);
  void fog(GLenum pname, const float* v);
  void hint(GLenum target, GLenum mode);
  void cull_face(GLenum m);
  void front_face(GLenum m);
  void polygon_mode(GLenum face, GLenum mode);
  void polygon_offset(float factor, float units);
  void point_size(float s);
  void line_width(float w);

  // --- the stencil buffer (stencil.cpp)
  void stencil_func(GLenum func, GLint ref, GLuint mask);
  void stencil_op(GLenum fail, GLenum depth_fail, GLenum pass);
  void stencil_mask(GLuint mask);
  void clear_stencil(GLint s);
  int stencil_bits() const { return stencil_bits_; }

  // --- selection (select.cpp)
  GLint render_mode(GLenum mode);
  void select_buffer(GLsizei size, GLuint* buffer);
  void init_names();
  void push_name(GLuint name);
  void pop_name();
  void load_name(GLuint name);
  bool selecting() const { return select_.mode == GL_SELECT; }
  const SelectState& selection() const { return select_; }

  // --- feedback (feedback.cpp)
  void feedback_buffer(GLsizei size, GLenum type, GLfloat* buffer);
  void pass_through(GLfloat token);
  bool feeding_back() const { return select_.mode == GL_FEEDBACK; }
  const FeedbackState& feedback() const { return feedback_; }
  // glBitmap, glDrawPixels, glCopyPixels in select or feedback mode: a hit, or `token`
  // and the raster position; true when nothing is to be drawn.
  bool pixels_not_rendered(GLenum token);

  // --- attribute stacks (attrib.cpp)
  void push_attrib(GLbitfield mask);
  void pop_attrib();
  void push_client_attrib(GLbitfield mask);
  void pop_client_attrib();
  int attrib_depth() const;
  int client_attrib_depth() const;

  // --- lighting (lighting.cpp)
  void light(GLenum light, GLenum pname, const float* v);
  bool get_light(GLenum light, GLenum pname, float* v);
  void light_model(GLenum pname, const float* v);
  void material(GLenum face, GLenum pname, const float* v);
  bool get_material(GLenum face, GLenum pname, float* v);
  void color_material(GLenum face, GLenum mode);
  void shade_model(GLenum m);

  // --- textures (texture.cpp)
  void gen_textures(GLsizei n, GLuint* out);
  void delete_textures(GLsizei n, const GLuint* ids);
  void bind_texture(GLenum target, GLuint id);
  bool is_texture(GLuint id) const { return texture_.objects.count(id) != 0; }
  // `rgba` holds width * height (* depth) texels already converted (see api.cpp); null
  // for a level with undefined contents. `depth`: a 3-D texture's slices.
  void tex_image(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                 const std::vector<uint32_t>* rgba, GLsizei depth = 1);
  void tex_sub_image(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                     const std::vector<uint32_t>& rgba, GLint z = 0, GLsizei depth = 1);
  void tex_parameter(GLenum target, GLenum pname, const float* v);
  void tex_env(GLenum target, GLenum pname, const float* v);
  // The internal format glTexImage2D's argument names, or 0 if none.
  static GLenum base_format(GLint internal);
  // The other sized internal formats of GL 1.1's table and GL 1.3's generic compressed
  // ones (texture_formats.cpp): their base format, or 0.
  static GLenum sized_base_format(GLint internal);
  GLint unpack_alignment = 4, pack_alignment = 4;  // glPixelStorei

  // --- 1-D textures (texture_1d.cpp)
  // The object bound to `target` (GL_TEXTURE_1D or GL_TEXTURE_2D), or null with
  // GL_INVALID_ENUM.
  TextureObject* target_texture(GLenum target);
  bool texturing() const { return texture_.enabled || texture_.enabled_1d || texture_.enabled_3d; }
  bool texturing_1d() const { return !texture_.enabled && !texture_.enabled_3d && texture_.enabled_1d; }  // 1-D is the one drawn

  // --- 3-D textures (texture_3d.cpp); api_texture_3d.cpp their C calls
  bool texturing_3d() const { return texture_.enabled_3d; }  // 3-D is the one drawn
  // The target whose texture the next draws sample (while texturing()).
  GLenum drawn_target() const { return texturing_3d() ? GL_TEXTURE_3D : texturing_1d() ? GL_TEXTURE_1D : GL_TEXTURE_2D; }
  // glTexImage3D(GL_PROXY_TEXTURE_3D): as proxy_tex_image. The arguments were checked.
  void proxy_tex_image_3d(GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d, GLint border = 0);
  // --- texture borders (texture_border.cpp)
  // A level's border on each axis: x, and y but for a 1-D texture, and z for a 3-D one.
  struct BorderAxes {
    int x, y, z;
  };
  static BorderAxes border_axes(GLenum target, int border);
  // Whether a sub-image at (x, y, z) of w x h x d lies inside level `l` with its border
  // (GL_INVALID_VALUE if not).
  static bool sub_image_inside(GLenum target, const Texture::Level& l, GLint x, GLint y, GLint z, GLsizei w, GLsizei h,
                               GLsizei d);
  // GL_GENERATE_MIPMAP's next level for a level that may have a border: the image's
  // box filter, its border ring the new image's edges repeated.
  static Texture::Level next_level_with_border(const Texture::Level& above, bool volume, bool one_d);
  // glCopyTexSubImage3D: a rectangle of the colour buffer into slice `zoffset`.
  void copy_tex_sub_image_3d(GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei w,
                             GLsizei h);

  // --- copies from the framebuffer, level queries (copy_texture.cpp)
  void copy_tex_image(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w, GLsizei h, GLint border);
  void copy_tex_sub_image(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei w,
                          GLsizei h);
  // glTexImage2D(GL_PROXY_TEXTURE_2D): the proxy's level says w x h if such an image
  // fits, else 0 x 0 (texture.cpp). The arguments were checked.
  void proxy_tex_image(GLint level, GLint internal, GLsizei w, GLsizei h, GLint border = 0);
  // glGetTexLevelParameteriv: true when *out was set (else GL's error is recorded).
  bool tex_level_parameter(GLenum target, GLint level, GLenum pname, GLint* out);
  void get_tex_image(GLenum target, GLint level, GLenum format, GLenum type, void* pixels);

  // --- vertex arrays (arrays.cpp)
  ArrayState arrays;
  void client_state(GLenum cap, bool on);
  void array_element(GLint i);
  void element(GLint i);  // array_element without the checks, after note_array_extras
  void note_array_extras();
  bool array_extras_ = false;
  void draw_arrays(GLenum mode, GLint first, GLsizei count);
  void draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices);

  // --- GL 1.5's buffer objects (buffer_objects.cpp)
  void gen_buffers(GLsizei n, GLuint* out);
  void delete_buffers(GLsizei n, const GLuint* ids);
  void bind_buffer(GLenum target, GLuint id);
  bool is_buffer(GLuint id) const { return buffers_.objects.count(id) != 0; }
  void buffer_data(GLenum target, GLsizeiptr size, const void* data, GLenum usage);
  void buffer_sub_data(GLenum target, GLintptr offset, GLsizeiptr size, const void* data);
  void get_buffer_sub_data(GLenum target, GLintptr offset, GLsizeiptr size, void* data);
  void* map_buffer(GLenum target, GLenum access);
  GLboolean unmap_buffer(GLenum target);
  void get_buffer_parameter(GLenum target, GLenum pname, GLint* out);
  void get_buffer_pointer(GLenum target, GLenum pname, void** out);
  bool get_buffer_binding(GLenum pname, std::vector<double>& out) const;  // glGet's *_BUFFER_BINDING
  // glDrawElements' `count` indices of `type`: `indices` itself, or the bytes at that
  // offset in the bound element buffer (null: they are not all inside it).
  const uint8_t* element_indices(GLsizei count, GLenum type, const void* indices) const;

  // --- GL 1.5's occlusion queries (occlusion.cpp)
  void gen_queries(GLsizei n, GLuint* out);
  void delete_queries(GLsizei n, const GLuint* ids);
  bool is_query(GLuint id) const { return queries_.objects.count(id) != 0; }
  void begin_query(GLenum target, GLuint id);
  void end_query(GLenum target);
  void get_query(GLenum target, GLenum pname, GLint* out);
  // glGetQueryObject(u)iv: false with GL's error recorded, else the value in *out.
  bool get_query_object(GLuint id, GLenum pname, uint64_t* out);

  // --- evaluators (evaluators.cpp)
  static int map1_components(GLenum target);  // 0: not a GL_MAP1_* target
  static int map2_components(GLenum target);  // 0: not a GL_MAP2_* target
  void map1(GLenum target, float u1, float u2, GLint stride, GLint order, const std::vector<float>& points);
  void map2(GLenum target, const Map2& map, GLint ustride, GLint vstride);  // map.points packed
  bool enable_evaluator(GLenum cap, bool on);  // false: not a GL_MAP* name or GL_AUTO_NORMAL
  bool evaluator_enabled(GLenum cap, bool* known) const;
  void eval_coord1(float u);
  void eval_coord2(float u, float v);
  void map_grid1(GLint n, float u1, float u2);
  void map_grid2(GLint un, float u1, float u2, GLint vn, float v1, float v2);
  float grid_u(GLint i) const;
  void eval_point2(GLint i, GLint j);
  void eval_mesh1(GLenum mode, GLint i1, GLint i2);
  void eval_mesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2);
  bool get_map(GLenum target, GLenum query, std::vector<double>& out);  // glGetMap
  bool get_eval(GLenum pname, std::vector<double>& out) const;         // glGet's

  // --- display lists (lists.cpp)
  GLuint gen_lists(GLsizei range);
  void new_list(GLuint list, GLenum mode);
  void end_list();
  void call_list(GLuint list);
  void delete_lists(GLuint list, GLsizei range);
  bool is_list(GLuint list) const { return lists_.stored.count(list) != 0; }
  bool compiling() const { return lists_.compiling != 0; }
  bool compile_and_execute() const { return lists_.mode == GL_COMPILE_AND_EXECUTE; }
  void record(ListCommand cmd);
  // Compiles a draw from the arrays (glDrawArrays, glDrawElements): what `body` records
  // becomes one command, which between glBegin and glEnd draws nothing and raises
  // GL_INVALID_OPERATION, as the call itself would have.
  void record_draw(const std::function<void()>& body);
  GLuint list_base() const { return lists_.base; }
  void set_list_base(GLuint base) { lists_.base = base; }

  // --- queries (queries.cpp)
  // glGet: the values of `pname` as doubles, with `kind` saying how glGetIntegerv maps
  // them (0: round; 1: a colour, mapped to the full integer range). False: unknown name.
  bool get(GLenum pname, std::vector<double>& out, int& kind);
  bool is_enabled(GLenum cap, bool* known) const;

  // --- read-back (read_pixels.cpp, frame.cpp)
  void read_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels);
  void finish();  // glFinish and glFlush: run the frame, colour to the caller's buffer

  // --- raster position and pixel rectangles (raster_pos.cpp, draw_pixels.cpp)
  PixelOpsState pixels;
  void raster_pos(Vec4 v);
  void window_pos(Vec3 v);
  // `bits`: unpack_bitmap's, or null (the raster position only moves).
  void bitmap(GLsizei w, GLsizei h, float xorig, float yorig, float xmove, float ymove, const std::vector<uint8_t>* bits);
  // `image`: unpack_pixels' for `format`.
  void draw_pixels(GLsizei w, GLsizei h, GLenum format, const std::vector<Vec4>& image);
  void copy_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type);
  // `indices`: unpack_stencil's (glDrawPixels' GL_STENCIL_INDEX).
  void draw_stencil_pixels(GLsizei w, GLsizei h, const std::vector<uint8_t>& indices);
  // GL_DEPTH_STENCIL_EXT: unpack_depth_stencil's depths and indices (draw_pixels.cpp).
  void draw_depth_stencil_pixels(GLsizei w, GLsizei h, const std::vector<Vec4>& depth,
                                 const std::vector<uint8_t>& indices);
  void pixel_zoom(float x, float y);
  void pixel_transfer(GLenum pname, double value);  // (pixel_transfer.cpp)
  void pixel_map(GLenum map, const std::vector<float>& values);       // glPixelMap (pixel_transfer.cpp)
  bool get_pixel_map(GLenum map, std::vector<float>& out, bool* colour);  // glGetPixelMap
  bool get_pixel_transfer(GLenum pname, std::vector<double>& out) const;
  void pixel_store(GLenum pname, double value);
  bool get_pixel_ops(GLenum pname, std::vector<double>& out, int& kind);

  // --- front and back colour buffers (buffers.cpp)
  // A GLX context on a double-buffered drawable (gl/glx/) has a back buffer: it draws
  // there until glDrawBuffer says otherwise.
  void set_double_buffered(bool on);
  bool double_buffered() const { return double_buffered_; }
  void draw_buffer(GLenum mode);
  void read_buffer(GLenum mode);
  void swap_buffers();  // glXSwapBuffers: the back buffer's colour copied to the front
  // The buffer made current, as it is, becomes the colour buffer (the back one where there
  // are two): for the EGL vendor, whose pbuffers own their pixels while their context
  // draws elsewhere. (OSMesa alone does not: Mesa's keeps the colour of the context, not
  // of the buffer, across OSMesaMakeCurrent, and so does pGL's.)
  void load_buffer_colour();
  // The front buffer's colour (RGBA, bottom row first) of a double-buffered context,
  // after the frame ran; null otherwise.
  const uint8_t* front_rows();
  bool draws_front() const { return double_buffered_ && (drawn_ & 1); }
  // GL_INVALID_OPERATION, and true, when glReadBuffer is GL_NONE.
  bool no_read_buffer();

  // --- multisample buffers (multisample.cpp)
  // A GLX configuration with samples (gl/glx/) gives its context k x k samples a pixel,
  // the renderer's super-sampling: set before the first frame.
  void set_samples_side(int k);
  bool get_multisample(GLenum pname, std::vector<double>& out) const;

  // --- the accumulation buffer (accum.cpp)
  void accum(GLenum op, float value);
  void clear_accum(float r, float g, float b, float a);

  // --- user clip planes (clip_planes.cpp)
  UserClipState user_clip;
  void clip_plane(GLenum plane, const double* eq);
  bool get_clip_plane(GLenum plane, double* eq);  // false: not a plane's name
  bool enable_clip_plane(GLenum cap, bool on);     // false: not a plane's name
  bool outside_clip_planes(const Vec4& eye) const;

  // --- texture coordinate generation (tex_gen.cpp)
  void tex_gen(GLenum coord, GLenum pname, const double* params);
  // false: not a coordinate's or a parameter's name; else `count` values in `out`.
  bool get_tex_gen(GLenum coord, GLenum pname, double* out, int* count);
  bool enable_tex_gen(GLenum cap, bool on);  // false: not GL_TEXTURE_GEN_S..Q
  bool tex_gen_enabled(GLenum cap) const { return tex_gen_.coords[cap - GL_TEXTURE_GEN_S].enabled; }

  // --- line stipple (line_stipple.cpp)
  void line_stipple(GLint factor, GLushort pattern);
  // --- polygon stipple (polygon_stipple.cpp)
  void polygon_stipple(const std::array<uint32_t, 32>& rows);
  void get_polygon_stipple(GLubyte* out) const;  // packed with the pixel store's pack state

  // --- GL 1.4's secondary colour and fog coordinates, GL 1.2's separate specular
  // --- colour (color_sum.cpp)
  void set_secondary_color(Vec4 c) { secondary_ = c; }
  void set_fog_coord(float f) { fog_coord_ = f; }
  bool enable_color_sum(GLenum cap, bool on);                // false: not GL_COLOR_SUM
  bool light_model_color_control(GLenum pname, float v);    // false: not its parameter
  bool fog_coord_source(GLenum pname, float v);             // false: not GL_FOG_COORD_SRC
  bool color_sum_client_state(GLenum cap, bool on);         // false: not one of its arrays
  bool get_color_sum(GLenum pname, std::vector<double>& out, int& kind) const;
  bool color_sum_enabled(GLenum cap, bool* known) const;    // glIsEnabled's
  // Does the colour sum apply to what is drawn now (GL_COLOR_SUM, or lighting with
  // GL_SEPARATE_SPECULAR_COLOR)?
  bool color_sum_applies() const { return color_sum_.enabled || (lighting_.enabled && color_sum_.separate_specular); }
  void save_color_sum(AttribFrame& f) const;
  void restore_color_sum(const AttribFrame& f);

  // --- GL 1.3's texture units (multitexture.cpp)
  void active_texture(GLenum unit);
  void client_active_texture(GLenum unit);
  void multi_tex_coord(GLenum unit, Vec4 t);
  bool get_multitexture(GLenum pname, std::vector<double>& out) const;
  // Unit u's coordinate array (whichever glClientActiveTexture selects is `arrays.texcoord`).
  const ClientArray& texcoord_array(int u) const { return u == live_client_unit_ ? arrays.texcoord : parked_texcoord_; }
  void unbind_deleted_unit_texture(GLuint id);  // glDeleteTextures: unit bindings not live
  // The live fields hold unit u's state (and, for the client state, unit u's array).
  void make_live(int u);
  void make_client_live(int u);
  int active_unit() const { return active_unit_; }
  void save_units(AttribFrame& f);  // (unit 0 live after it)
  void restore_units(const AttribFrame& f);
  void save_client_units(ClientAttribFrame& f);
  void restore_client_units(const ClientAttribFrame& f);
  // --- GL 1.3's GL_COMBINE environment, glGetTexEnv, glGetTexParameter (tex_combine.cpp)
  // false: not one of GL_COMBINE's parameters; else set (or GL's error recorded).
  bool tex_env_combine(GLenum pname, const float* v);
  // glGetTexEnv and glGetTexParameter: the number of values put in `out` (4 for a
  // colour, else 1; 0 after an error); `normalized`: glGet*iv maps them from [0, 1] to
  // [0, 2^31 - 1] (colours, the priority).
  int get_tex_env(GLenum target, GLenum pname, float* out, bool* normalized);
  int get_tex_parameter(GLenum target, GLenum pname, float* out, bool* normalized);
  // --- framebuffer objects (framebuffer_objects.cpp)
  void gen_framebuffers(GLsizei n, GLuint* out);
  void delete_framebuffers(GLsizei n, const GLuint* ids);
  void bind_framebuffer(GLenum target, GLuint id);
  bool is_framebuffer(GLuint id) const;
  GLenum check_framebuffer_status(GLenum target);
  // `dims`: 1, 2 or 3 (glFramebufferTexture1D, 2D, 3D / Layer).
  void framebuffer_texture(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level, int dims);
  void framebuffer_renderbuffer(GLenum target, GLenum attachment, GLenum rb_target, GLuint rb);
  void get_framebuffer_attachment_parameter(GLenum target, GLenum attachment, GLenum pname, GLint* out);
  void gen_renderbuffers(GLsizei n, GLuint* out);
  void delete_renderbuffers(GLsizei n, const GLuint* ids);
  void bind_renderbuffer(GLenum target, GLuint id);
  bool is_renderbuffer(GLuint id) const;
  void renderbuffer_storage(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h);
  void get_renderbuffer_parameter(GLenum target, GLenum pname, GLint* out);
  void generate_mipmap(GLenum target);
  bool get_framebuffer(GLenum pname, std::vector<double>& out) const;  // glGet's bindings and limits
  // GL_INVALID_FRAMEBUFFER_OPERATION, and true, when the framebuffer drawn into (or
  // read from) is an incomplete framebuffer object.
  bool framebuffer_incomplete();
  bool read_framebuffer_incomplete();
  // Runs `f` with the window's framebuffer as the context's own (GLX and OSMesa calls
  // that are about the window while a framebuffer object is bound).
  void with_window(const std::function<void()>& f);
  // The framebuffer read from (GL_READ_FRAMEBUFFER) becomes the context's surface for
  // a read, and the one drawn into again after it.
  void use_read_framebuffer() { use_surface(fb_.read); }
  void use_draw_framebuffer() { use_surface(fb_.draw); }
  // The window's size and whether its front buffer is drawn into, whichever framebuffer
  // is bound (GLX's showing of the front at glFlush).
  int window_width() const { return fbo_ ? window_.width : width_; }
  int window_height() const { return fbo_ ? window_.height : height_; }
  bool window_draws_front() const { return fbo_ ? window_.double_buffered && (window_.drawn & 1) : draws_front(); }
  // glBlitFramebuffer (blit.cpp)
  void blit_framebuffer(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
                        GLbitfield mask, GLenum filter);

 private:
  void update_clip_planes();
  // The "on" pieces of the line from prim_[a] (colour color_a) to prim_[b], as lines;
  // the stipple counter goes on from stipple_counter_.
  void stippled_line(uint32_t a, uint32_t b, Vec4 color_a, Vec4 color_b, bool offset);
  uint32_t stipple_counter_ = 0;  // reset by glBegin, each GL_LINES line, each polygon
  TexGenState tex_gen_;
  bool tex_gen_needs_eye() const;
  // The current texture coordinates with the enabled ones generated, for a vertex at
  // `object` (object space) and `eye` (eye space; needed by all but object linear).
  Vec4 generate_texcoord(const Vec4& object, const Vec4& eye) const { return generate_texcoord(tex_gen_, texcoord_, object, eye); }
  Vec4 generate_texcoord(const TexGenState& g, const Vec4& current, const Vec4& object, const Vec4& eye) const;
  static bool tex_gen_needs_eye(const TexGenState& g);

  // A window-space rectangle of fragments (glBitmap's, glDrawPixels'), drawn as two
  // triangles: the fragments whose centres it covers, with its colour and depth.
  struct WindowRect {
    float x0, y0, x1, y1, z;
    Vec4 color;
  };
  void draw_window_rects(const std::vector<WindowRect>& rects);
  // Rectangles of stencil indices (colour.x the index), written as GL writes them.
  void draw_stencil_rects(const std::vector<WindowRect>& rects);
  int stencil_write_ = -1;  // the index such rectangles write now (pixel_state), or -1
  void zoomed_rects(GLsizei w, GLsizei h, const Vec4* image, bool depth, std::vector<WindowRect>& out);
  Vec4 lit_front(const Vec4& eye);  // (vertex.cpp) the current normal's lit front colour


  // --- frames and batches (frame.cpp)
  struct Pending {
    PrimitiveKind kind = PrimitiveKind::Triangles;
    bool offset = false, stippled = false;
    PixelState state;
    // What the renderer's batch carries besides PixelState, as it was when the batch
    // opened (a width or height of 0 here is an empty viewport: nothing is drawn).
    Viewport viewport;
    float point_size = 1, line_width = 1;
    uint32_t clip_planes = 0;  // user clip distances per vertex (in clip_distance)
    std::vector<Vec4> position, color, texcoord;
    std::vector<float> fog, clip_distance;
    std::vector<uint32_t> index;
    std::vector<Vec4> secondary;  // with state.color_sum (color_sum.cpp)
    std::vector<Vec4> texcoord1;  // with state.texture1 (multitexture.cpp)
    bool stage0_unit1 = false;    // texcoord holds unit 1's (unit 0 is off)
    bool extras = false;          // texcoord1 or secondary is kept
    void clear() {
      position.clear(), color.clear(), texcoord.clear(), fog.clear(), clip_distance.clear(), index.clear();
      secondary.clear(), texcoord1.clear();
    }
  };
  void ensure_frame();
  void submit_pending();
  void run_frame();  // end the frame, copy colour (and depth) out
  void copy_depth();
  PixelState pixel_state(bool offset, bool stippled);
  void stencil_pixel_state(PixelState& s) const;          // stencil.cpp
  bool get_stencil(GLenum pname, std::vector<double>& out) const;  // stencil.cpp
  uint8_t stencil_clear_value() const;
  // Vertex `i` of prim_ into the pending batch; `shared`: with its own front colour,
  // so a vertex already in the batch is referenced again instead of copied.
  // `secondary`: its secondary colour where the batch has a colour sum (null: black).
  void emit_vertex(uint32_t i, const Vec4& color, bool shared, const Vec4* secondary = nullptr);
  // `stippled`: the draws of filled polygons, which the polygon stipple applies to.
  Pending& target(PrimitiveKind kind, bool offset, bool stippled = false);
  // Whether the pending batch takes one more primitive of this kind as it is (target()
  // opens a new one otherwise; the quick path asks first, inline).
  bool pending_takes(PrimitiveKind kind, bool offset, bool stippled) const {
    return have_pending_ && !pixel_dirty_ && pending_.kind == kind && pending_.offset == offset &&
           pending_.stippled == stippled && pending_.index.size() < kStreamBatchVertices;
  }
  void changed() { pixel_dirty_ = true; }

  // --- the vertex stage (vertex.cpp)
  void push_vertex(const Vertex& v);  // to prim_ and order_ (assembling independent ones now and then)
  Vertex* new_vertex();  // push_vertex in two: a new vertex's place (null: GL_OUT_OF_MEMORY),
  void vertex_added();   // then, once it is filled in, the assembly check
  void finish_vertex(Vertex& out, const Vec4& eye, const Vec4& object);  // texture coordinates, secondary colour
  void vertex_extras(Vertex& out, const Vec4& eye, const Vec4& object);
  bool vertex_extras_ = false;  // for this glBegin/glEnd
  // A lit vertex with GL_SEPARATE_SPECULAR_COLOR: the specular part kept apart (color_sum.cpp).
  void vertex_separate_specular(Vertex& out, const Vec4& eye, Vec3 n, const Vec4& object);
  void assemble(bool final);
  void polygon(const uint32_t* idx, int n, int provoking);
  void line_segment(uint32_t a, uint32_t b, uint32_t provoking);
  void point_vertex(uint32_t a);
  // `specular`: null, or where the specular part goes (it is then not in the result).
  Vec4 lit(const Vec4& eye, Vec3 normal, bool back, Vec3* specular = nullptr) const;
  Vec4 lit_unclamped(const Vec4& eye, Vec3 normal, bool back, Vec3* specular = nullptr) const;
  void prepare_lighting();
  shading::GlLight light_use_[kMaxLights];  // the enabled lights, for this glBegin
  int lights_used_ = 0;
  bool need_eye_ = false;
  // Under the usual lighting (directional lights, no spots, local viewer, two sides,
  // colour material, texturing or feedback) glVertex keeps the position and normal,
  // and a run of them is transformed and lit at once, in SIMD (shading/gl_vertices.hpp),
  // before anything reads them: before assembly and before glMaterial changes the
  // material. The vertices' prim_ entries wait, with their edge flags only, till then.
  bool run_vertices_ = false;
  std::vector<Vec4> run_position_, run_clip_, run_color_;
  std::vector<Vec3> run_normal_;
  void flush_vertices();
  // The clip positions and lit colours of n vertices under the run's lighting.
  void light_vertices(const Vec4* position, const Vec3* normal, size_t n, Vec4* clip, Vec4* color) const;

  // The quick path: independent triangles, filled on both sides, under the run's
  // lighting (run_vertices_; so no texture, fog, user clip plane, colour sum or
  // feedback), not selecting and not compiling a list. A vertex is its position and
  // normal (quick_vertex) till a run of them is transformed and lit, and a triangle
  // goes from those arrays to the pending batch (facing, culling, flat colour as
  // polygon() does) without a Vertex record, prim_ or order_. The batches are the same,
  // vertex for vertex, as the general path's.
  static constexpr uint32_t kQuickRun = 3072;  // vertices lit at once (a multiple of 3)
  bool quick_ = false;
  uint32_t quick_count_ = 0;  // vertices in quick_position_ / quick_normal_
  uint32_t quick_lit_ = 0;    // lit vertices in quick_clip_ / quick_color_ not yet in a triangle (< 3 between runs)
  std::vector<Vec4> quick_position_, quick_clip_, quick_color_;
  std::vector<Vec3> quick_normal_;
  void grow_quick_arrays(size_t n);
  void quick_flush();  // light the run, assemble its whole triangles
  void quick_flush_checked();  // quick_flush, out of memory as GL_OUT_OF_MEMORY (no exception leaves a GL call)
  // Triangles (clip[t[0]], clip[t[1]], clip[t[2]]) for each three of `order` (null:
  // 0, 1, 2, ...) into the pending batch. `shared`: a vertex already in the batch is
  // referenced again (emitted_, by the vertex's index in clip), as glDrawElements's are.
  template <bool kShared>
  void quick_triangles(const Vec4* clip, const Vec4* color, const uint32_t* order, size_t triangles);
  // glDrawElements(GL_TRIANGLES) on the quick path: each element fetched and lit once.
  template <class IndexAt>
  void quick_elements(GLsizei count, const IndexAt& index_at, size_t cache_size);
  std::vector<uint32_t> quick_order_;

  void update_derived();  // transform.cpp
  std::vector<Mat4>& stack();  // the one glMatrixMode selects
  void apply_color_material();  // lighting.cpp
  void store_material(GLenum face, GLenum pname, const float* v);
  TextureObject* bound_texture();  // texture.cpp
  const Texture* texture_for_draw(TextureObject& t);

  // The framebuffer and its frames.
  GLenum format_;
  int depth_bits_;
  int stencil_bits_;  // 0 or 8
  int accum_bits_;    // 0 or 16 per component (accum.cpp)
  std::vector<int16_t> accum_;  // RGBA, width_ x height_, bottom row first
  Vec4 accum_clear_{0, 0, 0, 0};
  bool accum_returning_ = false;  // GL_RETURN's rectangles: only scissor and colour mask
  Box accum_region() const;
  bool accum_buffer_ready();
  void clear_accum_buffer();
  void accum_return(const Box& region, float value);
  void* buffer_ = nullptr;
  int width_ = 0, height_ = 0;
  std::unique_ptr<Renderer> renderer_;
  bool in_frame_ = false, first_frame_ = true;
  // A glClear of the whole framebuffer before the frame began, to begin it with.
  bool start_clear_ = false, start_clear_color_ = false, start_clear_depth_ = false, start_clear_stencil_ = false;
  Vec4 start_color_{0, 0, 0, 0};
  float start_depth_ = 1;
  uint8_t start_stencil_ = 0;
  std::vector<uint8_t> colour_;  // the last frame's colour, RGBA, bottom row first
  bool direct_ = false;          // ... or in the caller's buffer (RGBA, Y_UP, its own width)
  // The read buffer's colour (buffers.cpp), and the back buffer's (what a GLX drawable shows).
  const uint8_t* colour_rows() const;
  const uint8_t* back_rows() const;
  std::vector<uint32_t> depth_out_;  // OSMesaGetDepthBuffer's copy
  bool depth_requested_ = false;

  GLenum error_ = GL_NO_ERROR;

  // The state, by area (state.hpp).
  TransformState transform_;
  LightingState lighting_;
  RasterState raster_;
  StencilState stencil_;
  SelectState select_;
  FeedbackState feedback_;
  // feedback.cpp: a polygon, line or point in feedback mode, clipped to the view volume.
  void feedback_polygon(const uint32_t* idx, int n, int provoking, bool back_colors);
  void feedback_line(uint32_t a, uint32_t b);
  void feedback_point(uint32_t a);
  void feedback_value(GLfloat v);
  void select_hit(const uint32_t* idx, int n, bool closed);  // select.cpp
  std::vector<uint32_t> read_colour_rect(GLint x, GLint y, GLsizei w, GLsizei h);  // copy_texture.cpp
  void write_hit_record();
  TextureState texture_;
  ListState lists_;

  // Front and back colour buffers (buffers.cpp): buffers as bits, 1 front, 2 back.
  bool double_buffered_ = false;
  GLenum draw_buffer_ = GL_FRONT, read_buffer_ = GL_FRONT;  // as glDrawBuffer / glReadBuffer named them
  int drawn_ = 1, read_ = 1;  // the buffers drawn (0: GL_NONE) and the one read
  int held_ = 1;              // the one the renderer's colour is
  std::vector<uint8_t> parked_;      // the other one's colour, RGBA, bottom row first
  std::unique_ptr<Renderer> mirror_;  // GL_FRONT_AND_BACK: the parked buffer, drawn into too
  BackendChoice backend_ = BackendChoice::Cpu;  // the renderers'
  void park_colour();  // parked_ at the framebuffer's size

  // Multisample buffers (multisample.cpp): the renderer's window coordinates are in
  // samples, k to a pixel's side; GL's pixel coordinates go to it through these.
  int ssaa_ = 1, ssaa_wanted_ = 1;  // in use; the configuration's
  void fit_samples();               // ssaa_: the wanted one where the sample buffer fits
  int samples_side_for(int width, int height) const;
  int to_samples(int pixels) const { return pixels * ssaa_; }
  void sample_scissor(const Box& b, int& x0, int& y0, int& x1, int& y1) const;
  void hold(int which);
  void start_mirror();
  bool get_buffers(GLenum pname, std::vector<double>& out) const;

  // glPushAttrib's and glPushClientAttrib's stacks (attrib.cpp).
  std::vector<AttribFrame> attrib_stack_;
  std::vector<ClientAttribFrame> client_attrib_stack_;

  // The current vertex attributes.
  Vec4 color_{1, 1, 1, 1}, texcoord_{0, 0, 0, 1};
  Vec3 normal_{0, 0, 1};
  bool edge_flag_ = true;

  // The primitive being assembled.
  bool in_begin_ = false;
  GLenum mode_ = GL_POINTS;
  std::vector<Vertex> prim_;       // the processed vertices of this glBegin/glEnd
  std::vector<uint32_t> order_;    // the primitive's vertex sequence, as indices into prim_
  // Per prim_ vertex: where it sits in the pending batch (valid while `gen` is
  // pending_gen_), so that shared vertices go to the renderer once.
  struct Emitted {
    uint32_t gen = 0, index = 0;
  };
  std::vector<Emitted> emitted_;
  uint32_t pending_gen_ = 1;
  // glDrawElements: array index -> prim_ index + 1, so that each element is processed once.
  std::vector<uint32_t> element_cache_;
  bool caching_ = false;

  // Batches.
  Pending pending_;
  bool have_pending_ = false, pixel_dirty_ = true;
  std::vector<Pending> submitted_;  // kept alive until the frame ends; reused
  size_t submitted_used_ = 0;
  std::vector<std::shared_ptr<const Texture>> frame_textures_;
  size_t frame_texture_bytes_ = 0;  // their texels' size
  size_t frame_vertices_ = 0;

  // The current attributes glDrawArrays and glDrawElements leave as they found them
  // (arrays.cpp).
  struct KeptCurrent;
  KeptCurrent keep_current() const;
  void restore_current(const KeptCurrent& k);

  // GL 1.5's buffer objects (buffer_objects.cpp).
  BufferState buffers_;
  std::shared_ptr<BufferObject>* buffer_binding(GLenum target);  // null: GL_INVALID_ENUM
  BufferObject* bound_buffer(GLenum target);
  BufferObject* buffer_range(GLenum target, GLintptr offset, GLsizeiptr size);

  // Evaluators (evaluators.cpp).
  EvalState eval_;
  Vec4 evaluate1(const Map1& m, int k, float u, Vec4 defaults) const;
  void evaluate2(const Map2& m, int k, float u, float v, float* out, float* du, float* dv) const;

  // GL 1.5's occlusion queries (occlusion.cpp).
  QueryState queries_;
  void settle_query(QueryObject& q);  // run the frame its draws are in, if it has not run

  // The colour sum and fog coordinates (color_sum.cpp): the state, the current
  // secondary colour and fog coordinate, and per prim_ vertex its secondary colours
  // (kept only while the colour sum applies: color_sum_on_, set by glBegin).
  ColorSumState color_sum_;
  Vec4 secondary_{0, 0, 0, 1};
  float fog_coord_ = 0;
  struct Secondary {
    Vec4 front, back;
  };
  std::vector<Secondary> prim_secondary_;
  bool color_sum_on_ = false, separate_on_ = false;

  // Texture units (multitexture.cpp). The live fields (texture_'s enables, bindings and
  // environment, transform_.texture, tex_gen_) hold unit live_unit_'s state, the
  // active unit's except between glBegin and glEnd (unit 0's there); parked_unit_ the
  // other's. Unit 1's coordinates per prim_ vertex while it is on (unit1_on_).
  int active_unit_ = 0, live_unit_ = 0, client_unit_ = 0, live_client_unit_ = 0;
  TextureUnitState parked_unit_;
  ClientArray parked_texcoord_;
  Vec4 texcoord1_{0, 0, 0, 1}, raster_texcoord1_{0, 0, 0, 1};
  std::vector<Vec4> prim_tex1_;
  bool unit1_on_ = false;
  bool stage0_unit1_ = false;  // what the last texture_stages said
  void swap_units();
  // Unit 1's state during glBegin/glEnd (parked there) and its coordinates for a vertex.
  bool unit1_texturing() const { return parked_unit_.enabled || parked_unit_.enabled_1d || parked_unit_.enabled_3d; }
  Vec4 unit1_texcoord(const Vec4& object, const Vec4& eye) const;
  // The texture stages of a draw from the units (unit 0 live): the enabled units in
  // order, first in PixelState::texture; true when that first one is unit 1.
  bool texture_stages(PixelState& s);
  bool unit_stage(TextureStage& st, const TextureUnitState& u);
  // The secondary colour of prim_ vertex i as drawn (flat: `provoking`'s), or null.
  const Vec4* secondary_of(uint32_t i, bool back) const {
    return color_sum_on_ ? (back ? &prim_secondary_[i].back : &prim_secondary_[i].front) : nullptr;
  }
  // Framebuffer objects (framebuffer_objects.cpp).
  FramebufferState fb_;
  Surface window_;                  // the window's surface while an FBO is drawn into
  FramebufferObject* fbo_ = nullptr;  // the FBO whose surface the context holds, or null
  struct AttachedImage {
    TextureObject* texture = nullptr;
    Renderbuffer* renderbuffer = nullptr;
    int width = 0, height = 0;
    bool colour = false, depth = false, stencil = false;  // what it can be attached as
    uint64_t serial = 0;
  };
  FramebufferObject* framebuffer_object(GLuint id);
  Renderbuffer* renderbuffer_object(GLuint id);
  FramebufferObject* bound_framebuffer(GLenum target);
  AttachedImage attached_image(const Attachment& a);
  GLenum framebuffer_status(GLuint id, int* width, int* height);
  void set_attachment(GLenum target, GLenum attachment, const Attachment& a);
  void detach_everywhere(GLenum type, GLuint name);
  void swap_surface(Surface& s);
  void use_surface(GLuint id);
  void prepare_framebuffer();  // the renderer sized and loaded from the attachments if they changed
  void write_back(FramebufferObject& f);
  void image_writing(GLenum type, GLuint name);
  void texture_writing(const TextureObject& t);
  void image_written();
  void framebuffer_buffers_changing();
  void window_attachment_parameter(GLenum attachment, GLenum pname, GLint* out);
  // The colour channels the framebuffer drawn into keeps (RGBA bits; an FBO's luminance,
  // alpha or RGB image fewer), ANDed into every colour mask.
  uint8_t channel_mask_ = 0xf;  // glDrawBuffer / glReadBuffer with an FBO bound
};

// A parameter in [0, 1] (NaN reads 0), and an enum passed as a float (glFogf,
// glTexParameterf...): anything that is not a whole number in GLenum's range becomes
// an invalid enum, never an out-of-range conversion.
inline float unit(double v) { return v > 0 ? (v < 1 ? float(v) : 1.0f) : 0.0f; }
inline GLenum to_enum(float v) { return v >= 0 && v < 4294967296.0f ? GLenum(v) : GLenum(0xffffffffu); }

// The calling thread's current context (OSMesaMakeCurrent), or null. Read by every GL
// call, twice a vertex in immediate mode: inline. (Not initial-exec TLS: the GLX vendor
// is dlopen'ed, and a library with any initial-exec TLS needs all of its thread-locals,
// the engine's included, in glibc's small static TLS surplus: dlopen then fails.)
namespace detail {
extern constinit thread_local Context* current_context;
}
inline Context* current() { return detail::current_context; }
inline void set_current(Context* c) { detail::current_context = c; }

}  // namespace velocity::gl
