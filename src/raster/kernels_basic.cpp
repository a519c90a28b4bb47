// The flat and smooth mesh kernels, and their per-vertex-textured forms.
// Compiled once per instruction set; see raster/tile-inl.h.
#include "raster/rasterize.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/kernels_basic.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/shade_mesh-inl.h"
#include "raster/tile-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

const KernelFn* basic_kernels() {
  // The filter is the sampler's, read per draw: one body serves all three ids.
  static const KernelFn table[] = {
      mesh_kernel<FlatShader>,      mesh_kernel<SmoothShader>,    mesh_kernel<FlatTexShader>,
      mesh_kernel<FlatTexShader>,   mesh_kernel<FlatTexShader>,   mesh_kernel<SmoothTexShader>,
      mesh_kernel<SmoothTexShader>, mesh_kernel<SmoothTexShader>,
  };
  static_assert(sizeof(table) / sizeof(table[0]) == size_t(KernelId::Phong) - size_t(KernelId::Flat));
  return table;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();
