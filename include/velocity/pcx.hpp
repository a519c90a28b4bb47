// ZSoft PCX images (the texture format of the DOS-era books and demos).
//
// Files are untrusted: the decoder checks every header field against the data and
// throws velocity::Error naming the file and the problem; it never reads past the
// data and never allocates more than the data can describe.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "velocity/image.hpp"

namespace velocity {

// Decodes a PCX file held in memory. Supported: 8 bits per pixel with 1 plane (256
// colours, palette from the 769-byte block at the end: 0x0C then 256 RGB triples),
// 3 planes (24-bit RGB) or 4 planes (RGBA); run-length encoded (the norm) or stored raw.
// Rows may be padded (BytesPerLine above the width, odd or even). Other depths (1-, 2-
// and 4-bit EGA files) are refused with a message saying so. `name` is used in errors.
// Returns an RGBA image; 256-colour and RGB images get alpha 255.
Image decode_pcx(std::span<const uint8_t> data, const std::string& name);

// Reads and decodes the PCX file at `path` (at most 256 MiB). Throws velocity::Error
// naming the file when it is missing, unreadable or not a valid PCX file.
Image read_pcx(const std::string& path);

}  // namespace velocity
