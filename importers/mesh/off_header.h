#pragma once
/// The counts an OFF file's header declares, checked before assimp reads the file. The header is
/// an optional keyword ([ST][C][N][4][n]OFF), a dimension after an "n" prefix, then the vertex,
/// face and edge counts; assimp 5.2 parses it this way, then allocates and zero-fills storage for
/// every declared vertex and face before it reads one line. An 89-byte file declaring
/// 499999999999999 vertices made it ask for 16.6 GB (the mesh_off fuzz target's finding,
/// tests/fuzz/regressions/mesh_off/).

#include <filesystem>

namespace viscera::importers {

/// Throws core::InputError naming the file when the vertex or face count does not fit the 32-bit
/// counter assimp reads it into, or when the declared vertices and faces need more bytes than
/// follow the counts: assimp reads each from a line of its own, at least one character and a line
/// end (2 bytes; the file's last line may lack its line end). A header assimp would refuse by
/// itself (no counts, a zero count, more than 3 coordinates) is left to assimp.
void check_off_counts(const std::filesystem::path& path);

}  // namespace viscera::importers
