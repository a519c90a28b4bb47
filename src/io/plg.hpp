// Internal: decoding PLG / PLX polygon descriptors (exposed for the unit tests).
#pragma once

#include <cstdint>

#include "velocity/material.hpp"
#include "velocity/math.hpp"

namespace velocity::detail {

// The two families of 16-bit polygon descriptors found in .plg files.
enum class PlgDialect {
  // Black Art of 3D Game Programming (LaMothe 1995), after REND386's PLG:
  //   bits 12-15 shading: 1 flat (Lambert), anything else constant (0; REND386's
  //              2 "metallic" and 3 "glass" are drawn constant by Black Art too);
  //   bits 8-11  non-zero: two-sided (the chapter 17 and 18 engines; the earlier ones
  //              always had 0 here);
  //   bits 0-7   colour index into the 256-colour palette.
  BlackArt,
  // Tricks of the 3D Game Programming Gurus (LaMothe 2003), "PLX":
  //   bit 15     1: RGB 4.4.4 colour in bits 0-11; 0: colour index in bits 0-7;
  //   bits 13-14 shading: 0 pure (constant), 1 flat, 2 Gouraud, 3 Phong;
  //   bit 12     two-sided.
  Plx,
};

// The material a descriptor describes; its name is the descriptor in hex ("0x109f").
// Constant ("pure") shading is drawn Shading::Unlit: one colour per face, as in the books.
// Indexed colours use vga_palette().
Material plg_material(uint16_t descriptor, PlgDialect dialect);

// Colour `index` of the IBM VGA's default 256-colour palette, in [0, 1].
Vec3 vga_palette(uint8_t index);

}  // namespace velocity::detail
