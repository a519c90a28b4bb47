// pGL's state, one struct per GL area as Mesa's gl_context holds it (src/mesa/main/
// mtypes.h): transform, lighting, raster (per-fragment and rasterization), textures,
// vertex arrays, display lists. Each area's entry points are in the .cpp of its name
// (transform.cpp, lighting.cpp, raster_state.cpp, texture.cpp, arrays.cpp, lists.cpp);
// the vertex stage (vertex.cpp) and the batches (frame.cpp) read them.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "clip_planes.hpp"
#include "pixel_ops.hpp"
#include "tex_gen.hpp"
#include "shading/lighting.hpp"
#include "velocity/math.hpp"
#include "velocity/primitives.hpp"
#include "velocity/texture.hpp"

namespace velocity::gl {

// OpenGL passes and returns matrices column-major, m[col * 4 + row] (glLoadMatrix,
// glMultMatrix, glGet(GL_MODELVIEW_MATRIX), GLU's arguments); velocity::Mat4, which
// pGL keeps, is row-major, m[row][col]. The two conversions:
template <class T>
Mat4 load_column_major(const T* m) {
  Mat4 r;
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) r.m[row][col] = float(m[col * 4 + row]);
  return r;
}
template <class T>
void store_column_major(const Mat4& a, T* out) {
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) out[col * 4 + row] = T(a.m[row][col]);
}

// Implementation limits (what glGet reports).
constexpr int kMaxLights = 8;
constexpr int kMaxModelviewDepth = 32, kMaxProjectionDepth = 32, kMaxTextureDepth = 10;
constexpr int kMaxTextureSize = 4096;
constexpr int kMaxTextureLevels = 13;  // 4096 down to 1
constexpr int kMax3DTextureSize = 256;  // GL_MAX_3D_TEXTURE_SIZE: 256^3 RGBA8 is 64 MiB (texture_3d.cpp)
constexpr float kMaxLodBias = 16;        // GL_MAX_TEXTURE_LOD_BIAS (llvmpipe's)
constexpr int kMaxListNesting = 64;
constexpr int kMaxAttribDepth = 16;
constexpr int kMaxNameDepth = 64;  // the selection name stack  // glPushAttrib's and glPushClientAttrib's stacks
constexpr size_t kMaxListCommands = size_t(1) << 24;  // per list; more is GL_OUT_OF_MEMORY
constexpr size_t kMaxVerticesPerFrame = size_t(1) << 22;  // more: the frame is run, a new one begun
// Texel bytes a frame may keep alive (textures replaced or deleted while the frame that
// draws with them is pending): more, and the frame is run, as for vertices.
constexpr size_t kMaxTextureBytesPerFrame = size_t(256) << 20;
// A batch goes to the renderer at the first primitive past this many vertices (one job
// of the renderer's triangle stage, 4,096 triangles): the renderer's workers set up and
// bin it while this thread records the next (src/frame.cpp, "Streaming").
constexpr size_t kStreamBatchVertices = 3 * 4096;
// A strip, fan, loop or polygon longer than this (GL_OUT_OF_MEMORY; the rest is dropped).
constexpr size_t kMaxPrimitiveVertices = size_t(1) << 22;
// Commands one outermost glCallList may run, nested lists included: lists that call each
// other twice over would otherwise run 2^64 of them (GL_OUT_OF_MEMORY, the rest skipped).
constexpr uint64_t kMaxListCallCommands = uint64_t(1) << 25;
constexpr int kMaxViewport = 16384;
// The largest point size and line width (glPointSize, glLineWidth clamp to it).
constexpr float kMaxPointLineSize = 64;

// A viewport or a scissor box (window coordinates, GL's bottom row 0).
struct Box {
  GLint x = 0, y = 0, width = 0, height = 0;
};
// The box glViewport or glScissor gives, kept within reach of the framebuffer's limits,
// so that x + width cannot overflow.
inline Box within_reach(GLint x, GLint y, GLsizei w, GLsizei h) {
  return {std::clamp(x, -kMaxViewport, kMaxViewport), std::clamp(y, -kMaxViewport, kMaxViewport),
          std::min(w, kMaxViewport), std::min(h, kMaxViewport)};
}

