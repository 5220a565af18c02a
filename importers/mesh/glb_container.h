#pragma once
/// The binary glTF container (glTF 2.0 specification §4.4, "GLB File Format"), checked before
/// assimp reads it: a 12-byte header (magic "glTF", version 2, total length) and chunks of
/// (length u32, type u32, data), all little-endian. Assimp 5.2 allocates whatever a chunk header
/// declares, so a damaged GLB of a few hundred bytes could ask for gigabytes (found by the
/// mesh_glb fuzz target, tests/fuzz/regressions/mesh_glb/).

#include <filesystem>

namespace viscera::importers {

/// True when the file starts with the GLB magic "glTF" (assimp reads it as GLB whatever the
/// extension).
bool is_glb_container(const std::filesystem::path& path);

/// Throws core::InputError naming the file and the byte offset when the header's version is not
/// 2, its total length differs from the file's size, or a chunk's declared length runs past the
/// end of the file.
void check_glb_container(const std::filesystem::path& path);

}  // namespace viscera::importers
