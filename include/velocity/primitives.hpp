// Pre-transformed primitives with fixed-function pixel state: the layer an
// immediate-mode front end draws through (Velocity's OpenGL 1.x library in gl/ does).
//
// The front end does its own vertex work (transform, lighting, texture-coordinate
// generation, culling, polygon modes, flat-shading colours) and hands the renderer
// points, lines and triangles in clip space with per-vertex RGBA colour, texture
// coordinates and fog coordinate. The renderer clips them (near, far, guard band),
// maps them through the batch's viewport, sets them up, bins them and rasterizes them
// on the same tiles, threads and SIMD kernels as meshes, applying the PixelState below
// in OpenGL's order: texture environment, fog, scissor, alpha test, stencil test,
// depth test, blend, colour mask.
//
//   velocity::PrimitiveBatch b;
//   b.kind = velocity::PrimitiveKind::Triangles;
//   b.position = clip.data(); b.color = rgba.data(); b.vertex_count = n;
//   renderer.draw(b, state);          // inside begin_frame / end_frame
//
// Everything the batch points to (arrays, textures) must stay alive and unchanged
// until end_frame() returns: the work is done by then, on every core. (The CPU
// backend may start a batch's vertex and triangle work on its worker threads as soon
// as it is drawn, while the caller records the next; src/frame.cpp, "Streaming".)
#pragma once

#include <atomic>
#include <cstdint>

#include "velocity/math.hpp"
#include "velocity/texture.hpp"