// --- transform (transform.cpp): matrix stacks, viewport, depth range ---------------
struct TransformState {
  GLenum matrix_mode = GL_MODELVIEW;
  std::vector<Mat4> modelview{Mat4{}}, projection{Mat4{}}, texture{Mat4{}};  // the stacks, top last
  // Derived from the tops when a glBegin needs them (update_derived).
  Mat4 mvp;            // projection * modelview, clip-space y negated
  Mat4 normal_matrix;  // inverse transpose of the modelview's upper 3x3
  bool derived_dirty = true, texture_identity = true;
  Box viewport;
  float depth_near = 0, depth_far = 1;
  bool normalize = false, rescale_normal = false;
};

// --- lighting (lighting.cpp): lights, materials, colour material ------------------
struct Light {
  Vec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  Vec4 position{0, 0, 1, 0};  // eye space (transformed by the modelview at glLight time)
  Vec3 spot_direction{0, 0, -1};  // eye space
  float spot_exponent = 0, spot_cutoff = 180;
  float constant = 1, linear = 0, quadratic = 0;
  bool enabled = false;
};

using Material = shading::GlMaterial;  // (src/shading/lighting.hpp)

struct LightingState {
  bool enabled = false;  // GL_LIGHTING
  Light lights[kMaxLights];
  Vec4 model_ambient{0.2f, 0.2f, 0.2f, 1};
  bool two_side = false, local_viewer = false;
  Material materials[2];  // front, back
  bool color_material = false;
  GLenum color_material_face = GL_FRONT_AND_BACK, color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  GLenum shade_model = GL_SMOOTH;
  LightingState() { lights[0].diffuse = lights[0].specular = {1, 1, 1, 1}; }
};

// --- raster state (raster_state.cpp): per-fragment tests, blending, fog, clears, ----
// --- masks, culling, polygon mode and offset, point and line size -----------------
struct RasterState {
  bool scissor_test = false;
  Box scissor;
  Vec4 clear_color{0, 0, 0, 0};
  float clear_depth = 1;
  bool depth_test = false, depth_write = true;
  GLenum depth_func = GL_LESS;
  bool color_mask[4] = {true, true, true, true};
  bool blend = false;
  GLenum blend_src = GL_ONE, blend_dst = GL_ZERO;  // (RGB; glBlendFunc sets alpha's too)
  GLenum blend_src_alpha = GL_ONE, blend_dst_alpha = GL_ZERO, blend_equation = GL_FUNC_ADD;  // blend.cpp
  Vec4 blend_color{0, 0, 0, 0};
  bool logic_op = false;  // GL_COLOR_LOGIC_OP
  GLenum logic_op_mode = GL_COPY;
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0;
  bool fog = false;
  GLenum fog_mode = GL_EXP;
  float fog_start = 0, fog_end = 1, fog_density = 1;
  Vec4 fog_color{0, 0, 0, 0};
  GLenum hints[5] = {GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE};
  bool cull = false;
  GLenum cull_mode = GL_BACK, front_face = GL_CCW;
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL};  // front, back
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0, offset_units = 0;
  float point_size = 1, line_width = 1;
  bool polygon_stipple = false;  // GL_POLYGON_STIPPLE (polygon_stipple.cpp)
  std::array<uint32_t, 32> stipple = all_ones();  // bit x of row y: pixel (x, y) mod 32
  static std::array<uint32_t, 32> all_ones() {
    std::array<uint32_t, 32> a;
    a.fill(~0u);
    return a;
  }
  bool line_stipple = false;  // GL_LINE_STIPPLE (line_stipple.cpp)
  GLint stipple_factor = 1;
  GLushort stipple_pattern = 0xffff;
  uint8_t color_mask_bits() const {
    return uint8_t((color_mask[0] ? 1 : 0) | (color_mask[1] ? 2 : 0) | (color_mask[2] ? 4 : 0) | (color_mask[3] ? 8 : 0));
  }
};

// --- the stencil buffer (stencil.cpp) --------------------------------------------
struct StencilState {
  bool test = false;  // GL_STENCIL_TEST
  GLenum func = GL_ALWAYS;
  GLint ref = 0;  // as given; clamped to the buffer's range where it is used and read
  GLuint value_mask = ~0u, write_mask = ~0u;
  GLenum fail = GL_KEEP, depth_fail = GL_KEEP, pass = GL_KEEP;
  GLint clear = 0;  // glClearStencil
};

