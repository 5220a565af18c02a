#pragma once
/// The header of a PLY file (Turk's polygon file format: "ply", a format line, element and
/// property lines, "end_header"), checked before assimp reads the file. Assimp 5.2 searches for
/// end_header for ever when a file lacks it (a 130-byte header kept it busy past 30 s: the
/// mesh_ply fuzz target's finding, tests/fuzz/regressions/mesh_ply/), and it sets up storage for
/// every declared element before reading them, so a short file declaring 400 million vertices
/// takes gigabytes.

#include <filesystem>

namespace viscera::importers {

/// Throws core::InputError naming the file when the header has no end_header line, an element
/// count does not fit a 32-bit count, or the declared elements need more bytes than follow
/// end_header. The least an element can take: in ASCII 2 bytes per property (a character and a
/// separator; a list at least its count), in binary the size of each scalar property and of each
/// list's count. Called only for files assimp's PLY reader will read, whatever their first line;
/// formats other than ascii, binary_little_endian and binary_big_endian are left to assimp (it
/// refuses them).
void check_ply_header(const std::filesystem::path& path);

}  // namespace viscera::importers