namespace velocity {

// OpenGL's comparison functions (glDepthFunc, glAlphaFunc), same order as GL's enums.
enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

// glBlendFunc's factors (GL 1.4 with the constant-colour ones of the imaging subset).
enum class BlendFactor : uint8_t {
  Zero,
  One,
  SrcColor,
  OneMinusSrcColor,
  DstColor,
  OneMinusDstColor,
  SrcAlpha,
  OneMinusSrcAlpha,
  DstAlpha,
  OneMinusDstAlpha,
  SrcAlphaSaturate,
  ConstantColor,
  OneMinusConstantColor,
  ConstantAlpha,
  OneMinusConstantAlpha,
};

// glBlendEquation: result = src * Fs (op) dst * Fd; Min and Max ignore the factors.
enum class BlendOp : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

// glLogicOp's operations on the framebuffer's 8-bit channels, s the fragment's colour,
// d the pixel's, in GL's order (GL_CLEAR + n).
enum class LogicOp : uint8_t {
  Clear,         // 0
  And,           // s & d
  AndReverse,    // s & ~d
  Copy,          // s
  AndInverted,   // ~s & d
  Noop,          // d
  Xor,           // s ^ d
  Or,            // s | d
  Nor,           // ~(s | d)
  Equiv,         // ~(s ^ d)
  Invert,        // ~d
  OrReverse,     // s | ~d
  CopyInverted,  // ~s
  OrInverted,    // ~s | d
  Nand,          // ~(s & d)
  Set,           // all ones
};

// glTexEnv's GL_TEXTURE_ENV_MODE.
enum class TexEnvMode : uint8_t { Modulate, Replace, Decal, Blend, Add, Combine };

// OpenGL 1.3's GL_COMBINE environment (TexEnvMode::Combine): the RGB and the alpha of
// the result are each one function (GL_COMBINE_RGB, GL_COMBINE_ALPHA) of up to three
// arguments, each argument a source's colour or alpha (GL_SOURCEi_*, GL_OPERANDi_*),
// the result times a scale (GL_RGB_SCALE, GL_ALPHA_SCALE), clamped to [0, 1].
// The defaults are OpenGL's initial state.
enum class CombineOp : uint8_t {
  Replace,      // a0
  Modulate,     // a0 a1
  Add,          // a0 + a1
  AddSigned,    // a0 + a1 - 0.5
  Interpolate,  // a0 a2 + a1 (1 - a2)
  Subtract,     // a0 - a1
  Dot3Rgb,      // 4 ((r0 - .5)(r1 - .5) + (g0 - .5)(g1 - .5) + (b0 - .5)(b1 - .5)) in R, G, B
  Dot3Rgba,     // the same in alpha too (the alpha function is then not used)
};
// Texture: this unit's texel; Constant: the unit's GL_TEXTURE_ENV_COLOR; Primary: the
// fragment's interpolated colour; Previous: the last unit's result (Primary on unit 0).
enum class CombineSource : uint8_t { Texture, Constant, Primary, Previous };
enum class CombineOperand : uint8_t { SrcColor, OneMinusSrcColor, SrcAlpha, OneMinusSrcAlpha };
struct TexCombine {
  CombineOp rgb = CombineOp::Modulate, alpha = CombineOp::Modulate;
  CombineSource source_rgb[3] = {CombineSource::Texture, CombineSource::Previous, CombineSource::Constant};
  CombineSource source_alpha[3] = {CombineSource::Texture, CombineSource::Previous, CombineSource::Constant};
  // The alpha arguments take SrcAlpha or OneMinusSrcAlpha only.
  CombineOperand operand_rgb[3] = {CombineOperand::SrcColor, CombineOperand::SrcColor, CombineOperand::SrcAlpha};
  CombineOperand operand_alpha[3] = {CombineOperand::SrcAlpha, CombineOperand::SrcAlpha, CombineOperand::SrcAlpha};
  float rgb_scale = 1, alpha_scale = 1;  // 1, 2 or 4
};

// What a texture's texels mean (glTexImage2D's base internal format). The Texture
// stores RGBA8 in any case; the format decides which of its channels the environment
// reads, as OpenGL's table of texture functions does: Luminance is stored (L, L, L, 1),
// LuminanceAlpha (L, L, L, A), Alpha (0, 0, 0, A) — only its A is read —,
// Intensity (I, I, I, I), Rgb (R, G, B, 1).
enum class TexFormat : uint8_t { Rgba, Rgb, Luminance, LuminanceAlpha, Alpha, Intensity };

enum class FogMode : uint8_t { Linear, Exp, Exp2 };

// glStencilOp's operations, on the 8-bit stencil value (the Wrap ones are GL 1.4's).
enum class StencilOp : uint8_t { Keep, Zero, Replace, Increment, Decrement, Invert, IncrementWrap, DecrementWrap };

// How a texture is read: OpenGL's magnification and minification filters and wrap
// modes. `mip` None samples level 0 only (GL_NEAREST / GL_LINEAR minification).
struct SamplerState {
  enum class Texel : uint8_t { Nearest, Linear };
  enum class Mip : uint8_t { None, Nearest, Linear };
  Texel mag = Texel::Linear;
  Texel min = Texel::Linear;
  Mip mip = Mip::Linear;
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
  Wrap wrap_r = Wrap::Repeat;  // a 3-D texture's third coordinate (Texture::volume)
  Vec4 border_color{0, 0, 0, 0};  // read outside the texture with Wrap::ClampToBorder
  // OpenGL's level-of-detail controls: the level of detail chosen is the texture's
  // plus lod_bias, then clamped to [min_lod, max_lod] (GL_TEXTURE_LOD_BIAS,
  // GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD); it picks magnification or minification too.
  float lod_bias = 0, min_lod = -1000, max_lod = 1000;
};

// The texture units a batch may use (OpenGL 1.3's multitexture, GL_MAX_TEXTURE_UNITS).
inline constexpr int kMaxTextureUnits = 2;

struct TextureStage {
  const Texture* texture = nullptr;  // null: no texturing
  TexFormat format = TexFormat::Rgba;
  TexEnvMode env = TexEnvMode::Modulate;
  Vec4 env_color{0, 0, 0, 0};  // GL_TEXTURE_ENV_COLOR, for TexEnvMode::Blend and Combine
  TexCombine combine;          // for TexEnvMode::Combine
  SamplerState sampler;
};

// Per-fragment state of one draw. The defaults are OpenGL's initial state, except that
// the depth test is on.
struct PixelState {
  TextureStage texture;
  // The second texture unit (OpenGL 1.3's multitexture): its environment takes what
  // `texture`'s gave, its coordinates are the batch's texcoord1. Read only when
  // `texture` is set (a front end hands its enabled units over in order, first here).
  TextureStage texture1;
  // OpenGL 1.4's colour sum (GL_COLOR_SUM, or lighting with GL_SEPARATE_SPECULAR_COLOR):
  // the batch's secondary colour (RGB) is added after the texture environments, before
  // fog, the sum clamped to 1.
  bool color_sum = false;

  // Fog: colour = f * colour + (1 - f) * fog_color (alpha unchanged), f clamped to
  // [0, 1] from the interpolated fog coordinate c: Linear (end - c) / (end - start),
  // Exp exp(-density * c), Exp2 exp(-(density * c)^2).
  bool fog = false;
  FogMode fog_mode = FogMode::Exp;
  float fog_start = 0, fog_end = 1, fog_density = 1;
  Vec4 fog_color{0, 0, 0, 0};

  // Scissor: only pixels in [x0, x1) x [y0, y1) are touched (framebuffer pixels, row 0
  // at the top; the front end flips GL's bottom-up rectangle).
  bool scissor = false;
  int scissor_x0 = 0, scissor_y0 = 0, scissor_x1 = 0, scissor_y1 = 0;

  bool alpha_test = false;
  CompareFunc alpha_func = CompareFunc::Always;
  float alpha_ref = 0;

  bool depth_test = true;
  CompareFunc depth_func = CompareFunc::Less;
  bool depth_write = true;
  // glPolygonOffset, for triangles (when offset_fill) and the lines and points of
  // polygon modes (when offset_line / offset_point — the front end sets the one that
  // applies): depth += factor * max(|dz/dx|, |dz/dy|) + units * 2^-24.
  bool polygon_offset = false;
  float offset_factor = 0, offset_units = 0;