// --- textures (texture.cpp) -------------------------------------------------------
struct TextureObject {
  // Levels as glTexImage2D gave them (RGBA8 after the internal format was applied);
  // width 0: the level was never specified.
  std::array<Texture::Level, kMaxTextureLevels> levels{};
  TexFormat format = TexFormat::Rgba;
  GLenum internal_format = GL_RGBA;
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT;
  GLenum wrap_r = GL_REPEAT;  // GL_TEXTURE_WRAP_R (3-D textures, texture_3d.cpp)
  Vec4 border{0, 0, 0, 0};
  bool generate_mipmap = false;
  int base_level = 0, max_level = 1000;  // GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL
  GLenum target = 0;  // GL_TEXTURE_1D or GL_TEXTURE_2D once first bound (texture_1d.cpp)
  float min_lod = -1000, max_lod = 1000, lod_bias = 0;  // GL_TEXTURE_MIN_LOD, _MAX_LOD, _LOD_BIAS
  uint64_t serial = 0;  // changed by every write of its texels (framebuffer_objects.cpp)
  // What the renderer samples, built when first drawn after a change (null: not yet,
  // or incomplete). Draws already recorded keep their own reference.
  std::shared_ptr<const Texture> built;
  bool dirty = true, complete = false;
};

struct TextureState {
  bool enabled = false;  // GL_TEXTURE_2D
  std::map<GLuint, std::unique_ptr<TextureObject>> objects;
  TextureObject default_object;  // name 0
  GLuint bound = 0;
  GLuint next_name = 1;
  GLenum env_mode = GL_MODULATE;
  Vec4 env_color{0, 0, 0, 0};
  TexCombine combine;  // GL_COMBINE's parameters (tex_combine.cpp)
  // 1-D textures (texture_1d.cpp): height-1 images in the same objects and sampler.
  bool enabled_1d = false;  // GL_TEXTURE_1D (GL_TEXTURE_2D takes precedence)
  GLuint bound_1d = 0;
  TextureObject default_1d;  // name 0 on GL_TEXTURE_1D
  float lod_bias = 0;  // GL 1.4's glTexEnv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS)
  TextureObject proxy;  // GL_PROXY_TEXTURE_2D: levels' sizes only, never texels
  // 3-D textures (texture_3d.cpp): levels of slices in the same objects, sampled at (s, t, r).
  bool enabled_3d = false;  // GL_TEXTURE_3D (takes precedence over GL_TEXTURE_2D and 1D)
  GLuint bound_3d = 0;
  TextureObject default_3d = [] {  // name 0 on GL_TEXTURE_3D
    TextureObject t;
    t.target = GL_TEXTURE_3D;
    return t;
  }();
  TextureObject proxy_3d;    // GL_PROXY_TEXTURE_3D
};

// --- buffer objects (buffer_objects.cpp): GL 1.5's vertex and index data kept by ---
// --- the library ------------------------------------------------------------------
// A buffer of more than kMaxBufferBytes, or one that would take all buffers past
// kMaxBufferTotalBytes, is GL_OUT_OF_MEMORY.
constexpr size_t kMaxBufferBytes = size_t(256) << 20;
constexpr size_t kMaxBufferTotalBytes = size_t(1) << 30;
constexpr size_t kMaxBufferObjects = size_t(1) << 20;

struct BufferObject {
  GLuint name = 0;
  std::vector<uint8_t> data;  // `size` bytes, and at least one (a map of 0 bytes is not null)
  size_t size = 0;
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;  // glMapBuffer's, while mapped
  bool mapped = false;
};

struct BufferState {
  std::map<GLuint, std::shared_ptr<BufferObject>> objects;  // the names bound at least once
  GLuint next_name = 1;
  size_t total_bytes = 0;  // of the objects' data
};

// --- occlusion queries (occlusion.cpp): GL 1.5's GL_SAMPLES_PASSED ----------------
struct QueryObject {
  // The draws between glBeginQuery and glEndQuery count into it as their frame runs
  // (PixelState::samples_passed).
  std::atomic<uint64_t> samples{0};
  bool pending = false;  // ended while its frame had not run
};

constexpr size_t kMaxQueryObjects = size_t(1) << 20;  // more is GL_OUT_OF_MEMORY

struct QueryState {
  std::map<GLuint, std::unique_ptr<QueryObject>> objects;  // the names begun at least once
  GLuint next_name = 1;
  GLuint active = 0;  // the query between glBeginQuery and glEndQuery, or 0
  QueryObject* active_object = nullptr;
};

