#pragma once
// Checks a mesh file's declared counts against its bytes before Assimp reads it. Assimp 5.2
// allocates what a header declares before it reads the data (a 400-byte PLY declaring 10^11 faces
// took 19 GB), wraps counts beyond 32 bits (4294967308 faces read as 12), and imports a file whose
// data ends early as the shorter mesh it holds. So: every count must fit in the bytes that follow
// the header, and the data must not end before the counts are met.

#include <string>
#include <string_view>

namespace hullinspect::world::detail {

/// Throws InputError naming `source` if the STL or PLY in `bytes` (`format` "stl", "obj" or
/// "ply") declares more than it holds, or (PLY) has a header without an end_header line.
void check_mesh_counts(std::string_view bytes, const std::string& format,
                       const std::string& source);

}  // namespace hullinspect::world::detail
