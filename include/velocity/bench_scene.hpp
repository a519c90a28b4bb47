// The reference scene convention (../shared/tools/README.md, shared with glref), so that
// `velocity bench`, the golden tests and any user's comparison draw exactly the same
// frame as the OpenGL reference.
#pragma once

#include <string>

#include "velocity/material.hpp"
#include "velocity/mesh.hpp"
#include "velocity/renderer.hpp"

namespace velocity::bench {

// "sphere:SEGS" (the UV sphere) or a model file (all its meshes merged, node matrices
// applied, normals recomputed as smooth normals averaged over faces sharing a
// position), moved to its bounding-box centre and scaled to a unit bounding sphere.
// Throws velocity::Error for a bad spec or file.
Mesh make_mesh(const std::string& spec);

// The convention's material for a shading mode: colour (0.8, 0.7, 0.6); Phong adds
// white specular 0.5 with exponent 32; wireframe is (0.9, 0.9, 0.9).
Material make_material(Shading shading);

// Renderer options for a shading mode: back faces culled except in wireframe.
RenderOptions make_options(Shading shading);

// Draws frame `frame` of `frames`: camera at (0, 0, 3) looking down -Z, 45 degrees,
// near 0.1, far 100; the light from (0.3, 0.5, 1) in eye space; the mesh turned
// 360 * frame / frames degrees about +Y; `copies` copies in a ceil(sqrt(N)) grid
// filling [-1, 1]^2; clear colour (0.1, 0.1, 0.15).
void draw_frame(Renderer& renderer, const Mesh& mesh, const Material& material, int frame, int frames, int copies = 1);

}  // namespace velocity::bench
