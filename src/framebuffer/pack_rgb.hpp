// RGBA8 pixels to RGB8 (the alpha bytes dropped), for read-backs that want RGB.
#pragma once

#include <cstddef>
#include <cstdint>

namespace velocity {

// rgb (3 * pixels bytes) from rgba (4 * pixels bytes); the two must not overlap.
void pack_rgb(const uint8_t* rgba, uint8_t* rgb, size_t pixels);

}  // namespace velocity