// --- evaluators (evaluators.cpp) --------------------------------------------------
constexpr int kMap1Targets = 9;    // GL_MAP1_COLOR_4 .. GL_MAP1_VERTEX_4
constexpr int kMap2Targets = 9;    // GL_MAP2_COLOR_4 .. GL_MAP2_VERTEX_4
constexpr int kMaxEvalOrder = 30;  // GL_MAX_EVAL_ORDER (Mesa's)

struct Map1 {
  float u1 = 0, u2 = 1;
  int order = 1;
  std::vector<float> points;  // order control points of the target's components
};

struct Map2 {
  float u1 = 0, u2 = 1, v1 = 0, v2 = 1;
  int uorder = 1, vorder = 1;
  std::vector<float> points;  // uorder x vorder control points, u-major (as glGetMap gives them)
};

// One axis of glMapGrid: n segments from a to b.
struct EvalGrid {
  GLint n = 1;
  float a = 0, b = 1;
};

// The maps (not in any attribute group) and the flags and grids (GL_EVAL_BIT).
struct EvalState {
  Map1 maps[kMap1Targets];
  Map2 maps2[kMap2Targets];
  bool enabled[kMap1Targets] = {};
  bool enabled2[kMap2Targets] = {};
  bool auto_normal = false;
  EvalGrid grid1, grid2u, grid2v;
  EvalState();
};

// --- vertex arrays (arrays.cpp) ---------------------------------------------------
// One vertex array (glVertexPointer and the like).
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;
  // The GL_ARRAY_BUFFER bound when the pointer was given: `pointer` is then an offset
  // into it, and an element outside it reads as the defaults.
  std::shared_ptr<BufferObject> buffer;
  bool usable() const { return buffer || pointer; }
  // Element `index`'s first `bytes` bytes, or null where they are outside the buffer.
  const unsigned char* element(GLint index, size_t bytes) const;
  Vec4 fetch(GLint index, Vec4 defaults) const;
  // A colour's or a normal's first `components`: integer types map to [0, 1] (unsigned)
  // or [-1, 1] (signed).
  Vec4 fetch_normalized(GLint index, Vec4 defaults, int components) const;
};

struct ArrayState {
  ClientArray vertex, normal, color, texcoord;
  // glEdgeFlagPointer: GLbooleans `stride` bytes apart (0: packed).
  bool edge_enabled = false;
  GLsizei edge_stride = 0;
  const GLboolean* edge_pointer = nullptr;
  std::shared_ptr<BufferObject> edge_buffer;  // (as ClientArray::buffer)
  bool edge_usable() const { return edge_buffer || edge_pointer; }
  bool edge(GLint i) const;  // (arrays.cpp; outside its buffer: true)
  // GL 1.5's GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER bindings (buffer_objects.cpp).
  std::shared_ptr<BufferObject> array_buffer, element_buffer;
  // GL 1.4's secondary colour and fog coordinate arrays; the colour index array's state
  // (never drawn: no colour index mode) (color_sum.cpp).
  ClientArray secondary_color, fog_coord, index;
  ArrayState() { secondary_color.size = 3, fog_coord.size = 1, index.size = 1; }
};

// --- multitexture (multitexture.cpp): GL 1.3's texture units ---------------------
constexpr int kTextureUnits = 2;  // GL_MAX_TEXTURE_UNITS (the renderer's kMaxTextureUnits)
// A texture unit's server state while another unit's is in the live fields (the
// TextureState enables, bindings, environment and bias, the texture matrix stack, the
// glTexGen state): the context keeps the active unit's there, for every call that works
// on "the" unit, and the other one here.
struct TextureUnitState {
  bool enabled = false, enabled_1d = false, enabled_3d = false;
  GLuint bound = 0, bound_1d = 0, bound_3d = 0;
  GLenum env_mode = GL_MODULATE;
  Vec4 env_color{0, 0, 0, 0};
  TexCombine combine;
  float lod_bias = 0;
  std::vector<Mat4> matrix{Mat4{}};
  bool matrix_identity = true;
  TexGenState tex_gen;
};

// --- GL 1.2's separate specular colour, GL 1.4's colour sum and fog coordinate ----
// --- source (color_sum.cpp) -------------------------------------------------------
struct ColorSumState {
  bool enabled = false;            // GL_COLOR_SUM (GL_FOG_BIT and GL_ENABLE_BIT)
  bool separate_specular = false;  // GL_LIGHT_MODEL_COLOR_CONTROL (GL_LIGHTING_BIT)
  GLenum fog_coord_src = 0x8452;   // GL_FOG_COORD_SRC: GL_FRAGMENT_DEPTH (GL_FOG_BIT)
};

