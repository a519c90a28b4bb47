// Internal: the structural check a PLY file must pass before Assimp reads it.
//
// Assimp 5.2.5's PLY reader trusts its input: on a header cut short it loops forever,
// it allocates whatever the header's counts ask for (3.5 GB for a 60-byte file claiming
// 300 million vertices), a face list cut short becomes a face with no corners that
// aborts the process in Assimp's triangulation, and corrupted list lengths crash it.
// So Velocity walks the whole file first (header grammar, every element instance, every
// list length, every face index) and hands Assimp only files that are complete and
// consistent. The walk allocates nothing in proportion to the file's counts.
#pragma once

#include <string>
#include <string_view>

namespace velocity::detail {

// True when `bytes` starts as Assimp's PLY reader wants ("ply" in any case), whatever
// the file's extension: Assimp falls back to picking its reader by content.
bool looks_like_ply(std::string_view bytes);

// Throws velocity::Error naming `path` (and the line, in the header and in ASCII
// bodies) unless `bytes` is a complete PLY file: a well-formed header ending in
// "end_header", then every element instance the header declares, each list within the
// file (ASCII: within its line), every face's vertex index below the vertex count.
void check_ply(std::string_view bytes, const std::string& path);

}  // namespace velocity::detail
