// pGL's context: the OpenGL 1.x state machine on Velocity's pipeline.
//
// The context does OpenGL's vertex work itself — modelview and projection transforms,
// GL lighting, texture matrix, fog coordinate, primitive assembly for the ten modes,
// face culling, polygon modes, flat shading with GL's provoking vertex — and hands the
// renderer clip-space points, lines and triangles with per-fragment state
// (velocity::PrimitiveBatch + PixelState). Consecutive primitives of one kind with the
// same per-fragment state go into one batch; a batch is handed over when that changes.
// The renderer keeps a frame open until something needs the pixels (glFinish,
// glFlush, glReadPixels, OSMesaMakeCurrent, OSMesaGetDepthBuffer): then the frame runs
// on every core and the colour lands in the caller's buffer.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "velocity/primitives.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace velocity::gl {

// A 4x4 matrix as OpenGL stores it: column-major, m[col * 4 + row].
struct M4 {
  float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  Vec4 operator*(const Vec4& v) const {
    return {m[0] * v.x + m[4] * v.y + m[8] * v.z + m[12] * v.w, m[1] * v.x + m[5] * v.y + m[9] * v.z + m[13] * v.w,
            m[2] * v.x + m[6] * v.y + m[10] * v.z + m[14] * v.w, m[3] * v.x + m[7] * v.y + m[11] * v.z + m[15] * v.w};
  }
  M4 operator*(const M4& b) const;
  bool is_identity() const;
};
// The inverse; false (and `out` unchanged) for a singular matrix.
bool invert(const M4& a, M4& out);

// Implementation limits (what glGet reports).
constexpr int kMaxLights = 8;
constexpr int kMaxModelviewDepth = 32, kMaxProjectionDepth = 32, kMaxTextureDepth = 10;
constexpr int kMaxTextureSize = 4096;
constexpr int kMaxTextureLevels = 13;  // 4096 down to 1
constexpr int kMaxListNesting = 64;
constexpr size_t kMaxListCommands = size_t(1) << 24;  // per list; more is GL_OUT_OF_MEMORY
constexpr size_t kMaxVerticesPerFrame = size_t(1) << 22;  // more: the frame is run, a new one begun
constexpr size_t kMaxBatchVertices = size_t(1) << 20;     // more: the batch goes to the renderer
// A strip, fan, loop or polygon longer than this (GL_OUT_OF_MEMORY; the rest is dropped).
constexpr size_t kMaxPrimitiveVertices = size_t(1) << 22;
// Commands one outermost glCallList may run, nested lists included: lists that call each
// other twice over would otherwise run 2^64 of them (GL_OUT_OF_MEMORY, the rest skipped).
constexpr uint64_t kMaxListCallCommands = uint64_t(1) << 25;
constexpr int kMaxViewport = 16384;

struct Light {
  Vec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  Vec4 position{0, 0, 1, 0};  // eye space (transformed by the modelview at glLight time)
  Vec3 spot_direction{0, 0, -1};  // eye space
  float spot_exponent = 0, spot_cutoff = 180;
  float constant = 1, linear = 0, quadratic = 0;
  bool enabled = false;
};

struct Material {
  Vec4 ambient{0.2f, 0.2f, 0.2f, 1}, diffuse{0.8f, 0.8f, 0.8f, 1}, specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  float shininess = 0;
};

struct TextureObject {
  // Levels as glTexImage2D gave them (RGBA8 after the internal format was applied);
  // width 0: the level was never specified.
  std::array<Texture::Level, kMaxTextureLevels> levels{};
  TexFormat format = TexFormat::Rgba;
  GLenum internal_format = GL_RGBA;
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT;
  Vec4 border{0, 0, 0, 0};
  bool generate_mipmap = false;
  // What the renderer samples, built when first drawn after a change (null: not yet,
  // or incomplete). Draws already recorded keep their own reference.
  std::shared_ptr<const Texture> built;
  bool dirty = true, complete = false;
};

