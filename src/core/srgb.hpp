// sRGB's transfer function (IEC 61966-2-1) and the tables the pipeline uses: a
// 256-entry decode of 8-bit sRGB values (super-sampling's resolve) and an encode of
// linear light to 8 bits indexed by the value's 4096ths (the kernels' output;
// docs/appearance.md). Textures are decoded once each, to 16 bits
// (Texture::linear_levels).
#pragma once

#include <cstdint>

namespace velocity::color {

// The exact curves, for colours converted once (material factors, vertex colours).
float srgb_to_linear(float c);
float linear_to_srgb(float c);

struct SrgbTables {
  static constexpr int kEncodeSize = 4096;
  float decode[256];  // 8-bit sRGB value -> linear [0, 1]
  // Linear x in [0, 1] -> round(255 * linear_to_srgb(x)), at index round(x * 4095).
  // One index step moves the output by under 0.81 of an 8-bit step (the steepest part,
  // near black); above linear 0.03 by under 0.25.
  uint32_t encode[kEncodeSize];
};

// Built once, on first use (thread-safe); read-only after.
const SrgbTables& srgb_tables();

// 8-bit encode of one linear value (clamped), through the table.
inline uint8_t encode8(const SrgbTables& t, float x) {
  x = x > 0 ? (x < 1 ? x : 1) : 0;
  return uint8_t(t.encode[int(x * float(SrgbTables::kEncodeSize - 1) + 0.5f)]);
}

}  // namespace velocity::color
