// The directional albedo E(roughness, N.V) of glTF's specular lobe alone (GGX, Smith's
// height-correlated visibility, Fresnel 1): the share of light it reflects in one
// bounce. What it loses is light that bounces more than once between the microfacets,
// which the PBR kernels give back to the lobe (Turquin 2019, "Practical multiple
// scattering compensation for microfacet models", eq. 16, as three.js and Filament do):
//
//   specular *= 1 + f0 (1 / E - 1)
//
// so that a white rough metal under uniform light reflects all of it, not half.
#pragma once

namespace velocity::shading {

// E on a kGgxAlbedoSize x kGgxAlbedoSize grid, row j for N.V = (j + 0.5) / size and
// column i for roughness (i + 0.5) / size (texel centres: read it bilinearly, clamped
// at the edges). Integrated numerically once, on first use (thread-safe), then shared.
inline constexpr int kGgxAlbedoSize = 16;
const float* ggx_albedo_table();

// The same, scalar: bilinear in the table (tests, and the reference for the kernels).
float ggx_albedo(float roughness, float n_dot_v);

}  // namespace velocity::shading