// A vertex after the vertex stage.
struct Vertex {
  Vec4 clip;
  Vec4 front, back;  // lit colours (back only with two-sided lighting)
  Vec4 tex;
  float fog = 0;
};

class Context;
using ListCommand = std::function<void(Context&)>;

// One vertex array (glVertexPointer and the like).
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;
  Vec4 fetch(GLint index, Vec4 defaults) const;
};

class Context {
 public:
  Context(GLenum format, int depth_bits);
  ~Context();

  // --- OSMesa
  bool make_current(void* buffer, GLenum type, int width, int height);
  void release();  // no longer current: run what is pending
  bool depth_buffer(GLint* width, GLint* height, GLint* bytes_per_value, void** buffer);
  GLenum format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
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

  // --- primitives
  void begin(GLenum mode);
  void end();
  void vertex(Vec4 v);
  void set_color(Vec4 c);
  void set_normal(Vec3 n) { normal_ = n; }
  void set_texcoord(Vec4 t) { texcoord_ = t; }
  void rect(float x1, float y1, float x2, float y2);

  // --- matrices
  void matrix_mode(GLenum mode);
  void load_identity() { load(M4{}); }
  void load(const M4& m);
  void multiply(const M4& m);
  void push_matrix();
  void pop_matrix();
  const M4& matrix(GLenum which) const;
  int stack_depth(GLenum which) const;

  // --- per-fragment and rasterization state
  void enable(GLenum cap, bool on);
  bool is_enabled(GLenum cap, bool* known) const;
  void viewport(GLint x, GLint y, GLsizei w, GLsizei h);
  void depth_range(double n, double f);
  void scissor(GLint x, GLint y, GLsizei w, GLsizei h);
  void clear(GLbitfield mask);
  void clear_color(Vec4 c) { clear_color_ = c; }
  void clear_depth(double d);
  void depth_func(GLenum f);
  void depth_mask(bool on);
  void color_mask(bool r, bool g, bool b, bool a);
  void blend_func(GLenum s, GLenum d);
  void alpha_func(GLenum f, float ref);
  void fog(GLenum pname, const float* v);
  void hint(GLenum target, GLenum mode);
  void cull_face(GLenum m);
  void front_face(GLenum m);
  void polygon_mode(GLenum face, GLenum mode);
  void polygon_offset(float factor, float units);
  void point_size(float s);
  void line_width(float w);
  void shade_model(GLenum m);

  // --- lighting
  void light(GLenum light, GLenum pname, const float* v);
  bool get_light(GLenum light, GLenum pname, float* v);
  void light_model(GLenum pname, const float* v);
  void material(GLenum face, GLenum pname, const float* v);
  bool get_material(GLenum face, GLenum pname, float* v);
  void color_material(GLenum face, GLenum mode);

  // --- textures
  void gen_textures(GLsizei n, GLuint* out);
  void delete_textures(GLsizei n, const GLuint* ids);
  void bind_texture(GLenum target, GLuint id);
  bool is_texture(GLuint id) const { return textures_.count(id) != 0; }
  // `rgba` holds width * height texels already converted (see api.cpp); null for a
  // level with undefined contents.
  void tex_image(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLint border,
                 const std::vector<uint32_t>* rgba);
  void tex_sub_image(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h,
                     const std::vector<uint32_t>& rgba);
  void tex_parameter(GLenum target, GLenum pname, const float* v);
  void tex_env(GLenum target, GLenum pname, const float* v);
  // The internal format glTexImage2D's argument names, or 0 if none.
  static GLenum base_format(GLint internal);
  GLint unpack_alignment = 4, pack_alignment = 4;

