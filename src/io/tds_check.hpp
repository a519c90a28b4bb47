// Internal: the check a 3D Studio (.3ds) file must pass before Assimp reads it.
//
// A .3ds file is a tree of chunks (a 2-byte id, a 4-byte length that includes the
// 6-byte header, then data and sub-chunks). Assimp 5.2.5 trusts the counts inside
// them: a keyframe track whose 32-bit key count is damaged makes it reserve gigabytes
// (std::bad_alloc, or a fatal report under AddressSanitizer), and it leaks memory on
// some damaged files. So the chunks Assimp reads are walked here first: every chunk
// lies inside its parent, and every counted array fits in its chunk.
#pragma once

#include <string>
#include <string_view>

namespace velocity::detail {

// Throws velocity::Error naming `path` and the chunk's offset unless, in `bytes` (a
// whole .3ds file): the file is one MAIN3DS chunk (0x4d4d); every chunk inside the
// editor (0x3d3d) and keyframer (0xb000) sections, their objects, meshes, materials
// and node tags lies inside its parent; object and material names end inside their
// chunk; and vertex, face, face-material, uv and keyframe-track counts fit the bytes
// their chunk holds.
void check_3ds(std::string_view bytes, const std::string& path);

}  // namespace velocity::detail
