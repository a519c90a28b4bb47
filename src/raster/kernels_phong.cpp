// The per-pixel lighting kernels: Phong, with a base texture and/or an environment map.
// Compiled once per instruction set; see raster/tile-inl.h.
#include "raster/rasterize.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/kernels_phong.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/shade_mesh-inl.h"
#include "raster/tile-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using namespace velocity::simd::HWY_NAMESPACE;

const KernelFn* phong_kernels() {
  static const KernelFn table[] = {
      mesh_kernel<PhongShader<false, false>>,
      mesh_kernel<PhongShader<true, false>>, mesh_kernel<PhongShader<true, false>>, mesh_kernel<PhongShader<true, false>>,
      mesh_kernel<PhongShader<false, true>>, mesh_kernel<PhongShader<false, true>>, mesh_kernel<PhongShader<false, true>>,
      mesh_kernel<PhongShader<true, true>>,  mesh_kernel<PhongShader<true, true>>,  mesh_kernel<PhongShader<true, true>>,
  };
  static_assert(sizeof(table) / sizeof(table[0]) == size_t(KernelId::Pbr) - size_t(KernelId::Phong));
  return table;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();