// --- display lists (lists.cpp) ----------------------------------------------------
class Context;
using ListCommand = std::function<void(Context&)>;

struct ListState {
  std::map<GLuint, std::vector<ListCommand>> stored;
  GLuint compiling = 0;  // the list between glNewList and glEndList, or 0
  GLenum mode = GL_COMPILE;
  std::vector<ListCommand> recorded;  // what glNewList has recorded so far
  bool overflow = false;
  int depth = 0;        // glCallList nesting now
  uint64_t budget = 0;  // commands the outermost glCallList may still run
  GLuint base = 0;      // glListBase
};

// --- selection (select.cpp): glRenderMode(GL_SELECT), the name stack, hit records --
struct SelectState {
  GLenum mode = GL_RENDER;
  GLuint* buffer = nullptr;  // glSelectBuffer's
  size_t size = 0, used = 0, hits = 0;
  bool overflow = false;
  std::vector<GLuint> names;
  bool hit = false;  // since the last record
  float min_z = 1, max_z = 0;
};

// --- feedback (feedback.cpp): glRenderMode(GL_FEEDBACK), glFeedbackBuffer -----------
struct FeedbackState {
  GLenum type = GL_2D;        // glFeedbackBuffer's: which values a vertex writes
  GLfloat* buffer = nullptr;  // the program's
  size_t size = 0, used = 0;  // values written (counted past `size` on overflow)
};

// --- attribute stacks (attrib.cpp): what glPushAttrib and glPushClientAttrib saved --
struct AttribFrame {
  GLbitfield mask = 0;
  RasterState raster;
  LightingState lighting;
  StencilState stencil;
  Vec4 accum_clear;
  Box viewport;
  float depth_near = 0, depth_far = 1;
  GLenum matrix_mode = GL_MODELVIEW;
  bool normalize = false, rescale_normal = false;
  bool texture_enabled = false;
  GLuint texture_bound = 0;
  bool texture_enabled_1d = false;
  GLuint texture_bound_1d = 0;
  bool texture_enabled_3d = false;
  GLuint texture_bound_3d = 0;
  GLenum env_mode = GL_MODULATE;
  Vec4 env_color;
  TexCombine combine;  // GL_TEXTURE_BIT
  Vec4 color, texcoord;
  Vec3 normal;
  bool edge_flag = true;
  GLuint list_base = 0;
  RasterPosition raster_pos;  // GL_CURRENT_BIT
  float zoom_x = 1, zoom_y = 1;  // GL_PIXEL_MODE_BIT
  UserClipState user_clip;  // GL_TRANSFORM_BIT (planes and enables), GL_ENABLE_BIT (enables)
  TexGenState tex_gen;      // GL_TEXTURE_BIT (all of it), GL_ENABLE_BIT (enables)
  GLenum draw_buffer = GL_FRONT;  // GL_COLOR_BUFFER_BIT (buffers.cpp)
  GLenum read_buffer = GL_FRONT;  // GL_PIXEL_MODE_BIT
  PixelTransfer transfer;         // GL_PIXEL_MODE_BIT (pixel_transfer.cpp)
  ColorSumState color_sum;        // (color_sum.cpp: by bit)
  Vec4 secondary{0, 0, 0, 1};     // GL_CURRENT_BIT
  float fog_coord = 0;            // GL_CURRENT_BIT
  // multitexture.cpp: the other unit (unit 1: the frame is taken with unit 0 live),
  // the active unit, unit 1's current coordinates.
  TextureUnitState unit1;  // GL_TEXTURE_BIT, GL_ENABLE_BIT (its enables)
  int active_unit = 0;     // GL_TEXTURE_BIT
  Vec4 texcoord1{0, 0, 0, 1}, raster_texcoord1{0, 0, 0, 1};  // GL_CURRENT_BIT
  EvalState eval;  // GL_EVAL_BIT (its flags and grids), GL_ENABLE_BIT (the enables)
};

struct ClientAttribFrame {
  GLbitfield mask = 0;
  GLint unpack_alignment = 4, pack_alignment = 4;
  PixelStore unpack, pack;  // every GL_UNPACK_* and GL_PACK_* value
  ArrayState arrays;
  ClientArray texcoord1;  // unit 1's coordinate array (multitexture.cpp; unit 0 live)
  int client_unit = 0;
};

}  // namespace velocity::gl
