#include "core/srgb.hpp"

#include <cmath>

namespace velocity::color {

float srgb_to_linear(float c) {
  if (!(c > 0)) return 0;
  if (c >= 1) return 1;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linear_to_srgb(float c) {
  if (!(c > 0)) return 0;
  if (c >= 1) return 1;
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

const SrgbTables& srgb_tables() {
  static const SrgbTables tables = [] {
    SrgbTables t;
    for (int i = 0; i < 256; ++i) t.decode[i] = srgb_to_linear(float(i) / 255.0f);
    for (int i = 0; i < SrgbTables::kEncodeSize; ++i)
      t.encode[i] = uint32_t(std::lround(255.0f * linear_to_srgb(float(i) / float(SrgbTables::kEncodeSize - 1))));
    return t;
  }();
  return tables;
}

}  // namespace velocity::color