  // --- vertex arrays
  ClientArray vertex_array, normal_array, color_array, texcoord_array;
  void client_state(GLenum cap, bool on);
  void array_element(GLint i);
  void draw_arrays(GLenum mode, GLint first, GLsizei count);
  void draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices);

  // --- display lists
  GLuint gen_lists(GLsizei range);
  void new_list(GLuint list, GLenum mode);
  void end_list();
  void call_list(GLuint list);
  void delete_lists(GLuint list, GLsizei range);
  bool is_list(GLuint list) const { return lists_.count(list) != 0; }
  bool compiling() const { return compiling_ != 0; }
  bool compile_and_execute() const { return compile_mode_ == GL_COMPILE_AND_EXECUTE; }
  void record(ListCommand cmd);
  GLuint list_base = 0;

  // --- queries, read-back
  // glGet: the values of `pname` as doubles, with `kind` saying how glGetIntegerv maps
  // them (0: round; 1: a colour, mapped to the full integer range). False: unknown name.
  bool get(GLenum pname, std::vector<double>& out, int& kind);
  void read_pixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels);
  void finish();  // glFinish and glFlush: run the frame, colour to the caller's buffer

 private:
  struct Pending {
    PrimitiveKind kind = PrimitiveKind::Triangles;
    bool offset = false;
    PixelState state;
    std::vector<Vec4> position, color, texcoord;
    std::vector<float> fog;
    std::vector<uint32_t> index;
    void clear() { position.clear(), color.clear(), texcoord.clear(), fog.clear(), index.clear(); }
  };

  void ensure_frame();
  void submit_pending();
  void run_frame();  // end the frame, copy colour (and depth) out
  void copy_depth();
  PixelState pixel_state(bool offset);
  // Vertex `i` of prim_ into the pending batch; `shared`: with its own front colour,
  // so a vertex already in the batch is referenced again instead of copied.
  void emit_vertex(uint32_t i, const Vec4& color, bool shared);
  void push_vertex(const Vertex& v);  // to prim_ and order_ (assembling independent ones now and then)
  Pending& target(PrimitiveKind kind, bool offset);
  void assemble(bool final);
  void polygon(const uint32_t* idx, int n, int provoking);
  void line_segment(uint32_t a, uint32_t b, uint32_t provoking);
  void point_vertex(uint32_t a);
  Vec4 lit(const Vec4& eye, Vec3 normal, bool back) const;
  void prepare_lighting();
  struct LightUse {
    const Light* light = nullptr;
    bool positional = false, spot = false;
    float cos_cutoff = -1;
    Vec3 direction, half, spot_direction;
  };
  LightUse light_use_[kMaxLights];
  int lights_used_ = 0;
  bool need_eye_ = false;
  void update_derived();
  TextureObject* bound_texture();
  const Texture* texture_for_draw(TextureObject& t);
  void changed() { pixel_dirty_ = true; }
  M4& top();
  void execute_list(GLuint list, int depth);

  GLenum format_;
  int depth_bits_;
  void* buffer_ = nullptr;
  int width_ = 0, height_ = 0;
  std::unique_ptr<Renderer> renderer_;
  bool in_frame_ = false, first_frame_ = true;
  // A glClear of the whole framebuffer before the frame began, to begin it with.
  bool start_clear_ = false, start_clear_color_ = false, start_clear_depth_ = false;
  Vec4 start_color_{0, 0, 0, 0};
  float start_depth_ = 1;
  std::vector<uint8_t> colour_;  // the last frame's colour, RGBA, bottom row first
  bool direct_ = false;          // ... or in the caller's buffer (RGBA, Y_UP, its own width)
  const uint8_t* colour_rows() const { return direct_ ? static_cast<const uint8_t*>(buffer_) : colour_.data(); }
  std::vector<uint32_t> depth_out_;  // OSMesaGetDepthBuffer's copy
  bool depth_requested_ = false;

  GLenum error_ = GL_NO_ERROR;

  // primitives
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
  Vec4 color_{1, 1, 1, 1}, texcoord_{0, 0, 0, 1};
  Vec3 normal_{0, 0, 1};

  // batches
  Pending pending_;
  bool have_pending_ = false, pixel_dirty_ = true;
  PixelState base_state_;
  std::vector<Pending> submitted_;  // kept alive until the frame ends; reused
  size_t submitted_used_ = 0;
  std::vector<std::shared_ptr<const Texture>> frame_textures_;
  size_t frame_vertices_ = 0;

  // matrices
  GLenum matrix_mode_ = GL_MODELVIEW;
  std::vector<M4> modelview_{M4{}}, projection_{M4{}}, texture_matrix_{M4{}};
  M4 mvp_;
  M4 normal_matrix_;  // inverse transpose of the modelview (upper 3x3 used)
  bool derived_dirty_ = true, texture_identity_ = true;

  // state
  GLint vp_x_ = 0, vp_y_ = 0, vp_w_ = 0, vp_h_ = 0;
  float depth_near_ = 0, depth_far_ = 1;
  GLint sc_x_ = 0, sc_y_ = 0, sc_w_ = 0, sc_h_ = 0;
  bool scissor_test_ = false;
  Vec4 clear_color_{0, 0, 0, 0};
  float clear_depth_ = 1;
  bool depth_test_ = false, depth_write_ = true;
  GLenum depth_func_ = GL_LESS;
  bool mask_[4] = {true, true, true, true};
  bool blend_ = false;
  GLenum blend_src_ = GL_ONE, blend_dst_ = GL_ZERO;
  bool alpha_test_ = false;
  GLenum alpha_func_ = GL_ALWAYS;
  float alpha_ref_ = 0;
  bool fog_ = false;
  GLenum fog_mode_ = GL_EXP;
  float fog_start_ = 0, fog_end_ = 1, fog_density_ = 1;
  Vec4 fog_color_{0, 0, 0, 0};
  GLenum hints_[5] = {GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE};
  bool cull_ = false;
  GLenum cull_mode_ = GL_BACK, front_face_ = GL_CCW;
  GLenum polygon_mode_[2] = {GL_FILL, GL_FILL};  // front, back
  bool offset_fill_ = false, offset_line_ = false, offset_point_ = false;
  float offset_factor_ = 0, offset_units_ = 0;
  float point_size_ = 1, line_width_ = 1;
  GLenum shade_model_ = GL_SMOOTH;
  bool normalize_ = false, rescale_normal_ = false;

  // lighting
  bool lighting_ = false;
  Light lights_[kMaxLights];
  Vec4 model_ambient_{0.2f, 0.2f, 0.2f, 1};
  bool two_side_ = false, local_viewer_ = false;
  Material materials_[2];  // front, back
  bool color_material_ = false;
  GLenum color_material_face_ = GL_FRONT_AND_BACK, color_material_mode_ = GL_AMBIENT_AND_DIFFUSE;
  void apply_color_material();

  // textures
  bool texture_2d_ = false;
  std::map<GLuint, std::unique_ptr<TextureObject>> textures_;
  TextureObject default_texture_;
  GLuint bound_ = 0;
  GLuint next_texture_ = 1;
  GLenum env_mode_ = GL_MODULATE;
  Vec4 env_color_{0, 0, 0, 0};

  // display lists
  std::map<GLuint, std::vector<ListCommand>> lists_;
  GLuint compiling_ = 0;
  GLenum compile_mode_ = GL_COMPILE;
  std::vector<ListCommand> compiling_commands_;
  bool list_overflow_ = false;
  int list_depth_ = 0;
  uint64_t list_budget_ = 0;

  friend struct ContextAccess;
};

// A parameter in [0, 1] (NaN reads 0), and an enum passed as a float (glFogf,
// glTexParameterf...): anything that is not a whole number in GLenum's range becomes
// an invalid enum, never an out-of-range conversion.
inline float unit(double v) { return v > 0 ? (v < 1 ? float(v) : 1.0f) : 0.0f; }
inline GLenum to_enum(float v) { return v >= 0 && v < 4294967296.0f ? GLenum(v) : GLenum(0xffffffffu); }

// The calling thread's current context (OSMesaMakeCurrent), or null.
Context* current();
void set_current(Context* c);

}  // namespace velocity::gl