  bool blend = false;
  BlendFactor blend_src_rgb = BlendFactor::One, blend_dst_rgb = BlendFactor::Zero;
  BlendFactor blend_src_alpha = BlendFactor::One, blend_dst_alpha = BlendFactor::Zero;
  BlendOp blend_op = BlendOp::Add;
  Vec4 blend_color{0, 0, 0, 0};
  // The logic op (GL_COLOR_LOGIC_OP) takes the place of blending: the fragment's colour,
  // as the framebuffer stores it, combined bit by bit with the pixel's.
  bool logic_op = false;
  LogicOp logic = LogicOp::Copy;

  // The stencil test, between the alpha and the depth test: it passes where
  // (ref & value_mask) func (stencil & value_mask); the stencil value then becomes
  // fail's result where it failed, depth_fail's where the depth test failed, pass's
  // where both passed (or there is no depth test), written under write_mask.
  bool stencil_test = false;
  CompareFunc stencil_func = CompareFunc::Always;
  uint8_t stencil_ref = 0, stencil_value_mask = 0xff, stencil_write_mask = 0xff;
  StencilOp stencil_fail = StencilOp::Keep, stencil_depth_fail = StencilOp::Keep, stencil_pass = StencilOp::Keep;

  uint8_t color_mask = 0xf;  // bit 0 red, 1 green, 2 blue, 3 alpha (glColorMask)

  // Polygon stipple (glPolygonStipple): a fragment at framebuffer pixel (x, y) is kept
  // where bit x % 32 of stipple[y % 32] is set. The front end sets it for the draws of
  // filled polygons only.
  bool polygon_stipple = false;
  uint32_t stipple[32] = {};

  // An occlusion query (OpenGL's GL_SAMPLES_PASSED): when set, the fragments that pass
  // the stencil and depth tests (all that reach them, without the tests) are counted
  // into it, as the draw's tiles finish. It must stay alive until end_frame() returns.
  std::atomic<uint64_t>* samples_passed = nullptr;
};

enum class PrimitiveKind : uint8_t { Points, Lines, Triangles };

// User clip planes a batch may carry (OpenGL's GL_MAX_CLIP_PLANES).
inline constexpr uint32_t kMaxUserClipPlanes = 6;

// glViewport and glDepthRange in framebuffer pixels, row 0 at the top. A zero width or
// height means the whole framebuffer.
struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  float depth_near = 0, depth_far = 1;
};

struct PrimitiveBatch {
  PrimitiveKind kind = PrimitiveKind::Triangles;
  // Per vertex. `position` (clip space) is required; the rest may be null: colour
  // defaults to opaque white, texture coordinates to (0, 0, 0, 1), fog to 0, the
  // secondary colour to black. Texture
  // coordinates are projective: s/q and t/q are read, interpolated perspective-correct.
  const Vec4* position = nullptr;
  const Vec4* color = nullptr;     // RGBA, each in [0, 1]
  const Vec4* texcoord = nullptr;  // (s, t, r, q)
  const float* fog = nullptr;      // fog coordinate (GL: eye-space distance)
  const Vec4* texcoord1 = nullptr;  // the second texture unit's (PixelState::texture1)
  const Vec4* secondary = nullptr;  // secondary colour, RGB in [0, 1] (PixelState::color_sum)
  uint32_t vertex_count = 0;
  // The vertices of each primitive (1 per point, 2 per line, 3 per triangle); null
  // means 0, 1, 2, ... vertex_count - 1. Out-of-range indices drop their primitive.
  const uint32_t* indices = nullptr;
  uint32_t index_count = 0;
  Viewport viewport;
  // Points are size x size squares centred on the vertex, lines `width` pixels thick
  // across their minor axis (OpenGL's aliased wide points and lines), both >= 1.
  float point_size = 1, line_width = 1;
  // User clip planes (OpenGL's glClipPlane): `clip_planes` (at most kMaxUserClipPlanes)
  // signed distances per vertex, vertex v's at clip_distance[v * clip_planes + k]. The
  // clipper keeps the part of each primitive where every distance, interpolated
  // linearly in clip space, is >= 0; a point with a negative one is dropped.
  const float* clip_distance = nullptr;
  uint32_t clip_planes = 0;
  // Triangles are drawn whatever their winding: culling is the front end's decision.
};

// A clear inside a frame, in draw order (glClear with the scissor and colour mask).
struct ClearRequest {
  bool color = true, depth = true;
  Vec4 color_value{0, 0, 0, 0};
  float depth_value = 1;
  uint8_t color_mask = 0xf;
  bool depth_write = true;  // false: depth is left alone (glDepthMask(GL_FALSE))
  bool stencil = false;      // the stencil buffer, to stencil_value under stencil_mask
  uint8_t stencil_value = 0, stencil_mask = 0xff;
  bool scissor = false;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // as PixelState's scissor
};

}  // namespace velocity
