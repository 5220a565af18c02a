#pragma once
/// Writing surface meshes for other tools: one entry point that dispatches on the extension.
///
/// | extension | writer | carries                                          |
/// |-----------|--------|--------------------------------------------------|
/// | .obj      | assimp | triangles, normals, UVs; one group per object     |
/// | .stl      | assimp | binary STL triangles, one solid per object merged |
/// | .ply      | assimp | binary PLY triangles, normals, UVs                |
///
/// Positions are written in metres. The output is written to a temporary sibling and renamed
/// into place, so a failure leaves no partial file.

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"

namespace viscera::exporters {

/// A named surface to export.
struct NamedSurface {
  std::string name;
  const core::SurfaceMesh* mesh = nullptr;
};

/// The extensions write_meshes() understands, e.g. ".obj".
std::vector<std::string> mesh_writer_extensions();

/// Writes the surfaces into one file whose format follows the extension. Throws
/// core::UsageError for an unknown extension, core::InputError for an empty or non-finite
/// mesh, and core::OutputError naming the file when writing fails.
void write_meshes(const std::vector<NamedSurface>& surfaces, const std::filesystem::path& path);

}  // namespace viscera::exporters
