// The glTF metallic-roughness kernels (raster/shade_pbr-inl.h): with and without a
// normal map's tangents and vertex colours, each with the three texture filters (the
// filter is the draw's sampler state; the ids only keep the table uniform). Compiled
// once per instruction set; see raster/tile-inl.h.
#include "raster/rasterize.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/kernels_pbr.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/shade_pbr-inl.h"
#include "raster/tile-inl.h"

HWY_BEFORE_NAMESPACE();
namespace velocity::raster {
namespace HWY_NAMESPACE {

const KernelFn* pbr_kernels() {
  static const KernelFn table[] = {
      pbr_kernel<PbrShader<false, false>>, pbr_kernel<PbrShader<false, false>>, pbr_kernel<PbrShader<false, false>>,
      pbr_kernel<PbrShader<false, true>>,  pbr_kernel<PbrShader<false, true>>,  pbr_kernel<PbrShader<false, true>>,
      pbr_kernel<PbrShader<true, false>>,  pbr_kernel<PbrShader<true, false>>,  pbr_kernel<PbrShader<true, false>>,
      pbr_kernel<PbrShader<true, true>>,   pbr_kernel<PbrShader<true, true>>,   pbr_kernel<PbrShader<true, true>>,
  };
  static_assert(sizeof(table) / sizeof(table[0]) == size_t(KernelId::Fixed) - size_t(KernelId::Pbr));
  return table;
}

}  // namespace HWY_NAMESPACE
}  // namespace velocity::raster
HWY_AFTER_NAMESPACE();
