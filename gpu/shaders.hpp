// The GLSL programs of the GPU backend: one source for every mesh shading variant
// (flat, Gouraud, Phong, unlit, wireframe, points; textures and sphere environment
// maps), selected by uniforms, and the lighting model of src/shading/lighting.hpp
// written once in GLSL (kLightingGlsl). The unit test GpuLighting.GlslIsTheScalarModel
// holds the two to each other on random inputs.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace velocity::gpu {

// The most lights a frame may have of each kind (directional, point): uniform arrays.
inline constexpr int kMaxLights = 16;

// light() and apply() of shading/lighting.hpp, term for term, in GLSL.
extern const char* const kLightingGlsl;

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

// The program for pre-transformed primitives with fixed-function pixel state (pGL's path).
GLuint build_batch_program();

// For the test: a vertex shader that lights `a_normal` at `a_position` with kLightingGlsl
// into transform-feedback outputs `o_diffuse` and `o_specular`.
GLuint build_lighting_test_program();

}  // namespace velocity::gpu
