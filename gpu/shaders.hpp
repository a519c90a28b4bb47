// The GLSL programs of the GPU backend: one source for every mesh shading variant
// (flat, Gouraud, Phong, unlit, wireframe, points; textures and sphere environment
// maps), selected by uniforms, a second for glTF's metallic-roughness PBR; the lighting
// model of src/shading/lighting.hpp written once in GLSL (kLightingGlsl), and the Pbr
// kernel's BRDF (kPbrGlsl). The unit tests GpuLighting.GlslIsTheScalarModel and
// PbrGlslIsTheKernelModel hold them to the CPU's on random inputs.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace velocity::gpu {

// The most lights a frame may have of each kind (directional, point): uniform arrays.
inline constexpr int kMaxLights = 16;
// The shadow maps kLightingGlsl reads: shading::kShadowLights lights, 6 maps for a point light.
inline constexpr int kMaxShadowMaps = 24;

// light() and apply() of shading/lighting.hpp, term for term, in GLSL.
extern const char* const kLightingGlsl;

// raster/shade_pbr-inl.h's BRDF in GLSL (pbr_light), on kLightingGlsl's lights.
extern const char* const kPbrGlsl;

// The frame's colour pipeline in GLSL: to_pipeline() (geometry::pipeline_color) and
// finish() (raster/output-inl.h: exposure, tone map, sRGB encoding).
extern const char* const kColorGlsl;

// What the mesh program's `u_mode` selects (the CPU's kernel families, raster/).
enum Mode : int { kFlat = 0, kSmooth = 1, kPhong = 2, kSolid = 3 /* wireframe, points, replace: one colour */ };
// Where a corner's base colour comes from (triangle/mesh_job.cpp's base_color).
enum BaseSource : int { kMaterialColor = 0, kFaceColor = 1, kVertexColor = 2 };

// A compiled and linked program; throws velocity::Error with the driver's log.
GLuint build_program(const std::string& vertex, const std::string& geometry, const std::string& fragment);

// The mesh program; `affine`: varyings interpolated in screen space (RenderOptions::affine);
// `primitive`: 0 triangles, 1 their edges, 2 their corners (those three with a geometry
// shader), 3 triangles without one (Gouraud, Phong, unlit: no per-face colour).
GLuint build_mesh_program(bool affine, int primitive);

// The program for Shading::Pbr materials (no geometry stage: nothing per face).
GLuint build_pbr_program(bool affine);

// The depth-only program of the shadow maps (`u_mvp`, positions at location 0).
GLuint build_depth_program();

// The program for pre-transformed primitives with fixed-function pixel state (pGL's path).
// `lines`: its variant for lines, drawn by the CPU's rule (a geometry shader makes a quad
// of each, the fragment shader keeps the pixels the rule lights).
GLuint build_batch_program(bool lines);

// The super-sampling resolve pass: u_samples (the k x k sample image), u_k.
GLuint build_resolve_program();

// The windowed path's 2D layer: u_layer (premultiplied RGBA, top row first) over the
// viewport u_viewport (x, y, width, height in window pixels), nearest texel per pixel;
// only the texels in u_box (x0, y0, x1, y1: this frame's upload).
GLuint build_overlay_program();

// For the test: a vertex shader that lights `a_normal` at `a_position` with kLightingGlsl
// into transform-feedback outputs `o_diffuse` and `o_specular`.
GLuint build_lighting_test_program();

// For the test: a vertex shader that evaluates pbr_light() at `a_position` with normal
// `a_normal`, direction to the eye `a_view`, base colour `a_base` and (metallic,
// roughness, occlusion) `a_material` into the transform-feedback output `o_color`.
GLuint build_pbr_test_program();

}  // namespace velocity::gpu
