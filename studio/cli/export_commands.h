#pragma once
/// `viscera export PKG --format vtk|gltf|glb|obj|stl|ply|msh|sofa -o OUT` (DESIGN.md §9):
/// a package, or some of its objects, for ParaView, Unity, Blender, gmsh or SOFA.

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `export` to `app`.
void add_export_commands(CLI::App& app);

}  // namespace viscera::cli
