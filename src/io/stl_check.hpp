// Internal: the check an STL file must pass before Assimp reads it.
//
// A binary STL file is an 80-byte header, a triangle count and 50 bytes per triangle,
// so its size says whether it is whole; Assimp 5.2.5 checks that. An ASCII one is a
// stream of keywords and numbers, and Assimp's reader takes what it can from a damaged
// one without a word: a file cut short loads the facets before the cut, a mangled
// number ("1k0") or keyword is skipped, and on such files it leaks memory. So an ASCII
// file must parse whole here first.
#pragma once

#include <string>
#include <string_view>

namespace velocity::detail {

// True when Assimp will read `bytes` (a whole .stl file) as ASCII: it starts with
// "solid" after blanks, and its size is not that of a binary file with the triangle
// count at byte 80 (binary files may start with "solid" too).
bool is_ascii_stl(std::string_view bytes);

// Throws velocity::Error naming `path` and the line unless `bytes` is a complete ASCII
// STL file: one or more `solid [NAME]` ... `endsolid [NAME]` blocks, each holding
// facets `facet normal N N N / outer loop / vertex X Y Z (three times) / endloop /
// endfacet`, each statement on a line of its own, keywords in lower case as Assimp
// reads them, every number finite, nothing after the last block.
void check_ascii_stl(std::string_view bytes, const std::string& path);

}  // namespace velocity::detail
