// The reference scene convention (../shared/tools/README.md, shared with glref), so that
// `velocity bench`, the golden tests and any user's comparison draw exactly the same
// frame as the OpenGL reference.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "velocity/material.hpp"
#include "velocity/mesh.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"

namespace velocity::bench {

// "sphere:SEGS" (the UV sphere) or a model file (all its meshes merged, node matrices
// applied, normals recomputed as smooth normals averaged over faces sharing a
// position), moved to its bounding-box centre and scaled to a unit bounding sphere.
// Throws velocity::Error for a bad spec or file.
Mesh make_mesh(const std::string& spec);

// How the convention draws one of its shading modes: the material and renderer options.
struct Look {
  Material material;
  RenderOptions options;
};

// The convention's look for "flat", "gouraud", "phong", "wire", "tex" or "env" (nullopt
// for anything else): material colour (0.8, 0.7, 0.6); "phong" adds white specular 0.5
// with exponent 32; "wire" is (0.9, 0.9, 0.9), unculled; "tex" is Gouraud lighting of a
// white material modulating `texture` (trilinear); "env" is "phong" with the base colour
// from `texture` used as a sphere environment map. Velocity's own rows: "pbr" is glTF's
// metallic-roughness (metallic 0.3, roughness 0.5), per pixel in the linear pipeline;
// "pbrtex" adds `texture` as its base colour texture. A null
// `texture` means the convention's 256x256 checkerboard.
std::optional<Look> make_look(std::string_view shade, std::shared_ptr<const Texture> texture = nullptr);

// Draws frame `frame` of `frames`: camera at (0, 0, 3) looking down -Z, 45 degrees,
// near 0.1, far 100; the light from (0.3, 0.5, 1) in eye space; the mesh turned
// 360 * frame / frames degrees about +Y; `copies` copies in a ceil(sqrt(N)) grid
// filling [-1, 1]^2; clear colour (0.1, 0.1, 0.15).
void draw_frame(Renderer& renderer, const Mesh& mesh, const Material& material, int frame, int frames, int copies = 1);

}  // namespace velocity::bench
